"""Independent check of examples/irrational-end.toml (constructed basis, header of that file):

  k = (λ² − 4λ)/4, u = t(1 − t),
  b0 = (1 − t)²(1 − k t²),  b1 = 2u(1 + k u),  b2 = t²(1 − k(1 − t)²),   t ∈ [0, 1], printed λ ∈ [−0.8, 4.8].
"""

import sympy as sp
from _exact import check, describe_alg, param_set, range_contains, show_intervals, nonneg_on

t, lam = sp.symbols("t lambda")
k = (lam**2 - 4 * lam) / 4
u = t * (1 - t)
b = [(1 - t) ** 2 * (1 - k * t**2), 2 * u * (1 + k * u), t**2 * (1 - k * (1 - t) ** 2)]

print("irrational-end: constructed quadratic basis with irrational range ends")
check(sp.expand(sum(b) - 1) == 0, "IE-unity: Σ b_i = 1")
check(all(sp.expand(b[i].subs(t, 1 - t) - b[2 - i]) == 0 for i in range(3)), "symmetry b_i(t) = b_{2−i}(1 − t)")
iv, samples, crit = param_set(b, t, lam, 0, 1)
print("  critical λ values:")
for r in crit:
    print("    ", describe_alg(r))
for l0, ok, w in samples:
    print(f"  sample λ={l0}: {'ok' if ok else f'b{w[0]}({w[1]}) < 0'}")
print("  maximal nonnegativity set:", show_intervals(iv))
lo, hi = 2 - 2 * sp.sqrt(2), 2 + 2 * sp.sqrt(2)
check(len(iv) == 1 and sp.simplify(iv[0][0] - lo) == 0 and sp.simplify(iv[0][1] - hi) == 0,
      "maximal range = [2 − 2√2, 2 + 2√2], ends are the roots of λ² − 4λ − 4")
check(sp.Rational(-83, 100) < lo < sp.Rational(-82, 100) and sp.Rational(482, 100) < hi < sp.Rational(483, 100),
      "isolating intervals: 2 − 2√2 ∈ (−83/100, −82/100), 2 + 2√2 ∈ (241/50, 483/100)")
check(range_contains(iv, sp.Rational(-4, 5), sp.Rational(24, 5)), "IE-inside holds: [−4/5, 24/5] ⊂ maximal range")
check(iv[0] != (sp.Rational(-4, 5), sp.Rational(24, 5)), "IE-maximal fails: the printed range is not the maximal one")
l0 = sp.Rational(-41, 50)
check(all(nonneg_on(f.subs(lam, l0), t, 0, 1)[0] for f in b) and not (sp.Rational(-4, 5) <= l0),
      f"  witness of non-maximality: λ = −41/50 lies outside [−0.8, 4.8] and all b_i ≥ 0 (k = {k.subs(lam, l0)} ≤ 1)")
l1 = sp.Rational(-83, 100)
t1 = sp.Rational(999, 1000)
v = b[0].subs({lam: l1, t: t1})
print(f"  λ = −83/100: k = {k.subs(lam, l1)} > 1; b0({t1}) = {v}")
check(v < 0, "  witness just outside the exact range: λ = −83/100, t = 999/1000, b0 < 0")
check(sp.expand(k - ((lam - 2) ** 2 / 4 - 1)) == 0 and sp.expand(4 * (k - 1) - (lam**2 - 4 * lam - 4)) == 0,
      "b0, b2 ≥ 0 ⇔ k ≤ 1 ⇔ λ² − 4λ − 4 ≤ 0; b1 ≥ 0 ⇔ k ≥ −4, always (k = (λ−2)²/4 − 1 ≥ −1)")
print("done")
