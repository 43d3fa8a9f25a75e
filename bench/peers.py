#!/usr/bin/env python3
"""Peers of the batch benchmarks (crates/core/benches/batch.rs), same points.

The thesis cubic (3.7), all four functions, m = 3/5, at the points
u_i = i/(n-1) of [0, 1], theta = pi*u/2:

* NumPy, vectorised (the form a Python user writes), n = 10^6, float64;
* mpmath at 336 bits, one point at a time, n = 10^3.

Prints nanoseconds (NumPy) or microseconds (mpmath) per point, the best of
several repeats. NumPy and mpmath are installed with pip for this script
only (`pip install numpy mpmath`); they are not project dependencies.
Run: python3 bench/peers.py
"""

import timeit

import mpmath
import numpy as np

N = 1_000_000
MP_POINTS = 1_000
PREC = 336
M = 0.6


def numpy_cubic(u, m):
    theta = u * (np.pi / 2)
    s = np.sin(theta)
    c = np.cos(theta)
    b0 = (1 - s) ** 2 * (1 - m * s)
    b1 = m * s * (1 - s) ** 2 - 2 * s * (s - 1)
    b2 = m * c * (1 - c) ** 2 - 2 * c * (c - 1)
    b3 = (1 - c) ** 2 * (1 - m * c)
    return b0, b1, b2, b3


def numpy_sin_cos(u):
    theta = u * (np.pi / 2)
    return np.sin(theta), np.cos(theta)


def mpmath_cubic(us, m):
    half_pi = mpmath.pi / 2
    out = []
    for u in us:
        theta = u * half_pi
        s = mpmath.sin(theta)
        c = mpmath.cos(theta)
        out.append(
            (
                (1 - s) ** 2 * (1 - m * s),
                m * s * (1 - s) ** 2 - 2 * s * (s - 1),
                m * c * (1 - c) ** 2 - 2 * c * (c - 1),
                (1 - c) ** 2 * (1 - m * c),
            )
        )
    return out


def best(stmt, number, repeat=7):
    return min(timeit.repeat(stmt, number=number, repeat=repeat)) / number


def main():
    u = np.linspace(0.0, 1.0, N)
    cubic = best(lambda: numpy_cubic(u, M), 3)
    sincos = best(lambda: numpy_sin_cos(u), 3)
    print(f"numpy {np.__version__}: thesis cubic, 4 functions, vectorised: {cubic / N * 1e9:.1f} ns/point")
    print(f"numpy {np.__version__}: np.sin + np.cos alone: {sincos / N * 1e9:.1f} ns/point")
    mpmath.mp.prec = PREC
    us = [mpmath.mpf(i) / (MP_POINTS - 1) for i in range(MP_POINTS)]
    m = mpmath.mpf(3) / 5
    t = best(lambda: mpmath_cubic(us, m), 1, repeat=5)
    print(f"mpmath {mpmath.__version__} ({PREC} bits): thesis cubic, 4 functions: {t / MP_POINTS * 1e6:.2f} us/point")
    t = best(lambda: [mpmath.sin(x) for x in us], 1, repeat=5) + best(lambda: [mpmath.cos(x) for x in us], 1, repeat=5)
    print(f"mpmath {mpmath.__version__} ({PREC} bits): sin + cos alone: {t / MP_POINTS * 1e6:.2f} us/point")


if __name__ == "__main__":
    main()
