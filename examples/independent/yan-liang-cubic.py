"""Independent check of examples/yan-liang-cubic.toml (Yan & Liang, AMC 218 (2011) 2863-2879, (2.1)).

  b0 = (1 − λt)(1 − t)³, b1 = t(1 − t)²(3 + λ(1 − t)), b2 = t²(1 − t)(3 + λt), b3 = (1 − λ + λt)t³,
  t ∈ [0, 1], λ ∈ [−3, 1].  Polynomial; derivatives w.r.t. t.
"""

import sympy as sp
from _exact import check, describe_alg, param_set, show_intervals, mp_min

t, lam = sp.symbols("t lambda")
b = [(1 - lam * t) * (1 - t) ** 3, t * (1 - t) ** 2 * (3 + lam * (1 - t)),
     t**2 * (1 - t) * (3 + lam * t), (1 - lam + lam * t) * t**3]

print("yan-liang-cubic: Yan & Liang 2011 cubic λ-Bézier basis")
check(sp.expand(sum(b) - 1) == 0, "YL-unity: Σ b_i = 1 (polynomial identity)")
check(all(sp.expand(b[i].subs(t, 1 - t) - b[3 - i]) == 0 for i in range(4)), "symmetry b_i(t) = b_{3−i}(1 − t)")

iv, samples, crit = param_set(b, t, lam, 0, 1)
print("  critical λ values:", [describe_alg(r) for r in crit])
for l0, ok, w in samples:
    print(f"  sample λ={l0}: {'nonnegative' if ok else f'b{w[0]}({w[1]}) = {b[w[0]].subs({lam: l0, t: w[1]})} < 0'}")
print("  maximal nonnegativity set of λ:", show_intervals(iv))
check(iv == [(-3, 1)], "YL-range holds: maximal range exactly [−3, 1]")
for l0, i, t0 in [(-4, 1, sp.Rational(1, 8)), (2, 0, sp.Rational(3, 4)), (sp.Rational(11, 10), 0, sp.Rational(19, 20))]:
    v = b[i].subs({lam: l0, t: t0})
    check(v < 0, f"witness λ={l0}: b{i}({t0}) = {v} < 0")

d1 = [sp.expand(sp.diff(f, t).subs(t, 0)) for f in b]
check(d1 == [-(3 + lam), 3 + lam, 0, 0], "YL-tangent holds: (b0', b1', b2', b3')(0) = (−(3+λ), 3+λ, 0, 0)")
for end in (0, 1):
    for k in (1, 2, 3):
        print(f"  order {k} at t={end}: {[sp.factor(sp.diff(f, t, k).subs(t, end)) for f in b]}")
for l0 in (-3, 1):
    print(f"  mpmath grid min at λ={l0}:", [sp.N(sp.Float(str(v), 30), 6) for v in mp_min([f.subs(lam, l0) for f in b], t, 0, 1)])
print("done")
