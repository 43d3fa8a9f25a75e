"""Part C6: a half-angle basis on t ∈ [0, π/2] with a shape parameter λ (CONSTRUCTED, flagged as such).

Start from the quadratic B-basis of span{1, cos t, sin t} on [0, π/2] in half angles (B4 at α = π/2,
BVP 2022 eq. (2); examples/trig-bbasis-half-angle.toml): with
  x = sin(π/4 − t/2)/sin(π/4) = cos(t/2) − sin(t/2),   y = sin(t/2)/sin(π/4) = √2 sin(t/2),
one has x² + √2·xy + y² = 1. Add a Han-type parameter to the end functions:
  b0 = x²(1 − λy),   b2 = y²(1 − λx),   b1 = 1 − b0 − b2 = xy(√2 + λ(x + y)).
(I know no paper printing exactly this family; it is the simplest honest half-angle analogue of Han 2002.)
Derivatives w.r.t. t.
"""

import sympy as sp
from _exact import check, iv_digits, iv_sign, trig_zero

t, lam, u = sp.symbols("t lambda u", real=True)
R = sp.Rational
r2 = sp.sqrt(2)
X = sp.cos(t / 2) - sp.sin(t / 2)
Y = r2 * sp.sin(t / 2)
b0 = X**2 * (1 - lam * Y)
b2 = Y**2 * (1 - lam * X)
b1 = 1 - b0 - b2
b1c = X * Y * (r2 + lam * (X + Y))
b = [b0, b1c, b2]
H = lambda e: e.subs(t, 2 * u)   # noqa: E731
print("half-angle-lambda: b0 = x²(1 − λy), b1 = xy(√2 + λ(x + y)), b2 = y²(1 − λx) on [0, π/2]")
check(trig_zero(H(sp.sin(sp.pi / 4 - t / 2) / sp.sin(sp.pi / 4) - X), [u]), "x = sin(π/4 − t/2)/sin(π/4) = cos(t/2) − sin(t/2)")
check(trig_zero(H(X**2 + r2 * X * Y + Y**2 - 1), [u]), "x² + √2·xy + y² = 1")
check(trig_zero(H(b1 - b1c), [u]), "b1 = 1 − b0 − b2 = xy(√2 + λ(x + y)); unity holds by construction")
check(all(trig_zero(H(b[i].subs(t, sp.pi / 2 - t) - b[2 - i]), [u]) for i in range(3)), "symmetry b_i(t) = b_{2−i}(π/2 − t) (x ↔ y)")
check(trig_zero(H(X + Y - sp.cos(sp.pi / 8 - t / 2) / sp.cos(sp.pi / 8)), [u]),
      "x + y = cos(π/8 − t/2)/cos(π/8) ∈ [1, sec(π/8)] on [0, π/2] (max at t = π/4, min 1 at both ends)")
print("  On [0, π/2]: x, y ≥ 0, y = √2 sin(t/2) ∈ [0, 1], x ∈ [0, 1].")
print("  b0 ≥ 0 ⇔ 1 − λy ≥ 0 for y ∈ [0, 1] ⇔ λ ≤ 1 (near t = π/2, where y → 1 and x² > 0 for t < π/2); b2 likewise.")
print("  b1 ≥ 0 ⇔ √2 + λ(x + y) ≥ 0 on [1, sec(π/8)] ⇔ λ ≥ −√2 cos(π/8) (binding at t = π/4).")
lo = -r2 * sp.cos(sp.pi / 8)
z = sp.Symbol("z")
mp_ = sp.minimal_polynomial(lo, z)
check(mp_ == 2 * z**4 - 4 * z**2 + 1 and sp.simplify(lo + sp.sqrt(1 + r2 / 2)) == 0,
      "left end λ₋ = −√2 cos(π/8) = −√(1 + √2/2) = −√(4 + 2√2)/2 ≈ −1.306562964876; minimal polynomial 2z⁴ − 4z² + 1")
Pz = sp.Poly(mp_, z)
iso = [iv for iv, _ in Pz.intervals(eps=R(1, 10**9)) if iv[0] <= sp.N(lo, 30) <= iv[1]][0]
check(R(-1307, 1000) < lo < R(-1306, 1000), f"isolating interval of λ₋: (−1307/1000, −1306/1000); finer [{iso[0]}, {iso[1]}]")
print(f"  ⇒ MAXIMAL RANGE exactly [−√(1 + √2/2), 1] ≈ [{sp.N(lo, 13)}, 1] (both ends closed).")
print("    In z = tan(t/4) ∈ [0, √2 − 1] the functions are polynomials over Q(√2) up to the factor (1 + z²)^{−3}.")
# witnesses at the left end: t = π/4 (x = y = 1/(2cos(π/8)))
for l0, sgn in [(R(-131, 100), -1), (R(-1307, 1000), -1), (R(-1306, 1000), 1)]:
    val = b1c.subs({lam: l0, t: sp.pi / 4})
    s_ = iv_sign(val, {})
    check(s_ == sgn, f"λ = {l0}, t = π/4: b1 = {iv_digits(val, {})} ({'< 0: outside' if sgn < 0 else '> 0: inside; min of √2 + λ(x+y) is there'})")
wv = b1c.subs({lam: R(-3, 2), t: sp.pi / 4})
check(sp.simplify(wv - (r2 - R(3, 2) / sp.cos(sp.pi / 8)) / (2 + r2)) == 0 and iv_sign(wv, {}) < 0,
      f"λ = −3/2, t = π/4: b1 = (√2 − (3/2)sec(π/8))/(2 + √2) = {iv_digits(wv, {})} < 0 (xy = 1/(2 + √2), x + y = sec(π/8))")
# witnesses at the right end λ = 1: t near π/2 (y → 1)
for l0, t0 in [(R(101, 100), R(157, 100)), (2, sp.pi / 3)]:
    val = b0.subs({lam: l0, t: t0})
    check(iv_sign(val, {}) < 0, f"λ = {l0}, t = {t0}: b0 = {iv_digits(val, {})} < 0")
check(sp.simplify(b0.subs({lam: 2, t: sp.pi / 3}) - (1 - r2) * (2 - sp.sqrt(3)) / 2) == 0,
      "exact: λ = 2, t = π/3: b0 = (1 − √2)(2 − √3)/2 ≈ −0.0555 (x = (√3 − 1)/2, y = √2/2)")
print("  just inside the right end: λ = 1: 1 − y ≥ 0 on [0, π/2], so b0, b2 ≥ 0 (and b1 ≥ 0 since λ > 0).")

# ---- endpoint derivatives (w.r.t. t); b_i^(k)(π/2) = (−1)^k b_{2−i}^(k)(0)
print("  endpoint derivatives at t = 0 (b0, b1, b2):")
expect = {
    0: [1, 0, 0],
    1: [-(r2 * lam + 2) / 2, (r2 * lam + 2) / 2, 0],
    2: [r2 * lam, -r2 * lam + lam - 1, 1 - lam],
    3: [(r2 * lam + 8) / 8, -(r2 * lam + 12 * lam + 8) / 8, 3 * lam / 2],
}
for kk in range(4):
    at0 = [sp.nsimplify(sp.simplify(sp.diff(f, t, kk).subs(t, 0))) for f in b]
    atE = [sp.simplify(sp.diff(f, t, kk).subs(t, sp.pi / 2)) for f in b]
    check(all(sp.simplify(p_ - q_) == 0 for p_, q_ in zip(at0, expect[kk])), f"order {kk} at t = 0: {expect[kk]}")
    check(all(sp.simplify(atE[i] - (-1) ** kk * at0[2 - i]) == 0 for i in range(3)), f"order {kk} at π/2 mirrors t = 0")
d1 = [sp.simplify(sp.diff(f, t).subs(t, 0)) for f in b]
check(sp.simplify(d1[0] + 1 + lam * r2 / 2) == 0 and sp.simplify(d1[1] - 1 - lam * r2 / 2) == 0 and d1[2] == 0,
      "b'(0) = (−(1 + λ/√2), 1 + λ/√2, 0): r'(0) = (1 + λ√2/2)(P1 − P0); vanishes at λ = −√2 (outside the range)")
print("done")
