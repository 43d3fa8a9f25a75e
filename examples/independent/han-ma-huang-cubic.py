"""Independent check of examples/han-ma-huang-cubic.toml and Part B3 (joins, terminal properties).

Han, Ma & Huang, "The cubic trigonometric Bézier curve with two shape parameters",
Appl. Math. Lett. 22 (2009) 226-231, (1):
  b0 = (1 − s)²(1 − λs),  b1 = s(1 − s)(2 + λ − λs),
  b2 = c(1 − c)(2 + μ − μc),  b3 = (1 − c)²(1 − μc),   s = sin t, c = cos t, t ∈ [0, π/2], λ, μ ∈ [−2, 1].
Derivatives are w.r.t. the angle t unless said otherwise (u = 2t/π ∈ [0,1]: multiply order k by (π/2)^k).
"""

import sympy as sp
from _exact import (PYTH_M, check, numerator_posden, param_set, show_intervals, trig_at, trig_zero,
                    weierstrass, mp_min)

t, lam, mu, m = sp.symbols("t lambda mu m")
S, C = sp.sin(t), sp.cos(t)


def basis(l, u):
    return [(1 - S) ** 2 * (1 - l * S), S * (1 - S) * (2 + l - l * S),
            C * (1 - C) * (2 + u - u * C), (1 - C) ** 2 * (1 - u * C)]


b = basis(lam, mu)
print("han-ma-huang-cubic: Han, Ma & Huang 2009")
check(trig_zero(sum(b) - 1, [t]), "HMH-unity: Σ b_i = 1 (exact); b0+b1 = cos²t, b2+b3 = sin²t")
check(trig_zero(b[0] + b[1] - C**2, [t]) and trig_zero(b[2] + b[3] - S**2, [t]), "  pair sums verified")

# ---- region of (λ, μ): b0, b1 involve λ only, b2, b3 μ only, so the region is a product
check(all(not f.has(mu) for f in b[:2]) and all(not f.has(lam) for f in b[2:]), "b0,b1 free of μ; b2,b3 free of λ")
N = [numerator_posden(weierstrass(f, t, m), m) for f in b]
ivl, sl, _ = param_set(N[:2], m, lam, 0, 1, prefer=PYTH_M)
ivm, sm, _ = param_set(N[2:], m, mu, 0, 1, prefer=PYTH_M)
for name, off, smp in (("λ", 0, sl), ("μ", 2, sm)):
    for l0, ok, w in smp:
        print(f"  sample {name}={l0}: {'ok' if ok else f'b{w[0] + off} < 0 at m = tan(t/2) = {w[1]}'}")
print("  λ-range:", show_intervals(ivl), "  μ-range:", show_intervals(ivm))
check(ivl == [(-2, 1)] and ivm == [(-2, 1)], "HMH-region holds: exact region = [−2, 1] × [−2, 1] (the declared box)")
for (l0, u0, i, mm) in [(2, 0, 0, sp.Rational(1, 2)), (sp.Rational(11, 10), 0, 0, sp.Rational(3, 4)),
                        (-3, 0, 1, sp.Rational(1, 8)), (0, -3, 2, sp.Rational(7, 8)), (0, 2, 3, sp.Rational(1, 2))]:
    v = trig_at(b[i].subs({lam: l0, mu: u0}), t, mm)
    check(v < 0, f"witness (λ,μ)=({l0},{u0}): b{i} at (sin,cos)=({trig_at(S, t, mm)},{trig_at(C, t, mm)}) = {v} < 0")

# ---- symmetry (B3)
bx = basis(mu, lam)  # parameters exchanged
check(all(trig_zero(b[i] - bx[3 - i].subs(t, sp.pi / 2 - t), [t]) for i in range(4)),
      "exchange symmetry b_i(t; λ, μ) = b_{3−i}(π/2 − t; μ, λ) holds (exact)")
sym_plain = [sp.factor(sp.expand_trig(b[i] - b[3 - i].subs(t, sp.pi / 2 - t))) for i in range(4)]
print("  b_i(t;λ,μ) − b_{3−i}(π/2 − t;λ,μ) =", sym_plain)
mm = sp.Rational(1, 2)
v0 = trig_at(b[0].subs({lam: 0, mu: 1}), t, mm)
v3 = trig_at(b[3].subs(t, sp.pi / 2 - t).subs({lam: 0, mu: 1}), t, mm)
check(v0 != v3, f"symmetry WITHOUT exchange fails for λ≠μ: λ=0, μ=1, sin t=4/5: b0(t) = {v0}, b3(π/2−t) = {v3}")

# ---- endpoint derivatives (w.r.t. t)
D = {}
for end, nm in [(0, "0"), (sp.pi / 2, "π/2")]:
    for k in (1, 2, 3):
        D[(nm, k)] = [sp.factor(sp.simplify(sp.diff(f, t, k).subs(t, end))) for f in b]
        print(f"  order {k} at t={nm}: {D[(nm, k)]}")
check(D[("0", 1)] == [-(lam + 2), lam + 2, 0, 0], "b'(0) = (−(λ+2), λ+2, 0, 0)")
check(D[("π/2", 1)] == [0, 0, -(mu + 2), mu + 2], "b'(π/2) = (0, 0, −(μ+2), μ+2)")
check([sp.expand(x) for x in D[("0", 2)]] == [sp.expand(2 * (2 * lam + 1)), sp.expand(-4 * (lam + 1)), 2, 0],
      "b''(0) = (2(2λ+1), −4(λ+1), 2, 0)")
check([sp.expand(x) for x in D[("π/2", 2)]] == [0, 2, sp.expand(-4 * (mu + 1)), sp.expand(2 * (2 * mu + 1))],
      "b''(π/2) = (0, 2, −4(μ+1), 2(2μ+1))")

# ---- curve terminal properties, control points as symbols (componentwise identities)
P = sp.symbols("P0:4")
Q = sp.symbols("Q0:4")
r = sum(bi * Pi for bi, Pi in zip(b, P))
r1 = sp.expand(sp.diff(r, t).subs(t, 0))
check(sp.expand(r1 - (lam + 2) * (P[1] - P[0])) == 0, "r'(0) = (λ+2)(P1 − P0) holds w.r.t. t  [w.r.t. u: (π/2)(λ+2)(P1 − P0)]")
check(sp.expand(sp.diff(r, t).subs(t, sp.pi / 2) - (mu + 2) * (P[3] - P[2])) == 0, "r'(π/2) = (μ+2)(P3 − P2)")
check(sp.expand(sp.diff(r, t, 2).subs(t, 0) - (2 * (2 * lam + 1) * (P[0] - P[1]) + 2 * (P[2] - P[1]))) == 0,
      "r''(0) = 2(2λ+1)(P0 − P1) + 2(P2 − P1)")
check(sp.expand(sp.diff(r, t, 2).subs(t, sp.pi / 2) - (2 * (P[1] - P[2]) + 2 * (2 * mu + 1) * (P[3] - P[2]))) == 0,
      "r''(π/2) = 2(P1 − P2) + 2(2μ+1)(P3 − P2)")

# ---- joins: segment 1 (λ1, μ1; P), segment 2 (λ2, μ2; Q); both on [0, π/2], derivatives w.r.t. t
l1, m1, l2, m2 = sp.symbols("lambda1 mu1 lambda2 mu2")
rA = sum(bi * Pi for bi, Pi in zip(basis(l1, m1), P))
rB = sum(bi * Qi for bi, Qi in zip(basis(l2, m2), Q))
e1 = sp.expand(sp.diff(rB, t).subs(t, 0) - sp.diff(rA, t).subs(t, sp.pi / 2))
e2 = sp.expand(sp.diff(rB, t, 2).subs(t, 0) - sp.diff(rA, t, 2).subs(t, sp.pi / 2))
sol1 = sp.solve(e1.subs(Q[0], P[3]), Q[1], dict=True)[0]
print("  C¹ (with Q0 = P3): Q1 =", sp.collect(sp.factor(sol1[Q[1]] - P[3]), [P[2], P[3]]), "+ P3")
check(sp.simplify(sol1[Q[1]] - (P[3] + (m1 + 2) / (l2 + 2) * (P[3] - P[2]))) == 0,
      "C¹: Q0 = P3, (λ2+2)(Q1 − Q0) = (μ1+2)(P3 − P2), i.e. Q1 = P3 + (μ1+2)/(λ2+2)·(P3 − P2), λ2 ≠ −2")
check(sp.expand(e1.subs({Q[0]: P[3], l2: -2})) == sp.expand(-(m1 + 2) * (P[3] - P[2])),
      "at λ2 = −2 (in the closed range) r2'(0) = 0 for every Q1: C¹ then needs (μ1+2)(P3 − P2) = 0")
sol2 = sp.solve(e2.subs({Q[0]: P[3]}), Q[2], dict=True)[0]
Q2 = sp.expand(sol2[Q[2]])
print("  C² (with C¹): Q2 =", sp.collect(Q2, [P[1], P[2], P[3], Q[1]]))
check(sp.expand(Q2 - (P[1] - P[2] + (2 * m1 + 1) * (P[3] - P[2]) + Q[1] + (2 * l2 + 1) * (Q[1] - P[3]))) == 0,
      "C²: Q2 = Q1 + (P1 − P2) + (2μ1+1)(P3 − P2) + (2λ2+1)(Q1 − P3)")
Q2full = sp.expand(Q2.subs(Q[1], sol1[Q[1]]))
kappa = 2 * ((m1 + 1) + (l2 + 1) * (m1 + 2) / (l2 + 2))
check(sp.simplify(Q2full - (P[1] + kappa * (P[3] - P[2]))) == 0,
      "C² with Q1 substituted: Q2 = P1 + 2[(μ1+1) + (λ2+1)(μ1+2)/(λ2+2)]·(P3 − P2)")
check(sp.expand(Q2full.subs({l2: 1, m1: 1}) - (P[1] - 8 * P[2] + 8 * P[3])) == 0,
      "check at λ2 = μ1 = 1: Q1 = 2P3 − P2, Q2 = P1 − 8P2 + 8P3")
check(sp.expand(Q2full.subs({l2: 0, m1: 0}) - (P[1] - 4 * P[2] + 4 * P[3])) == 0,
      "check at λ2 = μ1 = 0: Q1 = 2P3 − P2, Q2 = P1 − 4P2 + 4P3")
print("  note: C¹ and C² involve only μ1 (end of segment 1) and λ2 (start of segment 2); λ1, μ2 are free")

for (l0, u0) in [(-2, -2), (1, 1), (-2, 1)]:
    print(f"  mpmath grid min at (λ,μ)=({l0},{u0}):",
          [sp.N(sp.Float(str(v), 30), 6) for v in mp_min([f.subs({lam: l0, mu: u0}) for f in b], t, 0, sp.pi / 2)])
print("done")
