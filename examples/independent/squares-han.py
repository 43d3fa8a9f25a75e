"""Part C7: a basis whose end functions are perfect squares (CONSTRUCTED, flagged as such).

The squares of the end functions of Han's quadratic trigonometric basis (Han, CAGD 19 (2002); A1):
  b0 = (1 − sin t)²(1 − λ sin t)²,   b2 = (1 − cos t)²(1 − λ cos t)²,   b1 = 1 − b0 − b2,   t ∈ [0, π/2].
b0 and b2 are squares, so their discriminants (in t or in m = tan(t/2)) vanish identically and a boundary
polynomial must come from the square-free part. Derivatives w.r.t. t.
"""

import sympy as sp
from _exact import (PYTH_M, check, describe_alg, numerator_posden, param_set, pyth, show_intervals, trig_at,
                    trig_zero, weierstrass)

t, lam, m = sp.symbols("t lambda m", real=True)
R = sp.Rational
s, c = sp.sin(t), sp.cos(t)
b0 = (1 - s) ** 2 * (1 - lam * s) ** 2
b2 = (1 - c) ** 2 * (1 - lam * c) ** 2
b1 = 1 - b0 - b2
b = [b0, b1, b2]
print("squares-han: b0 = (1 − s)²(1 − λs)², b2 = (1 − c)²(1 − λc)², b1 = 1 − b0 − b2 on [0, π/2]")
check(all(trig_zero(b[i].subs(t, sp.pi / 2 - t) - b[2 - i], [t]) for i in range(3)), "symmetry b_i(t) = b_{2−i}(π/2 − t)")
N = [numerator_posden(weierstrass(f, t, m), m) for f in b]
for i, n in enumerate(N):
    print(f"  numerator of b{i} in m = tan(t/2) (denominator (1 + m²)⁴ removed): {sp.factor(n)}")
F1 = lam * m**2 - lam * m + m**2 + 1
F2 = lam * (m**4 + 2 * m**3 + 2 * m**2 - 2 * m + 1) + (1 + m**2) ** 2
check(sp.expand(N[1] + 4 * m * (m - 1) * F1 * F2) == 0,
      "b1 numerator = 4m(1 − m)·F1·F2, F1 = (1 + λ)m² − λm + 1, F2 = λ(m⁴ + 2m³ + 2m² − 2m + 1) + (1 + m²)²")
check(sp.discriminant(N[0], m) == 0 and sp.discriminant(N[2], m) == 0,
      "disc_m of the numerators of b0 and b2 vanish identically (perfect squares)")
sf0 = sp.sqf_part(N[0], m)
print("  square-free part of b0's numerator:", sp.factor(sf0), "→ critical λ from its discriminant/ends only (no sign change: a square)")
iv, samples, crit = param_set(N, m, lam, 0, 1, prefer=PYTH_M)
print("  critical λ:", [describe_alg(r) for r in crit])
for l0, ok, w in samples:
    print(f"    sample λ = {l0}: {'all ≥ 0' if ok else f'b{w[0]} < 0 at m = {w[1]}'}")
print("  maximal nonnegativity set:", show_intervals(iv))
hi = 2 + 2 * sp.sqrt(2)
check(len(iv) == 1 and iv[0][0] == -1 and sp.simplify(iv[0][1] - hi) == 0,
      "MAXIMAL RANGE exactly [−1, 2 + 2√2] (right end: root of λ² − 4λ − 4, ≈ 4.828427124746)")
print("  why: F2(0) = 1 + λ (b1'(0) = 4(1 + λ)) ⇒ λ ≥ −1; F2 ≥ 0 on [0, 1] for λ ≥ −1 (F2 = (1+λ)(1+m²)² − 2λm(1−m)(1+m)·…,")
print("  checked exactly by the cell decision above). F1 = 1 + m² − λm(1 − m) ≥ 0 ⇔ λ ≤ min (1 + m²)/(m(1 − m)) = 2 + 2√2")
print("  (at m = √2 − 1, i.e. t = π/4).")
check(sp.simplify(((1 + m**2) / (m * (1 - m))).subs(m, sp.sqrt(2) - 1) - hi) == 0 and
      sp.solve(sp.diff((1 + m**2) / (m * (1 - m)), m), m) == [-1 + sp.sqrt(2), -sp.sqrt(2) - 1],
      "(1 + m²)/(m(1 − m)) has its minimum 2 + 2√2 on (0, 1) at m = √2 − 1 (t = π/4)")
# witnesses with rational sin, cos
for l0, mm in [(R(-11, 10), R(1, 50)), (R(-101, 100), R(1, 1000)), (R(49, 10), R(2, 5)), (5, R(2, 5))]:
    val = trig_at(b1.subs(lam, l0), t, mm)
    sn, cs = pyth(mm)
    check(val < 0, f"λ = {l0}, (sin t, cos t) = ({sn}, {cs}): b1 = {val} ≈ {sp.N(val, 6)} < 0")
check(all(sp.Poly(N[1].subs(lam, l0), m).count_roots(R(1, 10**6), 1 - R(1, 10**6)) == 0 for l0 in [R(-99, 100), R(24, 5)]),
      "λ = −99/100, 24/5: b1's numerator has no zero in (0, 1) (Sturm) — b1 > 0 inside")
# endpoint derivatives
print("  endpoint derivatives at t = 0 (b0, b1, b2); b_i^(k)(π/2) = (−1)^k b_{2−i}^(k)(0):")
q2 = 2 * (lam**2 + 4 * lam + 1)
q3 = 2 * (lam + 1) * (6 * lam - 1)
exp0 = {0: [1, 0, 0], 1: [-2 * (1 + lam), 2 * (1 + lam), 0], 2: [q2, -q2, 0], 3: [-q3, q3, 0]}
for kk in range(4):
    at0 = [sp.expand(sp.diff(f, t, kk).subs(t, 0)) for f in b]
    atE = [sp.expand(sp.diff(f, t, kk).subs(t, sp.pi / 2)) for f in b]
    check(all(sp.expand(p_ - q_) == 0 for p_, q_ in zip(at0, exp0[kk])), f"order {kk} at t = 0: {[sp.factor(v) for v in exp0[kk]]}")
    check(all(sp.expand(atE[i] - (-1) ** kk * at0[2 - i]) == 0 for i in range(3)), f"order {kk} at π/2 mirrors t = 0")
d1 = [sp.expand(sp.diff(f, t).subs(t, 0)) for f in b]
print("  (b2 = (1 − cos t)²(…)² has a zero of order 4 at t = 0, so its column is 0 up to order 3.)")
check(d1 == [sp.expand(-2 * (1 + lam)), sp.expand(2 * (1 + lam)), 0], "b'(0) = (−2(1 + λ), 2(1 + λ), 0): r'(0) = 2(1 + λ)(P1 − P0), 0 at the end λ = −1")
# joins (the spec audit's standard battery): b2 has a zero of order 4 at t = 0, so Q2 never enters Q''(0)
P = sp.symbols("P0:3")
Q = sp.symbols("Q0:3")
rP = sum(f * p for f, p in zip(b, P))
rQ = sum(f * q for f, q in zip(b, Q))
c1 = {Q[0]: P[2], Q[1]: 2 * P[2] - P[1]}
check(sp.expand(sp.diff(rQ, t).subs(t, 0).subs(c1) - sp.diff(rP, t).subs(t, sp.pi / 2)) == 0,
      "C¹ join: Q0 = P2, Q1 = 2P2 − P1 (for λ ≠ −1; at λ = −1 both end tangents vanish)")
jump2 = sp.factor(sp.expand(sp.diff(rQ, t, 2).subs(t, 0).subs(c1) - sp.diff(rP, t, 2).subs(t, sp.pi / 2)))
check(sp.expand(jump2 - 4 * (lam**2 + 4 * lam + 1) * (P[1] - P[2])) == 0,
      "C² join: Q''(0) − P''(π/2) = 4(λ² + 4λ + 1)(P1 − P2), free of Q2: C² only if λ = −2 ± √3 or P1 = P2"
      " (λ = −2 + √3 ≈ −0.268 lies inside [−1, 1]: there every C¹ join is C²)")
print("done")
