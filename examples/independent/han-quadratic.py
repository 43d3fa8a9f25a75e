"""Independent check of examples/han-quadratic.toml (Han, CAGD 19 (2002) 503-512, Section 2).

  b0 = (1 − sin t)(1 − λ sin t),  b1 = (1 + λ)(sin t + cos t − 1),  b2 = (1 − cos t)(1 − λ cos t),
  t ∈ [0, π/2], λ ∈ [−1, 1].  Derivatives are with respect to the angle t.
"""

import sympy as sp
from _exact import (PYTH_M, check, describe_alg, numerator_posden, param_set, range_contains,
                    show_intervals, trig_at, trig_zero, weierstrass, mp_min)

t, lam, m = sp.symbols("t lambda m")
S, C = sp.sin(t), sp.cos(t)
b = [(1 - S) * (1 - lam * S), (1 + lam) * (S + C - 1), (1 - C) * (1 - lam * C)]

print("han-quadratic: Han 2002 quadratic trigonometric basis")
check(trig_zero(sum(b) - 1, [t]), "HQ-unity: b0 + b1 + b2 = 1 (exact trig reduction)")
check(all(trig_zero(b[i].subs(t, sp.pi / 2 - t) - b[2 - i], [t]) for i in range(3)),
      "symmetry b_i(t) = b_{2-i}(π/2 − t) (exact)")

# nonnegativity: m = tan(t/2) ∈ [0, 1] <-> t ∈ [0, π/2]
N = [numerator_posden(weierstrass(f, t, m), m) for f in b]
for i, n in enumerate(N):
    print(f"  numerator of b{i} in m = tan(t/2) (denominator (1+m²)^k > 0): {sp.factor(n)}")
iv, samples, crit = param_set(N, m, lam, 0, 1, prefer=PYTH_M)
print("  critical λ values:", [describe_alg(r) for r in crit])
for l0, ok, w in samples:
    print(f"  sample λ={l0}: {'nonnegative' if ok else 'NEGATIVE somewhere'}")
print("  maximal nonnegativity set of λ:", show_intervals(iv))
check(iv == [(-1, 1)], "HQ-range holds: the maximal range is exactly [−1, 1]")

# witnesses outside, chosen by hand and verified exactly
for l0, i, mm in [(-2, 1, sp.Rational(1, 2)), (sp.Rational(-11, 10), 1, sp.Rational(1, 2)),
                  (sp.Rational(11, 10), 0, sp.Rational(3, 4)), (2, 0, sp.Rational(1, 2))]:
    v = trig_at(b[i].subs(lam, l0), t, mm)
    s0, c0 = trig_at(S, t, mm), trig_at(C, t, mm)
    check(v < 0, f"witness λ={l0}: b{i} at sin t={s0}, cos t={c0} (t=2·atan({mm})) equals {v} < 0")
check(not range_contains(iv, -2, 1), "HQ-wider fails ([−2, 1] ⊄ [−1, 1]); witness λ=−2 above")

# endpoint derivatives (w.r.t. t)
for end, name in [(0, "0"), (sp.pi / 2, "π/2")]:
    for k in (1, 2, 3):
        vals = [sp.factor(sp.simplify(sp.diff(f, t, k).subs(t, end))) for f in b]
        print(f"  order {k} at t={name}: {vals}")
check([sp.expand(sp.diff(f, t).subs(t, 0)) for f in b] == [-1 - lam, 1 + lam, 0],
      "b'(0) = (−(1+λ), 1+λ, 0)  (w.r.t. t; w.r.t. u = 2t/π multiply by π/2)")

# mpmath cross-check (100 digits, grid) at the range ends and just outside
for l0 in (-1, 1, sp.Rational(-101, 100), sp.Rational(101, 100)):
    mins = mp_min([f.subs(lam, l0) for f in b], t, 0, sp.pi / 2, n=2000)
    print(f"  mpmath grid min at λ={l0}: {[sp.N(sp.Float(str(v), 30), 6) for v in mins]}"
          "  (|values| < 1e-90 are rounding at t = 0, π/2 where b1 = 0)")
print("done")
