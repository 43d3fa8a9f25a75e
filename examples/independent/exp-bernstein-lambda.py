"""Part C5: exponential Bernstein functions with a shape parameter λ (rate), on t ∈ [0, 1]:

  w(t) = (e^{λt} − 1)/(e^λ − 1),   b_i(t) = C(3, i) w^i (1 − w)^{3−i},   span{1, e^{λt}, e^{2λt}, e^{3λt}}, λ ≠ 0.

This is B7 (exp-bernstein-cubic.py, span{1, e^t, e^{2t}, e^{3t}} on [0, α]) rescaled: b_i(t; λ) = B7_i(λt; α = λ).
(The family is that of the exponential Bernstein operators, Aldaz, Kounchev & Render, Constr. Approx. 29 (2009);
citation from memory, the formulas are derived here.) The printed range in the spec file is λ ∈ (0, ∞).
Derivatives w.r.t. t; E = e^λ.
"""

import sympy as sp
from _exact import check, iv_digits

t, lam = sp.symbols("t lambda", real=True)
q, Es = sp.symbols("q E", positive=True)   # q = e^{λt}, E = e^λ: d/dt = λ q d/dq; t = 0 ↔ q = 1, t = 1 ↔ q = E
w = (q - 1) / (Es - 1)
b = [sp.binomial(3, i) * w**i * (1 - w) ** (3 - i) for i in range(4)]
print("exp-bernstein-lambda: exponential Bernstein functions of rate λ on [0, 1]  (q = e^{λt}, E = e^λ)")
check(sp.simplify(sum(b) - 1) == 0, "unity Σ b_i = 1 (binomial theorem in w)")
print("  b_i(t; λ) = B7_i(λt; α = λ): B7 is the same polynomial in e^{t} over e^{α} − 1 (exp-bernstein-cubic.py).")
dw = lam * q * sp.diff(w, q)
check(sp.simplify(dw - lam * q / (Es - 1)) == 0,
      "w' = λe^{λt}/(e^λ − 1) > 0 for every λ ≠ 0 (numerator and denominator have the sign of λ); w(0) = 0, w(1) = 1")
print("  ⇒ 0 ≤ w ≤ 1 and all b_i ≥ 0 on [0, 1] for EVERY λ ≠ 0. λ = 0: e^λ − 1 = 0, undefined as written")
print("    (removable: the limit is the cubic Bernstein basis). Maximal range containing (0, ∞): (0, ∞) itself,")
print("    ends: 0 (excluded — the formula is undefined there, though the limit exists), ∞. The set of all admissible")
print("    λ as written is (−∞, 0) ∪ (0, ∞).")
bt = [f.subs({q: sp.exp(lam * t), Es: sp.exp(lam)}) for f in b]
check(all(sp.expand(sp.limit(f, lam, 0) - sp.binomial(3, i) * t**i * (1 - t) ** (3 - i)) == 0 for i, f in enumerate(bt)),
      "λ → 0: b_i → C(3, i) t^i (1 − t)^{3−i} (the singularity at λ = 0 is removable)")
# w(t; −λ) = (e^{−λt} − 1)/(e^{−λ} − 1) = (e^{λ} − e^{λ(1−t)})/(e^{λ} − 1) = 1 − w(1 − t; λ); with q' = e^{λ(1−t)} = E/q:
wneg = (1 / q - 1) / (1 / Es - 1)
check(sp.simplify(wneg - (1 - w.subs(q, Es / q))) == 0,
      "w(t; −λ) = 1 − w(1 − t; λ) ⇒ b_i(t; −λ) = b_{3−i}(1 − t; λ) (symmetry exchanging λ ↔ −λ)")
half = sp.Rational(1, 2)
v0 = iv_digits(bt[0].subs(t, half), {lam: 1})
v3 = iv_digits(bt[3].subs(t, 1 - half), {lam: 1})
print(f"  plain symmetry b_i(t) = b_{{3−i}}(1 − t) FAILS for every λ ≠ 0: at λ = 1, t = 1/2: w = 1/(√e + 1),")
print(f"    b0(1/2) = (1 − w)³ = {v0}, b3(1/2) = w³ = {v3} (30 certified digits)")
check(sp.simplify(w.subs({q: sp.sqrt(Es)}) - 1 / (sp.sqrt(Es) + 1)) == 0, "w(1/2) = 1/(e^{λ/2} + 1) (= 1/2 only at λ = 0)")
# endpoint derivatives
print("  endpoint derivatives (E = e^λ), listed as (b0, b1, b2, b3):")


def dt(f, k):
    for _ in range(k):
        f = lam * q * sp.diff(f, q)
    return f


forms0 = {
    1: [-3 * lam / (Es - 1), 3 * lam / (Es - 1), 0, 0],
    2: [-3 * lam**2 * (Es - 3) / (Es - 1) ** 2, 3 * lam**2 * (Es - 5) / (Es - 1) ** 2, 6 * lam**2 / (Es - 1) ** 2, 0],
    3: [-3 * lam**3 * (Es**2 - 8 * Es + 9) / (Es - 1) ** 3, 3 * lam**3 * (Es**2 - 14 * Es + 19) / (Es - 1) ** 3,
        18 * lam**3 * (Es - 2) / (Es - 1) ** 3, 6 * lam**3 / (Es - 1) ** 3],
}
forms1 = {
    1: [0, 0, -3 * lam * Es / (Es - 1), 3 * lam * Es / (Es - 1)],
    2: [0, 6 * lam**2 * Es**2 / (Es - 1) ** 2, -3 * lam**2 * Es * (5 * Es - 1) / (Es - 1) ** 2, 3 * lam**2 * Es * (3 * Es - 1) / (Es - 1) ** 2],
    3: [-6 * lam**3 * Es**3 / (Es - 1) ** 3, 18 * lam**3 * Es**2 * (2 * Es - 1) / (Es - 1) ** 3,
        -3 * lam**3 * Es * (19 * Es**2 - 14 * Es + 1) / (Es - 1) ** 3, 3 * lam**3 * Es * (9 * Es**2 - 8 * Es + 1) / (Es - 1) ** 3],
}
for kk in (1, 2, 3):
    at0 = [dt(f, kk).subs(q, 1) for f in b]
    at1 = [dt(f, kk).subs(q, Es) for f in b]
    check(all(sp.simplify(x - y) == 0 for x, y in zip(at0, forms0[kk])), f"order {kk} at t = 0: {[sp.factor(y) for y in forms0[kk]]}")
    check(all(sp.simplify(x - y) == 0 for x, y in zip(at1, forms1[kk])), f"order {kk} at t = 1: {[sp.factor(y) for y in forms1[kk]]}")
print("  (= λ^k times the B7 tables with E = e^λ.) Terminal tangents: r'(0) = 3λ/(e^λ − 1)·(P1 − P0),")
print("  r'(1) = 3λe^λ/(e^λ − 1)·(P3 − P2); both → 3 as λ → 0.")
E = sp.exp(lam)
check(sp.limit(3 * lam / (E - 1), lam, 0) == 3 and sp.limit(3 * lam * E / (E - 1), lam, 0) == 3, "limits 3 (cubic Bézier)")
print("  sample (λ = 2, t = 1/2):", [iv_digits(f.subs(t, half), {lam: 2}, 20) for f in bt])
print("done")
