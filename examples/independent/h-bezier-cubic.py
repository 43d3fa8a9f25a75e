"""Part B2: the cubic H-Bézier basis, span{1, t, sinh t, cosh t} on t ∈ [0, α], α > 0.

Sources: Y. Lü, G. Wang, X. Yang, "Uniform hyperbolic polynomial B-spline curves", CAGD 19 (2002) 379-393,
and "Unifying C-curves and H-curves by extending the calculation to complex numbers" (Lü, Wang & Yang, 2002);
the H-Bézier basis is the hyperbolic twin of the C-Bézier basis (sin, cos -> sinh, cosh), constructed by the same
integral recursion with C_0^1 = sinh(α − t)/sinh α, C_1^1 = sinh t/sinh α (checked below).
Derivatives w.r.t. t.
"""

import sympy as sp
import mpmath as mpm
from _exact import check, hyp_zero

t, s, a, v, tau = sp.symbols("t s alpha v tau", positive=True)
sh, ch = sp.sinh, sp.cosh
A = sh(a) - a                          # sinh α − α
g = a * sh(a) - 2 * ch(a) + 2          # α sinh α − 2cosh α + 2
cm = ch(a) - 1
b3 = (sh(t) - t) / A
b0 = b3.subs(t, a - t)
N = lambda x: A * (ch(x) - 1) - cm * (sh(x) - x)   # noqa: E731
b1 = cm * N(a - t) / (A * g)
b2 = cm * N(t) / (A * g)
b = [b0, b1, b2, b3]
print("h-bezier-cubic: cubic H-Bézier basis on [0, α]")
for i, f in enumerate(b):
    print(f"  b{i}(t) =", f)


def up(Cn):
    n = len(Cn) - 1
    I = [sp.integrate(c.subs(t, s), (s, 0, t)) for c in Cn]
    d = [1 / sp.integrate(c, (t, 0, a)) for c in Cn]
    return [1 - d[0] * I[0]] + [d[i - 1] * I[i - 1] - d[i] * I[i] for i in range(1, n + 1)] + [d[n] * I[n]]


C2 = up([sh(a - t) / sh(a), sh(t) / sh(a)])
check(hyp_zero(C2[0] - (ch(a - t) - 1) / (ch(a) - 1), [t, a]) and hyp_zero(C2[2] - (ch(t) - 1) / (ch(a) - 1), [t, a]),
      "recursion, degree 2: (cosh(α−t) − 1)/(cosh α − 1), ·, (cosh t − 1)/(cosh α − 1)")
# C^3 by the recursion ⇔ b_i(0) = [i = 0] and b_i' = δ_{i−1} C_{i−1}^2 − δ_i C_i^2 (δ_{−1} = δ_3 = 0)
d = [1 / sp.integrate(c, (t, 0, a)) for c in C2]
for i in range(4):
    rhs = (d[i - 1] * C2[i - 1] if i > 0 else 0) - (d[i] * C2[i] if i < 3 else 0)
    check(hyp_zero(sp.diff(b[i], t) - rhs, [t, a]) and sp.simplify(b[i].subs(t, 0)) == (1 if i == 0 else 0),
          f"recursion C_{i}^3 equals the closed form b{i} (derivative and value at 0)")
check(hyp_zero(sum(b) - 1, [t, a]), "unity Σ b_i = 1 (exact, via exp)")
check(all(hyp_zero(b[i].subs(t, a - t) - b[3 - i], [t, a]) for i in range(4)), "symmetry b_i(t) = b_{3−i}(α − t)")

# ---- nonnegativity for every α > 0
check(hyp_zero((g - 2 * sh(a / 2) * (a * ch(a / 2) - 2 * sh(a / 2))).subs(a, 2 * v), [v]),
      "g(α) = α sinh α − 2cosh α + 2 = 2 sinh(α/2)(α cosh(α/2) − 2 sinh(α/2))")
k = 2 * v * ch(v) - 2 * sh(v)
check(sp.simplify(sp.diff(k, v) - 2 * v * sh(v)) == 0 and k.subs(v, 0) == 0,
      "κ(x) = 2x cosh x − 2 sinh x: κ(0) = 0, κ' = 2x sinh x > 0 ⇒ g > 0 for α > 0; also sinh α − α > 0")
f = (ch(tau) - 1) / (sh(tau) - tau)
check(hyp_zero(sp.diff(f, tau) + g.subs(a, tau) / (sh(tau) - tau) ** 2, [tau]),
      "f(τ) = (cosh τ − 1)/(sinh τ − τ): f' = −g(τ)/(sinh τ − τ)² < 0, f decreasing on (0, ∞)")
check(hyp_zero(N(tau) - (sh(tau) - tau) * A * (f - f.subs(tau, a)), [tau, a]),
      "N(τ) = (sinh τ − τ)(sinh α − α)(f(τ) − f(α)) ≥ 0 for 0 ≤ τ ≤ α ⇒ b1, b2 ≥ 0")
print("  ⇒ nonnegative for every α ∈ (0, ∞) (no finite end; α → 0 gives the cubic Bernstein basis in t/α).")

# ---- endpoint derivatives
vals = {}
for kk in range(4):
    vals[(0, kk)] = [sp.diff(fi, t, kk).subs(t, 0) for fi in b]
    vals[(1, kk)] = [sp.diff(fi, t, kk).subs(t, a) for fi in b]
check(all(hyp_zero(vals[(1, kk)][i] - (-1) ** kk * vals[(0, kk)][3 - i], [a]) for kk in range(4) for i in range(4)),
      "b_i^{(k)}(α) = (−1)^k b_{3−i}^{(k)}(0)")
forms = [
    (0, 0, 1, "1"), (0, 1, 0, "0"), (0, 2, 0, "0"), (0, 3, 0, "0"),
    (1, 0, -cm / A, "−(cosh α − 1)/A"), (1, 1, cm / A, "(cosh α − 1)/A"), (1, 2, 0, "0"), (1, 3, 0, "0"),
    (2, 0, sh(a) / A, "sinh α/A"), (2, 1, -cm * (a * ch(a) - sh(a)) / (A * g), "−(cosh α − 1)(α cosh α − sinh α)/(A g)"),
    (2, 2, cm / g, "(cosh α − 1)/g"), (2, 3, 0, "0"),
    (3, 0, -ch(a) / A, "−cosh α/A"), (3, 1, cm * (a * sh(a) - ch(a) + 1) / (A * g), "(cosh α − 1)(α sinh α − cosh α + 1)/(A g)"),
    (3, 2, -cm**2 / (A * g), "−(cosh α − 1)²/(A g)"), (3, 3, 1 / A, "1/A"),
]
print("  A = sinh α − α, g = α sinh α − 2cosh α + 2")
for kk, i, e, txt in forms:
    check(hyp_zero(vals[(0, kk)][i] - e, [a]), f"b{i}^({kk})(0) = {txt};   b{3 - i}^({kk})(α) = {'−' if kk % 2 else ''}({txt})")
P = sp.symbols("P0:4")
r = sum(bi * Pi for bi, Pi in zip(b, P))
check(hyp_zero(sp.diff(r, t).subs(t, 0) - cm / A * (P[1] - P[0]), [a]), "r'(0) = (cosh α − 1)/(sinh α − α)·(P1 − P0)")
check(hyp_zero(sp.diff(r, t).subs(t, a) - cm / A * (P[3] - P[2]), [a]), "r'(α) = (cosh α − 1)/(sinh α − α)·(P3 − P2)")
check(sp.limit(a * cm / A, a, 0) == 3, "α·(cosh α − 1)/(sinh α − α) → 3 as α → 0")
check(hyp_zero(sp.diff(r, t, 2).subs(t, 0) - (sh(a) / A * (P[0] - P[1]) + cm / g * (P[2] - P[1])), [a]),
      "r''(0) = sinh α/(sinh α − α)·(P0 − P1) + (cosh α − 1)/(α sinh α − 2cosh α + 2)·(P2 − P1)")

mpm.mp.dps = 100
for al in [mpm.mpf("0.01"), mpm.mpf(1), mpm.mpf(5), mpm.mpf(30)]:
    fs = [sp.lambdify(t, fi.subs(a, sp.Float(str(al), 110)), "mpmath") for fi in b]
    mins = [min(fi(al * j / 400) for j in range(401)) for fi in fs]
    print(f"  mpmath grid min, α = {mpm.nstr(al, 6)}: {[mpm.nstr(x, 5) for x in mins]}")
print("done")
