"""Part D(b): linear independence — exact rank of the coefficient matrix over Q(parameters) in a stated
spanning set, with the exceptional parameter values where the rank drops.

Spanning sets: polynomial bases — the monomials; trigonometric bases on [0, π/2] — the numerators in
m = tan(t/2) over the common positive denominator (1 + m²)^k (a basis of functions is independent iff its
numerators are); algebraic-trigonometric bases — {1, t, cos t, sin t}. The rank drops exactly where all
maximal minors vanish (their gcd / Gröbner basis), and is recomputed there.
"""

import itertools

import sympy as sp
from _exact import check, numerator_posden, weierstrass

t, lam, m, x, a, b = sp.symbols("t lambda m x alpha beta", real=True)
s, c = sp.sin(t), sp.cos(t)


def coeffmat(N, v):
    d = max(sp.Poly(f, v).degree() for f in N)
    return sp.Matrix([[sp.Poly(f, v).coeff_monomial(v**k) for k in range(d + 1)] for f in N])


def maximal_minors(M):
    r, cn = M.shape
    return [sp.factor(M.extract(list(range(r)), list(J)).det()) for J in itertools.combinations(range(cn), r)]


# ---------------- Han 2002 quadratic (A1): rank drops at λ = −1
han = [(1 - s) * (1 - lam * s), (1 + lam) * (s + c - 1), (1 - c) * (1 - lam * c)]
M = coeffmat([numerator_posden(weierstrass(f, t, m), m) for f in han], m)
g = sp.factor(sp.gcd_list([y for y in maximal_minors(M) if y != 0]))
print("Han quadratic: numerators in m (degree 4), coefficient matrix", M.tolist())
check(sp.Poly(g, lam).real_roots() == [-1],
      f"gcd of the 3×3 minors = {g}: rank 3 for λ ≠ −1")
check(M.subs(lam, -1).rank() == 2 and sp.simplify(han[1].subs(lam, -1)) == 0, "λ = −1 (inside [−1, 1]): rank 2, b1 ≡ 0 — not a basis")

# ---------------- Bashir, Abbas & Ali quadratic (A4): rank drops only at (α, β) = (−1, −1)
bash = [(1 - s) * (1 - a * s), a * s * (1 - s) + b * c * (1 - c) + s + c - 1, (1 - c) * (1 - b * c)]
M = coeffmat([numerator_posden(weierstrass(f, t, m), m) for f in bash], m)
G = sp.groebner([sp.expand(y) for y in maximal_minors(M) if y != 0], a, b, order="lex")
check(list(G) == [a + 1, b + 1], f"Bashir: the 3×3 minors generate the ideal (α + 1, β + 1) (Gröbner basis {list(G)}): rank 3 except at (−1, −1)")
check(M.subs({a: -1, b: -1}).rank() == 2, "(α, β) = (−1, −1): rank 2 (b1 ≡ 0)")

# ---------------- Yan & Liang (A2): rank 4 except at the range end λ = −3
yl = [(1 - lam * x) * (1 - x) ** 3, x * (1 - x) ** 2 * (3 + lam * (1 - x)), x**2 * (1 - x) * (3 + lam * x), (1 - lam + lam * x) * x**3]
M = coeffmat(yl, x)
g = sp.gcd_list([y for y in maximal_minors(M) if y != 0])
check(sp.Poly(g, lam).real_roots() == [-3], f"Yan & Liang: gcd of the 4×4 minors over monomials 1..x⁴ = {g}: rank 4 for λ ≠ −3")
check(M.subs(lam, -3).rank() == 3 and sp.expand(yl[1].subs(lam, -3) - yl[2].subs(lam, -3)) == 0
      and sp.expand(yl[1].subs(lam, -3) - 3 * x**2 * (1 - x) ** 2) == 0,
      "λ = −3 (the closed left end of [−3, 1]): b1 ≡ b2 ≡ 3t²(1 − t)², rank 3 — not a basis")

# ---------------- rational quadratic (A5): numerators over the common D
w = sp.Symbol("w")
M = coeffmat([(1 - x) ** 2, 2 * w * x * (1 - x), x**2], x)
check(sp.factor(M.det()) == 2 * w, "rational quadratic: det of the numerators' coefficients = 2w: independent ⇔ w ≠ 0 (w = 0 ∈ [0, ∞): b1 ≡ 0)")

# ---------------- algebraic-trigonometric: coordinates in {1, t, cos t, sin t}
S_, C_ = sp.symbols("S_ C_")


def coords(f, names):
    e = sp.expand(sp.expand_trig(f)).subs({s: S_, c: C_})
    P = sp.Poly(e, t, S_, C_)
    assert all(mon in [(0, 0, 0), (1, 0, 0), (0, 0, 1), (0, 1, 0)] for mon in P.monoms()), P
    return [P.coeff_monomial(1), P.coeff_monomial(t), P.coeff_monomial(C_), P.coeff_monomial(S_)]


K = 2 * a * (1 - sp.cos(a))
kk = 1 / K
b3 = kk * (t - s)
b2 = kk * ((a - sp.sin(a)) + (1 - sp.cos(a)) * t + sp.sin(a) * (1 - c) - (2 + sp.cos(a)) * (t - s))
cbs = [b3.subs(t, a - t), b2.subs(t, a - t), b2, b3]
Mc = sp.Matrix([coords(sp.expand(f * K), None) for f in cbs])
det = sp.factor(sp.simplify(Mc.det()))
check(sp.simplify(det - 4 * a * (1 - sp.cos(a)) ** 2 * sp.sin(a)) == 0,
      "C-B-spline: det of K·b_i in {1, t, cos t, sin t} = 4α(1 − cos α)² sin α: independent ⇔ sin α ≠ 0 on (0, 2π) ⇔ α ≠ π")
cb_pi = [sp.simplify(f.subs(a, sp.pi)) for f in cbs]
check(sp.simplify(cb_pi[0] + cb_pi[2] - sp.Rational(1, 2)) == 0 and sp.simplify(cb_pi[1] + cb_pi[3] - sp.Rational(1, 2)) == 0,
      "C-B-spline at α = π: b0 + b2 ≡ b1 + b3 ≡ 1/2 — DEPENDENT (rank 3), although α = π lies in the nonnegativity range (0, α*]")
# cubic C-Bézier (B1)
A = a - sp.sin(a)
gg = 2 - 2 * sp.cos(a) - a * sp.sin(a)
Nf = lambda u: A * (1 - sp.cos(u)) - (1 - sp.cos(a)) * (u - sp.sin(u))   # noqa: E731
cz = [(a - t - sp.sin(a - t)) / A, (1 - sp.cos(a)) * Nf(a - t) / (A * gg), (1 - sp.cos(a)) * Nf(t) / (A * gg), (t - s) / A]
Mz = sp.Matrix([coords(sp.expand(f * A * gg), None) for f in cz])
detz = sp.factor(sp.simplify(Mz.det()))
check(all(sp.simplify(detz.subs(a, v)) != 0 for v in [sp.pi / 3, sp.pi / 2, sp.pi, 3 * sp.pi / 2]),
      "cubic C-Bézier: det of (A g)·b_i in {1, t, cos t, sin t} ≠ 0 at α = π/3, π/2, π, 3π/2; independent on all of (0, 2π):"
      " zero orders 0, 1, 2, 3 at t = 0 (b1'(0) = (1 − cos α)/A, b2''(0) = (1 − cos α)/g, b3'''(0) = 1/A, all > 0)")
# quadratic C-Bézier (B4): in {1, cos t, sin t}
q = [(1 - sp.cos(a - t)) / (1 - sp.cos(a)), -(1 - c + sp.cos(a) - sp.cos(a - t)) / (1 - sp.cos(a)), (1 - c) / (1 - sp.cos(a))]
Mq = sp.Matrix([[r_[0], r_[2], r_[3]] for r_ in (coords(sp.expand(f * (1 - sp.cos(a))), None) for f in q)])
detq = sp.factor(sp.simplify(Mq.det()))
check(sp.simplify(detq - sp.sin(a) * (1 - sp.cos(a))) == 0 or sp.simplify(detq + sp.sin(a) * (1 - sp.cos(a))) == 0,
      f"quadratic C-Bézier: det in {{1, cos t, sin t}} = {detq}: independent ⇔ α ≠ π (on (0, 2π)); at α = π, b1 ≡ 0")
print("quartic trigonometric B-basis (C4): zero orders 0..4 at t = 0 ⇒ independent ⇔ cos(α/2) ≠ 0; at α = π rank 3"
      " (trig-bernstein-quartic.py).")
print("half-angle λ-basis (C6): zero orders at t = 0 are 0, 1 (b1'(0) = 1 + λ/√2 ≠ 0 on the range), ≥ 2 ⇒ independent"
      " on the whole maximal range [−√(1+√2/2), 1] (b1 has order ≥ 2 only at λ = −√2, outside).")
print("squared Han basis (C7): zero orders 0, 1 (2 at λ = −1), 4 ⇒ independent for every λ.")
print("done")
