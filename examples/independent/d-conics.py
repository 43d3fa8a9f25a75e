"""Part D(c): conic arcs — for which parameter values the span contains 1, cos t, sin t (circles) or 1, t, t²
(parabolas); the control points of the unit circle arc from angle 0 to α, derived exactly, with the implicit
check x² + y² − 1 ≡ 0; and failing cases with exact residuals. All identities are exact (trig_zero / hyp_zero).
"""

import sympy as sp
from _exact import check, hyp_zero, iv_digits, trig_at, trig_zero

t, a, lam, x, y = sp.symbols("t alpha lambda x y", real=True)
R = sp.Rational
S, C = sp.sin, sp.cos


def curve(b, P):
    return (sum(f * p[0] for f, p in zip(b, P)), sum(f * p[1] for f, p in zip(b, P)))


H = lambda e: e.subs({t: 2 * x, a: 2 * y})   # noqa: E731   half angles → integer multiples

# ---------------- quadratic C-Bézier (B4) on [0, α]: span = span{1, cos t, sin t} for every α ∈ (0, π)
q = [(1 - C(a - t)) / (1 - C(a)), -(1 - C(t) + C(a) - C(a - t)) / (1 - C(a)), (1 - C(t)) / (1 - C(a))]
Pq = [(1, 0), (1, S(a / 2) / C(a / 2)), (C(a), S(a))]
X, Y = curve(q, Pq)
check(trig_zero(H(X - C(t)), [x, y]) and trig_zero(H(Y - S(t)), [x, y]),
      "quadratic C-Bézier: P0 = (1, 0), P1 = (1, tan(α/2)), P2 = (cos α, sin α) give exactly (cos t, sin t), t ∈ [0, α]")
check(trig_zero(H(X**2 + Y**2 - 1), [x, y]), "  implicit check x² + y² − 1 ≡ 0 (every α ∈ (0, π))")
print("  α = π: P1 is at infinity and b1 ≡ 0 — the curve is the chord P0P2; no half circle with this basis.")

# ---------------- cubic C-Bézier (B1): span{1, t, cos t, sin t} ∋ cos, sin for every α ∈ (0, 2π)
A = a - S(a)
g = 2 - 2 * C(a) - a * S(a)
Nf = lambda u: A * (1 - C(u)) - (1 - C(a)) * (u - S(u))   # noqa: E731
cz = [(a - t - S(a - t)) / A, (1 - C(a)) * Nf(a - t) / (A * g), (1 - C(a)) * Nf(t) / (A * g), (t - S(t)) / A]
h = A / (1 - C(a))
Pc = [(1, 0), (1, h), (C(a) + h * S(a), S(a) - h * C(a)), (C(a), S(a))]
X, Y = curve(cz, Pc)
check(trig_zero(X - C(t), [t, a]) and trig_zero(Y - S(t), [t, a]),
      "cubic C-Bézier: P0 = (1, 0), P1 = (1, h), P2 = (cos α + h sin α, sin α − h cos α), P3 = (cos α, sin α),"
      " h = (α − sin α)/(1 − cos α), give exactly (cos t, sin t)")
check(all(trig_zero((X**2 + Y**2 - 1).subs(a, v), [t]) for v in (sp.pi / 2, sp.pi)),
      "  implicit check x² + y² − 1 ≡ 0 in t at α = π/2 and α = π (h = π/2: a half circle); for every α it follows"
      " from the coordinate identities above")
# a wrong printed polygon: the polynomial cubic Bézier circle approximation h' = (4/3)tan(α/4)
hb = R(4, 3) * S(a / 4) / C(a / 4)
Pw = [(1, 0), (1, hb), (C(a) + hb * S(a), S(a) - hb * C(a)), (C(a), S(a))]
Xw, Yw = curve(cz, Pw)
res = sp.simplify((Xw**2 + Yw**2 - 1).subs({a: sp.pi / 2, t: sp.pi / 4}))
print("  a printed polygon with the polynomial value h' = (4/3)tan(α/4) (cubic Bézier circle approximation):")
check(iv_digits(res, {}) != "0" and abs(float(res)) > 1e-3,
      f"  α = π/2, t = π/4: x² + y² − 1 = {iv_digits(res, {})} ≠ 0 (exact value in π, √2; 30 certified digits): not the circle;"
      f" the correct h at α = π/2 is π/2 − 1 = {sp.N(sp.pi / 2 - 1, 12)} vs (4/3)tan(π/8) = {sp.N(R(4, 3) * sp.tan(sp.pi / 8), 12)}")

# ---------------- C-B-spline (C1): de Boor points on a circle of radius α/sin α
k = 1 / (2 * a * (1 - C(a)))
b3 = k * (t - S(t))
b2 = k * ((a - S(a)) + (1 - C(a)) * t + S(a) * (1 - C(t)) - (2 + C(a)) * (t - S(t)))
cbs = [b3.subs(t, a - t), b2.subs(t, a - t), b2, b3]
rho = a / S(a)
Pb = [(rho * C((i - 1) * a), rho * S((i - 1) * a)) for i in range(4)]
X, Y = curve(cbs, Pb)
check(trig_zero(X - C(t), [t, a]) and trig_zero(Y - S(t), [t, a]),
      "C-B-spline: de Boor points P_i = (α/sin α)(cos((i − 1)α), sin((i − 1)α)) give exactly (cos t, sin t) on the"
      " segment t ∈ [0, α] (P_{j+i} at angle (j + i − 1)α for segment j: a whole circle from a regular polygon)")
check(all(trig_zero((X**2 + Y**2 - 1).subs(a, v), [t]) for v in (sp.pi / 2, 2 * sp.pi / 3)),
      "  implicit check x² + y² − 1 ≡ 0 in t at α = π/2, 2π/3 (ρ = π/2, 4π/(3√3)); every α ≠ π by the identities above")
print("  α = π: sin α = 0 — no circle (the four functions are dependent there: d-independence.py).")

# ---------------- H-Bézier quadratic (C3): hyperbola yes, circle never
hq = [(sp.cosh(a - t) - 1) / (sp.cosh(a) - 1), None, (sp.cosh(t) - 1) / (sp.cosh(a) - 1)]
hq[1] = 1 - hq[0] - hq[2]
Ph = [(1, 0), (1, sp.sinh(a / 2) / sp.cosh(a / 2)), (sp.cosh(a), sp.sinh(a))]
X, Y = curve(hq, Ph)
check(hyp_zero(X - sp.cosh(t), [t, a]) and hyp_zero(Y - sp.sinh(t), [t, a]) and hyp_zero(X**2 - Y**2 - 1, [t, a]),
      "H-Bézier quadratic: P0 = (1, 0), P1 = (1, tanh(α/2)), P2 = (cosh α, sinh α) give (cosh t, sinh t): x² − y² − 1 ≡ 0")
print("  circle: never. Every f in span{1, sinh t, cosh t} satisfies f''' = f'; cos''' = sin ≠ −sin = cos', so cos ∉ span.")
print("  More: any curve with coordinates in the span is an affine image of (cosh t, sinh t) (or degenerate), i.e. an arc")
print("  of a hyperbola or a line, which meets a circle in at most 4 points — no H-Bézier quadratic curve is a circle arc.")
check(sp.simplify(sp.diff(C(t), t, 3) - sp.diff(C(t), t)) != 0, "  cos''' − cos' = 2 sin t ≢ 0")

# ---------------- Han 2002 quadratic (A1): circle only at λ = 0
han = [(1 - S(t)) * (1 - lam * S(t)), (1 + lam) * (S(t) + C(t) - 1), (1 - C(t)) * (1 - lam * C(t))]
Pn = [(1, 0), (1, 1), (0, 1)]
X, Y = curve(han, Pn)
check(trig_zero(X.subs(lam, 0) - C(t), [t]) and trig_zero(Y.subs(lam, 0) - S(t), [t]),
      "Han quadratic, λ = 0: P = (1, 0), (1, 1), (0, 1) give exactly (cos t, sin t), t ∈ [0, π/2] (quarter circle)")
resid = sp.factor(trig_at(X**2 + Y**2 - 1, t, R(1, 2)))
print(f"  λ ≠ 0 with the same polygon: x² + y² − 1 at (sin t, cos t) = (4/5, 3/5) equals {resid}")
check(resid.subs(lam, R(1, 2)) != 0 and resid.subs(lam, 1) != 0, f"  e.g. λ = 1/2: {resid.subs(lam, R(1, 2))}, λ = 1: {resid.subs(lam, 1)} (≠ 0)")
# span analysis in the basis (1, sin t, cos t, cos 2t)
rows = [[1 + lam / 2, -(1 + lam), 0, -lam / 2], [-(1 + lam), 1 + lam, 1 + lam, 0], [1 + lam / 2, 0, -(1 + lam), lam / 2]]
base = [1, S(t), C(t), C(2 * t)]
check(all(trig_zero(f - sum(r_ * g_ for r_, g_ in zip(row, base)), [t]) for f, row in zip(han, rows)),
      "  coordinates in (1, sin t, cos t, cos 2t): b0 = (1 + λ/2, −(1 + λ), 0, −λ/2), b1 = (1 + λ)(−1, 1, 1, 0),"
      " b2 = (1 + λ/2, 0, −(1 + λ), λ/2)")
Mh = sp.Matrix(rows)
for name, e_ in [("sin t", [0, 1, 0, 0]), ("cos t", [0, 0, 1, 0])]:
    dd = sp.factor(Mh.col_join(sp.Matrix([e_])).det())
    check(sp.Poly(dd, lam).real_roots() == [-1, 0] or set(sp.Poly(dd, lam).real_roots()) <= {-1, 0},
          f"  {name} ∈ span ⇒ det[M; e] = {dd} = 0 ⇒ λ ∈ {{0, −1}}")
    check(Mh.subs(lam, -1).col_join(sp.Matrix([e_])).rank() == 3, f"  λ = −1: rank 2 and {name} ∉ span{{cos² t, sin² t}}: so {name} ∈ span ⇔ λ = 0")

# ---------------- parabolas: Yan & Liang (A2)
yl = [(1 - lam * x) * (1 - x) ** 3, x * (1 - x) ** 2 * (3 + lam * (1 - x)), x**2 * (1 - x) * (3 + lam * x), (1 - lam + lam * x) * x**3]
M = sp.Matrix([[sp.Poly(sp.expand(f), x).coeff_monomial(x**kk) for kk in range(5)] for f in yl])
aug = M.col_join(sp.Matrix([[0, 0, 1, 0, 0]]))
d2 = sp.factor(aug.det())
check(sp.expand(d2 + 2 * lam * (lam + 3)) == 0, f"Yan & Liang: det[M; t²] = {d2}: for λ ≠ −3 (rank M = 4), t² ∈ span ⇔ λ = 0")
M3 = M.subs(lam, -3)
check(M3.rank() == 3 and M3.col_join(sp.Matrix([[0, 1, 0, 0, 0]])).rank() == 4 and M3.col_join(sp.Matrix([[0, 0, 1, 0, 0]])).rank() == 4,
      "  λ = −3 (rank 3): neither t nor t² is in the span")
Pp = [(0, 0), (R(1, 3), 0), (R(2, 3), R(1, 3)), (1, 1)]
X, Y = curve([f.subs(lam, 0) for f in yl], Pp)
check(sp.expand(X - x) == 0 and sp.expand(Y - x**2) == 0, "  λ = 0: P = (0, 0), (1/3, 0), (2/3, 1/3), (1, 1) give (t, t²): y − x² ≡ 0")
X, Y = curve(yl, Pp)
rp = sp.factor(sp.expand(Y - X**2).subs(x, R(1, 2)))
check(rp.subs(lam, 1) != 0, f"  λ ≠ 0, same polygon: y − x² at t = 1/2 equals {rp} (λ = 1: {rp.subs(lam, 1)})")
print("  λ ∉ {0}: no Yan–Liang curve is a parabola arc: if y = x² ∘ (affine) on an interval, q = a p² + b p + c as")
print("  polynomials, so deg p ≤ 2, p ∈ span ∩ P2 = span{1, t} and then t² ∈ span — false for λ ≠ 0.")
print("Polynomial splines and circles: a circle arc has no polynomial parametrisation (x² + y² = 1 with polynomials")
print("forces x, y constant), while a parabola is the polynomial curve (t, t²): 'polynomial splines cannot represent conics'")
print("is true for circles/ellipses/hyperbolas and false for parabolas.")
print("done")
