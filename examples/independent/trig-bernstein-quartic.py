"""Part C4: the normalised B-basis of the trigonometric polynomials of degree 2,
span{1, cos t, sin t, cos 2t, sin 2t}, on t ∈ [0, α].

Source: J. Sánchez-Reyes, "Harmonic rational Bézier curves, p-Bézier curves and trigonometric polynomials",
CAGD 15 (1998) 909-923 (form recalled, print NOT retrieved); the same basis for order n is written in
Á. Róth, arXiv:1404.3767, as t_{2n,i}^α sin^{2n−i}((α − t)/2) sin^i(t/2), α ∈ (0, π) (also recalled).
The coefficients are DERIVED here from unity: with S = sin(α/2), c = cos(α/2), x = sin((α−t)/2)/S,
y = sin(t/2)/S one has x² + 2c·xy + y² = 1, so 1 = (x² + 2cxy + y²)² gives
  b0 = x⁴, b1 = 4c x³y, b2 = (2 + 4c²) x²y², b3 = 4c xy³, b4 = y⁴.
Derivatives w.r.t. t.
"""

import sympy as sp
from _exact import check, iv_digits, iv_sign, trig_zero

t, a, u, v = sp.symbols("t alpha u v", real=True)
R = sp.Rational
S2, c = sp.sin(a / 2), sp.cos(a / 2)
X = sp.sin((a - t) / 2) / S2
Y = sp.sin(t / 2) / S2
b = [X**4, 4 * c * X**3 * Y, (2 + 4 * c**2) * X**2 * Y**2, 4 * c * X * Y**3, Y**4]
H = lambda e: e.subs({t: 2 * u, a: 2 * v})   # noqa: E731
print("trig-bernstein-quartic: B-basis of trigonometric polynomials of degree 2 on [0, α]")
for i, f in enumerate(b):
    print(f"  b{i} =", f)
check(trig_zero(H(X**2 + 2 * c * X * Y + Y**2 - 1), [u, v]), "x² + 2cos(α/2)·xy + y² = 1 (sin²(p+q) = sin²p + sin²q + 2cos(p+q) sin p sin q)")
check(trig_zero(H(sum(b) - 1), [u, v]), "unity Σ b_i = 1")
check(all(trig_zero(H(b[i].subs(t, a - t) - b[4 - i]), [u, v]) for i in range(5)), "symmetry b_i(t) = b_{4−i}(α − t)")
# the functions lie in the space: with t = 2u, α = 2v, b_i·sin⁴(α/2) is a product of four sines of ±u + const,
# i.e. a Laurent polynomial in Z = e^{iu} with exponents in {−4, −2, 0, 2, 4} only (frequencies 0, 1, 2 in t)
Z, W = sp.symbols("Z W")
for i, f in enumerate(b):
    e = sp.expand(H(f * S2**4).rewrite(sp.exp))
    rep = {}
    for ex in e.atoms(sp.exp):
        arg = sp.expand(ex.args[0] / sp.I)
        rep[ex] = Z ** arg.coeff(u) * W ** arg.coeff(v)
        assert sp.expand(arg - arg.coeff(u) * u - arg.coeff(v) * v) == 0
    e = sp.expand(e.xreplace(rep))
    ex = {sp.Poly(sp.expand(term * Z**10), Z).degree() - 10 for term in sp.Add.make_args(e)}
    assert ex <= {-4, -2, 0, 2, 4}, (i, ex)
check(True, "each b_i·sin⁴(α/2) has only the frequencies 0, 1, 2 in t: b_i ∈ span{1, cos t, sin t, cos 2t, sin 2t}")
zo = [sp.limit(f / t**i, t, 0) for i, f in enumerate(b)]
check(trig_zero(H(zo[1] - 2 * c / S2) ,[v]) and trig_zero(H(zo[3] - c / (2 * S2**3)), [v]) and zo[0] == 1,
      "b_i has a zero of order exactly i at t = 0 (leading coefficients 1, 2cos(α/2)/sin(α/2), (1 + 2cos²(α/2))/(2 sin²(α/2)),"
      " cos(α/2)/(2 sin³(α/2)), 1/(16 sin⁴(α/2))) ⇒ linearly independent ⇔ cos(α/2) ≠ 0 (α ∈ (0, 2π)); rank 3 at α = π")
print("  nonnegativity: x, y ≥ 0 on [0, α] for 0 < α < 2π; b0, b2, b4 ≥ 0 always; sign b1 = sign b3 = sign cos(α/2).")
print("  ⇒ nonnegative exactly for α ∈ (0, π]; at α = π, b1 ≡ b3 ≡ 0 (not a basis): a basis for α ∈ (0, π).")
print("    (α > 2π: x·y takes both signs, as for the quadratic; α = 2kπ undefined.)")
check(sp.simplify(b[1].subs(a, sp.pi)) == 0 and sp.simplify(b[3].subs(a, sp.pi)) == 0, "α = π: b1 ≡ b3 ≡ 0")
w = sp.nsimplify(sp.simplify(b[1].subs({a: 4 * sp.pi / 3, t: 2 * sp.pi / 3})))
check(w == -2, "exact witness: α = 4π/3, t = 2π/3: x = y = 1, c = −1/2: b1 = 4c = −2 (b3 = −2 too)")
vv = iv_digits(b[1], {a: R(63, 20), t: R(63, 40)})
check(iv_sign(b[1], {a: R(63, 20), t: R(63, 40)}) < 0, f"just outside: α = 63/20 = 3.15, t = 63/40: b1 = {vv} < 0")
check(iv_sign(c, {a: R(157, 50)}) > 0, "just inside: α = 157/50 = 3.14: cos(α/2) > 0, all b_i ≥ 0")

# ---- endpoint derivatives at t = 0 (b_i^(k)(α) = (−1)^k b_{4−i}^(k)(0)); K = cot(α/2)
K = c / S2
print("  endpoint derivatives at t = 0 (w.r.t. t), K = cot(α/2), Q = 1/sin²(α/2):")
Q = 1 / S2**2
exp_forms = {
    0: ([1, 0, 0, 0, 0], "(1, 0, 0, 0, 0)"),
    1: ([-2 * K, 2 * K, 0, 0, 0], "(−2K, 2K, 0, 0, 0)"),
    2: ([3 * K**2 - 1, -6 * K**2 + 1 - 1 + 0, (1 + 2 * c**2) * Q, 0, 0], "(3K² − 1, −6K², (1 + 2cos²(α/2))/sin²(α/2), 0, 0)"),
    3: ([(1 - 4 * sp.cos(a)) * K * Q, (2 + 7 * sp.cos(a)) * K * Q, -3 * (2 + sp.cos(a)) * K * Q, 3 * K * Q, 0],
        "(1 − 4cos α, 2 + 7cos α, −3(2 + cos α), 3, 0)·cos(α/2)/sin³(α/2)"),
}
for kk in range(4):
    at0 = [sp.diff(f, t, kk).subs(t, 0) for f in b]
    atA = [sp.diff(f, t, kk).subs(t, a) for f in b]
    ok = all(trig_zero(H(p - q), [v]) for p, q in zip(at0, exp_forms[kk][0]))
    if not ok:
        print("    computed:", [sp.simplify(p) for p in at0])
    check(ok, f"order {kk} at t = 0: {exp_forms[kk][1]}")
    check(all(trig_zero(H(atA[i] - (-1) ** kk * at0[4 - i]), [v]) for i in range(5)),
          f"order {kk} at t = α: b_i^({kk})(α) = (−1)^{kk} b_(4−i)^({kk})(0)")
P = sp.symbols("P0:5")
r = sum(f * p for f, p in zip(b, P))
check(trig_zero(H(sp.diff(r, t).subs(t, 0) - 2 * K * (P[1] - P[0])), [v]), "r'(0) = 2cot(α/2)(P1 − P0)")
check(sp.limit(a * 2 * sp.cot(a / 2), a, 0) == 4, "α·2cot(α/2) → 4 (quartic Bernstein in t/α)")
print("done")
