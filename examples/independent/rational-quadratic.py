"""Independent check of examples/rational-quadratic.toml (rational quadratic Bernstein basis, Farin ch. 12):

  D = (1 − t)² + 2w t(1 − t) + t²,  b0 = (1 − t)²/D, b1 = 2w t(1 − t)/D, b2 = t²/D,  t ∈ [0, 1], w ∈ [0, ∞).
"""

import sympy as sp
from _exact import check, param_set, show_intervals, nonneg_on

t, w, u = sp.symbols("t w u")
D = (1 - t) ** 2 + 2 * w * t * (1 - t) + t**2
Nn = [(1 - t) ** 2, 2 * w * t * (1 - t), t**2]
b = [n / D for n in Nn]

print("rational-quadratic: rational quadratic Bernstein basis with inner weight w")
check(sp.cancel(sum(b) - 1) == 0, "RQ-unity: Σ b_i = 1 (wherever D ≠ 0)")
check(sp.expand(D - (1 + 2 * (w - 1) * t * (1 - t))) == 0, "D = 1 + 2(w − 1)·t(1 − t); u = t(1 − t) ∈ [0, 1/4] on [0, 1]")

# ---- where D vanishes on [0, 1]
ivD, _, critD = param_set([D], t, w, 0, 1)
print("  D ≥ 0 on [0,1] ⇔ w ∈", show_intervals(ivD), "; critical w:", critD)
check(ivD == [(-1, sp.oo)], "D ≥ 0 on [0, 1] ⇔ w ≥ −1")
check(D.subs({w: -1, t: sp.Rational(1, 2)}) == 0, "at w = −1, D(1/2) = 0, so D > 0 on [0, 1] ⇔ w > −1 (D(1/2) = (1+w)/2)")
sol = sp.solve(D, w)
print("  zero set of D in the (t, w) plane: w =", sp.factor(sol[0]), " (≤ −1, = −1 only at t = 1/2)")
check(sp.simplify(sol[0] - (1 - 1 / (2 * t * (1 - t)))) == 0, "D = 0 ⇔ w = 1 − 1/(2t(1 − t)); for w < −1 two zeros t = (1 ± √((−1−w)/(1−w)))/2")

# ---- nonnegativity: b_i ≥ 0 with D ≠ 0 ⇔ N_i·D ≥ 0 and D ≠ 0
iv, samples, crit = param_set([sp.expand(n * D) for n in Nn], t, w, 0, 1)
for w0, ok, wit in samples:
    print(f"  sample w={w0}: {'ok' if ok else f'b{wit[0]}·D < 0 at t={wit[1]}'}")
print("  {w : N_i·D ≥ 0 on [0,1] ∀i} =", show_intervals(iv), "; intersect with D ≠ 0 (w > −1)")
check(iv == [(0, sp.oo)], "RQ-range holds: maximal range exactly [0, ∞) (w = 0 included: b1 ≡ 0 there, b0, b2 ≥ 0)")

# ---- the wide range [−1/10, 1000]
# D is affine in w for fixed t and affine in u = t(1−t) ∈ [0, 1/4]: min over the box is at a corner
corners = {(w0, u0): 1 + 2 * (w0 - 1) * u0 for w0 in (sp.Rational(-1, 10), 1000) for u0 in (0, sp.Rational(1, 4))}
print("  D at the corners (w, u):", corners)
mn = min(corners.values())
check(mn == sp.Rational(9, 20), "min of D over t ∈ [0,1], w ∈ [−1/10, 1000] is exactly 9/20, at w = −1/10, t = 1/2")
check(nonneg_on(D.subs(w, sp.Rational(-1, 10)) - sp.Rational(9, 20), t, 0, 1)[0], "  (certified: D(t, −1/10) − 9/20 = (11/5)(t − 1/2)² ≥ 0)")
check(sp.expand(D.subs(w, sp.Rational(-1, 10)) - sp.Rational(9, 20) - sp.Rational(11, 5) * (t - sp.Rational(1, 2)) ** 2) == 0,
      "  D(t, −1/10) = 9/20 + (11/5)(t − 1/2)²")
v = b[1].subs({w: sp.Rational(-1, 10), t: sp.Rational(1, 2)})
check(v == sp.Rational(-1, 9), "RQ-wide fails: w = −1/10, t = 1/2: D = 9/20, b1 = (−1/20)/(9/20) = −1/9 < 0")
check(sp.simplify(b[1].subs(t, sp.Rational(1, 2)) - w / (1 + w)) == 0,
      "b1(1/2) = w/(1 + w) < 0 for every −1 < w < 0 (so every negative weight in the range is a witness)")

for end in (0, 1):
    for k in (1, 2):
        print(f"  order {k} at t={end}: {[sp.factor(sp.diff(f, t, k).subs(t, end)) for f in b]}")
print("done")
