"""Issue 38, part 2: linear independence decided by exact rank, derived independently (SymPy only).

A finite set of functions is linearly independent iff the coefficient matrix of their coordinates in a
set of functions that is itself independent has full row rank; rank drops exactly where all maximal
minors vanish (their Gröbner basis gives the exact set). The Wronskian W = det[b_j^(i)] (derivatives
w.r.t. the variable t) is given too, because trig-audit decides `independent` by it: for analytic
functions, W ≡ 0 ⇔ dependent. Dependence relations Σ c_i b_i ≡ 0 are checked exactly.

  (a) Bernstein polynomials, n = 3, 6, 10, 15, 20, on [0, 1]
  (b) C(n,i) sin^{2i}t cos^{2(n−i)}t on [0, π/2], n = 3, 6, 10 (monomials c^b s^e, e ≤ 1, after s² = 1 − c²)
  (c) two parameters: a constructed basis with b1 = −2β(α+1)t(1−t) (dependent on the edge α = −1 and the
      segment β = 0) and the published degree-2 generalized Bernstein basis (dependent exactly at a corner)
  (d) three parameters: the published degree-3 generalized Bernstein basis (λ1, λ2, λ3): dependent exactly
      on three edges of its box, with exact relations
  (e) on [0, α]: cubic C-Bézier (independent for every α ∈ (0, π], indeed (0, 2π)); trigonometric
      Bernstein sin^{n−i}(α−t) sin^i t (n = 2, 3): dependent exactly at the end α = π
"""

import itertools
from math import comb, factorial, prod

import sympy as sp
from _exact import check, trig_zero

R = sp.Rational
t, s, c = sp.symbols("t s c")
al, be, l1, l2, l3 = sp.symbols("alpha beta lambda1 lambda2 lambda3")


def cm(fs, x, deg):
    return sp.Matrix([[sp.Poly(sp.expand(f), x).coeff_monomial(x**k) for k in range(deg + 1)] for f in fs])


def wronskian_poly(fs, x):
    n = len(fs)
    return sp.expand(sp.Matrix([[sp.diff(f, x, k) for f in fs] for k in range(n)]).det(method="berkowitz"))


def maximal_minors(M):
    r, cn = M.shape
    return [sp.expand(M.extract(list(range(r)), list(J)).det()) for J in itertools.combinations(range(cn), r)]


# =============================================================================================== (a)
print("(a) Bernstein basis B_i^n = C(n,i) t^i (1 − t)^(n−i) on [0, 1]")
print('    spec: variable = "polynomial"; b_i = "C*t^i*(1 - t)^(n-i)" with the integer C = C(n,i) written out')
for n in (3, 6, 10, 15, 20):
    B = [comb(n, i) * t**i * (1 - t)**(n - i) for i in range(n + 1)]
    M = cm(B, t, n)
    detM = M.det()
    # W(B) = det(M)·W(1, t, ..., t^n), and W(1, ..., t^n) = Π_{k ≤ n} k! (upper triangular, constant)
    Wexp = detM * prod(factorial(k) for k in range(n + 1))
    PB = [sp.Poly(f, t) for f in B]
    Wat = sp.Matrix([[P.diff((t, k)).eval(R(1, 3)) if k else P.eval(R(1, 3)) for P in PB] for k in range(n + 1)]).det()
    check(M.rank() == n + 1 and detM == prod(comb(n, i) for i in range(n + 1)) and Wat == Wexp,
          f"n = {n}: coefficient matrix in 1, t, …, t^{n} is ({n + 1})×({n + 1}) of rank {n + 1} (triangular, det = Π C(n,i) ="
          f" {detM}); Wronskian constant = Π C(n,i)·Π k! = {Wexp if n <= 10 else sp.N(Wexp, 7)}"
          f" (exact value at t = 1/3 agrees) ⇒ independent")
    if n == 3:
        check(wronskian_poly(B, t) == Wexp == 108, "  n = 3: symbolic Wronskian ≡ 108")

# =============================================================================================== (b)
print()
print("(b) C(n,i) sin^(2i) t cos^(2(n−i)) t on [0, π/2] (= Bernstein polynomials in x = sin² t)")
print('    spec: variable = "angle"; b_i = "C*s^(2*i)*c^(2*(n-i))" with the numbers written out, e.g. n = 3:')
print('    b0 = "c^6", b1 = "3*s^2*c^4", b2 = "3*s^4*c^2", b3 = "s^6"')


def nf(e):
    _, r = sp.reduced(sp.expand(e), [s**2 + c**2 - 1], s, c, order="lex")
    return sp.expand(r)


def Dt(f):       # d/dt on polynomials in s = sin t, c = cos t
    return sp.expand(c * sp.diff(f, s) - s * sp.diff(f, c))


for n in (3, 6, 10):
    T = [comb(n, i) * s**(2 * i) * c**(2 * (n - i)) for i in range(n + 1)]
    red = [nf(f) for f in T]
    mons = sorted({m for f in red for m in sp.Poly(f, s, c).monoms()}, key=lambda m: (m[0], m[1]))
    check(all(m[0] == 0 for m in mons) and {m[1] for m in mons} == set(range(0, 2 * n + 1, 2)),
          f"n = {n}: after s² = 1 − c² every function is a polynomial in c² alone: monomials c^0, c^2, …, c^{2 * n} (e = 0)")
    M = sp.Matrix([[sp.Poly(f, s, c).coeff_monomial(c**(2 * j)) for j in range(n + 1)] for f in red])
    N = n * (n + 1) // 2
    K = prod(comb(n, i) for i in range(n + 1)) * prod(factorial(k) for k in range(n + 1))
    # W_t(B(x(t))) = x'(t)^(0+1+…+n) W_x(B) = (2 s c)^N · K   (chain rule, triangular structure)
    rows = [T]
    for _ in range(n):
        rows.append([Dt(f) for f in rows[-1]])
    pts = [(R(3, 5), R(4, 5)), (R(4, 5), R(3, 5)), (R(5, 13), R(12, 13))]
    okW = all(sp.Matrix([[f.subs({s: sv, c: cv}) for f in row] for row in rows]).det() == K * (2 * sv * cv)**N for sv, cv in pts)
    check(M.rank() == n + 1 and okW,
          f"  coefficient matrix {n + 1}×{n + 1} in c^(2j): rank {n + 1}, det = {M.det()} ⇒ independent;"
          f" Wronskian W = {K}·(2 sin t cos t)^{N} (exact at (s, c) = (3/5, 4/5), (4/5, 3/5), (5/13, 12/13))")
    if n == 3:
        Wsym = sp.Matrix(rows).det(method="berkowitz")
        check(nf(Wsym - K * (2 * s * c)**N) == 0, f"  n = 3: symbolic Wronskian ≡ {K}·(2sc)^6 = {K * 2**N}·s^6c^6 (reduced:"
              f" {K * 2**N}·c^6(1 − c²)^3)")
    print(f"    reduced Wronskian numerator: {K * 2**N}·c^{N}·" + (f"(1 − c²)^{N // 2}" if N % 2 == 0 else f"s·(1 − c²)^{(N - 1) // 2}")
          + f"  (degree {2 * N if N % 2 == 0 else 2 * N - 1} in c)")

# =============================================================================================== (c)
print()
print("(c1) constructed two-parameter basis, (α, β) ∈ [−1, 1]², K = −β(α + 1):")
print('     spec: variable = "polynomial"; alpha, beta in "[-1, 1]";')
print('     b0 = "(1 - t)*(1 + beta*(alpha + 1)*t)", b1 = "-2*beta*(alpha + 1)*t*(1 - t)",')
print('     b2 = "t*(1 + beta*(alpha + 1) - beta*(alpha + 1)*t)"')
K = -be * (al + 1)
bc = [(1 - t) * (1 - K * t), 2 * K * t * (1 - t), t * (1 - K + K * t)]
check(sp.expand(sum(bc) - 1) == 0 and sp.expand(bc[1] + 2 * be * (al + 1) * t * (1 - t)) == 0, "unity; b1 = −2β(α + 1)t(1 − t)")
Mc = cm(bc, t, 2)
check(sp.factor(Mc.det()) == sp.factor(2 * K), f"det of the coefficients in 1, t, t² = {sp.factor(Mc.det())}")
Wc = wronskian_poly(bc, t)
check(sp.expand(Wc - 4 * K) == 0, f"Wronskian W = 2·det = {sp.factor(Wc)} (constant in t)")
print("    ⇒ dependent exactly where β(α + 1) = 0: the edge α = −1 (every β) and the segment β = 0 (every α, inside the box)")
for av, bv in [(-1, R(1, 2)), (R(1, 2), 0), (0, 0), (-1, -1)]:
    check(sp.expand(bc[1].subs({al: av, be: bv})) == 0, f"  (α, β) = ({av}, {bv}): b1 ≡ 0 — relation 0·b0 + 1·b1 + 0·b2 ≡ 0")
check(Mc.subs({al: 1, be: 1}).rank() == 3 and Mc.subs({al: -1, be: 0}).rank() == 2,
      "  (1, 1): rank 3 (W = −8);  (−1, 0): rank 2")

print()
print("(c2) generalized Bernstein basis of degree 2 (Han, Ma & Huang, JCAM 217 (2008) 180-193; as quoted in")
print("     Hu, Bo & Qin, J. Inequal. Appl. 2017:115, Def. 1, (1)), λ1, λ2 ∈ [−2, 1]:")
print('     b0 = "(1 - t)^2*(1 - lambda1*t)", b1 = "t*(1 - t)*(2 + lambda1 - lambda1*t + lambda2*t)",')
print('     b2 = "t^2*(1 - lambda2 + lambda2*t)"')
g2 = [(1 - t)**2 * (1 - l1 * t), t * (1 - t) * (2 + l1 - l1 * t + l2 * t), t**2 * (1 - l2 + l2 * t)]
M2 = cm(g2, t, 3)
mins = [sp.factor(x) for x in maximal_minors(M2) if x != 0]
G = list(sp.groebner(mins, l1, l2, order="lex"))
check(G == [l1 + 2, l2 + 2], f"3×3 minors of the 3×4 coefficient matrix {mins}: Gröbner basis {G} ⇒ rank 3 except at (−2, −2)")
W2 = wronskian_poly(g2, t)
W2c = sp.Poly(W2, t).coeffs()
print(f"    Wronskian W = {sp.factor(W2)}")
check(list(sp.groebner(W2c, l1, l2, order="lex")) == [l1 + 2, l2 + 2],
      "  its coefficients in t^a vanish together exactly at (λ1, λ2) = (−2, −2)")
check(sp.expand(g2[1].subs({l1: -2, l2: -2})) == 0 and M2.subs({l1: -2, l2: -2}).rank() == 2,
      "  (−2, −2), the lower-left CORNER of the box: b1 ≡ 0 (relation b1 ≡ 0), rank 2; b0 = (1 − t)²(1 + 2t), b2 = t²(3 − 2t)")
check(sp.expand(W2.subs({l1: -2, l2: 1}) - W2.subs({l1: -2, l2: 1})) == 0 and W2.subs({l1: -2, l2: 1}) != 0
      and W2.subs({l1: 1, l2: -2}) != 0, f"  the other corners are independent: W(−2, 1) = {sp.factor(W2.subs({l1: -2, l2: 1}))},"
      f" W(1, −2) = {sp.factor(W2.subs({l1: 1, l2: -2}))}, W(1, 1) = {sp.factor(W2.subs({l1: 1, l2: 1}))}")
print("    (Bashir, Abbas & Ali 2013, examples/bashir-quadratic.toml, is the trigonometric twin: dependent exactly at the")
print("     corner (−1, −1), where b1 ≡ 0 — d-independence.py.)")

# =============================================================================================== (d)
print()
print("(d) generalized Bernstein basis of degree 3, three shape parameters (same source, n = 3, [n/2] = 2):")
print('    spec: variable = "polynomial"; lambda1 in "[-3, 1]", lambda2 in "[-3, 3]", lambda3 in "[-3, 1]";')
print('    b0 = "(1 - t)^3*(1 - lambda1*t)", b1 = "t*(1 - t)^2*(3 + lambda1 - lambda1*t - lambda2*t)",')
print('    b2 = "t^2*(1 - t)*(3 + lambda2 - lambda2*t + lambda3*t)", b3 = "t^3*(1 - lambda3 + lambda3*t)"')
g3 = [(1 - t)**3 * (1 - l1 * t), t * (1 - t)**2 * (3 + l1 - l1 * t - l2 * t),
      t**2 * (1 - t) * (3 + l2 - l2 * t + l3 * t), t**3 * (1 - l3 + l3 * t)]
check(sp.expand(sum(g3) - 1) == 0, "unity (exact)")
M3 = cm(g3, t, 4)
mins = [x for x in maximal_minors(M3) if x != 0]
G = list(sp.groebner(mins, l1, l2, l3, order="lex"))
print(f"    4×4 minors of the 4×5 coefficient matrix: {[sp.factor(x) for x in mins]}")
check([sp.factor(g_) for g_ in G] == [(l1 + 3) * (l2 + 3), (l1 + 3) * (l3 + 3), (l2 - 3) * (l3 + 3)],
      f"  Gröbner basis {[sp.factor(g_) for g_ in G]}")
sol = sp.solve(G, [l1, l2, l3], dict=True)
lines = {frozenset(d.items()) for d in sol}
check(lines == {frozenset({(l1, -3), (l2, 3)}), frozenset({(l1, -3), (l3, -3)}), frozenset({(l2, -3), (l3, -3)})},
      "  zero set = three lines, each an EDGE of the box: E1 = {λ1 = −3, λ2 = 3}, E2 = {λ1 = −3, λ3 = −3}, E3 = {λ2 = −3, λ3 = −3}")
W3 = wronskian_poly(g3, t)
GW = list(sp.groebner(sp.Poly(W3, t).coeffs(), l1, l2, l3, order="lex"))
check(all(sp.expand(W3.subs(q)) == 0 for q in ({l1: -3, l2: 3}, {l1: -3, l3: -3}, {l2: -3, l3: -3})),
      "  the Wronskian vanishes identically on each of the three edges")
solW = sp.solve(GW, [l1, l2, l3], dict=True)
check({frozenset(d.items()) for d in solW} == lines, "  and its coefficients in t^a have no other common zero (same three lines)")
print(f"    Wronskian at λ = 0 (cubic Bernstein): {sp.factor(W3.subs({l1: 0, l2: 0, l3: 0}))}")
# exact relations at rational points of the edges
rel = [({l1: -3, l2: 3, l3: 0}, (0, 1, 0, 0)), ({l1: -3, l2: 3, l3: -3}, (0, 1, 0, 0)),
       ({l1: -3, l2: 0, l3: -3}, (0, 1, -1, 0)), ({l1: -3, l2: 1, l3: -3}, (0, 2, -1, 0)),
       ({l1: 0, l2: -3, l3: -3}, (0, 0, 1, 0)), ({l1: 1, l2: -3, l3: -3}, (0, 0, 1, 0))]
for q, cf in rel:
    check(sp.expand(sum(ci * f.subs(q) for ci, f in zip(cf, g3))) == 0 and M3.subs(q).rank() == 3,
          f"  (λ1, λ2, λ3) = {tuple(q.values())}: relation {' + '.join(f'{ci}·b{i}' for i, ci in enumerate(cf) if ci)} ≡ 0, rank 3")
check(sp.expand((3 + l2) * g3[1] - (3 - l2) * g3[2]).subs({l1: -3, l3: -3}) == 0,
      "  along E2: (3 + λ2)·b1 − (3 − λ2)·b2 ≡ 0 (b1 = (3 − λ2)t²(1 − t)², b2 = (3 + λ2)t²(1 − t)²)")
check(all(M3.subs(q).rank() == 4 for q in ({l1: 1, l2: 3, l3: 1}, {l1: -3, l2: -3, l3: 1}, {l1: 1, l2: -3, l3: 1},
                                            {l1: -3, l2: 0, l3: 1}, {l1: R(-1, 2), l2: R(1, 3), l3: R(-5, 2)})),
      "  off the edges, e.g. the corners (1, 3, 1), (−3, −3, 1), (1, −3, 1) and (−3, 0, 1), (−1/2, 1/3, −5/2): rank 4")

# =============================================================================================== (e)
print()
print("(e1) cubic C-Bézier basis of span{1, t, sin t, cos t} on [0, α] (Zhang, CAGD 13 (1996) 199-217; closed form of")
print("     examples/independent/README.md B1): A = α − sin α, g = 2 − 2cos α − α sin α,")
print("     N(τ) = A(1 − cos τ) − (1 − cos α)(τ − sin τ); b0 = (α − t − sin(α − t))/A, b1 = (1 − cos α)N(α − t)/(A g),")
print("     b2 = (1 − cos α)N(t)/(A g), b3 = (t − sin t)/A;  spec: examples/c-bezier-cubic.toml (alpha in (0, pi))")
A = al - sp.sin(al)
g = 2 - 2 * sp.cos(al) - al * sp.sin(al)
Nf = lambda u: A * (1 - sp.cos(u)) - (1 - sp.cos(al)) * (u - sp.sin(u))   # noqa: E731
cz = [(al - t - sp.sin(al - t)) / A, (1 - sp.cos(al)) * Nf(al - t) / (A * g), (1 - sp.cos(al)) * Nf(t) / (A * g), (t - sp.sin(t)) / A]
S_, C_ = sp.symbols("S_ C_")


def coords4(f):
    e = sp.expand(sp.expand_trig(sp.expand(f))).subs({sp.sin(t): S_, sp.cos(t): C_})
    P = sp.Poly(e, t, S_, C_)
    assert set(P.monoms()) <= {(0, 0, 0), (1, 0, 0), (0, 0, 1), (0, 1, 0)}, P.monoms()
    return [P.coeff_monomial(1), P.coeff_monomial(t), P.coeff_monomial(C_), P.coeff_monomial(S_)]


Tm = sp.Matrix([coords4(f) for f in cz])
check(all(trig_zero(f - (r[0] + r[1] * t + r[2] * sp.cos(t) + r[3] * sp.sin(t)), [t, al]) for f, r in zip(cz, Tm.tolist())),
      "coordinates in (1, t, cos t, sin t) verified exactly")
dT = sp.simplify(Tm.det())
closed = (1 - sp.cos(al))**2 / (A**2 * g)
check(trig_zero(dT - closed, [al]), "det = (1 − cos α)²/((α − sin α)²(2 − 2cos α − α sin α))")
w0 = sp.Matrix([[sp.diff(f, t, k) for f in (1, t, sp.cos(t), sp.sin(t))] for k in range(4)]).det()
check(sp.simplify(w0) == 1, "W(1, t, cos t, sin t) = 1 ⇒ W(b0..b3) = det (constant in t)")
print("    g = 2 sin(α/2)(2 sin(α/2) − α cos(α/2)) > 0, α − sin α > 0, 1 − cos α > 0 on (0, 2π) (README B1) ⇒")
print("    W > 0: independent for EVERY α ∈ (0, π] (indeed (0, 2π)).")
for av in (sp.pi / 2, sp.pi, R(1, 2), 3):
    v = closed.subs(al, av)
    check(sp.N(v, 30) > 0, f"  α = {av}: W = {sp.nsimplify(sp.simplify(v)) if av in (sp.pi / 2, sp.pi) else sp.N(v, 20)}")
check(sp.simplify(closed.subs(al, sp.pi) - 1 / sp.pi**2) == 0, "  α = π (closed end of (0, π]): W = 4/(π²·4) = 1/π²")
check(sp.limit(closed * al**6, al, 0, "+") == 108, "  α⁶·W → 108 as α → 0⁺ (the cubic Bernstein Wronskian: t = αx)")

print()
print("(e2) trigonometric Bernstein functions on [0, α], α ∈ (0, π] (Sánchez-Reyes, CAGD 15 (1998) 909-923, without the")
print("     normalising 1/sin^n α, which is undefined at α = π):")
print('     spec: variable = "t", domain = "[0, alpha]", alpha in "(0, pi]";')
print('     n = 2: b0 = "sin(alpha - t)^2", b1 = "sin(alpha - t)*sin(t)", b2 = "sin(t)^2"')
u, v = sp.sin(al - t), sp.sin(t)
for n in (2, 3):
    F = [u**(n - i) * v**i for i in range(n + 1)]
    W = sp.Matrix([[sp.diff(f, t, k) for f in F] for k in range(n + 1)]).det()
    Kn = prod(factorial(k) for k in range(n + 1))
    check(trig_zero(W - Kn * sp.sin(al)**(n * (n + 1) // 2), [t, al]),
          f"n = {n}: W = {Kn}·sin^{n * (n + 1) // 2}(α) (exact; u v' − u' v = sin α for u = sin(α − t), v = sin t)")
print("    ⇒ on (0, π] the Wronskian vanishes exactly at α = π (sin α > 0 on (0, π)): dependent exactly at the END α = π.")
F2 = [u**2, u * v, v**2]
Mt = sp.Matrix([[R(1, 2), -sp.cos(2 * al) / 2, -sp.sin(2 * al) / 2],
                [-sp.cos(al) / 2, sp.cos(al) / 2, sp.sin(al) / 2],
                [R(1, 2), -R(1, 2), 0]])
check(all(trig_zero(f - (r[0] + r[1] * sp.cos(2 * t) + r[2] * sp.sin(2 * t)), [t, al]) for f, r in zip(F2, Mt.tolist())),
      "n = 2 coordinates in (1, cos 2t, sin 2t): rows (1/2, −cos 2α/2, −sin 2α/2), (−cos α/2, cos α/2, sin α/2), (1/2, −1/2, 0)")
dM = sp.simplify(Mt.det())
check(trig_zero(dM + sp.sin(al)**3 / 4, [al]) or trig_zero(dM - sp.sin(al)**3 / 4, [al]), f"  det = {sp.factor(dM)} (= ±sin³α/4)")
Mpi = Mt.subs(al, sp.pi)
check(Mpi.rank() == 1, f"  α = π: rank 1 (rows {Mpi.tolist()})")
Fpi = [sp.expand(f.subs(al, sp.pi)) for f in F2]
check(sp.simplify(Fpi[0] - Fpi[2]) == 0 and sp.simplify(Fpi[1] - Fpi[2]) == 0,
      "  α = π: b0 − b2 ≡ 0 and b1 − b2 ≡ 0 (all equal sin² t): two independent relations")
for av in (sp.pi / 2, 2 * sp.pi / 3, sp.pi / 6):
    check(Mt.subs(al, av).rank() == 3, f"  α = {av}: rank 3 (det = {sp.nsimplify(dM.subs(al, av))})")
print("    The normalised functions C(n,i) sin^(n−i)(α − t) sin^i t / sin^n α are undefined at α = π (division by 0);")
print("    on α ∈ (0, π) they are independent (W = Π k!·Π C(n,i)/sin^(n(n+1)/2) α ≠ 0).")
print("done")
