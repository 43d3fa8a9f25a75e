"""Part B6: B-splines that are not four uniform segments.

(a) uniform quadratic polynomial B-spline (three pieces), (b) uniform quartic polynomial B-spline (five pieces),
(c) a Han-type uniform quadratic trigonometric B-spline with shape parameter λ (three pieces on [0, π/2]):
      b0 = (1 − sin t)(1 − λ sin t)/2, b2 = (1 − cos t)(1 − λ cos t)/2, b1 = 1 − b0 − b2,
    segment r_i(t) = b0 P_i + b1 P_{i+1} + b2 P_{i+2}.  RECONSTRUCTED, NOT CHECKED AGAINST PRINT: this is the
    form I recall for X. Han, CAGD 19 (2002) 503-512 (B-spline part); verify against the paper before citing.
(d) the uniform B-spline of span{1, cos t, sin t} with knot spacing α (derived here, not quoted).

"Piece j" of the B-spline N lives on the j-th knot interval, local parameter t ∈ [0, h]; N = b_{k−j} there.
C^r at a knot means the one-sided derivatives of orders 0..r agree (derivatives w.r.t. t).
"""

import sympy as sp
from _exact import PYTH_M, check, describe_alg, numerator_posden, param_set, show_intervals, trig_zero, weierstrass

t, lam, a, m, x = sp.symbols("t lambda alpha m x")


def knot_jumps(pieces, h, maxk, simp=sp.simplify):
    """jumps[knot][k] = (right − left) k-th derivative at each knot 0..len(pieces) (outside N = 0)."""
    n = len(pieces)
    out = []
    for j in range(n + 1):
        row = []
        for k in range(maxk + 1):
            left = sp.diff(pieces[j - 1], t, k).subs(t, h) if j > 0 else 0
            right = sp.diff(pieces[j], t, k).subs(t, 0) if j < n else 0
            row.append(simp(right - left))
        out.append(row)
    return out


def order(row):
    for k, v in enumerate(row):
        if v != 0:
            return k - 1
    return None


# ---------------- (a) quadratic
b = [(1 - t) ** 2 / 2, (1 + 2 * t - 2 * t**2) / 2, t**2 / 2]
print("(a) uniform quadratic polynomial B-spline, knots 0,1,2,3; pieces N = t²/2, (1 + 2t − 2t²)/2, (1 − t)²/2")
check(sp.expand(sum(b) - 1) == 0, "unity of the segment basis")
J = knot_jumps(b[::-1], 1, 3)
for j, row in enumerate(J):
    print(f"    knot {j}: jumps of orders 0..3 = {row}  ⇒ C^{order(row)}")
check(all(order(r) == 1 for r in J), "exactly C¹ at every knot (second-derivative jumps 1, −3, 3, −1)")

# ---------------- (b) quartic, by truncated powers
def N4(xx, j):
    """quartic B-spline on [j, j+1]: Σ_{k ≤ j} (−1)^k C(5, k) (x − k)^4 / 24 (truncated powers)."""
    return sum((-1) ** k * sp.binomial(5, k) * (xx - k) ** 4 for k in range(j + 1)) / 24


pieces4 = [sp.expand(N4(t + j, j)) for j in range(5)]   # piece j on [j, j+1], local t
print("(b) uniform quartic polynomial B-spline, knots 0..5; pieces (local t ∈ [0,1]):")
for j, p in enumerate(pieces4):
    print(f"    piece {j}: {sp.factor(p)}")
seg = pieces4[::-1]   # segment basis b_i = piece (4 − i)
check(sp.expand(sum(seg) - 1) == 0, "unity: Σ_i b_i(t) = 1 (five pieces)")
check(all(sp.expand(seg[i].subs(t, 1 - t) - seg[4 - i]) == 0 for i in range(5)), "symmetry b_i(t) = b_{4−i}(1 − t)")
J = knot_jumps(pieces4, 1, 5)
for j, row in enumerate(J):
    print(f"    knot {j}: jumps of orders 0..5 = {row}  ⇒ C^{order(row)}")
check(all(order(r) == 3 for r in J) and [r[4] for r in J] == [1, -5, 10, -10, 5, -1],
      "exactly C³ at every knot; fourth-derivative jumps (−1)^k·C(5,k)")
check(all(sp.Poly(p, t).count_roots(0, 1) - int(p.subs(t, 0) == 0) - int(p.subs(t, 1) == 0) == 0 and p.subs(t, sp.Rational(1, 2)) > 0
          for p in pieces4), "every piece > 0 on (0, 1)")
print("    values at knots:", [p.subs(t, 0) for p in pieces4] + [0], "  (1/24, 11/24, 11/24, 1/24)")

# ---------------- (c) Han-type trigonometric λ B-spline (reconstructed)
S, C = sp.sin(t), sp.cos(t)
bh = [(1 - S) * (1 - lam * S) / 2, 1 - (1 - S) * (1 - lam * S) / 2 - (1 - C) * (1 - lam * C) / 2, (1 - C) * (1 - lam * C) / 2]
print("(c) Han-type quadratic trigonometric B-spline with λ (reconstructed form, see header)")
check(trig_zero(bh[1] - ((1 + lam) * (S + C) - lam) / 2, [t]), "b1 = ((1 + λ)(sin t + cos t) − λ)/2")
Nh = [numerator_posden(weierstrass(f, t, m), m) for f in bh]
iv, samples, crit = param_set(Nh, m, lam, 0, 1, prefer=PYTH_M)
print("    critical λ:", [describe_alg(r) for r in crit])
print("    nonnegativity set of λ:", show_intervals(iv))
check(len(iv) == 1 and sp.simplify(iv[0][0] + 2 + sp.sqrt(2)) == 0 and iv[0][1] == 1,
      "pieces ≥ 0 exactly for λ ∈ [−2 − √2, 1] (min. poly of the left end λ² + 4λ + 2; b1 ≥ 0 ⇔ (1+λ)√2 ≥ λ at t = π/4)")
Jh = knot_jumps(bh[::-1], sp.pi / 2, 3, simp=lambda e: sp.factor(sp.simplify(e)))
for j, row in enumerate(Jh):
    print(f"    knot {j}: jumps of orders 0..3 = {row}")
check(all(r[0] == 0 and r[1] == 0 for r in Jh), "C¹ at every knot for every λ")
check(sp.solve(Jh[0][2], lam) == [1] and sp.solve(Jh[1][2], lam) == [sp.Rational(-1, 3)],
      "second-derivative jumps vanish at the support ends only for λ = 1 and at the inner knots only for λ = −1/3:"
      " incompatible, so the curve is exactly C¹ for every λ (continuity never rises)")
P = sp.symbols("P0:4")
ri = sum(f * p for f, p in zip(bh, P[:3]))
rj = sum(f * p for f, p in zip(bh, P[1:]))
jump2 = sp.expand(sp.diff(rj, t, 2).subs(t, 0) - sp.diff(ri, t, 2).subs(t, sp.pi / 2))
print("    curve: r_{i+1}''(0) − r_i''(π/2) =", sp.collect(jump2, P))
jump1 = sp.expand(sp.diff(rj, t).subs(t, 0) - sp.diff(ri, t).subs(t, sp.pi / 2))
check(jump1 == 0, "curve C¹ identically; r_i'(π/2) = (1+λ)/2·(P_{i+2} − P_{i+1})")

# ---------------- (d) trigonometric B-spline of span{1, cos, sin}, spacing α
K = 1 / (2 * (1 - sp.cos(a)))
pd = [K * (1 - sp.cos(t)), 1 - K * (1 - sp.cos(t)) - K * (1 - sp.cos(a - t)), K * (1 - sp.cos(a - t))]
print("(d) uniform trigonometric B-spline of span{1, cos t, sin t}, knot spacing α: pieces")
print("    (1 − cos t)/(2(1 − cos α)), middle = 1 − the other two, (1 − cos(α − t))/(2(1 − cos α))")
check(trig_zero(pd[1] - (-2 * sp.cos(a) + sp.cos(t) + sp.cos(a - t)) * K, [t, a]),
      "middle piece = (cos t + cos(α − t) − 2cos α)/(2(1 − cos α)) = (cos(α/2)cos(t − α/2) − cos α)/(1 − cos α)")
Jd = knot_jumps(pd, a, 2, simp=lambda e: sp.factor(sp.simplify(e)))
for j, row in enumerate(Jd):
    print(f"    knot {j}: jumps of orders 0..2 = {row}")
check(all(trig_zero(r[0], [a]) and trig_zero(r[1], [a]) for r in Jd), "C¹ at every knot for every α")
check(trig_zero(Jd[1][2] + (1 + 2 * sp.cos(a)) / (2 * (1 - sp.cos(a))), [a]),
      "inner-knot second-derivative jump = −(1 + 2cos α)/(2(1 − cos α)): zero only at α = 2π/3,"
      " but the support-end jump 1/(2(1 − cos α)) never vanishes ⇒ exactly C¹ for every α")
print("done")
