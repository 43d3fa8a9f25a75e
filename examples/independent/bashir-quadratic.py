"""Independent check of examples/bashir-quadratic.toml
(Bashir, Abbas & Ali, Appl. Math. Comput. 219 (2013) 10183-10197, Section 2; formulas as transcribed there):

  b0 = (1 − sin t)(1 − α sin t),
  b1 = α sin t(1 − sin t) + β cos t(1 − cos t) + sin t + cos t − 1,
  b2 = (1 − cos t)(1 − β cos t),      t ∈ [0, π/2], α, β ∈ [−1, 1].
Derivatives w.r.t. the angle t (w.r.t. u = 2t/π multiply order k by (π/2)^k).
"""

import sympy as sp
from _exact import (PYTH_M, check, numerator_posden, param_set, show_intervals, trig_at, trig_zero,
                    weierstrass, mp_min)

t, al, be, m = sp.symbols("t alpha beta m")
S, C = sp.sin(t), sp.cos(t)
b = [(1 - S) * (1 - al * S), al * S * (1 - S) + be * C * (1 - C) + S + C - 1, (1 - C) * (1 - be * C)]

print("bashir-quadratic: Bashir, Abbas & Ali 2013 QTB basis")
check(trig_zero(sum(b) - 1, [t]), "QTB-unity: Σ b_i = 1 (exact)")
check(trig_zero(b[1] - ((1 + al) * S * (1 - S) + (1 + be) * C * (1 - C)), [t]),
      "b1 = (1+α) sin t(1 − sin t) + (1+β) cos t(1 − cos t)  (exact rewriting)")
check(all(trig_zero(b[i].subs(t, sp.pi / 2 - t) - b[2 - i].subs({al: be, be: al}, simultaneous=True), [t]) for i in range(3)),
      "symmetry b_i(t; α, β) = b_{2−i}(π/2 − t; β, α) (exact)")

# ---- region. b0 involves α only, b2 β only.
N = [numerator_posden(weierstrass(f, t, m), m) for f in b]
iva, _, _ = param_set([N[0]], m, al, 0, 1, prefer=PYTH_M)
ivb, _, _ = param_set([N[2]], m, be, 0, 1, prefer=PYTH_M)
print("  b0 ≥ 0 ⇔ α ∈", show_intervals(iva), ";  b2 ≥ 0 ⇔ β ∈", show_intervals(ivb))
check(iva == [(-sp.oo, 1)] and ivb == [(-sp.oo, 1)], "b0 ≥ 0 ⇔ α ≤ 1, b2 ≥ 0 ⇔ β ≤ 1")
# b1 in m = tan(t/2): (1+m²)² b1 = 2m(1−m)·G(m),  G = (1+α)(1−m) + (1+β)m(1+m)
G = (1 + al) * (1 - m) + (1 + be) * m * (1 + m)
check(sp.simplify(weierstrass(b[1], t, m) - 2 * m * (1 - m) * G / (1 + m**2) ** 2) == 0,
      "(1+m²)²·b1 = 2m(1 − m)·G(m), G = (1+α)(1 − m) + (1+β)m(1 + m), m = tan(t/2)")
print("  G(0) = 1+α, G(1) = 2(1+β); if α, β ≥ −1 every term of G is ≥ 0 on [0,1];")
print("  if α < −1, G(0) < 0 so b1 < 0 near t = 0; if β < −1, G(1) < 0 so b1 < 0 near t = π/2.")
print("  ⇒ b1 ≥ 0 on [0, π/2] ⇔ α ≥ −1 and β ≥ −1 (boundary lines: G(0)=0 ⇔ α=−1, G(1)=0 ⇔ β=−1).")
# an exact check of that statement on the two-parameter family via the one-parameter tool:
for fix_name, fix, var in [("β=1", {be: 1}, al), ("β=−1", {be: -1}, al), ("α=1", {al: 1}, be), ("α=−1", {al: -1}, be)]:
    iv, _, _ = param_set([sp.expand(G.subs(fix))], m, var, 0, 1)
    print(f"    with {fix_name}: b1 ≥ 0 ⇔ {var} ∈ {show_intervals(iv)}")
print("  ⇒ QTB-nonneg holds and QTB-maximal holds: exact region = [−1, 1]² (the declared box)")
for (a0, b0_, i, mm) in [(-2, 1, 1, sp.Rational(1, 4)), (1, -2, 1, sp.Rational(3, 4)), (2, 0, 0, sp.Rational(1, 2)),
                         (0, 2, 2, sp.Rational(1, 2)), (sp.Rational(-11, 10), 1, 1, sp.Rational(1, 40))]:
    v = trig_at(b[i].subs({al: a0, be: b0_}), t, mm)
    check(v < 0, f"witness (α,β)=({a0},{b0_}): b{i} at (sin,cos)=({trig_at(S, t, mm)},{trig_at(C, t, mm)}) = {v} < 0")
check(trig_zero(b[1].subs({al: -1, be: -1}), [t]),
      "degeneracy inside the closed box: at (α,β)=(−1,−1) b1 ≡ 0 (b0 = cos²t, b2 = sin²t): not a basis there")

# ---- endpoint values and derivatives (w.r.t. t)
for end, nm in [(0, "0"), (sp.pi / 2, "π/2")]:
    for k in (0, 1, 2, 3):
        print(f"  order {k} at t={nm}: {[sp.factor(sp.simplify(sp.diff(f, t, k).subs(t, end))) for f in b]}")
check([sp.simplify(f.subs(t, 0)) for f in b] == [1, 0, 0], "QTB-ends holds: b(0) = (1, 0, 0)")
check([sp.expand(sp.diff(f, t).subs(t, 0)) for f in b] == [-1 - al, 1 + al, 0],
      "QTB-tangent holds w.r.t. t: b'(0) = (−(1+α), 1+α, 0); w.r.t. u = 2t/π it would be (π/2)× these (fails as printed)")
print("  note: at α = −1 (closed end) b0'(0) = b1'(0) = 0: the curve's start tangent vanishes.")
for (a0, b0_) in [(-1, -1), (1, 1), (-1, 1)]:
    print(f"  mpmath grid min at (α,β)=({a0},{b0_}):",
          [sp.N(sp.Float(str(v), 30), 6) for v in mp_min([f.subs({al: a0, be: b0_}) for f in b], t, 0, sp.pi / 2)])
print("done")
