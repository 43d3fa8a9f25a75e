#!/usr/bin/env python3
"""Independent check of `trig-audit fit-surface` (issue 39): the 1x1 least-squares
fit of the volcano grid solved densely with NumPy's `lstsq` (one design matrix
of 87*61 rows and 16 columns, b_i(u) b_j(v), no Kronecker separation), with the
basis functions typed here from their sources: the cubic Bernstein polynomials
and the thesis's cubic trigonometric basis (3.7) at m = 0.6,

  b0 = (1 - s)^2 (1 - m s),  b1 = m s (1 - s)^2 - 2 s (s - 1),
  b2 = m c (1 - c)^2 - 2 c (c - 1),  b3 = (1 - c)^2 (1 - m c),  s = sin(pi u/2), c = cos(pi u/2).

Compares max, mean and RMS error with the tool's (printed to 4 decimals).
Usage: python3 issue39_lstsq_check.py [path/to/trig-audit]   (default target/release/trig-audit)
"""
import csv
import json
import pathlib
import subprocess
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target/release/trig-audit")
GRID = ROOT / "data/volcano/volcano.csv"
rows = list(csv.reader(open(GRID)))
Z = np.array([[float(x) for x in r[1:]] for r in rows[1:]])
u = np.arange(Z.shape[0]) / (Z.shape[0] - 1)
v = np.arange(Z.shape[1]) / (Z.shape[1] - 1)


def bernstein(t):
    return np.stack([(1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t ** 2 * (1 - t), t ** 3], axis=1)


def thesis(t, m=0.6):
    s, c = np.sin(np.pi * t / 2), np.cos(np.pi * t / 2)
    return np.stack([(1 - s) ** 2 * (1 - m * s), m * s * (1 - s) ** 2 - 2 * s * (s - 1),
                     m * c * (1 - c) ** 2 - 2 * c * (c - 1), (1 - c) ** 2 * (1 - m * c)], axis=1)


def dense(b):
    Bu, Bv = b(u), b(v)
    # row (i, j), column (k, l): b_k(u_i) b_l(v_j)
    A = np.einsum("ik,jl->ijkl", Bu, Bv).reshape(len(u) * len(v), 16)
    x, *_ = np.linalg.lstsq(A, Z.ravel(), rcond=None)
    e = np.abs(A @ x - Z.ravel())
    return e.max(), e.mean(), np.sqrt((e ** 2).mean())


def tool(family):
    out = subprocess.run([BIN, "fit-surface", "--grid", str(GRID), "--family", family,
                          "--patches", "1x1", "--summary", "--format", "json"],
                         check=True, capture_output=True, text=True).stdout
    table = json.loads(out)["tables"][0]
    cols = table["columns"]
    vals = [c["text"] for c in table["rows"][0]["values"]]
    return tuple(float(vals[cols.index(k)]) for k in ("Max", "Mean", "RMS"))


for family, b in (("bernstein3", bernstein), ("thesis-cubic", thesis)):
    ours, theirs = dense(b), tool(family)
    print(f"{family:13} dense lstsq max {ours[0]:.6f} mean {ours[1]:.6f} RMS {ours[2]:.6f}"
          f" | tool {theirs[0]:.4f} {theirs[1]:.4f} {theirs[2]:.4f}")
    for a, t in zip(ours, theirs):
        assert abs(a - t) <= 5.1e-5, (family, ours, theirs)
print("[ok] the tool's 1x1 errors are the dense least-squares errors (to the 4 printed decimals)")
