"""Part B7: a cubic basis using exp — the exponential Bernstein functions of span{1, e^t, e^{2t}, e^{3t}} on [0, α]:

  x(t) = (e^t − 1)/(e^α − 1),   b_i(t) = C(3, i) x^i (1 − x)^{3−i},   t ∈ [0, α], α > 0.

(Bernstein basis in the variable x = affine image of e^t; cf. the "exponential Bernstein operators" of
Aldaz, Kounchev & Render, Constr. Approx. 29 (2009) — citation from memory, the formula itself is derived here.)
Also: span{1, t, e^t, e^{−t}} = span{1, t, sinh t, cosh t}, i.e. the H-Bézier space (h-bezier-cubic.py).
Derivatives w.r.t. t; E = e^α.
"""

import sympy as sp
from _exact import check, hyp_zero

t, a = sp.symbols("t alpha", positive=True)
E = sp.Symbol("E", positive=True)
X = (sp.exp(t) - 1) / (sp.exp(a) - 1)
b = [sp.binomial(3, i) * X**i * (1 - X) ** (3 - i) for i in range(4)]
print("exp-bernstein-cubic: exponential Bernstein functions, frequencies 0,1,2,3")
for i, f in enumerate(b):
    print(f"  b{i}(t) = {sp.binomial(3, i)}·(e^t − 1)^{i}·(e^α − e^t)^{3 - i}/(e^α − 1)^3")
    check(hyp_zero(f - sp.binomial(3, i) * (sp.exp(t) - 1) ** i * (sp.exp(a) - sp.exp(t)) ** (3 - i) / (sp.exp(a) - 1) ** 3, [t, a]), f"  b{i} closed form")
check(hyp_zero(sum(b) - 1, [t, a]), "unity Σ b_i = 1 (binomial theorem in x)")
# span: each b_i is a cubic polynomial in e^t, and the 4 are independent (Bernstein in x)
Y = sp.Symbol("Y")
M = sp.Matrix([[sp.Poly(sp.expand(f.subs(sp.exp(t), Y)), Y).coeff_monomial(Y**k) for k in range(4)] for f in b])
check(sp.simplify(M.det()) != 0, f"b_i ∈ span{{1, e^t, e^{{2t}}, e^{{3t}}}} and independent (det = {sp.factor(sp.simplify(M.det()))})")
print("  nonnegativity: x(t) increases from 0 to 1 on [0, α] for every α > 0, so b_i ≥ 0 for every α ∈ (0, ∞).")
check(hyp_zero(sp.diff(X, t) - sp.exp(t) / (sp.exp(a) - 1), [t, a]), "x'(t) = e^t/(e^α − 1) > 0, x(0) = 0, x(α) = 1")

# ---- symmetry fails (the space is not invariant under t -> α − t)
al, t0 = sp.log(3), sp.log(2)
v0 = sp.nsimplify(sp.simplify(b[0].subs({a: al, t: t0})))
v3 = sp.nsimplify(sp.simplify(b[3].subs({a: al}).subs(t, al - t0)))
check(v0 == sp.Rational(1, 8) and v3 == sp.Rational(1, 64),
      "symmetry b_i(t) = b_{3−i}(α − t) FAILS: α = ln 3, t = ln 2: b0(t) = 1/8 (x = 1/2), b3(α − t) = 1/64 (x = 1/4)")
print("  (what holds instead: b_i(t; e) = b_{3−i}(α − t; e^{−1}), i.e. reflecting t also flips the frequency sign)")
bneg = [sp.binomial(3, i) * ((sp.exp(-t) - 1) / (sp.exp(-a) - 1)) ** i * (1 - (sp.exp(-t) - 1) / (sp.exp(-a) - 1)) ** (3 - i) for i in range(4)]
check(all(hyp_zero(b[i] - bneg[3 - i].subs(t, a - t), [t, a]) for i in range(4)),
      "b_i(t) = b̃_{3−i}(α − t) where b̃ is the same construction with e^{−t}")

# ---- endpoint derivatives (in E = e^α)
def at(expr, tt):
    e = expr.subs(t, tt)
    return sp.factor(sp.simplify(e.subs(sp.exp(a), E)))


for k in range(4):
    z = [at(sp.diff(f, t, k), 0) for f in b]
    w = [at(sp.diff(f, t, k), a) for f in b]
    print(f"  order {k}: t=0 {z}")
    print(f"           t=α {w}")
d0 = [at(sp.diff(f, t), 0) for f in b]
dA = [at(sp.diff(f, t), a) for f in b]
check([sp.simplify(q - r) for q, r in zip(d0, [-3 / (E - 1), 3 / (E - 1), 0, 0])] == [0] * 4, "b'(0) = (−3, 3, 0, 0)/(E − 1)")
check([sp.simplify(q - r) for q, r in zip(dA, [0, 0, -3 * E / (E - 1), 3 * E / (E - 1)])] == [0] * 4, "b'(α) = (0, 0, −3E, 3E)/(E − 1)")
d2 = [at(sp.diff(f, t, 2), 0) for f in b]
hand = [-3 * (E - 3) / (E - 1) ** 2, 3 * (E - 5) / (E - 1) ** 2, 6 / (E - 1) ** 2, 0]   # from x' = x'' = 1/(E−1) at 0
check(all(sp.simplify(q - r) == 0 for q, r in zip(d2, hand)), "b''(0) = (−3(E − 3), 3(E − 5), 6, 0)/(E − 1)²")
check(sp.simplify(at(sp.diff(b[3], t, 2), a) - 3 * E * (3 * E - 1) / (E - 1) ** 2) == 0,
      "b3''(α) = 6x·x'² + 3x²·x'' = 3E(3E − 1)/(E − 1)² (x' = x'' = E/(E − 1) at α)")
print("  terminal tangents: r'(0) = 3/(e^α − 1)·(P1 − P0),  r'(α) = 3e^α/(e^α − 1)·(P3 − P2)  (unequal speeds: no symmetry)")
check(sp.limit(a * 3 / (sp.exp(a) - 1), a, 0) == 3 and sp.limit(a * 3 * sp.exp(a) / (sp.exp(a) - 1), a, 0) == 3,
      "α·r'-factors → 3 as α → 0 (cubic Bézier in t/α)")
# ---- span{1, t, e^t, e^{-t}} = span{1, t, sinh t, cosh t}
check(hyp_zero(sp.exp(t) - (sp.sinh(t) + sp.cosh(t)), [t]) and hyp_zero(sp.exp(-t) - (sp.cosh(t) - sp.sinh(t)), [t]),
      "e^{±t} = cosh t ± sinh t: span{1, t, e^t, e^{−t}} is the H-Bézier space of h-bezier-cubic.py")
print("done")
