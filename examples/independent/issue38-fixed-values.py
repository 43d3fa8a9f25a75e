"""Issue 38, part 1: conic claims at FIXED parameter values, derived independently (SymPy only).

For each basis: the curve r = Σ b_i P_i for stated control points, the implicit polynomial F(X, Y) it is
checked against, the parameter value(s) where F(r) ≡ 0 holds, and, at another rational parameter value,
a rational point (t, or (sin t, cos t) rational) where the residual F(r) is nonzero, with its exact value.

Trigonometric bases are handled as polynomials in s = sin t, c = cos t reduced modulo s² + c² − 1
(normal form: monomials c^b s^e, e ≤ 1); a zero normal form is a proof of the identity. Every
witness (s, c) lies on the unit circle with t ∈ [0, π/2].

Bases (spec-file formulas are printed before each section):
  F1  Han 2002 quadratic trigonometric, λ ∈ [−1, 1]            (brief candidate (a); basis in examples/han-quadratic.toml)
  F2  rational quadratic Bernstein, w ∈ [0, ∞)                   (brief candidate (b); basis in examples/rational-quadratic.toml)
  F3  Han 2004 cubic trigonometric, λ ∈ [−2, 1]                  (published; the same functions as thesis-cubic.toml in u)
  F4  Han, Ma & Huang 2009 cubic trigonometric, λ, μ ∈ [−2, 1]   (two parameters: a parabola for λ = 0 and EVERY μ)
  F5  generalized Bernstein basis of Han, Ma & Huang 2008, degree 2 (λ1, λ2) and degree 3 (λ1, λ2, λ3)   (not in examples)
"""

import itertools

import sympy as sp
from _exact import check

R = sp.Rational
s, c, t, X, Y = sp.symbols("s c t X Y")
lam, mu, w, l1, l2, l3 = sp.symbols("lambda mu w lambda1 lambda2 lambda3")
CIRCLE = X**2 + Y**2 - 1


def nf(e):
    """Normal form of a polynomial in s, c (coefficients in Q(params)) modulo s² + c² − 1: e ≤ 1 in s."""
    num, den = sp.fraction(sp.together(sp.expand(e)))
    _, r = sp.reduced(sp.expand(num), [s**2 + c**2 - 1], s, c, order="lex")
    return sp.expand(r) / den


def curve(b, P):
    return (sum(f * p[0] for f, p in zip(b, P)), sum(f * p[1] for f, p in zip(b, P)))


def resid(F, b, P):
    x, y = curve(b, P)
    return F.subs({X: x, Y: y}, simultaneous=True)


def at_sc(e, sv, cv, extra=None):
    env = {s: sv, c: cv}
    env.update(extra or {})
    assert sv**2 + cv**2 == 1 and sv >= 0 and cv >= 0
    return sp.nsimplify(sp.factor(sp.expand(e).subs(env)))


SC = (R(3, 5), R(4, 5))   # (sin t, cos t), t = 2·atan(1/3) ∈ (0, π/2)

# =============================================================================================== F1
print("F1  Han 2002 quadratic trigonometric basis (Han, CAGD 19 (2002) 503-512, Section 2)")
print('    spec: variable = "angle"; parameter lambda, range "[-1, 1]";')
print('    b0 = "(1 - s)*(1 - lambda*s)", b1 = "1 - b0 - b2", b2 = "(1 - c)*(1 - lambda*c)"')
h0, h2 = (1 - s) * (1 - lam * s), (1 - c) * (1 - lam * c)
han = [h0, 1 - h0 - h2, h2]
check(nf(han[1] - (1 + lam) * (s + c - 1)) == 0, "b1 = 1 − b0 − b2 equals the printed (1 + λ)(sin t + cos t − 1) (exact)")
P1 = [(1, 0), (1, 1), (0, 1)]
r1 = sp.factor(nf(resid(CIRCLE, han, P1)))
print(f"    P = (1,0), (1,1), (0,1); X² + Y² − 1 on the curve, normal form = {r1}")
check(sp.expand(nf(resid(CIRCLE, han, P1)).subs(lam, 0)) == 0,
      "λ = 0: X² + Y² − 1 ≡ 0 (the curve is (cos t, sin t): the unit quarter circle)")
coeffs = sp.Poly(sp.expand(sp.numer(sp.together(nf(resid(CIRCLE, han, P1))))), s, c).coeffs()
check(sp.solve(coeffs, lam, dict=True) == [{lam: 0}], "the residual's coefficients (in c^b s^e) vanish together only at λ = 0")
for lv, (sv, cv) in [(1, SC), (R(1, 2), SC), (-1, SC), (1, (R(4, 5), R(3, 5)))]:
    v = at_sc(resid(CIRCLE, han, P1), sv, cv, {lam: lv})
    print(f"    witness λ = {lv}, (sin t, cos t) = ({sv}, {cv}): X² + Y² − 1 = {v}")
    assert v != 0
g35 = sp.factor(at_sc(resid(CIRCLE, han, P1), *SC))
check(sp.expand(g35 - 4 * lam * (13 * lam + 85) / 625) == 0,
      f"  at (sin t, cos t) = (3/5, 4/5): X² + Y² − 1 = {g35} (as a function of λ; by the symmetry of the data it equals"
      " the value 4λ(13λ + 85)/625 at (4/5, 3/5) found in d-conics.py)")
check(at_sc(resid(CIRCLE, han, P1), *SC, {lam: 1}) == R(392, 625), "  ⇒ λ = 1: residual 392/625;  λ = 1/2: 183/625;  λ = −1: −288/625")
check(at_sc(resid(CIRCLE, han, P1), *SC, {lam: -1}) == R(-288, 625), "  λ = −1 (the closed left end) is NOT on the circle")
# λ = −1: the curve degenerates to the segment X + Y = 1 (a degenerate conic)
LINE = X + Y - 1
check(nf(resid(LINE, han, P1)).subs(lam, -1) == 0 and sp.factor(nf(resid(LINE, han, P1))) != 0,
      "λ = −1: X + Y − 1 ≡ 0 (b1 ≡ 0, the curve is (cos² t, sin² t): the segment P0P2 — a degenerate conic)")
v = at_sc(resid(LINE, han, P1), *SC, {lam: 0})
check(v == R(2, 5), f"  witness λ = 0, (3/5, 4/5): X + Y − 1 = {v}")
# implicit equation for general λ: eliminate s, c from X = 1 − b2, Y = 1 − b0, s² + c² = 1
e1 = lam * s**2 - (1 + lam) * s + Y      # (1 − s)(1 − λs) = 1 − Y
e2 = lam * c**2 - (1 + lam) * c + X
Fh = sp.factor(sp.resultant(sp.resultant(e1, s**2 + c**2 - 1, s), e2, c))
Fq = sp.expand(sp.cancel(Fh / lam**2))
check(sp.Poly(Fq, X, Y).total_degree() == 4 and sp.expand(Fq.subs(lam, 0) - 2 * CIRCLE) == 0,
      "implicit equation of the curve for general λ (resultant): a quartic F_λ(X, Y) with F_0 = 2(X² + Y² − 1)")
print(f"    F_λ = {sp.collect(Fq, [X, Y])}")
check(sp.expand(sp.Poly(Fq, X, Y).homogenize(sp.Symbol('Z')).as_expr().subs(sp.Symbol('Z'), 0) - lam**2 * (X + Y)**4) == 0,
      "  its quartic part is λ²(X + Y)⁴: degree 4 exactly when λ ≠ 0")
check(sp.factor(Fq.subs(lam, -1)) == -(X + Y - 1)**4 or sp.factor(Fq.subs(lam, -1)) == (X + Y - 1)**4,
      f"  F_(−1) = {sp.factor(Fq.subs(lam, -1))}: the line, as found")
for lv in (R(1, 2), 1, R(-1, 2), R(-1, 4)):
    fl = sp.factor_list(sp.expand(Fq.subs(lam, lv)))
    check(len(fl[1]) == 1 and fl[1][0][1] == 1 and sp.Poly(fl[1][0][0], X, Y).total_degree() == 4,
          f"  λ = {lv}: F_λ is irreducible over Q and not a power ⇒ the curve is a quartic, on no conic")
print("    Any Han curve is an affine image of (b0, b2) (span{b0, b1, b2} = span{1, b0, b2}) or degenerate, so for")
print("    these λ no control polygon (P1 depending on λ or not) gives a conic arc; circles: sin t ∈ span ⇔ λ = 0 (d-conics.py).")

# =============================================================================================== F2
print()
print("F2  rational quadratic Bernstein basis (Farin, Curves and Surfaces for CAGD, ch. 12)")
print('    spec: variable = "polynomial"; parameter w, range "[0, inf)"; D = (1 - t)^2 + 2*w*t*(1 - t) + t^2;')
print('    b0 = "(1 - t)^2 / D", b1 = "2*w*t*(1 - t) / D", b2 = "t^2 / D"  (D written out or as a [[definitions]] entry)')
D = (1 - t)**2 + 2 * w * t * (1 - t) + t**2
rq = [(1 - t)**2 / D, 2 * w * t * (1 - t) / D, t**2 / D]
P2 = [(1, 0), (1, 1), (0, 1)]
Gw = (X + Y - 1)**2 - 4 * w**2 * (1 - X) * (1 - Y)
check(sp.cancel(resid(Gw, rq, P2)) == 0, "P = (1,0), (1,1), (0,1): the curve lies on the conic (X + Y − 1)² − 4w²(1 − X)(1 − Y) = 0"
      " for EVERY w (barycentric τ1² = 4w²τ0τ2)")
rc = sp.factor(sp.cancel(resid(CIRCLE, rq, P2)))
check(sp.cancel(rc - 2 * (2 * w**2 - 1) * t**2 * (1 - t)**2 / D**2) == 0,
      f"X² + Y² − 1 on the curve = 2(2w² − 1)t²(1 − t)²/D² ⇒ ≡ 0 ⇔ w² = 1/2 ⇔ w = √2/2 (the only value in [0, ∞))")
check(sp.simplify(rc.subs(w, sp.sqrt(2) / 2)) == 0, "  w = √2/2: X² + Y² − 1 ≡ 0 (the unit quarter circle)")
for wv, tv in [(1, R(1, 2)), (0, R(1, 2)), (R(1, 2), R(1, 2)), (1, R(1, 3))]:
    v = sp.nsimplify(rc.subs({w: wv, t: tv}))
    print(f"    witness w = {wv}, t = {tv}: X² + Y² − 1 = {v}")
    assert v != 0
check(rc.subs({w: 1, t: R(1, 2)}) == R(1, 8) and rc.subs({w: 0, t: R(1, 2)}) == R(-1, 2), "  w = 1, t = 1/2: 1/8;  w = 0, t = 1/2: −1/2")
PAR = sp.expand(Gw.subs(w, 1))
check(sp.expand(PAR - ((X - Y)**2 + 2 * X + 2 * Y - 3)) == 0, f"w = 1: the conic is the parabola (X − Y)² + 2X + 2Y − 3 = 0 (= {PAR})")
rp = sp.factor(sp.cancel(resid(PAR, rq, P2)))
check(sp.cancel(rp - 4 * (w**2 - 1) * t**2 * (1 - t)**2 / D**2) == 0,
      "  (X − Y)² + 2X + 2Y − 3 on the curve = 4(w² − 1)t²(1 − t)²/D² ⇒ ≡ 0 ⇔ w = 1 (w ≥ 0)")
check(rp.subs({w: 0, t: R(1, 2)}) == -1 and rp.subs({w: 2, t: R(1, 2)}) == R(1, 3),
      "  witnesses: w = 0, t = 1/2: −1;  w = 2, t = 1/2: 1/3;  w = √2/2, t = 1/2: " + str(sp.nsimplify(sp.radsimp(rp.subs({w: sp.sqrt(2) / 2, t: R(1, 2)})))))
# a circle arc with RATIONAL weight and points: cos θ = 4/5, sin θ = 3/5, arc from 0 to 2θ
P2r = [(1, 0), (1, R(3, 4)), (R(7, 25), R(24, 25))]
rr = sp.factor(sp.cancel(resid(CIRCLE, rq, P2r)))
check(rr.subs(w, R(4, 5)) == 0, "rational variant: w = 4/5, P = (1, 0), (1, 3/4), (7/25, 24/25) (arc 0..2θ, cos θ = 4/5): X² + Y² − 1 ≡ 0")
print(f"    its residual for general w: {rr}")
check(sp.solve(sp.numer(sp.together(rr)), w) == [R(-4, 5), R(4, 5)] or set(sp.solve(sp.numer(sp.together(rr)), w)) == {R(-4, 5), R(4, 5)},
      "  ≡ 0 ⇔ w = ±4/5, i.e. w = 4/5 in [0, ∞)")
v = sp.nsimplify(rr.subs({w: 1, t: R(1, 2)}))
check(v == R(81, 1600), f"  witness w = 1, t = 1/2: X² + Y² − 1 = {v}")

# =============================================================================================== F3
print()
print("F3  Han 2004 cubic trigonometric basis (Han, CAGD 21 (2004) 535-548; also thesis-cubic.toml in u = 2t/π)")
print('    spec: variable = "angle"; parameter lambda, range "[-2, 1]";')
print('    b0 = "(1 - s)^2*(1 - lambda*s)", b1 = "s*(1 - s)*(2 + lambda - lambda*s)",')
print('    b2 = "c*(1 - c)*(2 + lambda - lambda*c)", b3 = "(1 - c)^2*(1 - lambda*c)"')
H4 = lambda a, b_: [(1 - s)**2 * (1 - a * s), s * (1 - s) * (2 + a - a * s),   # noqa: E731
                    c * (1 - c) * (2 + b_ - b_ * c), (1 - c)**2 * (1 - b_ * c)]
han4 = H4(lam, lam)
check(nf(sum(han4) - 1) == 0, "unity (exact)")
P3 = [(1, 0), (1, R(1, 2)), (R(1, 2), 1), (0, 1)]
x3, y3 = curve(han4, P3)
check(nf(x3.subs(lam, 0) - c) == 0 and nf(y3.subs(lam, 0) - s) == 0,
      "λ = 0, P = (1,0), (1,1/2), (1/2,1), (0,1): the curve is exactly (cos t, sin t) ⇒ X² + Y² − 1 ≡ 0")
r3 = sp.factor(nf(resid(CIRCLE, han4, P3)))
print(f"    X² + Y² − 1 on the curve (normal form) = {r3}")
cf = sp.Poly(sp.numer(sp.together(nf(resid(CIRCLE, han4, P3)))), s, c).coeffs()
check(sp.solve(cf, lam, dict=True) == [{lam: 0}], "  ≡ 0 ⇔ λ = 0")
for lv in (1, R(1, 2), -2):
    v = at_sc(resid(CIRCLE, han4, P3), *SC, {lam: lv})
    print(f"    witness λ = {lv}, (sin t, cos t) = (3/5, 4/5): X² + Y² − 1 = {v}")
    assert v != 0
check(at_sc(resid(CIRCLE, han4, P3), *SC, {lam: 1}) == R(268, 3125), "  (λ = 1: 268/3125)")

# =============================================================================================== F4
print()
print("F4  Han, Ma & Huang 2009 cubic trigonometric basis, two parameters (Appl. Math. Lett. 22 (2009) 226-231, (1))")
print('    spec: examples/han-ma-huang-cubic.toml (b0..b3 with lambda, mu in [-2, 1])')
hmh = H4(lam, mu)
# span analysis: coordinates in (1, s, s², s³, c, c³) (c² = 1 − s²)
MONS = [(0, 0), (1, 0), (2, 0), (3, 0), (0, 1), (2, 1)]


def coords(f):
    f = sp.expand(f)
    f = sp.expand(f.subs(c**3, c * (1 - s**2)).subs(c**2, 1 - s**2))
    P = sp.Poly(f, s, c)
    assert set(P.monoms()) <= set(MONS), P.monoms()
    return [P.coeff_monomial(s**a * c**b_) for a, b_ in MONS]


M = sp.Matrix([coords(f) for f in hmh])
G4 = list(sp.groebner([sp.expand(M.extract(list(range(4)), list(J)).det()) for J in itertools.combinations(range(6), 4)], lam, mu))
check(G4 == [1], f"coordinates in (1, s, s², s³, c, c³) (c² = 1 − s²): the 4×4 minors have no common zero (Gröbner basis {G4}): rank 4 for all λ, μ")
for name, e in [("sin t", [0, 1, 0, 0, 0, 0]), ("cos t", [0, 0, 0, 0, 1, 0])]:
    A = M.col_join(sp.Matrix([e]))
    mins = [sp.factor(A.extract(list(range(5)), list(J)).det()) for J in itertools.combinations(range(6), 5)]
    mins = [x for x in mins if x != 0]
    G = list(sp.groebner(mins, lam, mu, order="lex"))
    print(f"    {name} ∈ span ⇔ all 5×5 minors of [M; e] vanish (M has rank 4): minors {mins}, Gröbner basis {G}")
    if name == "sin t":
        check(G == [lam], "  sin t ∈ span ⇔ λ = 0 (μ free)")
    else:
        check(G == [mu], "  cos t ∈ span ⇔ μ = 0 (λ free)")
check(nf(hmh[2] + hmh[3] - s**2) == 0 and nf(hmh[0] + hmh[1] - c**2) == 0, "b2 + b3 = sin² t and b0 + b1 = cos² t for every λ, μ")
P4 = [(0, 0), (R(1, 2), 0), (1, 1), (1, 1)]
PARA = Y - X**2
r4 = sp.factor(nf(resid(PARA, hmh, P4)))
x4, y4 = curve(hmh, P4)
check(nf(y4 - s**2) == 0 and nf(x4 - (s + lam * s * (1 - s)**2 / 2)) == 0,
      "P = (0,0), (1/2,0), (1,1), (1,1): Y = sin² t and X = sin t + λ sin t(1 − sin t)²/2 (μ does not enter)")
check(nf(y4 - x4**2 + lam * s**2 * (1 - s)**2 * (1 + lam * (1 - s)**2 / 4)) == 0,
      "  Y − X² = −λ s²(1 − s)²(1 + λ(1 − s)²/4) ⇒ Y − X² ≡ 0 ⇔ λ = 0, for EVERY μ (a parabola arc: fixing one parameter)")
for lv, mv in [(1, 0), (1, 1), (-2, R(1, 2)), (R(1, 2), -2)]:
    v = at_sc(y4 - x4**2, *SC, {lam: lv, mu: mv})
    print(f"    witness (λ, μ) = ({lv}, {mv}), (sin t, cos t) = (3/5, 4/5): Y − X² = {v}")
    assert v != 0
check(at_sc(y4 - x4**2, *SC, {lam: 1, mu: 0}) == R(-936, 15625), "  ((1, μ): −936/15625 = −(9/25)(4/25)(26/25) for every μ)")
x5, y5 = curve(hmh, P3)
check(nf(x5 - c).subs(mu, 0) == 0 and nf(y5 - s).subs(lam, 0) == 0,
      "circle: P = (1,0), (1,1/2), (1/2,1), (0,1) give X = cos t exactly when μ = 0 and Y = sin t exactly when λ = 0")
rc4 = nf(resid(CIRCLE, hmh, P3))
check(sp.solve(sp.Poly(sp.numer(sp.together(rc4)), s, c).coeffs(), [lam, mu], dict=True) == [{lam: 0, mu: 0}],
      "  X² + Y² − 1 ≡ 0 ⇔ (λ, μ) = (0, 0)")
for lv, mv in [(0, 1), (1, 0)]:
    v = at_sc(rc4, *SC, {lam: lv, mu: mv})
    print(f"    witness (λ, μ) = ({lv}, {mv}), (3/5, 4/5): X² + Y² − 1 = {v}")
    assert v != 0

# =============================================================================================== F5
print()
print("F5  generalized Bernstein basis with shape parameters: Han, Ma & Huang, 'A novel generalization of Bézier")
print("    curve and surface', J. Comput. Appl. Math. 217 (2008) 180-193 — as quoted in Hu, Bo & Qin, J. Inequal.")
print("    Appl. 2017:115 (doi 10.1186/s13660-017-1390-3), Definition 1, eq. (1); [n/2] = (n+1)/2 for odd n;")
print("    λ_i ∈ [−C(n,i), C(n,i−1)] (i ≤ [n/2]), λ_i ∈ [−C(n,i−1), C(n,i)] (i > [n/2]).")
print('    n = 2 spec: variable = "polynomial"; lambda1, lambda2 in "[-2, 1]";')
print('      b0 = "(1 - t)^2*(1 - lambda1*t)", b1 = "t*(1 - t)*(2 + lambda1 - lambda1*t + lambda2*t)",')
print('      b2 = "t^2*(1 - lambda2 + lambda2*t)"')
g2 = [(1 - t)**2 * (1 - l1 * t), t * (1 - t) * (2 + l1 - l1 * t + l2 * t), t**2 * (1 - l2 + l2 * t)]
check(sp.expand(sum(g2) - 1) == 0, "n = 2: unity (exact)")
Pb2 = [(0, 0), (R(1, 2), 0), (1, 1)]
x, y = curve(g2, Pb2)
e2 = sp.factor(sp.expand(y - x**2))
check(sp.expand(e2 + t**2 * (1 - t)**2 * ((l1 * (1 - t) - l2 * t)**2 + 4 * (l1 + l2)) / 4) == 0,
      "P = (0,0), (1/2,0), (1,1) (the Bernstein polygon of (t, t²)): Y − X² = −t²(1 − t)²[(λ1(1 − t) − λ2t)² + 4(λ1 + λ2)]/4")
check(sp.solve(sp.Poly(sp.expand(y - x**2), t).coeffs(), [l1, l2], dict=True) == [{l1: 0, l2: 0}], "  ≡ 0 ⇔ (λ1, λ2) = (0, 0)")
for pv, tv in [((1, 0), R(1, 2)), ((0, 1), R(1, 2)), ((1, -1), R(1, 2)), ((-2, -2), R(1, 2))]:
    v = sp.expand(y - x**2).subs({l1: pv[0], l2: pv[1], t: tv})
    print(f"    witness (λ1, λ2) = {pv}, t = {tv}: Y − X² = {v}")
    assert v != 0
check(sp.expand(y - x**2).subs({l1: 1, l2: 0, t: R(1, 2)}) == R(-17, 256), "  ((1, 0), t = 1/2: −17/256)")
# span: parabola representable with some polygon ⇔ t, t² ∈ span (degree argument as in d-conics.py)
Mg = sp.Matrix([[sp.Poly(sp.expand(f), t).coeff_monomial(t**k) for k in range(4)] for f in g2])
dt = sp.factor(Mg.col_join(sp.Matrix([[0, 1, 0, 0]])).det())
dt2 = sp.factor(Mg.col_join(sp.Matrix([[0, 0, 1, 0]])).det())
print(f"    rank 3 except at (−2, −2) (independence script); det[M; t] = {dt}, det[M; t²] = {dt2}")
check(sp.solve([dt, dt2], [l1, l2], dict=True) == [{l1: -2, l2: -2}, {l1: 0, l2: 0}] or
      {tuple(sorted(d.items(), key=str)) for d in sp.solve([dt, dt2], [l1, l2], dict=True)} ==
      {((l1, -2), (l2, -2)), ((l1, 0), (l2, 0))},
      "  both vanish only at (0, 0) and the corner (−2, −2)")
Mc = Mg.subs({l1: -2, l2: -2})
check(Mc.rank() == 2 and Mc.col_join(sp.Matrix([[0, 1, 0, 0]])).rank() == 3,
      "  at (−2, −2) (rank 2, b1 ≡ 0) t ∉ span ⇒ a parabola arc is representable exactly at (λ1, λ2) = (0, 0)")

print('    n = 3 spec: lambda1 in "[-3, 1]", lambda2 in "[-3, 3]", lambda3 in "[-3, 1]";')
print('      b0 = "(1 - t)^3*(1 - lambda1*t)", b1 = "t*(1 - t)^2*(3 + lambda1 - lambda1*t - lambda2*t)",')
print('      b2 = "t^2*(1 - t)*(3 + lambda2 - lambda2*t + lambda3*t)", b3 = "t^3*(1 - lambda3 + lambda3*t)"')
g3 = [(1 - t)**3 * (1 - l1 * t), t * (1 - t)**2 * (3 + l1 - l1 * t - l2 * t),
      t**2 * (1 - t) * (3 + l2 - l2 * t + l3 * t), t**3 * (1 - l3 + l3 * t)]
check(sp.expand(sum(g3) - 1) == 0, "n = 3: unity (exact)")
Pb3 = [(0, 0), (R(1, 3), 0), (R(2, 3), R(1, 3)), (1, 1)]
x, y = curve(g3, Pb3)
e3 = sp.expand(y - x**2)
check(sp.solve(sp.Poly(e3, t).coeffs(), [l1, l2, l3], dict=True) == [{l1: 0, l2: 0, l3: 0}],
      "P = (0,0), (1/3,0), (2/3,1/3), (1,1): Y − X² ≡ 0 ⇔ λ1 = λ2 = λ3 = 0")
e3h = sp.factor(e3.subs(t, R(1, 2)))
print(f"    Y − X² at t = 1/2: {e3h}")
check(e3.subs({l1: 1, l2: 0, l3: 0, t: R(1, 2)}) == R(-49, 2304), "  witness (1, 0, 0), t = 1/2: −49/2304")
check(e3.subs({l1: R(-1, 3), l2: -1, l3: 1, t: R(1, 2)}) != 0,
      f"  witness (−1/3, −1, 1), t = 1/2: {e3.subs({l1: R(-1, 3), l2: -1, l3: 1, t: R(1, 2)})}")
# but the span contains the parabola on a whole curve of parameters
M3 = sp.Matrix([[sp.Poly(sp.expand(f), t).coeff_monomial(t**k) for k in range(5)] for f in g3])
d1 = sp.factor(M3.col_join(sp.Matrix([[0, 1, 0, 0, 0]])).det())
d2 = sp.factor(M3.col_join(sp.Matrix([[0, 0, 1, 0, 0]])).det())
print(f"    det[M; t] = {d1};  det[M; t²] = {d2}")
lc1, lc2 = -l3 / (2 * l3 + 1), -2 * l3 / (l3 + 1)
check(sp.simplify(d1.subs({l1: lc1, l2: lc2})) == 0 and sp.simplify(d2.subs({l1: lc1, l2: lc2})) == 0,
      "  t, t² ∈ span (off the dependence edges) on the rational curve λ1 = −λ3/(2λ3 + 1), λ2 = −2λ3/(λ3 + 1)")
xr = sp.Symbol("x", real=True)
inbox = sp.Interval(-3, 1)
for lo, hi, fn in [(-3, 1, lc1), (-3, 3, lc2)]:
    inbox = inbox.intersect(sp.solve_univariate_inequality(fn.subs(l3, xr) >= lo, xr, relational=False)
                            ).intersect(sp.solve_univariate_inequality(fn.subs(l3, xr) <= hi, xr, relational=False))
check(inbox == sp.Union(sp.FiniteSet(-3, R(-3, 5)), sp.Interval(R(-1, 3), 1)),
      f"  the curve meets the box for λ3 ∈ {inbox}: the isolated points are (−3, 3, −3/5) and (−3/5, −3, −3), on the dependence"
      " edges (rank 3); the arc λ3 ∈ [−1/3, 1] runs from (1, 1, −1/3) through (0, 0, 0) to (−1/3, −1, 1)")
check(all(M3.subs({l1: lc1, l2: lc2, l3: v}).rank() == 4 for v in (R(-1, 3), 0, R(1, 2), 1)), "  rank 4 along the arc (λ3 = −1/3, 0, 1/2, 1)")
E1 = M3.subs({l1: -3, l2: 3, l3: 0})
check(E1.rank() == 3 and E1.col_join(sp.Matrix([[0, 1, 0, 0, 0]])).rank() == 4,
      "  on the edge λ1 = −3, λ2 = 3 (rank 3; sample λ3 = 0) t ∉ span: no parabola there")
for name, q, free in [("E1", {l1: -3, l2: 3}, l3), ("E2", {l1: -3, l3: -3}, l2), ("E3", {l2: -3, l3: -3}, l1)]:
    both = None
    for e in ([0, 1, 0, 0, 0], [0, 0, 1, 0, 0]):
        A = M3.subs(q).col_join(sp.Matrix([e]))
        mins = [sp.expand(A.extract(list(I), list(J)).det()) for I in itertools.combinations(range(5), 4)
                for J in itertools.combinations(range(5), 4)]
        G = list(sp.groebner([x for x in mins if x != 0] or [0], free))
        both = G if both is None else list(sp.groebner(both + G, free))
    check(both == [1], f"  edge {name} (rank 3 along it): t and t² are never both in the span (Gröbner basis of the 4×4 minors: {both})")
for q in ({l1: -3, l2: 3, l3: R(-3, 5)}, {l1: R(-3, 5), l2: -3, l3: -3}):
    Mq = M3.subs(q)
    inn = [Mq.col_join(sp.Matrix([e])).rank() == Mq.rank() for e in ([0, 1, 0, 0, 0], [0, 0, 1, 0, 0])]
    check(Mq.rank() == 3 and inn != [True, True], f"  isolated point {tuple(q.values())}: rank 3, (t, t²) ∈ span: {inn} ⇒ no parabola")
pt = {l1: R(-1, 3), l2: -1, l3: 1}
Mp = M3.subs(pt)
check(Mp.rank() == 4, "  e.g. λ3 = 1 ⇒ (λ1, λ2, λ3) = (−1/3, −1, 1), inside the box, rank 4")
xs, ys = sp.symbols("x0:4"), sp.symbols("y0:4")
gp = [f.subs(pt) for f in g3]
solx = sp.solve(sp.Poly(sp.expand(sum(f * v for f, v in zip(gp, xs)) - t), t).coeffs(), xs, dict=True)[0]
soly = sp.solve(sp.Poly(sp.expand(sum(f * v for f, v in zip(gp, ys)) - t**2), t).coeffs(), ys, dict=True)[0]
Pq = [(solx[xs[i]], soly[ys[i]]) for i in range(4)]
print(f"    control points giving exactly (t, t²) at (−1/3, −1, 1): {Pq}")
xq, yq = curve(gp, Pq)
check(sp.expand(yq - xq**2) == 0, "  with them Y − X² ≡ 0 at (λ1, λ2, λ3) = (−1/3, −1, 1)")
xg, yg = curve(g3, Pq)
eq = sp.expand(yg - xg**2)
check(eq.subs({l1: 0, l2: 0, l3: 0, t: R(1, 2)}) != 0,
      f"  the same points at (0, 0, 0), t = 1/2: Y − X² = {eq.subs({l1: 0, l2: 0, l3: 0, t: R(1, 2)})} ≠ 0")
print("done")
