#!/usr/bin/env python3
"""Peer for `trig-audit fit-surface` (issue 39): SciPy's bicubic splines (FITPACK)
on the same volcano grid, with the same number of coefficients as each of the
tool's fits. Not a project dependency: `pip install scipy numpy`.

Parameters as the tool's: row i -> u = i/86, column j -> v = j/60.

* `LSQBivariateSpline` (FITPACK `surfit`, kx = ky = 3, least squares with the
  interior knots given): a C2 bicubic spline with n interior knots per direction
  has n + 4 coefficients per direction. The tool's C1 fit of p patches has
  2p + 2 per direction, its C0 fit 3p + 1; so n = 2p - 2 (C1) or 3p - 3 (C0)
  equally spaced interior knots give the same count. For 1x1 there are no
  interior knots: the bicubic polynomials, the very space of the tool's 1x1
  Bernstein fit, so both must agree to rounding.
* `RectBivariateSpline` (FITPACK `regrid`, kx = ky = 3) chooses its knots
  itself from a smoothing factor s; s is bisected for the coefficient count
  closest to the target (its knots are adaptive, not equally spaced), and the
  count reached is printed.

Errors |S(u_i, v_j) - z_ij| over the 87 x 61 grid points, in metres; times are
the best of 7 runs of the fit alone (the grid already read).
"""
import csv
import pathlib
import sys
import time

import numpy as np
import scipy
from scipy.interpolate import LSQBivariateSpline, RectBivariateSpline

ROOT = pathlib.Path(__file__).resolve().parents[2]
rows = list(csv.reader(open(ROOT / "data/volcano/volcano.csv")))
Z = np.array([[float(x) for x in r[1:]] for r in rows[1:]])
assert Z.shape == (87, 61)
u = np.arange(87) / 86.0
v = np.arange(61) / 60.0
U, V = np.meshgrid(u, v, indexing="ij")


def best_time(f, runs=7):
    best = float("inf")
    out = None
    for _ in range(runs):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return out, best


def stats(S):
    e = np.abs(S - Z)
    return e.max(), e.mean(), np.sqrt((e ** 2).mean())


def lsq(nu, nv):
    tx = np.arange(1, nu + 1) / (nu + 1)
    ty = np.arange(1, nv + 1) / (nv + 1)
    f = lambda: LSQBivariateSpline(U.ravel(), V.ravel(), Z.ravel(), tx, ty, kx=3, ky=3)
    spl, t = best_time(f)
    return spl(u, v), (nu + 4) * (nv + 4), t


def rect(target):
    def fit(s):
        return RectBivariateSpline(u, v, Z, kx=3, ky=3, s=s)

    def count(spl):
        tx, ty = spl.get_knots()
        return (len(tx) - 4) * (len(ty) - 4)  # full knot vectors: n - 4 cubic coefficients each

    lo, hi = 0.0, float(((Z - Z.mean()) ** 2).sum())
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if count(fit(mid)) > target:
            lo = mid
        else:
            hi = mid
    best = min((hi, lo), key=lambda s: abs(count(fit(s)) - target))
    spl, t = best_time(lambda: fit(best))
    return spl(u, v), count(spl), t


print(f"SciPy {scipy.__version__}, NumPy {np.__version__}, Python {sys.version.split()[0]}")
print()
print("| Continuity of the tool's fit | Patches | Tool coefficients | Peer | Peer coefficients | Max | Mean | RMS | Time (ms) |")
print("|---|---|---|---|---|---|---|---|---|")
for join, per in (("C1", lambda p: 2 * p - 2), ("C0", lambda p: 3 * p - 3)):
    for pu, pv in ((1, 1), (2, 2), (4, 4), (8, 6)):
        nu, nv = per(pu), per(pv)
        ours = (nu + 4) * (nv + 4)
        S, n, t = lsq(nu, nv)
        mx, mean, rms = stats(S)
        print(f"| {join} | {pu}×{pv} | {ours} | LSQBivariateSpline ({nu}+{nv} equally spaced interior knots) | {n} | {mx:.4f} | {mean:.4f} | {rms:.4f} | {1000 * t:.2f} |")
        S, n, t = rect(ours)
        mx, mean, rms = stats(S)
        print(f"| {join} | {pu}×{pv} | {ours} | RectBivariateSpline (s bisected, adaptive knots) | {n} | {mx:.4f} | {mean:.4f} | {rms:.4f} | {1000 * t:.2f} |")
