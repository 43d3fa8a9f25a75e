"""Part D(e): the effect of a shape parameter, under the definition

  "the curve approaches the control polygon as λ increases"  :⇔  on the whole domain × range,
  ∂b_0/∂λ ≤ 0 and ∂b_n/∂λ ≤ 0 (end weights decrease) and ∂b_i/∂λ ≥ 0 for 0 < i < n (inner weights increase).

Each derivative is computed exactly and factored into factors of known sign on the domain.
"""

import sympy as sp
from _exact import check, iv_digits, iv_sign, trig_at, trig_zero

t, lam, x, a = sp.symbols("t lambda x alpha", real=True)
R = sp.Rational
s, c = sp.sin(t), sp.cos(t)


def dl(fs):
    return [sp.factor(sp.diff(f, lam)) for f in fs]


# ---------------- Han 2002 quadratic: holds (for every λ; the basis is affine in λ)
han = [(1 - s) * (1 - lam * s), (1 + lam) * (s + c - 1), (1 - c) * (1 - lam * c)]
d = dl(han)
check(sp.simplify(sp.expand_trig(s + c - 1 - 2 * sp.sqrt(2) * sp.sin(t / 2) * sp.sin(sp.pi / 4 - t / 2))) == 0 and
      trig_zero(d[0] + s * (1 - s), [t]) and trig_zero(d[1] - (s + c - 1), [t]) and trig_zero(d[2] + c * (1 - c), [t]),
      "Han quadratic: ∂b/∂λ = (−sin t(1 − sin t), sin t + cos t − 1, −cos t(1 − cos t)) — signs (≤ 0, ≥ 0, ≤ 0) on [0, π/2]"
      " (sin t + cos t − 1 = 2√2 sin(t/2) sin(π/4 − t/2) ≥ 0): HOLDS for every λ")

# ---------------- Yan & Liang cubic: holds
yl = [(1 - lam * x) * (1 - x) ** 3, x * (1 - x) ** 2 * (3 + lam * (1 - x)), x**2 * (1 - x) * (3 + lam * x), (1 - lam + lam * x) * x**3]
d = dl(yl)
check([sp.expand(v) for v in d] == [sp.expand(v) for v in [-x * (1 - x) ** 3, x * (1 - x) ** 3, x**3 * (1 - x), -x**3 * (1 - x)]],
      "Yan & Liang: ∂b/∂λ = (−t(1−t)³, t(1−t)³, t³(1−t), −t³(1−t)): HOLDS for every λ")

# ---------------- half-angle λ-basis (C6): holds
X = sp.cos(t / 2) - sp.sin(t / 2)
Y = sp.sqrt(2) * sp.sin(t / 2)
hal = [X**2 * (1 - lam * Y), X * Y * (sp.sqrt(2) + lam * (X + Y)), Y**2 * (1 - lam * X)]
d = dl(hal)
check(sp.simplify(d[0] + X**2 * Y) == 0 and sp.simplify(d[1] - X * Y * (X + Y)) == 0 and sp.simplify(d[2] + X * Y**2) == 0,
      "half-angle λ-basis: ∂b/∂λ = (−x²y, xy(x + y), −xy²), x, y ≥ 0: HOLDS")

# ---------------- squared Han basis (C7): holds on [−1, 1], fails on the maximal range [−1, 2 + 2√2]
sq0 = (1 - s) ** 2 * (1 - lam * s) ** 2
sq2 = (1 - c) ** 2 * (1 - lam * c) ** 2
sq = [sq0, 1 - sq0 - sq2, sq2]
d = dl(sq)
check(trig_zero(d[0] + 2 * s * (1 - s) ** 2 * (1 - lam * s), [t]) and trig_zero(d[2] + 2 * c * (1 - c) ** 2 * (1 - lam * c), [t]),
      "squared Han: ∂b0/∂λ = −2 sin t (1 − sin t)²(1 − λ sin t), ∂b2/∂λ = −2 cos t (1 − cos t)²(1 − λ cos t), ∂b1 = −∂b0 − ∂b2")
print("  λ ≤ 1: 1 − λ sin t ≥ 0 and 1 − λ cos t ≥ 0 on [0, π/2] ⇒ HOLDS on [−1, 1] (the printed range).")
v = trig_at(d[0].subs(lam, 2), t, R(1, 2))
check(v == R(24, 625), f"  λ = 2 ∈ (1, 2 + 2√2], (sin t, cos t) = (4/5, 3/5): ∂b0/∂λ = {v} > 0 — FAILS on the maximal range")
print("  (the end weight b0 grows with λ where λ sin t > 1).")

# ---------------- exponential Bernstein with rate λ (C5): the trace does not depend on λ at all
print("exponential Bernstein (rate λ): b_i(t; λ) = B_i(w(t; λ)) with the cubic Bernstein B_i and w increasing from 0 to 1,")
print("  so the curve Σ b_i P_i is the SAME cubic Bézier curve for every λ (only reparametrised): λ has no shape effect.")
print("  Pointwise weights: w(t; λ) = ∫_0^t e^{λs}ds / ∫_0^1 e^{λs}ds; the densities have increasing ratio e^{(λ2−λ1)s},")
print("  so w decreases in λ for t ∈ (0, 1) (stochastic order) ⇒ ∂b0/∂λ > 0 > ∂b3/∂λ: the definition FAILS for every λ.")
q = sp.Symbol("q")
w = (sp.exp(lam * t) - 1) / (sp.exp(lam) - 1)
dw = sp.diff(w, lam)
db0 = sp.diff((1 - w) ** 3, lam)
val = iv_digits(db0.subs(t, R(1, 2)), {lam: 1})
check(iv_sign(dw.subs(t, R(1, 2)), {lam: 1}) < 0 and iv_sign(db0.subs(t, R(1, 2)), {lam: 1}) > 0,
      f"  λ = 1, t = 1/2: ∂w/∂λ < 0 and ∂b0/∂λ = {val} > 0 (certified)")

# ---------------- quadratic C-Bézier with α as the shape parameter (normalised variable u = t/α)
w2 = sp.cos(a / 2)
mid = 2 * sp.cos(a / 2) * sp.sin(a / 4) ** 2 / sp.sin(a / 2) ** 2       # b1 at t = α/2
check(trig_zero((mid - w2 / (1 + w2)).subs(a, 4 * x), [x]),
      "quadratic C-Bézier: at the midpoint t = α/2, b1 = cos(α/2)/(1 + cos(α/2))")
check(sp.simplify(sp.diff(w2 / (1 + w2), a) + sp.sin(a / 2) / (2 * (1 + sp.cos(a / 2)) ** 2)) == 0,
      "  d/dα [cos(α/2)/(1 + cos(α/2))] = −sin(α/2)/(2(1 + cos(α/2))²) < 0 on (0, π]: the inner weight DEcreases as α grows —"
      " 'approaches the polygon as α increases' FAILS (the curve, a conic with weight cos(α/2), moves toward the chord)")
print("done")
