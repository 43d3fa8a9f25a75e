"""Issue 40: independent check of examples/rational-trig-two-shape.toml (SymPy only, no Rust code read).

Rational quadratic trigonometric Bézier (RQTB) basis with two shape parameters and a weight, after
U. Bashir, M. Abbas, J. M. Ali, Appl. Math. Comput. 219 (2013) 10183-10197, in the form w0 = w2 = 1,
w1 = w (as we read it):

  q0 = (1 − s)(1 − αs),  q1 = αs(1 − s) + βc(1 − c) + s + c − 1,  q2 = (1 − c)(1 − βc),
  D = q0 + w q1 + q2,    R0 = q0/D,  R1 = w q1/D,  R2 = q2/D,
  s = sin t, c = cos t, t ∈ [0, π/2], α, β ∈ [−1, 1], w ∈ (0, ∞).

Every derivative is with respect to t (for u = 2t/π multiply order k by (π/2)^k).
Run:  cd examples/independent && python3 issue40_rational_two_shape.py   (about 10 s)
"""

import itertools

import sympy as sp
from _exact import check, trig_zero

R = sp.Rational
t, m = sp.symbols("t m")
al, be, w = sp.symbols("alpha beta w")
a1, b1, w1, a2, b2, w2 = sp.symbols("alpha1 beta1 w1 alpha2 beta2 w2")
gam, dlt = sp.symbols("gamma delta")
P0, P1, P2, Q0, Q1, Q2 = sp.symbols("P0 P1 P2 Q0 Q1 Q2")   # one coordinate: every condition is linear
S, C = sp.sin(t), sp.cos(t)


def qbasis(a, b):
    return [(1 - S) * (1 - a * S), a * S * (1 - S) + b * C * (1 - C) + S + C - 1, (1 - C) * (1 - b * C)]


def rbasis(a, b, ww):
    q = qbasis(a, b)
    D = q[0] + ww * q[1] + q[2]
    return [q[0] / D, ww * q[1] / D, q[2] / D], q, D


Rb, q, D = rbasis(al, be, w)


def at(expr, t0):
    return sp.factor(sp.simplify(expr.subs(t, t0)))


def d_at(expr, k, t0):
    return sp.factor(sp.simplify(sp.diff(expr, t, k).subs(t, t0)))


print("issue 40: rational QTB basis with α, β and weight w (Bashir, Abbas & Ali 2013, w0 = w2 = 1)")

# ---------------------------------------------------------------------------------------- unity
check(trig_zero(sum(Rb) - 1, [t]), "RQTB-unity / battery unity: R0 + R1 + R2 = 1 (exact: q0 + q1 + q2 = 1 so D − Σ = 0)")
check(trig_zero(sum(q) - 1, [t]), "  (the polynomial QTB functions sum to 1, hence D = 1 + (w − 1)q1)")

# ---------------------------------------------------------------------------------------- nonnegativity
# Weierstrass m = tan(t/2) ∈ [0, 1]: (1+m²)² q0 = (1−m)²(m² − 2αm + 1), (1+m²)² q2 = 2m²((1+β)m² + 1 − β),
# (1+m²)² q1 = 2m(1 − m)G, G = (1+α)(1 − m) + (1+β)m(1 + m).
ws = {S: 2 * m / (1 + m**2), C: (1 - m**2) / (1 + m**2)}
Nq = [sp.factor(sp.cancel(f.subs(ws) * (1 + m**2) ** 2)) for f in q]
G = (1 + al) * (1 - m) + (1 + be) * m * (1 + m)
check(sp.expand(Nq[0] - (1 - m) ** 2 * (m**2 - 2 * al * m + 1)) == 0, "(1+m²)²q0 = (1−m)²(m² − 2αm + 1)")
check(sp.expand(Nq[1] - 2 * m * (1 - m) * G) == 0, "(1+m²)²q1 = 2m(1−m)G, G = (1+α)(1−m) + (1+β)m(1+m)")
check(sp.expand(Nq[2] - 2 * m**2 * ((1 + be) * m**2 + 1 - be)) == 0, "(1+m²)²q2 = 2m²((1+β)m² + 1 − β)")
check(sp.expand((m**2 - 2 * al * m + 1) - (1 - m) ** 2 - 2 * m * (1 - al)) == 0,
      "m² − 2αm + 1 = (1−m)² + 2m(1−α) ≥ (1−m)² for α ≤ 1, m ≥ 0: q0 ≥ 0, and q0 > 0 for m < 1")
print("  (1+β)m² + 1 − β = (1+β)·m² + (1−β)·1 ≥ 0 for β ∈ [−1, 1]; G ≥ 0 termwise for α, β ≥ −1 on [0, 1]")
print("  q0 + q2 > 0 on [0, 1]: q0 > 0 for m < 1 and q2 = 1 at m = 1; so D = q0 + w·q1 + q2 > 0 for w ≥ 0")
print("  ⇒ RQTB-nonneg HOLDS on [−1, 1]² × (0, ∞) (each R_i a nonnegative numerator over D > 0)")
# exact spot check on a rational grid (every value exact)
grid_ab = [R(-1), R(-1, 2), R(0), R(1, 3), R(1)]
grid_w = [R(1, 100), R(1, 2), R(1), R(4), R(1000)]
grid_m = [R(0), R(1, 8), R(1, 3), R(1, 2), R(3, 4), R(7, 8), R(1)]
Rm = [sp.cancel(f.subs(ws)) for f in Rb]
ok = True
for A, B, W, M in itertools.product(grid_ab, grid_ab, grid_w, grid_m):
    vals = [f.subs({al: A, be: B, w: W, m: M}) for f in Rm]
    ok &= all(v >= 0 for v in vals) and sum(vals) == 1
check(ok, f"exact grid {len(grid_ab)**2 * len(grid_w) * len(grid_m)} points of [−1,1]²×(0,∞)×[0,π/2]: all R_i ≥ 0, Σ = 1")

# the maximal set (battery 'nonnegativity' claims the declared box is exactly the admissible set)
print("  maximal set of (α, β, w) with every R_i ≥ 0 (and D ≠ 0) on [0, π/2]:")
print("    {w > 0, α, β ∈ [−1, 1]} ∪ {w = 0, α, β ≤ 1} ∪ {w < 0, α, β ≤ −1}")
print("    (w < 0 needs q1 ≤ 0 everywhere, i.e. G(0) = 1+α ≤ 0 and G(1) = 2(1+β) ≤ 0, then w·q1 ≥ 0, D > 0)")


def Rval(A, B, W, M):
    return [sp.cancel(f.subs({al: A, be: B, w: W, m: M})) for f in Rm]


v = Rval(R(-2), R(-3), R(-1), R(1, 2))
check(all(x >= 0 for x in v), f"outside the box but admissible: (α, β, w) = (−2, −3, −1), t = 2atan(1/2): R = {v}")
ok = all(all(x >= 0 for x in Rval(A, B, W, M)) for A in (R(-1), R(-3, 2), R(-5)) for B in (R(-1), R(-2), R(-7))
         for W in (R(-1, 10), R(-1), R(-50)) for M in grid_m)
check(ok, "exact grid: R_i ≥ 0 for α ∈ {−1, −3/2, −5}, β ∈ {−1, −2, −7}, w ∈ {−1/10, −1, −50} (7 points t each)")
v = Rval(R(0), R(0), R(0), R(1, 2))
check(all(x >= 0 for x in v), f"w = 0 (excluded by the open end) is admissible too: R = {v} at α = β = 0, t = 2atan(1/2)")
v = Rval(R(0), R(0), R(-1, 10), R(1, 2))
check(v[1] < 0, f"w = −1/10, α = β = 0, (sin t, cos t) = (4/5, 3/5): R1 = {v[1]} < 0 (negative weight in the box fails)")
v = Rval(R(2), R(0), R(1), R(1, 2))
check(v[0] < 0, f"α = 2, β = 0, w = 1, (4/5, 3/5): R0 = {v[0]} < 0")
v = Rval(R(-2), R(0), R(1), R(1, 8))
check(v[1] < 0, f"α = −2, β = 0, w = 1, (16/65, 63/65): R1 = {v[1]} < 0")
print("  ⇒ battery 'nonnegativity' (declared ranges = the exact set): FAILS as a maximality statement;")
print("    containment of [−1, 1]² × (0, ∞) holds. (3 parameters: the tool decides containment only.)")

# ---------------------------------------------------------------------------------------- ends, derivatives
tab = {}
for e, nm in [(0, "0"), (sp.pi / 2, "π/2")]:
    for k in range(4):
        tab[(nm, k)] = [d_at(f, k, e) if k else at(f, e) for f in Rb]
        print(f"  order {k} at t = {nm}: {tab[(nm, k)]}")
check(tab[("0", 0)] == [1, 0, 0], "RQTB-ends-start holds: R(0) = (1, 0, 0)")
check(tab[("π/2", 0)] == [0, 0, 1], "RQTB-ends-end holds: R(π/2) = (0, 0, 1); battery interpolation holds")
check([sp.expand(x) for x in tab[("0", 1)]] == [sp.expand(-w * (1 + al)), sp.expand(w * (1 + al)), 0],
      "R'(0) = (−w(1+α), w(1+α), 0)")
check([sp.expand(x) for x in tab[("π/2", 1)]] == [0, sp.expand(-w * (1 + be)), sp.expand(w * (1 + be))],
      "R'(π/2) = (0, −w(1+β), w(1+β))")
for k in (1, 2, 3):   # symmetry of the tables: R_i^(k)(π/2; α, β) = (−1)^k R_{2−i}^(k)(0; β, α)
    sw = [sp.expand((-1) ** k * x.subs({al: be, be: al}, simultaneous=True)) for x in tab[("0", k)][::-1]]
    assert sw == [sp.expand(x) for x in tab[("π/2", k)]], k
print("  [ok] tables at π/2 = (−1)^k × tables at 0 reversed, α ↔ β (orders 1–3)")


def curve(b, P):
    return sum(f * p for f, p in zip(b, P))


r = curve(Rb, (P0, P1, P2))
check(sp.simplify(d_at(r, 1, 0) - w * (1 + al) * (P1 - P0)) == 0, "RQTB-tangent-start holds: r'(0) = w(1+α)(P1 − P0)")
check(sp.simplify(d_at(r, 1, sp.pi / 2) - w * (1 + be) * (P2 - P1)) == 0,
      "RQTB-tangent-end holds: r'(π/2) = w(1+β)(P2 − P1)")
c1s = w * (be - 2 * al - 1 - 2 * (w - 1) * (1 + al) ** 2)
check(sp.simplify(d_at(r, 2, 0) - (c1s * (P1 - P0) + (1 - be) * (P2 - P0))) == 0,
      "r''(0) = w(β − 2α − 1 − 2(w−1)(1+α)²)(P1 − P0) + (1 − β)(P2 − P0)")
c1e = w * (al - 2 * be - 1 - 2 * (w - 1) * (1 + be) ** 2)
check(sp.simplify(d_at(r, 2, sp.pi / 2) - (c1e * (P1 - P2) + (1 - al) * (P0 - P2))) == 0,
      "r''(π/2) = w(α − 2β − 1 − 2(w−1)(1+β)²)(P1 − P2) + (1 − α)(P0 − P2)")

# fixed weight w = 1/2
half = [sp.expand(x.subs(w, R(1, 2))) for x in tab[("0", 1)]]
check(half == [sp.expand(-(1 + al) / 2), sp.expand((1 + al) / 2), 0],
      "RQTB-half-weight holds: at w = 1/2, R'(0) = (−(1+α)/2, (1+α)/2, 0)")
check(trig_zero(sum(Rb).subs(w, 1) - 1, [t]) and all(trig_zero((Rb[i] - q[i]).subs(w, 1), [t]) for i in range(3)),
      "(at w = 1 the RQTB basis is the polynomial QTB basis of bashir-quadratic.toml)")

# ---------------------------------------------------------------------------------------- symmetry
Rx = [f.subs(t, sp.pi / 2 - t) for f in rbasis(be, al, w)[0]]
check(all(trig_zero(Rb[i] - Rx[2 - i], [t]) for i in range(3)),
      "RQTB-symmetry holds: R_i(t; α, β, w) = R_{2−i}(π/2 − t; β, α, w)")
Rk = [f.subs(t, sp.pi / 2 - t) for f in Rb]
diff0 = sp.factor(sp.simplify(sp.expand_trig(Rb[0] - Rk[2])))
print("  without the exchange: R0(t) − R2(π/2 − t) =", diff0)
env = {al: 0, be: -1, w: 32}
v0, v2 = sp.nsimplify(sp.radsimp(Rb[0].subs(env).subs(t, sp.pi / 4))), sp.nsimplify(sp.radsimp(Rk[2].subs(env).subs(t, sp.pi / 4)))
check(sp.simplify(v0 - (33 * sp.sqrt(2) - 4) / 1081) == 0 and sp.simplify(v2 - (31 * sp.sqrt(2) + 29) / 1081) == 0,
      f"battery symmetry (parameters kept) FAILS: α = 0, β = −1, w = 32, t = π/4: R0 = {v0}, R2(π/2 − t) = {v2}")
v1, v1x = sp.radsimp(Rb[1].subs(env).subs(t, sp.pi / 6)), sp.radsimp(Rb[1].subs(env).subs(t, sp.pi / 3))
check(v1 == R(32, 35) and sp.simplify(v1x - (3360 - 256 * sp.sqrt(3)) / 3611) == 0,
      f"  and R1(π/6) = {v1}, R1(π/3) = {sp.nsimplify(v1x)} (the tool's second witness, exact)")
check(all(trig_zero((Rb[i] - Rk[2 - i]).subs(be, al), [t]) for i in range(3)), "  (it holds on the line α = β)")

# ---------------------------------------------------------------------------------------- joins
Rp = rbasis(a1, b1, w1)[0]
Rq = rbasis(a2, b2, w2)[0]
p = curve(Rp, (P0, P1, P2))
qq = curve(Rq, (Q0, Q1, Q2))
p1, p2 = d_at(p, 1, sp.pi / 2), d_at(p, 2, sp.pi / 2)
q0v, q1, q2 = at(qq, 0), d_at(qq, 1, 0), d_at(qq, 2, 0)
check(sp.simplify(q0v - Q0) == 0 and sp.simplify(at(p, sp.pi / 2) - P2) == 0, "C0: Q0 = P2")

k = w1 * (1 + b1) / (w2 * (1 + a2))
C1_print = {Q0: P2, Q1: P2 + k * (P2 - P1)}
C1_sign = {Q0: P2, Q1: P2 - k * (P2 - P1)}
sol = sp.solve([q0v - P2, q1 - p1], [Q0, Q1], dict=True)[0]
print("  derived C1:", {kk: sp.factor(vv) for kk, vv in sol.items()})
check(all(sp.simplify(sol[x] - C1_print[x]) == 0 for x in (Q0, Q1)),
      "RQTB-C1: printed = derived as rational functions; the only pole is w2(1 + α2) = 0, i.e. α2 = −1 (w2 > 0)")
res = sp.factor(sp.simplify((q1 - p1).subs(C1_sign)))
check(sp.simplify(res - (-2 * w1 * (1 + b1) * (P2 - P1))) == 0,
      f"RQTB-C1-sign FAILS: Q'(0) − P'(π/2) = {res} = −2w1(1+β1)(P2 − P1) ≠ 0 "
      "(the '−' before the increment should be '+'; zero only if β1 = −1 or P1 = P2)")
wit = {a1: 0, b1: 0, w1: 1, a2: 1, b2: 0, w2: 1, P1: 0, P2: 1}
check(C1_sign[Q1].subs(wit) == R(1, 2) and sol[Q1].subs(wit) == R(3, 2),
      "  witness α2 = 1, w1 = w2 = 1, β1 = 0, P1 = 0, P2 = 1: printed Q1 = 1/2, derived Q1 = 3/2")
print("  at the pole α2 = −1: Q'(0) = w2(1 + α2)(Q1 − Q0) = 0 for every Q1; C¹ then needs w1(1+β1)(P2 − P1) = 0,")
print("  so the printed solved form 'holds wherever defined' and the pole is a genuine exclusion inside [−1, 1].")
check(sp.simplify(q1.subs(a2, -1)) == 0, "  (Q'(0) ≡ 0 at α2 = −1)")

# C1 at the fixed weight w1 = w2 = 1/2
sol_h = {x: sp.simplify(vv.subs({w1: R(1, 2), w2: R(1, 2)})) for x, vv in sol.items()}
check(sp.simplify(sol_h[Q1] - (P2 + (1 + b1) / (1 + a2) * (P2 - P1))) == 0,
      "RQTB-C1-half holds (wherever defined, α2 ≠ −1): at w = 1/2, Q1 = P2 + (1+β1)/(1+α2)(P2 − P1)")

# G1: Q'(0) = γ P'(π/2)
G1_print = {Q0: P2, Q1: P2 + gam * k * (P2 - P1)}
check(sp.simplify((q1 - gam * p1).subs(G1_print)) == 0, "RQTB-G1 holds wherever defined (α2 ≠ −1): Q'(0) = γ P'(π/2)")

# C2 and G2
e1 = w2 * (b2 - 2 * a2 - 1 - 2 * (w2 - 1) * (1 + a2) ** 2)
c1p = w1 * (a1 - 2 * b1 - 1 - 2 * (w1 - 1) * (1 + b1) ** 2)
C2_print = dict(C1_print)
C2_print[Q2] = P2 + ((1 - a1) * (P0 - P2) + (c1p + w1 * (1 + b1) * (b2 - 2 * a2 - 1 - 2 * (w2 - 1) * (1 + a2) ** 2) / (1 + a2))
                     * (P1 - P2)) / (1 - b2)
sol2 = sp.solve([q0v - P2, q1 - p1, q2 - p2], [Q0, Q1, Q2], dict=True)[0]
check(sp.simplify(sol2[Q2] - C2_print[Q2]) == 0,
      "RQTB-C2 holds wherever defined: printed Q2 = derived; poles α2 = −1 and β2 = 1 (1 − β2 is the Q2-coefficient of Q''(0))")
print("  derived Q2 denominator:", sp.factor(sp.denom(sp.together(sol2[Q2]))))
check(sp.simplify(sp.diff(q2, Q2) - (1 - b2)) == 0,
      "  Q''(0) = … + (1 − β2)Q2: at β2 = 1 (inside [−1, 1]) Q2 does not enter Q''(0) and C² is a condition on P, Q1")
G2_print = dict(G1_print)
G2_print[Q2] = P2 + (gam**2 * (1 - a1) * (P0 - P2)
                     + (gam**2 * c1p + gam * w1 * (1 + b1) * (b2 - 2 * a2 - 1 - 2 * (w2 - 1) * (1 + a2) ** 2) / (1 + a2)
                        - dlt * w1 * (1 + b1)) * (P1 - P2)) / (1 - b2)
check(sp.simplify((q1 - gam * p1).subs(G2_print)) == 0 and
      sp.simplify((q2 - gam**2 * p2 - dlt * p1).subs(G2_print)) == 0,
      "RQTB-G2 holds wherever defined (α2 ≠ −1, β2 ≠ 1): Q''(0) = γ²P''(π/2) + δP'(π/2)")

# battery joins: the same α, β, w on both segments
same = {a1: al, a2: al, b1: be, b2: be, w1: w, w2: w}
bq1 = sp.factor(sol[Q1].subs(same))
check(sp.simplify(bq1 - ((2 + al + be) * P2 - (1 + be) * P1) / (1 + al)) == 0,
      f"battery join-C1: Q1 = ((2 + α + β)P2 − (1 + β)P1)/(1 + α) (w cancels; pole α = −1)")
bq2 = sp.factor(sp.simplify(sol2[Q2].subs(same)))
print("  battery join-C2: Q2 =", bq2)
# the tool's printed Q2 of the battery (copied from its report, for comparison only)
tool_q2 = sp.sympify(
    "(2*beta**2*alpha*P1*w**2 - 2*beta**2*alpha*P2*w**2 + 2*beta*alpha**2*P1*w**2 - 2*beta*alpha**2*P2*w**2"
    " - 2*beta**2*alpha*P1*w + 2*beta**2*alpha*P2*w + 2*beta**2*P1*w**2 - 2*beta**2*P2*w**2 - 2*beta*alpha**2*P1*w"
    " + 2*beta*alpha**2*P2*w + 8*beta*alpha*P1*w**2 - 8*beta*alpha*P2*w**2 + 2*alpha**2*P1*w**2 - 2*alpha**2*P2*w**2"
    " - 3*beta**2*P1*w + 3*beta**2*P2*w - 4*beta*alpha*P1*w + 4*beta*alpha*P2*w + 6*beta*P1*w**2 - 6*beta*P2*w**2"
    " - 3*alpha**2*P1*w + 3*alpha**2*P2*w + 6*alpha*P1*w**2 - 6*alpha*P2*w**2 + beta*alpha*P2 - 4*beta*P1*w"
    " + 4*beta*P2*w + alpha**2*P0 - alpha**2*P2 - 4*alpha*P1*w + 4*alpha*P2*w + 4*P1*w**2 - 4*P2*w**2 + beta*P2"
    " - alpha*P2 - 2*P1*w + 2*P2*w - P0)/((beta - 1)*(alpha + 1))",
    locals={"alpha": al, "beta": be, "w": w, "P0": P0, "P1": P1, "P2": P2})
check(sp.simplify(bq2 - tool_q2) == 0, "  = the tool's battery join-C2 Q2 (poles α = −1, β = 1)")

# ---------------------------------------------------------------------------------------- conventions
# u = 2t/π on both segments: every order-k condition scales by (π/2)^k on both sides: C1, C2, G1 unchanged;
# G2 with the same symbol δ: Q''_u = γ²P''_u + δ_u P'_u  with δ_u = (π/2)δ_t  (still G2, another δ).
# x with spacings h1 ≠ h2 (t = π(x − x_i)/(2h_i)): Q'_x = (h1/h2)·P'_x for the printed C1 points: not C1 in x,
# but G1 with γ_x = γh1/h2 > 0 (geometric continuity is invariant under these affine reparametrisations).
h1, h2 = sp.symbols("h1 h2", positive=True)
resx = sp.factor(sp.simplify((sp.pi / (2 * h2) * q1 - sp.pi / (2 * h1) * p1).subs(C1_print)))
print("  C1 points, derivative in x with spacings h1, h2: Q'_x(0) − P'_x(end) =", resx)
check(sp.simplify(resx.subs(h2, h1)) == 0, "  zero iff h1 = h2 (so 'fails in x (h1 ≠ h2)' is a convention the claim, wrt = t, does not state)")
resu = sp.factor(sp.simplify(((sp.pi / 2) ** 2 * q2 - gam**2 * (sp.pi / 2) ** 2 * p2 - dlt * (sp.pi / 2) * p1).subs(G2_print)))
print("  G2 points, in u with the same δ: residual =", resu)
check(sp.simplify(((sp.pi / 2) ** 2 * q2 - gam**2 * (sp.pi / 2) ** 2 * p2 - (sp.pi / 2 * dlt) * (sp.pi / 2) * p1).subs(G2_print)) == 0,
      "  with δ_u = (π/2)δ the same points are G2 in u: the u 'failure' is a renamed δ, not a failed G2")
print("done")
