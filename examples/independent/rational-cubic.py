"""Independent check of examples/rational-cubic.toml (rational cubic Bernstein basis, Farin ch. 13):

  D = (1 − t)³ + 3w1 t(1 − t)² + 3w2 t²(1 − t) + t³,
  b0 = (1 − t)³/D, b1 = 3w1 t(1 − t)²/D, b2 = 3w2 t²(1 − t)/D, b3 = t³/D,  t ∈ [0, 1], w1, w2 ∈ [0, ∞).
"""

import sympy as sp
from _exact import check, nonneg_on, param_set, show_intervals

t, w1, w2, tau = sp.symbols("t w1 w2 tau")
D = (1 - t) ** 3 + 3 * w1 * t * (1 - t) ** 2 + 3 * w2 * t**2 * (1 - t) + t**3
Nn = [(1 - t) ** 3, 3 * w1 * t * (1 - t) ** 2, 3 * w2 * t**2 * (1 - t), t**3]
b = [n / D for n in Nn]

print("rational-cubic: rational cubic Bernstein basis with inner weights w1, w2")
check(sp.cancel(sum(b) - 1) == 0, "RC-unity: Σ b_i = 1 (wherever D ≠ 0)")
check(sp.expand(D - (1 + 3 * t * (1 - t) * (w1 * (1 - t) + w2 * t - 1))) == 0,
      "D = 1 + 3t(1 − t)·(w1(1 − t) + w2 t − 1); D(0) = D(1) = 1")

# ---- nonnegativity region
print("  necessity: D(0) = 1 > 0, so near t = 0 sign b1 = sign w1 (b1 ~ 3w1·t); near t = 1 sign b2 = sign w2.")
print("  sufficiency: w1, w2 ≥ 0 ⇒ D ≥ (1−t)³ + t³ = 1 − 3t(1−t) ≥ 1/4 > 0 and every numerator ≥ 0.")
check(nonneg_on((1 - t) ** 3 + t**3 - sp.Rational(1, 4), t, 0, 1)[0], "(1−t)³ + t³ ≥ 1/4 on [0, 1] (certified)")
print("  ⇒ RC-region holds: exact region = [0, ∞)² (boundary lines w1 = 0, w2 = 0)")
for W1, W2, i, t0 in [(sp.Rational(-1, 10), 0, 1, sp.Rational(1, 10)), (0, sp.Rational(-1, 10), 2, sp.Rational(9, 10)),
                      (sp.Rational(-1, 10), 5, 1, sp.Rational(1, 10))]:
    d0 = D.subs({w1: W1, w2: W2, t: t0})
    v = b[i].subs({w1: W1, w2: W2, t: t0})
    check(d0 > 0 and v < 0, f"witness (w1,w2)=({W1},{W2}), t={t0}: D = {d0} > 0, b{i} = {v} < 0")
# one-parameter slices by the generic tool
for fix, var in [({w2: 1}, w1), ({w2: 0}, w1), ({w1: 1}, w2)]:
    iv, _, _ = param_set([sp.expand(n * D).subs(fix) for n in Nn], t, var, 0, 1)
    print(f"    slice {fix}: all N_i·D ≥ 0 ⇔ {var} ∈ {show_intervals(iv)}")

# ---- where D vanishes (the basis is undefined)
disc = sp.factor(sp.discriminant(D, t))
print("  disc_t(D) =", disc)
Delta = 4 * w1**3 + 4 * w2**3 - 3 * w1**2 * w2**2 - 6 * w1 * w2 + 1
check(sp.expand(disc + 27 * Delta) == 0, "disc_t D = −27·(4w1³ + 4w2³ − 3w1²w2² − 6w1w2 + 1)")
g = 1 - 1 / (3 * tau * (1 - tau))
e1 = sp.simplify(g - tau * sp.diff(g, tau))
e2 = sp.simplify(g + (1 - tau) * sp.diff(g, tau))
print("  envelope (double root of D at t = τ ∈ (0,1)): w1 =", sp.factor(e1), ", w2 =", sp.factor(e2))
check(sp.simplify(Delta.subs({w1: e1, w2: e2})) == 0, "the envelope lies on Δ = 0")
check(sp.simplify(D.subs({w1: e1, w2: e2, t: tau})) == 0 and sp.simplify(sp.diff(D, t).subs({w1: e1, w2: e2, t: tau})) == 0,
      "on the envelope D(τ) = D'(τ) = 0")
for tv in (sp.Rational(1, 2), sp.Rational(1, 3), sp.Rational(2, 3), sp.Rational(1, 4)):
    print(f"    τ = {tv}: (w1, w2) = ({e1.subs(tau, tv)}, {e2.subs(tau, tv)})")
print("  D > 0 on [0,1] ⇔ w1(1−t) + w2·t > 1 − 1/(3t(1−t)) for all t ∈ (0,1): a convex region bounded by the")
print("  envelope branch above (part of Δ = 0); it strictly contains [0, ∞)², e.g. (w1, w2) = (−1/10, 0):")
check(nonneg_on(D.subs({w1: sp.Rational(-1, 10), w2: 0}), t, 0, 1)[0] and
      sp.Poly(D.subs({w1: sp.Rational(-1, 10), w2: 0}), t).count_roots(0, 1) == 0,
      "D(t; −1/10, 0) > 0 on [0, 1]: defined, yet b1 < 0 (witness above)")
check(sp.expand(D.subs({w1: sp.Rational(-1, 3), w2: sp.Rational(-1, 3)}) - (1 - 2 * t) ** 2) == 0,
      "boundary point (−1/3, −1/3): D = (1 − 2t)², double zero at t = 1/2")
check(sp.Poly(D.subs({w1: -1, w2: -1}), t).count_roots(0, 1) == 2, "(−1, −1): D has 2 zeros in [0, 1]")
for end in (0, 1):
    print(f"  order 1 at t={end}: {[sp.factor(sp.diff(f, t).subs(t, end)) for f in b]}")
print("done")
