"""Issue 41: an independent check of the spec-language constructs added in session 4
(identity with readings, joins with segments named as printed and segment-params,
also-params, join-singular, one-maximum, umbrellas, negated claims), on a basis that is
in neither examples/*.toml nor examples/catalog/:

  the generalized Bernstein basis of degree 3 with three shape parameters (GB3),
  X.-A. Han, Y.-C. Ma, X.-L. Huang, "A novel generalization of Bézier curve and surface",
  J. Comput. Appl. Math. 217 (2008) 180–193, as quoted in G. Hu, C. Bo, X. Qin,
  "Continuity conditions for Q-Bézier curves of degree n", J. Inequal. Appl. 2017:115,
  Definition 1, eq. (1), the case n = 3 ([n/2] = 2):

    b0 = (1 − t)³(1 − λ1 t),
    b1 = t(1 − t)²(3 + λ1 − λ1 t − λ2 t),
    b2 = t²(1 − t)(3 + λ2 − λ2 t + λ3 t),
    b3 = t³(1 − λ3 + λ3 t),        t ∈ [0, 1],
    λ1 ∈ [−3, 1], λ2 ∈ [−3, 3], λ3 ∈ [−3, 1].

Expected values for examples/gb3-three-shape.toml and examples/gb-2008/document.toml,
asserted by tests/tests/constructs_independent.rs. Derivatives in t (each segment its own
t ∈ [0, 1]). SymPy only (run: python3 examples/independent/issue41_constructs.py).
"""

import sympy as sp
from sympy import Rational as R

t = sp.Symbol("t")
l1, l2, l3 = sp.symbols("lambda1 lambda2 lambda3")
u1, u2, u3, v1, v2, v3 = sp.symbols("u1 u2 u3 v1 v2 v3")
alpha, beta = sp.symbols("alpha beta")
P = sp.symbols("P0:8")  # P0..P3 the first segment, P4..P7 the second (as printed)


def gb3(a, b, c):
    return [
        (1 - t) ** 3 * (1 - a * t),
        t * (1 - t) ** 2 * (3 + a - a * t - b * t),
        t**2 * (1 - t) * (3 + b - b * t + c * t),
        t**3 * (1 - c + c * t),
    ]


def check(ok, what):
    assert ok, what
    print("  ok  " + what)


B = gb3(l1, l2, l3)
print("GB3 (Han, Ma & Huang 2008; Hu, Bo & Qin 2017 Def. 1, n = 3)")

# ---------------------------------------------------------------- 1. unity, nonnegativity
check(sp.expand(sum(B) - 1) == 0, "partition of unity: Σ b_i − 1 = 0 identically")
# nonnegativity on the box: each function is a product of powers of t, 1 − t and a
# factor linear in t, which is ≥ 0 at t = 0 and t = 1 for every λ of the box
lin = [1 - l1 * t, 3 + l1 - (l1 + l2) * t, 3 + l2 + (l3 - l2) * t, 1 - l3 + l3 * t]
ends = [(f.subs(t, 0), f.subs(t, 1)) for f in lin]
print("  linear factors at t = 0, 1:", ends)
check(ends == [(1, 1 - l1), (l1 + 3, 3 - l2), (l2 + 3, l3 + 3), (1 - l3, 1)],
      "the linear factors are ≥ 0 at both ends exactly on the box: b_i ≥ 0 there (the declared box)")

# ---------------------------------------------------------------- 2. end derivatives
d = {k: [sp.factor(sp.diff(f, t, k).subs(t, 0)) for f in B] for k in (1, 2, 3)}
e = {k: [sp.factor(sp.diff(f, t, k).subs(t, 1)) for f in B] for k in (1, 2, 3)}
for k in (1, 2, 3):
    print(f"  b_i^({k})(0) = {d[k]}")
    print(f"  b_i^({k})(1) = {e[k]}")
check(d[1] == [-(l1 + 3), l1 + 3, 0, 0] and e[1] == [0, 0, -(l3 + 3), l3 + 3],
      "b0'(0) = −(3 + λ1), b1'(0) = 3 + λ1; b2'(1) = −(3 + λ3), b3'(1) = 3 + λ3")
check(sp.expand(d[2][0] - 6 * (1 + l1)) == 0 and sp.expand(d[2][1] + 2 * (3 * l1 + l2 + 6)) == 0
      and sp.expand(d[2][2] - 2 * (l2 + 3)) == 0 and d[2][3] == 0,
      "b0''(0) = 6(1 + λ1), b1''(0) = −2(3λ1 + λ2 + 6), b2''(0) = 2(λ2 + 3), b3''(0) = 0")
check(sp.expand(e[2][1] - 2 * (3 - l2)) == 0 and sp.expand(e[2][2] + 2 * (6 - l2 + 3 * l3)) == 0
      and sp.expand(e[2][3] - 6 * (1 + l3)) == 0,
      "b1''(1) = 2(3 − λ2), b2''(1) = −2(6 − λ2 + 3λ3), b3''(1) = 6(1 + λ3)")
check(sp.expand(d[3][3] - 6 * (1 - l3)) == 0, "b3'''(0) = 6(1 − λ3): the C³ pivot")

# the curve R = Σ b_i P_i and its end derivatives
Rc = sum(f * p for f, p in zip(B, P[:4]))
R1_0 = sp.expand(sp.diff(Rc, t).subs(t, 0))
R1_1 = sp.expand(sp.diff(Rc, t).subs(t, 1))
R2_0 = sp.expand(sp.diff(Rc, t, 2).subs(t, 0))
R2_1 = sp.expand(sp.diff(Rc, t, 2).subs(t, 1))
check(sp.expand(R1_0 - (3 + l1) * (P[1] - P[0])) == 0, "R'(0) = (3 + λ1)(P1 − P0)")
check(sp.expand(R1_1 - (3 + l3) * (P[3] - P[2])) == 0, "R'(1) = (3 + λ3)(P3 − P2)")
R2_0_print = 6 * (1 + l1) * (P[0] - P[1]) + 2 * (3 + l2) * (P[2] - P[1])
check(sp.expand(R2_0 - R2_0_print) == 0, "R''(0) = 6(1 + λ1)(P0 − P1) + 2(3 + λ2)(P2 − P1)")
R2_1_print = 6 * (1 + l3) * (P[3] - P[2]) + 2 * (3 - l2) * (P[1] - P[2])
check(sp.expand(R2_1 - R2_1_print) == 0, "R''(1) = 6(1 + λ3)(P3 − P2) + 2(3 − λ2)(P1 − P2)")

# ---------------------------------------------------------------- 3. printed identities
print("printed identities (claim GB3-identities):")
# (a) garbled: R'(1) printed with a flipped sign; read as (3 + λ3)
garbled = (3 - l3) * (P[3] - P[2])
res = sp.factor(R1_1 - garbled)
print("  R'(1) − (3 − λ3)(P3 − P2) =", res)
check(sp.expand(res - 2 * l3 * (P[3] - P[2])) == 0,
      "the print R'(1) = (3 − λ3)(P3 − P2) fails: residual 2λ3(P3 − P2); the reading (3 + λ3) holds")
# (b) a wrong coefficient with no reading: R''(0) printed with 2(3 + λ1) for 6(1 + λ1)
wrong = 2 * (3 + l1) * (P[0] - P[1]) + 2 * (3 + l2) * (P[2] - P[1])
res_b = sp.factor(R2_0 - wrong)
print("  R''(0) − [2(3 + λ1)(P0 − P1) + 2(3 + λ2)(P2 − P1)] =", res_b)
check(sp.expand(res_b - 4 * l1 * (P[0] - P[1])) == 0, "a wrong coefficient: residual 4λ1(P0 − P1)")
# its value at a witness: λ1 = 1, P0 = 1, P1 = 0 gives 4
check(res_b.subs({l1: 1, P[0]: 1, P[1]: 0}) == 4, "  at λ1 = 1, P0 = 1, P1 = 0 the residual is 4")

# ---------------------------------------------------------------- 4. the maximum of b1
print("the maximum of b1:")
A, Bc = 3 + l1, l1 + l2
b1p = sp.factor(sp.diff(B[1], t))
print("  b1' =", b1p)
bracket = sp.expand(A - (2 * Bc + 3 * A) * t + 4 * Bc * t**2)
check(sp.expand(sp.diff(B[1], t) - (1 - t) * bracket) == 0,
      "b1' = (1 − t)(A − (2B + 3A)t + 4Bt²), A = 3 + λ1, B = λ1 + λ2")
check(sp.expand(bracket.subs(t, R(1, 4)) - (A - Bc) / 4) == 0,
      "at t = 1/4 the bracket is (A − B)/4 = (3 − λ2)/4: b1'(1/4) = 0 exactly when λ2 = 3")
b1_at3 = sp.factor(B[1].subs(l2, 3))
print("  b1 at λ2 = 3:", b1_at3)
check(sp.expand(b1_at3 - (l1 + 3) * t * (1 - t) ** 3) == 0,
      "at λ2 = 3, b1 = (3 + λ1)t(1 − t)³: its maximum is at t = 1/4 (for λ1 > −3)")
wrong_max = sp.factor(sp.diff(B[1], t).subs({l2: 3, t: R(1, 3)}))
print("  b1'(1/3) at λ2 = 3:", wrong_max)
check(sp.expand(wrong_max + R(4, 27) * (l1 + 3)) == 0,
      "the print 'maximum at t = 1/3' (b1'(1/3) = 0) at λ2 = 3 fails: b1'(1/3) = −4(λ1 + 3)/27")
check(wrong_max.subs(l1, 0) == R(-4, 9), "  e.g. at λ1 = 0: b1'(1/3) = −4/9")

# one maximum per function
print("one maximum per function:")
# b0' = (1 − t)²(4λ1 t − 3 − λ1) ≤ 0 on [0, 1] for λ1 ∈ [−3, 1]: b0 decreasing, max at t = 0
b0p = sp.factor(sp.diff(B[0], t))
check(sp.expand(b0p - (1 - t) ** 2 * (4 * l1 * t - 3 - l1)) == 0, "b0' = (1 − t)²(4λ1t − 3 − λ1) ≤ 0 on the box (−3 − λ1 ≤ 0 at t = 0, 3λ1 − 3 ≤ 0 at t = 1)")
at_pt = {l1: 0, l2: 1, l3: 0}
for i, f in enumerate(B):
    g = sp.Poly(sp.diff(f, t).subs(at_pt), t)
    print(f"  at (λ1, λ2, λ3) = (0, 1, 0): b{i}' real roots in [0, 1]:",
          [r for r in sp.real_roots(g) if 0 <= r <= 1])
# at (0, 1, 0): b1' = (1 − t)(3 − 11t + 4t²)... each function one maximum
check(all(len(set(r for r in sp.real_roots(sp.Poly(sp.diff(f, t).subs(at_pt), t)) if 0 < r < 1)) <= 1
          for f in B), "at (0, 1, 0) each b_i' has at most one interior root: one maximum each")
# outside the box, λ = (1, 10, 0): b1 = t(1 − t)²(4 − 11t) is negative on (4/11, 1) and 0 at t = 1
b1_out = B[1].subs({l1: 1, l2: 10, l3: 0})
b1_out_p = sp.Poly(sp.diff(b1_out, t), t)
roots = [r for r in sp.real_roots(b1_out_p) if 0 <= r <= 1]
print("  at (1, 10, 0): b1 =", sp.factor(b1_out), " b1' roots in [0, 1]:", roots)
check(b1_out.subs(t, R(1, 2)) == R(-3, 16) and b1_out.subs(t, R(1, 4)) == R(45, 256),
      "at (1, 10, 0): b1(1/4) = 45/256 > 0, b1(1/2) = −3/16 < 0, b1(1) = 0: two maxima (at (17 − √113)/44 and at t = 1)")
check(sp.diff(b1_out, t).subs(t, R(19, 20)) > 0, "  b1' > 0 just before t = 1: the end t = 1 is a maximum")
# the edges where a function vanishes identically (no single maximum there)
check(sp.expand(B[1].subs({l1: -3, l2: 3})) == 0, "b1 ≡ 0 at λ1 = −3, λ2 = 3 (an edge of the box)")
check(sp.expand(B[2].subs({l2: -3, l3: -3})) == 0, "b2 ≡ 0 at λ2 = −3, λ3 = −3 (an edge of the box)")

# ---------------------------------------------------------------- 5. joins, different parameters
print("joins: first segment (u1, u2, u3), points P0..P3; second (v1, v2, v3), points P4..P7")
Pc = sum(f * p for f, p in zip(gb3(u1, u2, u3), P[:4]))
Qc = sum(f * p for f, p in zip(gb3(v1, v2, v3), P[4:]))
X4, X5, X6, X7 = sp.symbols("X4 X5 X6 X7")
Qx = Qc.subs({P[4]: X4, P[5]: X5, P[6]: X6, P[7]: X7}, simultaneous=True)
eqs = [sp.diff(Qx, t, k).subs(t, 0) - sp.diff(Pc, t, k).subs(t, 1) for k in range(4)]
sol = sp.solve(eqs, [X4, X5, X6, X7], dict=True)[0]
P4s = sp.factor(sol[X4])
P5s = sp.factor(sol[X5])
P6s = sp.factor(sol[X6])
P7s = sp.factor(sol[X7])
print("  C0: P4 =", P4s)
print("  C1: P5 =", P5s)
print("  C2: P6 =", P6s)
print("  C3: P7 =", sp.factor(sp.denom(sp.together(P7s))), "(denominator)")
check(P4s == P[3], "C0: P4 = P3")
C1_print = P[3] + (3 + u3) / (3 + v1) * (P[3] - P[2])
check(sp.cancel(P5s - C1_print) == 0, "C1: P5 = P3 + (3 + u3)/(3 + v1)(P3 − P2)")
# the C2 point as a paper would print it (P5 kept as a point):
# (3 + v2)P6 = (3 + v2)P5 + 3(1 + v1)(P5 − P4) + 3(1 + u3)(P3 − P2) + (3 − u2)(P1 − P2)
C2_print = P[5] + (3 * (1 + v1) * (P[5] - P[3]) + 3 * (1 + u3) * (P[3] - P[2]) + (3 - u2) * (P[1] - P[2])) / (3 + v2)
Qc2 = sp.diff(Qc, t, 2).subs(t, 0).subs(P[4], P[3])
check(sp.cancel(sp.solve(sp.Eq(Qc2, sp.diff(Pc, t, 2).subs(t, 1)), P[6])[0] - C2_print) == 0,
      "C2: P6 = P5 + [3(1 + v1)(P5 − P3) + 3(1 + u3)(P3 − P2) + (3 − u2)(P1 − P2)]/(3 + v2)")
check(sp.cancel(C2_print.subs(P[5], P5s) - P6s) == 0, "  (the same P6 as the full solve with P5 substituted)")
# the C2 print with a sign typo in one term: + (3 − u2)(P2 − P1)
C2_sign = P[5] + (3 * (1 + v1) * (P[5] - P[3]) + 3 * (1 + u3) * (P[3] - P[2]) + (3 - u2) * (P[2] - P[1])) / (3 + v2)
check(sp.cancel(C2_sign - C2_print) != 0, "C2 printed with (3 − u2)(P2 − P1): a sign typo in one term (fails as printed)")
# a wrong coefficient in C1: (3 + u1) for (3 + u3)
C1_wrong = P[3] + (3 + u1) / (3 + v1) * (P[3] - P[2])
check(sp.cancel(C1_wrong - C1_print) != 0, "C1 printed with (3 + u1)/(3 + v1): fails (a wrong parameter)")
# a sign flip of the bracket in C1
C1_sign = P[3] + (3 + u3) / (3 + v1) * (P[2] - P[3])
check(sp.cancel(C1_sign - C1_print) != 0, "C1 printed with (P2 − P3): a sign typo (holds after correction)")
# the C1 print under the swapped reading of the segments' parameters (also-params):
# first segment v, second u: derived P5 = P3 + (3 + v3)/(3 + u1)(P3 − P2) ≠ the print
swapped = P5s.subs({u1: v1, u2: v2, u3: v3, v1: u1, v2: u2, v3: u3}, simultaneous=True)
check(sp.cancel(swapped - (P[3] + (3 + v3) / (3 + u1) * (P[3] - P[2]))) == 0
      and sp.cancel(swapped - C1_print) != 0,
      "also-params (segments' parameters swapped): derived P5 = P3 + (3 + v3)/(3 + u1)(P3 − P2), the print fails there")
# G1: P5 = P3 + α(3 + u3)/(3 + v1)(P3 − P2)
Qg = sp.diff(Qc, t).subs(t, 0).subs(P[4], P[3])
G1_sol = sp.solve(sp.Eq(Qg, alpha * sp.diff(Pc, t).subs(t, 1)), P[5])[0]
check(sp.cancel(G1_sol - (P[3] + alpha * (3 + u3) / (3 + v1) * (P[3] - P[2]))) == 0,
      "G1: P5 = P3 + α(3 + u3)/(3 + v1)(P3 − P2)")

# ---------------------------------------------------------------- 6. where the joins are singular
print("join-singular: the pivots of the forced points P5, P6, P7 (second segment's parameters)")
piv = [sp.factor(sp.diff(f, t, k).subs(t, 0)) for k, f in zip((1, 2, 3), gb3(v1, v2, v3)[1:])]
print("  pivots b1'(0), b2''(0), b3'''(0):", piv)
check([sp.expand(a - b) for a, b in zip(piv, [v1 + 3, 2 * (v2 + 3), 6 * (1 - v3)])] == [0, 0, 0],
      "pivots 3 + v1 (C1, G1), 2(3 + v2) (C2, G2), 6(1 − v3) (C3)")
print("  they vanish inside the closed box at λ1 = −3 (C1 and above), λ2 = −3 (C2 and above), λ3 = 1 (C3)")
check(sp.denom(sp.together(P5s)) == v1 + 3 and sp.factor(sp.denom(sp.together(P6s))) in
      ((v1 + 3) * (v2 + 3), sp.factor((v1 + 3) * (v2 + 3))),
      "the solved P5 divides by (3 + v1), P6 by (3 + v1)(3 + v2)")
check(sp.factor(sp.denom(sp.together(P7s))).has(v3 - 1), "the solved P7 divides by (v3 − 1)")
print("  the print 'λ1 = −3 breaks the joins' alone: fails (λ2 = −3 and λ3 = 1 also break joins)")
print("  the print 'λ1 = −3, λ2 = −3, λ3 = 1 break the joins': holds")
# same parameters: P5 = P3 + (3 + λ3)/(3 + λ1)(P3 − P2)
same = P5s.subs({u1: l1, u2: l2, u3: l3, v1: l1, v2: l2, v3: l3})
check(sp.cancel(same - (P[3] + (3 + l3) / (3 + l1) * (P[3] - P[2]))) == 0,
      "same parameters: P5 = P3 + (3 + λ3)/(3 + λ1)(P3 − P2)")

# ---------------------------------------------------------------- 7. negated claims
print("negated claims ('is not C²'):")
# the classical Bézier C² rule P6 = P1 − 4P2 + 4P3 (λ = 0), with P5 = 2P3 − P2, for GB3 with one set of
# parameters: the derived P6 with P5 = 2P3 − P2 substituted is P1 − 4P2 + 4P3 only when ...
same6 = sp.factor(P6s.subs({u1: l1, u2: l2, u3: l3, v1: l1, v2: l2, v3: l3}))
bez5 = 2 * P[3] - P[2]
bez6 = P[1] - 4 * P[2] + 4 * P[3]
d5 = sp.cancel(same.subs({}) - bez5)
print("  P5(derived, same λ) − (2P3 − P2) =", sp.factor(d5))
check(sp.cancel(d5) != 0, "with the Bézier rule the GB3 curve is not C¹ in general (so not C²): 'is not C²' holds")
check(sp.cancel(same.subs({l1: 0, l3: 0}) - bez5) == 0 and sp.cancel(same6.subs({l1: 0, l2: 0, l3: 0}) - bez6) == 0,
      "  (at λ = 0 the Bézier rules are the GB3 rules: the Bernstein case)")
print("  'the curve joined by the derived C² points is not C²': fails (the derived points give C²)")

# ---------------------------------------------------------------- 8. GB2 (the umbrella's other basis)
print("GB2 (examples/gb2-independence.toml): unity, nonnegative on [−2, 1]²")
m1, m2 = sp.symbols("m1 m2")
G2 = [(1 - t) ** 2 * (1 - m1 * t), t * (1 - t) * (2 + m1 - m1 * t + m2 * t), t**2 * (1 - m2 + m2 * t)]
check(sp.expand(sum(G2) - 1) == 0, "GB2 partition of unity")
check([(f.subs(t, 0), f.subs(t, 1)) for f in (1 - m1 * t, 2 + m1 - m1 * t + m2 * t, 1 - m2 + m2 * t)]
      == [(1, 1 - m1), (m1 + 2, m2 + 2), (1 - m2, 1)], "GB2 linear factors ≥ 0 at both ends on [−2, 1]²")
# a false part of an umbrella: GB2's b1'(0) printed as 2 + λ2 (it is 2 + λ1)
g1p0 = sp.diff(G2[1], t).subs(t, 0)
check(sp.expand(g1p0 - (2 + m1)) == 0, "GB2 b1'(0) = 2 + λ1 (a part printing 2 + λ2 fails: residual λ1 − λ2)")
print("all checks passed")

# ---------------------------------------------------------------- 9. GB2 joins (document claims GB-3b, GB-4)
print("GB2 joins (same parameters m1, m2; points P0..P2, P3..P5):")
Y3, Y4, Y5 = sp.symbols("Y3 Y4 Y5")
Pg = sum(f * p for f, p in zip(G2, P[:3]))
Qg2 = sum(f * p for f, p in zip(G2, (Y3, Y4, Y5)))
sol2 = sp.solve([sp.diff(Qg2, t, k).subs(t, 0) - sp.diff(Pg, t, k).subs(t, 1) for k in range(3)], [Y3, Y4, Y5], dict=True)[0]
print("  C0..C2:", {k: sp.factor(v) for k, v in sol2.items()})
pivots2 = [sp.factor(sp.diff(G2[1], t).subs(t, 0)), sp.factor(sp.diff(G2[2], t, 2).subs(t, 0))]
print("  pivots b1'(0), b2''(0):", pivots2)
check(sp.expand(pivots2[0] - (m1 + 2)) == 0 and sp.expand(pivots2[1] - 2 * (1 - m2)) == 0,
      "GB2 pivots 2 + λ1 (C1) and 2(1 − λ2) (C2): singular at λ1 = −2 and λ2 = 1, both in [−2, 1]")
check(sp.cancel(sol2[Y4] - (P[2] + (2 + m2) / (2 + m1) * (P[2] - P[1]))) == 0,
      "GB2 C1: P4 = P2 + (2 + λ2)/(2 + λ1)(P2 − P1)")
check(sp.cancel(sol2[Y4] - (2 * P[2] - P[1])) != 0,
      "GB2 with the quadratic Bézier rule P4 = 2P2 − P1: not C¹ (unless λ1 = λ2), so 'is not C²' holds")
print("all GB2 join checks passed")

# ---------------------------------------------------------------- 10. residuals the audit prints
print("residuals of the failing conditions (as the audit prints them, expanded):")
# GB3 with the Bézier rules (same λ): Q'(0) − P'(1) with Q0 = P3, Q1 = 2P3 − P2
Pl = sum(f * p for f, p in zip(B, P[:4]))
Ql = sum(f * p for f, p in zip(B, (P[3], 2 * P[3] - P[2], P[1] - 4 * P[2] + 4 * P[3], P[7])))
r1 = sp.expand(sp.diff(Ql, t).subs(t, 0) - sp.diff(Pl, t).subs(t, 1))
r2 = sp.expand(sp.diff(Ql, t, 2).subs(t, 0) - sp.diff(Pl, t, 2).subs(t, 1))
print("  GB3 Bézier rules: order 1:", sp.collect(r1, P), "  order 2:", sp.collect(r2, P))
check(sp.expand(r1 - (l1 - l3) * (P[3] - P[2])) == 0, "GB3 order-1 residual (λ1 − λ3)(P3 − P2)")
check(sp.expand(r2 - (4 * l2 * P[1] + (6 * l1 - 8 * l2 + 6 * l3) * P[2] + (-6 * l1 + 4 * l2 - 6 * l3) * P[3])) == 0,
      "GB3 order-2 residual 4λ2·P1 + (6λ1 − 8λ2 + 6λ3)·P2 + (−6λ1 + 4λ2 − 6λ3)·P3")
Qb = sum(f * p for f, p in zip(G2, (P[2], 2 * P[2] - P[1], P[0] - 4 * P[1] + 4 * P[2])))
g_r1 = sp.expand(sp.diff(Qb, t).subs(t, 0) - sp.diff(Pg, t).subs(t, 1))
g_r2 = sp.expand(sp.diff(Qb, t, 2).subs(t, 0) - sp.diff(Pg, t, 2).subs(t, 1))
print("  GB2 Bézier rules: order 1:", sp.collect(g_r1, P), "  order 2:", sp.collect(g_r2, P))
check(sp.expand(g_r1 - (m1 - m2) * (P[2] - P[1])) == 0, "GB2 order-1 residual (λ1 − λ2)(P2 − P1)")
check(sp.expand(g_r2 - ((2 * m1 - 2 * m2) * P[0] + (2 * m1 + 10 * m2) * P[1] + (-4 * m1 - 8 * m2) * P[2])) == 0,
      "GB2 order-2 residual (2λ1 − 2λ2)P0 + (2λ1 + 10λ2)P1 + (−4λ1 − 8λ2)P2")
# the C² sign typo: residual of the order-2 condition 2(3 + v2)·(printed P6 − derived P6)
Qs = sp.diff(Qc, t, 2).subs(t, 0)
typo = sp.factor(sp.expand(Qs.subs({P[4]: P[3], P[6]: C2_sign}) - Qs.subs({P[4]: P[3], P[6]: C2_print})))
print("  C2 typo residual:", typo)
check(sp.expand(typo - (4 * u2 - 12) * P[1] - (-4 * u2 + 12) * P[2]) == 0,
      "GB3 C² typo: residual of the order-2 condition (4u2 − 12)P1 + (−4u2 + 12)P2")
# the reading of R''(0) that is wrong too: residual 2λ1(P0 − P1)
rd = sp.expand(R2_0 - (2 * (3 + 2 * l1) * (P[0] - P[1]) + 2 * (3 + l2) * (P[2] - P[1])))
check(sp.expand(rd - 2 * l1 * (P[0] - P[1])) == 0, "the wrong reading of R''(0): residual 2λ1(P0 − P1)")
print("all residual checks passed")

# ---------------------------------------------------------------- 11. symmetry (claims GB3-symmetry*)
print("symmetry:")
S = [f.subs(t, 1 - t) for f in gb3(l3, -l2, l1)]
check(all(sp.expand(B[i] - S[3 - i]) == 0 for i in range(4)),
      "b_i(t; λ1, λ2, λ3) = b_{3−i}(1 − t; λ3, −λ2, λ1) (λ2 negated)")
S2 = [f.subs(t, 1 - t) for f in gb3(l3, l2, l1)]
res_s = sp.factor(B[1] - S2[2])
print("  with λ2 kept: b1(t) − b2(1 − t; λ3, λ2, λ1) =", res_s)
check(sp.expand(res_s + 2 * l2 * t**2 * (1 - t) ** 2) == 0, "  residual −2λ2·t²(1 − t)²: fails unless λ2 = 0")
check(B[1].subs({l1: 0, l2: -3, t: R(1, 2)}) == R(9, 16) and S2[2].subs({l1: 0, l2: -3, l3: 0, t: R(1, 2)}) == R(3, 16),
      "  e.g. at λ = (0, −3, 0), t = 1/2: 9/16 against 3/16")
print("all symmetry checks passed")
