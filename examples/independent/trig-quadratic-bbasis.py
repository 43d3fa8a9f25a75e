"""Part B4: the normalised B-basis of span{1, cos t, sin t} on t ∈ [0, α] (half-angle form)

  b0 = sin²((α − t)/2)/sin²(α/2),  b2 = sin²(t/2)/sin²(α/2),  b1 = 1 − b0 − b2,   α ∈ (0, π).
Printed (as the "quadratic C-Bézier basis") in Boundary Value Problems 2022, doi 10.1186/s13661-022-01647-5, eq. (2):
  C_0^2 = (1 − cos(α − t))/(1 − cos α), C_1^2 = −(1 − cos t + cos α − cos(α − t))/(1 − cos α),
  C_2^2 = (1 − cos t)/(1 − cos α),  t ∈ [0, α], α ∈ (0, π].
Derivatives w.r.t. t.
"""

import sympy as sp
from _exact import check, trig_zero

t, a, x, y, u = sp.symbols("t alpha x y u", real=True)
h = lambda e: e.subs({t: 2 * x, a: 2 * y})   # half angles -> integer multiples   # noqa: E731
b0 = sp.sin((a - t) / 2) ** 2 / sp.sin(a / 2) ** 2
b2 = sp.sin(t / 2) ** 2 / sp.sin(a / 2) ** 2
b1 = 1 - b0 - b2
b1c = 2 * sp.cos(a / 2) * sp.sin(t / 2) * sp.sin((a - t) / 2) / sp.sin(a / 2) ** 2
b = [b0, b1c, b2]
print("trig-quadratic-bbasis: normalised B-basis of span{1, cos t, sin t} on [0, α]")
check(trig_zero(h(b1 - b1c), [x, y]), "closed form b1 = 2 cos(α/2) sin(t/2) sin((α − t)/2) / sin²(α/2)")
printed = [(1 - sp.cos(a - t)) / (1 - sp.cos(a)), -(1 - sp.cos(t) + sp.cos(a) - sp.cos(a - t)) / (1 - sp.cos(a)),
           (1 - sp.cos(t)) / (1 - sp.cos(a))]
check(all(trig_zero(h(p - q), [x, y]) for p, q in zip(printed, b)), "equals the printed C_i^2 of BVP 2022 eq. (2)")
check(trig_zero(h(sum(b) - 1), [x, y]), "unity (exact)")
check(all(trig_zero(h(b[i].subs(t, a - t) - b[2 - i]), [x, y]) for i in range(3)), "symmetry b_i(t) = b_{2−i}(α − t)")

# ---- nonnegativity in α
print("  b0, b2 ≥ 0 always (squares); for 0 < α ≤ 2π and t ∈ [0, α]: sin(t/2) ≥ 0, sin((α − t)/2) ≥ 0,")
print("  so sign b1 = sign cos(α/2): b1 ≥ 0 on [0, α] ⇔ α ≤ π.")
check(sp.simplify(b1c.subs(a, sp.pi)) == 0,
      "α = π: b1 ≡ 0 (cos(π/2) = 0): nonnegative but the three functions are not linearly independent")
v = sp.nsimplify(sp.simplify(b1c.subs({a: 4 * sp.pi / 3, t: 2 * sp.pi / 3})))
check(v == -1, "witness α = 4π/3, t = 2π/3: b1 = 2·(−1/2)·(3/4)/(3/4) = −1 < 0 (b0 = b2 = 1)")
print("  α ∈ (2π, 4π): sin(t/2)·sin((α−t)/2) changes sign on (0, α), so b1 takes both signs; α = 2kπ: undefined.")
print("  ⇒ nonnegativity exactly for α ∈ (0, π]; a basis (b1 ≢ 0) exactly for α ∈ (0, π).")
print("  The printed range (0, π] of BVP 2022 includes the degenerate α = π.")

# ---- link to the rational quadratic Bernstein basis with weight w = cos(α/2)
uu = sp.sin(t / 2) / (sp.sin(t / 2) + sp.sin((a - t) / 2))
w = sp.cos(a / 2)
D = (1 - uu) ** 2 + 2 * w * uu * (1 - uu) + uu**2
rq = [(1 - uu) ** 2 / D, 2 * w * uu * (1 - uu) / D, uu**2 / D]
check(all(trig_zero(h(p - q), [x, y]) for p, q in zip(rq, b)),
      "b_i(t) = rational quadratic Bernstein basis with w = cos(α/2) at u = sin(t/2)/(sin(t/2) + sin((α−t)/2))"
      " (so w ≥ 0 ⇔ α ≤ π, matching rational-quadratic's [0, ∞))")

# ---- endpoint derivatives
forms = {
    0: [1, 0, 0],
    1: [-sp.sin(a) / (1 - sp.cos(a)), sp.sin(a) / (1 - sp.cos(a)), 0],
    2: [sp.cos(a) / (1 - sp.cos(a)), -(1 + sp.cos(a)) / (1 - sp.cos(a)), 1 / (1 - sp.cos(a))],
    3: [sp.sin(a) / (1 - sp.cos(a)), -sp.sin(a) / (1 - sp.cos(a)), 0],
}
txt = {0: "(1, 0, 0)", 1: "(−cot(α/2), cot(α/2), 0) = (−sin α, sin α, 0)/(1 − cos α)",
       2: "(cos α, −(1 + cos α), 1)/(1 − cos α);  b1''(0) = −cot²(α/2)",
       3: "(sin α, −sin α, 0)/(1 − cos α) = (cot(α/2), −cot(α/2), 0)"}
for k in range(4):
    at0 = [sp.diff(f, t, k).subs(t, 0) for f in b]
    atA = [sp.diff(f, t, k).subs(t, a) for f in b]
    check(all(trig_zero(h(p - q), [x, y]) for p, q in zip(at0, forms[k])), f"order {k} at t = 0: {txt[k]}")
    check(all(trig_zero(h(atA[i] - (-1) ** k * forms[k][2 - i]), [x, y]) for i in range(3)),
          f"order {k} at t = α: b_i^({k})(α) = (−1)^{k} b_(2−i)^({k})(0)")
check(trig_zero(h(sp.sin(a) / (1 - sp.cos(a)) - sp.cos(a / 2) / sp.sin(a / 2)), [x, y]), "sin α/(1 − cos α) = cot(α/2)")
check(trig_zero(h((1 + sp.cos(a)) / (1 - sp.cos(a)) - sp.cos(a / 2) ** 2 / sp.sin(a / 2) ** 2), [x, y]),
      "(1 + cos α)/(1 − cos α) = cot²(α/2)")
print("  terminal tangents: r'(0) = cot(α/2)(P1 − P0), r'(α) = cot(α/2)(P2 − P1): both vanish at α = π.")
print("  α → 0: α·cot(α/2) → 2 (quadratic Bernstein in t/α).")
check(sp.limit(a * sp.cot(a / 2), a, 0) == 2, "limit α·cot(α/2) = 2")

# ---- the fixed α = π/2 version on [0, π/2]
bq = [sp.simplify(sp.expand_trig(f.subs(a, sp.pi / 2))) for f in printed]
print("  α = π/2:", bq)
check(trig_zero(bq[0] - (1 - sp.sin(t)), [t]) and trig_zero(bq[1] - (sp.sin(t) + sp.cos(t) - 1), [t]) and
      trig_zero(bq[2] - (1 - sp.cos(t)), [t]), "α = π/2: b = (1 − sin t, sin t + cos t − 1, 1 − cos t) (= Han's basis at λ = 0)")
check(sp.simplify(sp.expand_trig(bq[1] - 2 * sp.sqrt(2) * sp.sin(t / 2) * sp.sin(sp.pi / 4 - t / 2))) == 0,
      "α = π/2: b1 = 2√2 sin(t/2) sin(π/4 − t/2) ≥ 0 on [0, π/2]")
for k in range(4):
    print(f"    order {k}: t=0 {[sp.diff(f, t, k).subs(t, 0) for f in bq]},  t=π/2 {[sp.diff(f, t, k).subs(t, sp.pi / 2) for f in bq]}")
check([sp.diff(f, t).subs(t, 0) for f in bq] == [-1, 1, 0] and [sp.diff(f, t, 2).subs(t, 0) for f in bq] == [0, -1, 1],
      "α = π/2: b'(0) = (−1, 1, 0), b''(0) = (0, −1, 1); r'(0) = P1 − P0, r'(π/2) = P2 − P1")
print("done")
