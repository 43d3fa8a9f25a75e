"""Part B1: the cubic C-Bézier basis, span{1, t, sin t, cos t} on t ∈ [0, α].

Sources: J. Zhang, "C-curves: an extension of cubic curves", CAGD 13 (1996) 199-217; Q. Chen, G. Wang,
"A class of Bézier-like curves", CAGD 20 (2003) 29-39. The form checked "as printed" is the integral
recursion quoted (from Wang et al.) in Boundary Value Problems 2022, doi 10.1186/s13661-022-01647-5,
Definition 1, eq. (1): C_0^1 = sin(α−t)/sin α, C_1^1 = sin t/sin α,
  C_0^n = 1 − ∫_0^t δ_0^{n−1} C_0^{n−1},  C_i^n = ∫_0^t δ_{i−1}^{n−1} C_{i−1}^{n−1} − ∫_0^t δ_i^{n−1} C_i^{n−1},
  C_n^n = ∫_0^t δ_{n−1}^{n−1} C_{n−1}^{n−1},  δ_i^n = (∫_0^α C_i^n)^{−1},  α ∈ (0, π] as printed there.
Derivatives are w.r.t. t (the curve's own parameter on [0, α]).
"""

import sympy as sp
import mpmath as mpm
from _exact import check, trig_zero

t, s, a, v, tau = sp.symbols("t s alpha v tau", positive=True)
A = a - sp.sin(a)                       # α − sin α
g = 2 - 2 * sp.cos(a) - a * sp.sin(a)   # 2 − 2cos α − α sin α

# ---- closed form (derived: b3 has a triple zero at 0, b1 a simple zero at 0 and a double zero at α)
b3 = (t - sp.sin(t)) / A
b0 = b3.subs(t, a - t)
N = lambda x: A * (1 - sp.cos(x)) - (1 - sp.cos(a)) * (x - sp.sin(x))   # noqa: E731
b1 = (1 - sp.cos(a)) * N(a - t) / (A * g)
b2 = (1 - sp.cos(a)) * N(t) / (A * g)
b = [b0, b1, b2, b3]
print("c-bezier-cubic: cubic C-Bézier basis on [0, α]")
for i, f in enumerate(b):
    print(f"  b{i}(t) =", f)

# ---- the printed recursion, evaluated symbolically
def up(Cn):
    n = len(Cn) - 1
    I = [sp.integrate(c.subs(t, s), (s, 0, t)) for c in Cn]
    d = [1 / sp.integrate(c, (t, 0, a)) for c in Cn]
    return [1 - d[0] * I[0]] + [d[i - 1] * I[i - 1] - d[i] * I[i] for i in range(1, n + 1)] + [d[n] * I[n]]


C1 = [sp.sin(a - t) / sp.sin(a), sp.sin(t) / sp.sin(a)]
C2 = up(C1)
C3 = [sp.simplify(c) for c in up(C2)]
check(trig_zero(C2[0] - (1 - sp.cos(a - t)) / (1 - sp.cos(a)), [t, a]) and
      trig_zero(C2[1] + (1 - sp.cos(t) + sp.cos(a) - sp.cos(a - t)) / (1 - sp.cos(a)), [t, a]),
      "recursion gives the printed quadratic C-Bézier functions (BVP 2022 eq. (2))")
for i in range(4):
    check(trig_zero(C3[i] - b[i], [t, a]), f"recursion C_{i}^3 equals the closed form b{i}")
print("  recursion C_1^3 as SymPy returns it:", C3[1])
C12_printed = -(1 - sp.cos(t) + sp.cos(a) - sp.cos(a - t)) / (1 - sp.cos(a))
check(sp.simplify(C12_printed.subs(a, sp.pi)) == 0, "at α = π the printed quadratic C_1^2 ≡ 0, so δ_1^2 = 1/∫C_1^2 = 1/0:"
      " the recursion is undefined at α = π (and C^1 has sin α in its denominator), though the closed form"
      " of the cubic extends continuously to α = π")

# ---- unity, symmetry
check(trig_zero(sum(b) - 1, [t, a]), "unity Σ b_i = 1 (exact)")
check(all(trig_zero(b[i].subs(t, a - t) - b[3 - i], [t, a]) for i in range(4)), "symmetry b_i(t) = b_{3−i}(α − t) (exact)")

# ---- nonnegativity in α (analytic chain, each step an exact identity)
check(trig_zero((g - 2 * sp.sin(a / 2) * (2 * sp.sin(a / 2) - a * sp.cos(a / 2))).subs(a, 2 * v), [v]),
      "g(α) = 2 − 2cos α − α sin α = 2 sin(α/2)·(2 sin(α/2) − α cos(α/2))")
h = 2 * sp.sin(v) - 2 * v * sp.cos(v)
check(sp.simplify(sp.diff(h, v) - 2 * v * sp.sin(v)) == 0 and h.subs(v, 0) == 0,
      "h(x) = 2 sin x − 2x cos x: h(0) = 0, h'(x) = 2x sin x > 0 on (0, π) ⇒ h > 0 on (0, π] ⇒ g > 0 on (0, 2π)")
f = (1 - sp.cos(tau)) / (tau - sp.sin(tau))
check(trig_zero(sp.diff(f, tau) + g.subs(a, tau) / (tau - sp.sin(tau)) ** 2, [tau]),
      "f(τ) = (1 − cos τ)/(τ − sin τ): f'(τ) = −g(τ)/(τ − sin τ)² < 0 on (0, 2π), f strictly decreasing")
check(trig_zero(N(tau) - (tau - sp.sin(tau)) * A * (f - f.subs(tau, a)), [tau, a]),
      "N(τ) = (τ − sin τ)(α − sin α)(f(τ) − f(α)) ≥ 0 for 0 ≤ τ ≤ α < 2π; b1 = (1 − cos α)N(α − t)/((α − sin α) g(α))")
print("  ⇒ all four functions are ≥ 0 on [0, α] exactly for α ∈ (0, 2π); b1, b2 > 0 inside (0, α).")
print("  α = 2π: 1 − cos α = g = 0, b1, b2 → 0 (limits) and b0 + b3 = 1: no basis.")
b1_3pi = sp.simplify(b1.subs(a, 3 * sp.pi).subs(t, sp.pi))
check(b1_3pi == sp.Rational(-2, 3), "α = 3π > 2π: b1(π) = 2·(−4π)/(3π·4) = −2/3 < 0 (witness)")
print("  for any α > 2π with cos α ≠ 1: N(2π) = −2π(1 − cos α) < 0 while N(τ) ~ (α − sin α)τ²/2 > 0 near 0,")
print("  so b1 (wherever defined) takes both signs: the maximal α-set is exactly (0, 2π); printed (0, π) ⊂ it.")

# ---- endpoint derivatives, orders 0..3, at t = 0 and t = α (exact)
print("  endpoint derivatives (A = α − sin α, g = 2 − 2cos α − α sin α):")
vals = {}
for k in range(4):
    vals[(0, k)] = [sp.simplify(sp.diff(fi, t, k).subs(t, 0)) for fi in b]
    vals[(1, k)] = [sp.simplify(sp.diff(fi, t, k).subs(t, a)) for fi in b]
    print(f"    order {k} at t=0: {vals[(0, k)]}")
    print(f"    order {k} at t=α: {vals[(1, k)]}")
check(all(trig_zero(vals[(1, k)][i] - (-1) ** k * vals[(0, k)][3 - i], [a]) for k in range(4) for i in range(4)),
      "b_i^{(k)}(α) = (−1)^k b_{3−i}^{(k)}(0)")
# closed forms chosen by hand, each verified exactly (A = α − sin α, g = 2 − 2cos α − α sin α)
cm = 1 - sp.cos(a)
forms = [
    (1, 0, -cm / A, "−(1 − cos α)/A"), (1, 1, cm / A, "(1 − cos α)/A"), (1, 2, 0, "0"), (1, 3, 0, "0"),
    (2, 0, sp.sin(a) / A, "sin α/A"), (2, 1, cm * (a * sp.cos(a) - sp.sin(a)) / (A * g), "(1 − cos α)(α cos α − sin α)/(A g)"),
    (2, 2, cm / g, "(1 − cos α)/g"), (2, 3, 0, "0"),
    (3, 0, -sp.cos(a) / A, "−cos α/A"), (3, 1, cm * (a * sp.sin(a) + sp.cos(a) - 1) / (A * g), "(1 − cos α)(α sin α + cos α − 1)/(A g)"),
    (3, 2, -cm**2 / (A * g), "−(1 − cos α)²/(A g)"), (3, 3, 1 / A, "1/A"),
]
for k, i, e, txt in forms:
    check(trig_zero(vals[(0, k)][i] - e, [a]), f"b{i}^({k})(0) = {txt};   at t = α: b{3 - i}^({k})(α) = {'−' if k % 2 else ''}({txt})")
print("  terminal tangents of r(t) = Σ b_i P_i:")
P = sp.symbols("P0:4")
r = sum(bi * Pi for bi, Pi in zip(b, P))
k1 = (1 - sp.cos(a)) / A
check(trig_zero(sp.diff(r, t).subs(t, 0) - k1 * (P[1] - P[0]), [a]), "r'(0) = (1 − cos α)/(α − sin α)·(P1 − P0)")
check(trig_zero(sp.diff(r, t).subs(t, a) - k1 * (P[3] - P[2]), [a]), "r'(α) = (1 − cos α)/(α − sin α)·(P3 − P2)")
check(sp.limit(k1 * a, a, 0) == 3, "α·(1 − cos α)/(α − sin α) → 3 as α → 0 (cubic Bézier on [0, α] in t/α)")
r2 = sp.diff(r, t, 2).subs(t, 0)
check(trig_zero(r2 - (sp.sin(a) / A * (P[0] - P[1]) + (1 - sp.cos(a)) / g * (P[2] - P[1])), [a]),
      "r''(0) = sin α/(α − sin α)·(P0 − P1) + (1 − cos α)/(2 − 2cos α − α sin α)·(P2 − P1)")

# ---- mpmath cross-check at 100 digits
mpm.mp.dps = 100
for al in [mpm.pi / 6, mpm.pi / 2, mpm.pi, 3 * mpm.pi / 2, 2 * mpm.pi - mpm.mpf("0.01"), 3 * mpm.pi]:
    fs = [sp.lambdify(t, fi.subs(a, sp.Float(str(al), 110)), "mpmath") for fi in b]
    mins = [min(fi(al * j / 400) for j in range(401)) for fi in fs]
    print(f"  mpmath grid min, α = {mpm.nstr(al, 8)}: {[mpm.nstr(x, 5) for x in mins]}")
print("done")
