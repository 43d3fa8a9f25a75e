"""Part C3: the quadratic H-Bézier basis, span{1, sinh t, cosh t} on t ∈ [0, α], α > 0.

The hyperbolic twin of the quadratic C-Bézier basis (B4): the degree-2 step of the integral recursion with
C_0^1 = sinh(α − t)/sinh α, C_1^1 = sinh t/sinh α (checked in h-bezier-cubic.py), as quoted for the
H-Bézier functions in Boundary Value Problems 2022 (doi 10.1186/s13661-022-01647-5, after Wang et al.;
the degree-2 H-form itself was not retrieved — derived here):
  b0 = (cosh(α − t) − 1)/(cosh α − 1),  b2 = (cosh t − 1)/(cosh α − 1),  b1 = 1 − b0 − b2,
half-angle form: b0 = sinh²((α−t)/2)/sinh²(α/2), b2 = sinh²(t/2)/sinh²(α/2),
                 b1 = 2 cosh(α/2) sinh(t/2) sinh((α − t)/2)/sinh²(α/2).
The cubic H-Bézier basis is B2 (h-bezier-cubic.py). Derivatives w.r.t. t.
"""

import sympy as sp
from _exact import check, hyp_zero, iv_digits

t, a, x, y = sp.symbols("t alpha x y", positive=True)
sh, ch = sp.sinh, sp.cosh
cm = ch(a) - 1
b0 = (ch(a - t) - 1) / cm
b2 = (ch(t) - 1) / cm
b1 = 1 - b0 - b2
b = [b0, b1, b2]
half = [sh((a - t) / 2) ** 2 / sh(a / 2) ** 2, 2 * ch(a / 2) * sh(t / 2) * sh((a - t) / 2) / sh(a / 2) ** 2,
        sh(t / 2) ** 2 / sh(a / 2) ** 2]
H = lambda e: e.subs({t: 2 * x, a: 2 * y})   # noqa: E731
print("h-bezier-quadratic: span{1, sinh t, cosh t} on [0, α]")
check(all(hyp_zero(H(p - q), [x, y]) for p, q in zip(b, half)), "half-angle forms (b1 = 2 cosh(α/2) sinh(t/2) sinh((α−t)/2)/sinh²(α/2))")
check(hyp_zero(sum(b) - 1, [t, a]), "unity (by construction) and b1 = (cosh α + 1 − cosh t − cosh(α − t))/(cosh α − 1)")
check(all(hyp_zero(b[i].subs(t, a - t) - b[2 - i], [t, a]) for i in range(3)), "symmetry b_i(t) = b_{2−i}(α − t)")
print("  nonnegative for EVERY α > 0: b0, b2 are squares over sinh²(α/2) > 0; in b1 every factor is > 0 on (0, α).")
print("  No finite end: the maximal range is (0, ∞) (α → 0: the quadratic Bernstein basis in t/α).")
xx = sp.Symbol("u")
check(all(sp.expand(sp.limit(f.subs(t, a * xx), a, 0) - g) == 0 for f, g in zip(b, [(1 - xx) ** 2, 2 * xx * (1 - xx), xx**2])),
      "α → 0 with t = αu: ((1 − u)², 2u(1 − u), u²)")
# a sample value, certified (for the spec file's check of a large α)
print("  sample: α = 10, t = 5: b1 =", iv_digits(b1, {a: 10, t: 5}), "(= 2cosh 5 sinh² 2.5/sinh² 5, 30 digits)")

# ---- endpoint derivatives: b_i^(k)(α) = (−1)^k b_{2−i}^(k)(0)
forms = {
    0: [1, 0, 0],
    1: [-sh(a) / cm, sh(a) / cm, 0],
    2: [ch(a) / cm, -(1 + ch(a)) / cm, 1 / cm],
    3: [-sh(a) / cm, sh(a) / cm, 0],
}
txt = {0: "(1, 0, 0)", 1: "(−sinh α, sinh α, 0)/(cosh α − 1) = (−coth(α/2), coth(α/2), 0)",
       2: "(cosh α, −(1 + cosh α), 1)/(cosh α − 1);  b1''(0) = −coth²(α/2)",
       3: "(−sinh α, sinh α, 0)/(cosh α − 1) = (−coth(α/2), coth(α/2), 0)"}
for kk in range(4):
    at0 = [sp.diff(f, t, kk).subs(t, 0) for f in b]
    atA = [sp.diff(f, t, kk).subs(t, a) for f in b]
    check(all(hyp_zero(p - q, [a]) for p, q in zip(at0, forms[kk])), f"order {kk} at t = 0: {txt[kk]}")
    check(all(hyp_zero(atA[i] - (-1) ** kk * forms[kk][2 - i], [a]) for i in range(3)),
          f"order {kk} at t = α: b_i^({kk})(α) = (−1)^{kk} b_(2−i)^({kk})(0)")
check(hyp_zero(H(sh(a) / cm - ch(a / 2) / sh(a / 2)), [y]) and hyp_zero(H((1 + ch(a)) / cm - ch(a / 2) ** 2 / sh(a / 2) ** 2), [y]),
      "sinh α/(cosh α − 1) = coth(α/2), (1 + cosh α)/(cosh α − 1) = coth²(α/2)")
print("  note: order 3 at 0 is (−coth, coth, 0) here but (coth→cot: +cot, −cot, 0) for the trigonometric B4 (sinh''' = cosh, sin''' = −cos).")
P = sp.symbols("P0:3")
r = sum(f * p for f, p in zip(b, P))
check(hyp_zero(sp.diff(r, t).subs(t, 0) - sh(a) / cm * (P[1] - P[0]), [a]) and
      hyp_zero(sp.diff(r, t).subs(t, a) - sh(a) / cm * (P[2] - P[1]), [a]),
      "r'(0) = coth(α/2)(P1 − P0), r'(α) = coth(α/2)(P2 − P1)")
check(sp.limit(a / sp.tanh(a / 2), a, 0) == 2, "α·coth(α/2) → 2 as α → 0")
print("done")
