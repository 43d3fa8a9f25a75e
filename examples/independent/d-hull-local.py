"""Part D(a) convex hull and D(f) local control.

(a) For a basis with Σ b_i ≡ 1: every curve Σ b_i P_i lies in the convex hull of its control points (for every
    choice of points) ⇔ every b_i ≥ 0 on the domain, for every parameter of the stated range.
    ⇐: convex combination. ⇒: if b_j(t0) < 0, take P_j = (1, 0) and the other points (0, 0): the curve point
    (b_j(t0), 0) lies outside the hull, the segment [0, 1] × {0}. So the verdict is that of unity and
    nonnegativity on the stated (declared) range, and a failing witness is a nonnegativity witness.
(f) Local control of a B-spline: which segments a control point or a segment parameter enters.
"""

import sympy as sp
from _exact import check, iv_digits, trig_zero

t, a, lam, x = sp.symbols("t alpha lambda x", real=True)
R = sp.Rational
S, C = sp.sin, sp.cos

# ---------------- (a) C-B-spline: holds on (0, π), fails on (0, 2π)
k = 1 / (2 * a * (1 - C(a)))
b3 = k * (t - S(t))
b2 = k * ((a - S(a)) + (1 - C(a)) * t + S(a) * (1 - C(t)) - (2 + C(a)) * (t - S(t)))
cbs = [b3.subs(t, a - t), b2.subs(t, a - t), b2, b3]
print("(a) convex hull")
print("  C-B-spline, stated range (0, π): unity (exact) and nonnegativity (c-bspline.py) ⇒ HOLDS.")
P = [(0, 0), (1, 0), (0, 0), (0, 0)]
r0 = [sp.simplify(sum(f * p[i] for f, p in zip(cbs, P)).subs({a: 3 * sp.pi / 2, t: 0})) for i in range(2)]
check(r0 == [-2 / (3 * sp.pi), 0],
      "  stated range (0, 2π): FAILS — α = 3π/2, P0 = P2 = P3 = (0, 0), P1 = (1, 0): r(0) = (−2/(3π), 0) ∉ hull = [0, 1] × {0}")
print("  rational quadratic (A5), stated range w ∈ (−1, ∞): FAILS — w = −1/10, P1 = (1, 0), others (0, 0): r(1/2) = (−1/9, 0).")
wq = sp.Symbol("w")
D = (1 - x) ** 2 + 2 * wq * x * (1 - x) + x**2
check(sp.simplify((2 * wq * x * (1 - x) / D).subs({wq: R(-1, 10), x: R(1, 2)})) == R(-1, 9), "  (b1(1/2) = −1/9 at w = −1/10)")
print("  quadratic C-Bézier on (0, π], cubic C-Bézier on (0, 2π), H-Bézier quadratic on (0, ∞), quartic trigonometric on")
print("  (0, π], half-angle λ-basis on [−1, 1], squared Han on [−1, 1]: unity + nonnegativity ⇒ HOLD (Part C scripts).")
print("  half-angle λ-basis on [−3/2, 1]: FAILS — λ = −3/2, t = π/4, P1 = (1, 0): r = (−0.0613244409702265874662074907064, 0).")

# ---------------- (f) local control
print("(f) local control")
print("  C-B-spline (uniform, one α): segment r_i(t) = Σ_k b_k(t) P_{i+k}, k = 0..3, so P_j enters exactly the segments")
print("  i = j − 3, …, j (four), with weight b_{j−i}; moving P_j by δ moves r_i by b_{j−i}(t)δ.")
vals = [iv_digits(f, {a: 1, t: R(1, 2)}, 20) for f in cbs]
check(all(float(v) > 0 for v in vals), f"  every b_k ≢ 0 (at α = 1, t = 1/2: b = {vals}): P_j changes all FOUR segments;"
      " a claim 'P_j affects only three segments' FAILS with this witness")
print("  α is global (one value for all segments): 'α gives local shape control' FAILS — it enters every segment.")
# Han-type quadratic trigonometric B-spline (B6(c), reconstructed) with one λ_i per segment
l1, l2 = sp.symbols("lambda_i lambda_j")
s, c = S(t), C(t)
bh = lambda L: [(1 - s) * (1 - L * s) / 2, 1 - (1 - s) * (1 - L * s) / 2 - (1 - c) * (1 - L * c) / 2, (1 - c) * (1 - L * c) / 2]  # noqa: E731
Pp = sp.symbols("P0:4")
ri = sum(f * p for f, p in zip(bh(l1), Pp[:3]))        # segment i: P_i, P_{i+1}, P_{i+2}, parameter λ_i
rj = sum(f * p for f, p in zip(bh(l2), Pp[1:]))        # segment i+1: P_{i+1}, P_{i+2}, P_{i+3}, parameter λ_{i+1}
j0 = sp.simplify(rj.subs(t, 0) - ri.subs(t, sp.pi / 2))
j1 = sp.factor(sp.simplify(sp.diff(rj, t).subs(t, 0) - sp.diff(ri, t).subs(t, sp.pi / 2)))
check(j0 == 0, "  Han-type B-spline (B6(c)) with a parameter λ_i per segment: C⁰ for all λ_i, λ_{i+1} (joint point (P_{i+1} + P_{i+2})/2)")
check(sp.simplify(j1 - (l2 - l1) / 2 * (Pp[2] - Pp[1])) == 0,
      "  first-derivative jump r_{i+1}'(0) − r_i'(π/2) = (λ_{i+1} − λ_i)/2·(P_{i+2} − P_{i+1}): λ_i enters only segment i,"
      " but C¹ holds only if λ_i = λ_{i+1} (or P_{i+2} = P_{i+1}); with 1 + λ > 0 on both sides the join is G¹")
print("  ⇒ 'local shape parameters with C¹ continuity' FAILS for this B-spline; 'local parameters with G¹' holds for λ > −1.")
print("done")
