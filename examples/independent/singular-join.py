"""Part B5: join conditions whose solved coefficient is singular at a printed (closed) range end.

Main case, with the basis exactly as printed (retrieved text):
  Boundary Value Problems 2022, doi 10.1186/s13661-022-01647-5, eq. (2), quadratic C-Bézier basis
    C_0^2 = (1 − cos(α − t))/(1 − cos α), C_1^2 = −(1 − cos t + cos α − cos(α − t))/(1 − cos α),
    C_2^2 = (1 − cos t)/(1 − cos α),   t ∈ [0, α],  α ∈ (0, π]  (closed at π as printed).
  The paper's own join formulas were NOT retrievable (only the opening of the page is stored); the C¹/C² conditions
  below are derived and decided here, in the solved form a paper would print.
Companion cases (bases of examples/*.toml, terminal derivatives verified in their scripts):
  Han 2002 quadratic λ ∈ [−1, 1], Yan & Liang 2011 λ ∈ [−3, 1], Han, Ma & Huang 2009 λ, μ ∈ [−2, 1].
Derivatives w.r.t. each segment's own parameter t.
"""

import sympy as sp
from _exact import check, trig_zero

t, a1, a2, l1, l2, lam = sp.symbols("t alpha1 alpha2 lambda1 lambda2 lambda")
x, y = sp.symbols("x y")
P = sp.symbols("P0:3")
Q = sp.symbols("Q0:3")


def qcb(a):
    return [(1 - sp.cos(a - t)) / (1 - sp.cos(a)), -(1 - sp.cos(t) + sp.cos(a) - sp.cos(a - t)) / (1 - sp.cos(a)),
            (1 - sp.cos(t)) / (1 - sp.cos(a))]


p = sum(f * c for f, c in zip(qcb(a1), P))
q = sum(f * c for f, c in zip(qcb(a2), Q))
dp = sp.diff(p, t).subs(t, a1)
dq = sp.diff(q, t).subs(t, 0)
k1 = sp.sin(a1) / (1 - sp.cos(a1))
k2 = sp.sin(a2) / (1 - sp.cos(a2))
check(trig_zero(dp - k1 * (P[2] - P[1]), [a1]) and trig_zero(dq - k2 * (Q[1] - Q[0]), [a2]),
      "p'(α1) = cot(α1/2)(P2 − P1), q'(0) = cot(α2/2)(Q1 − Q0)  [sin α/(1 − cos α) = cot(α/2)]")
print("  C¹ (Q0 = P2): cot(α2/2)(Q1 − Q0) = cot(α1/2)(P2 − P1)   — the unsolved, always-correct form")
print("  solved as a paper prints it: Q1 = P2 + [sin α1 (1 − cos α2)] / [(1 − cos α1) sin α2] · (P2 − P1)")
coef = sp.sin(a1) * (1 - sp.cos(a2)) / ((1 - sp.cos(a1)) * sp.sin(a2))
check(trig_zero((k2 * coef - k1).subs({a1: 2 * x, a2: 2 * y}), [x, y]), "the solved coefficient = cot(α1/2)·tan(α2/2)")
check(sp.sin(sp.pi) == 0 and (1 - sp.cos(sp.pi)) == 2,
      "at α2 = π (inside the printed range (0, π]): denominator (1 − cos α1)·sin π = 0 — coefficient undefined")
print("  decision at α2 = π: q'(0) = cot(π/2)(Q1 − Q0) = 0 for every Q1, so C¹ holds iff cot(α1/2)(P2 − P1) = 0,")
print("  i.e. only if α1 = π too or P1 = P2: the solved formula fails (division by zero) and no choice of Q1 gives C¹.")
qpi = [sp.simplify(f.subs(a2, sp.pi)) for f in qcb(a2)]
check(sp.simplify(qpi[1]) == 0 and sp.simplify(qpi[0] + qpi[2] - 1) == 0,
      "at α = π the printed basis is (cos²(t/2), 0, sin²(t/2)): the segment is the straight line Q0Q2, Q1 is ignored")
dq2 = sp.simplify(sp.diff(q, t, 2).subs(t, 0).subs(a2, sp.pi))
check(sp.expand(dq2 - (Q[2] - Q[0]) / 2) == 0, "at α2 = π: q'(0) = 0, q''(0) = (Q2 − Q0)/2, so the start direction is Q2 − Q0")
print("  G¹ at α2 = π therefore needs Q2 − Q0 ∥ P2 − P1 (same sense), not a condition on Q1.")
# with λ = cos α the C¹ ratio is sqrt((1+λ1)(1−λ2)/((1−λ1)(1+λ2))); the C² condition
L1, L2 = sp.symbols("L1 L2")
d2p = sp.diff(p, t, 2).subs(t, a1)
d2q = sp.diff(q, t, 2).subs(t, 0)
check(trig_zero(d2p - (P[0] - (1 + sp.cos(a1)) * P[1] + sp.cos(a1) * P[2]) / (1 - sp.cos(a1)), [a1]) and
      trig_zero(d2q - (sp.cos(a2) * Q[0] - (1 + sp.cos(a2)) * Q[1] + Q[2]) / (1 - sp.cos(a2)), [a2]),
      "p''(α1) = (P0 − (1+λ1)P1 + λ1P2)/(1 − λ1), q''(0) = (λ2Q0 − (1+λ2)Q1 + Q2)/(1 − λ2), λi = cos αi")
Q2sol = sp.solve(sp.Eq((L2 * P[2] - (1 + L2) * Q[1] + Q[2]) / (1 - L2), (P[0] - (1 + L1) * P[1] + L1 * P[2]) / (1 - L1)), Q[2])[0]
check(sp.cancel(Q2sol - ((1 + L2) * Q[1] - L2 * P[2] + (1 - L2) / (1 - L1) * (P[0] - (1 + L1) * P[1] + L1 * P[2]))) == 0,
      "C² (with Q0 = P2): Q2 = (1+λ2)Q1 − λ2P2 + (1−λ2)/(1−λ1)·(P0 − (1+λ1)P1 + λ1P2)")
same = sp.cancel(Q2sol.subs({L1: lam, L2: lam, Q[1]: 2 * P[2] - P[1]}))
check(sp.expand(same - (P[0] + 2 * (1 + lam) * (P[2] - P[1]))) == 0,
      "equal α (λ = cos α), with C¹ (Q1 = 2P2 − P1): C² ⇔ Q2 = P0 + 2(1 + λ)(P2 − P1)")
print("  (λ → 1, i.e. α → 0, is excluded; the C² ratio (1 − λ2)/(1 − λ1) is regular on the printed range.)")

# ---- companion cases: coefficient c1/c2 with c2 vanishing at a closed range end
print("companion cases (solved C¹ coefficient, singular value inside the printed closed range):")
cases = [("Han 2002 quadratic, λ ∈ [−1, 1]", (1 + l1) / (1 + l2), -1, "r'(0) = (1+λ)(P1 − P0), r'(π/2) = (1+λ)(P2 − P1)"),
         ("Yan & Liang 2011 cubic, λ ∈ [−3, 1]", (3 + l1) / (3 + l2), -3, "r'(0) = (3+λ)(P1 − P0), r'(1) = (3+λ)(P3 − P2)"),
         ("Han, Ma & Huang 2009, λ, μ ∈ [−2, 1]", (2 + l1) / (2 + l2), -2, "r'(0) = (λ+2)(P1 − P0), r'(π/2) = (μ+2)(P3 − P2); here l1 = μ1")]
for name, c, sing, tang in cases:
    den = sp.denom(c)
    check(den.subs(l2, sing) == 0, f"{name}: Q1 − Q0 = {c}·(P_n − P_(n−1)) is singular at λ2 = {sing}  [{tang}]")
print("  in every case the unsolved form c(λ2)(Q1 − Q0) = c(μ1 or λ1)(P_n − P_(n−1)) is the correct statement;")
print("  at the singular end the start tangent of the second segment vanishes and C¹ needs the incoming tangent to vanish.")
print("done")
