"""Issue 38, part 3: total positivity (TP) with several parameters, derived independently (SymPy only).

A system (b_0, …, b_n) on an interval is TP if every collocation matrix (b_j(x_i)), x_0 < … < x_m, has all
minors ≥ 0 (every order, rows and columns in increasing order).

Certificate (sufficient): after an increasing change of variable (z = tan(t/2) on [0, π/2]; t itself on
[0, 1]) the basis is N(x)/D(x) with one positive D for all functions. Write N = M·B_d (B_d the Bernstein
basis of degree d, which is TP). Every collocation matrix of N is (collocation matrix of B_d)·M, so if every
minor of M is ≥ 0 on the parameter box, Cauchy–Binet makes every collocation minor ≥ 0, and dividing row i
by D(x_i) > 0 keeps the signs. Each minor of M is a polynomial in the parameters; it is proved ≥ 0 on the
box exactly: factor it; each factor of odd multiplicity must have all its tensor-product Bernstein
coefficients on the box ≥ 0 (or all ≤ 0) — then its sign on the box is constant — and the product of the
signs is ≥ 0.

Refutation: rational parameter values, rational points x_0 < … < x_k, a collocation submatrix (rows
increasing, columns increasing) and its exact negative determinant. A negative value is a 1×1 minor.

  1. GB2 (Han, Ma & Huang 2008), (λ1, λ2) ∈ [−2, 1]²: TP on the whole box (and nowhere outside it)
  2. GB3, λ1 ∈ [−3, 1], λ2 ∈ [−3, 3], λ3 ∈ [−3, 1]: TP on the whole box (and nowhere outside it)
  3. Han–Ma–Huang trigonometric cubic (2009), (λ, μ) ∈ [−2, 1]²: TP on the whole box (and nowhere outside)
  4. the "triangle" quadratic: TP exactly on a, b ≥ 0, a + b ≤ 1
  5. its cubic version (a, b, c) ∈ [0, 1]³: TP exactly where b + c ≤ 1
  6. a constructed two-parameter basis, nonnegative on [0, 2]², TP exactly on [0, 1]²
"""

import itertools
import time

import sympy as sp
from _exact import bernstein_matrix, check, minors, numerator_posden, weierstrass

T0 = time.time()
R = sp.Rational
t, z = sp.symbols("t z", real=True)
l1, l2, l3, l, m, a, b, c = sp.symbols("lambda1 lambda2 lambda3 lambda mu a b c", real=True)


# --------------------------------------------------------------------------- exact tools
def tensor_bernstein(f, xs, box):
    """Tensor-product Bernstein coefficients of the polynomial f(xs) on the box (list of (lo, hi))."""
    us = sp.symbols(f"u0:{len(xs)}")
    g = sp.expand(f.subs({x: lo + (hi - lo) * u for x, u, (lo, hi) in zip(xs, us, box)}, simultaneous=True))
    P = sp.Poly(g, *us)
    deg = [P.degree(u) for u in us]
    A = {mon: co for mon, co in zip(P.monoms(), P.coeffs())}
    out = []
    for J in itertools.product(*[range(d + 1) for d in deg]):
        v = 0
        for I in itertools.product(*[range(j + 1) for j in J]):
            if I in A:
                w = R(1)
                for ik, jk, dk in zip(I, J, deg):
                    w *= R(sp.binomial(jk, ik), sp.binomial(dk, ik))
                v += w * A[I]
        out.append(v)
    return out


def const_sign_on_box(f, xs, box):
    """+1 / −1 if all Bernstein coefficients of f on the box are ≥ 0 / ≤ 0 (proof of f ≥ 0 / f ≤ 0), else 0."""
    bc = tensor_bernstein(f, xs, box)
    if all(v >= 0 for v in bc):
        return 1
    if all(v <= 0 for v in bc):
        return -1
    return 0


def minor_nonneg_on_box(y, xs, box):
    """Exact proof that the polynomial y ≥ 0 on the box (factor by factor); False if not proved."""
    const, facs = sp.factor_list(sp.expand(y), *xs)
    sgn = sp.sign(const)
    for f, e in facs:
        if e % 2 == 0:
            continue
        s_ = const_sign_on_box(f, xs, box)
        if s_ == 0:
            return False
        sgn *= s_
    return sgn >= 0


def certify(N, x, d, xs, box, label):
    """All minors of the degree-d Bernstein coefficient matrix of N are ≥ 0 on the box (exact)."""
    M = bernstein_matrix(N, x, d)
    ms = minors(M)
    bad = [y for y in ms if not minor_nonneg_on_box(y, xs, box)]
    check(not bad, f"{label}: all {len(ms)} nonzero minors of the {M.shape[0]}×{M.shape[1]} Bernstein matrix (degree {d})"
          f" are ≥ 0 on the box ⇒ TP (Cauchy–Binet)")
    return M, ms


def colloc(fs, env, pts, rows=None, cols=None, var=t):
    """Exact collocation matrix (b_j(x_i)) at rational points, parameters env; optional sub-selection."""
    Mx = sp.Matrix([[sp.nsimplify(sp.expand(f.subs(env).subs(var, p))) for f in fs] for p in pts])
    if rows is not None:
        Mx = Mx.extract(rows, cols)
    return Mx


def unity(fs):
    return sp.simplify(sum(fs) - 1) == 0


def near_end_negative(f, x, end, env):
    """f(x) with parameters env is < 0 on a one-sided neighbourhood of `end` inside (0, 1): shown by the leading
    nonzero Taylor coefficient at the end (sign adjusted for the side). Returns a rational witness point too."""
    g = sp.expand(f.subs(env))
    h = sp.Symbol("h", positive=True)
    gh = sp.expand(g.subs(x, end + h) if end == 0 else g.subs(x, end - h))
    P = sp.Poly(gh, h)
    low = min(P.monoms())[0]
    lead = P.coeff_monomial(h**low)
    if lead >= 0:
        return None
    for k in range(1, 60):
        p = R(1, 2**k)
        xv = end + p if end == 0 else end - p
        if g.subs(x, xv) < 0:
            return xv, g.subs(x, xv)
    return None


def show(Mx):
    return "[" + "; ".join(", ".join(str(v) for v in row) for row in Mx.tolist()) + "]"


# =========================================================================================== 1. GB2
print("1. GB2 (Han, Ma & Huang, JCAM 217 (2008) 180–193), t ∈ [0, 1], (λ1, λ2) ∈ [−2, 1]²")
gb2 = [(1 - t)**2 * (1 - l1 * t), t * (1 - t) * (2 + l1 - l1 * t + l2 * t), t**2 * (1 - l2 + l2 * t)]
check(unity(gb2), "partition of unity")
M2 = bernstein_matrix(gb2, t, 3)
exp2 = sp.Matrix([[1, (1 - l1) / 3, 0, 0], [0, (2 + l1) / 3, (2 + l2) / 3, 0], [0, 0, (1 - l2) / 3, 1]])
check(sp.simplify(M2 - exp2) == sp.zeros(3, 4),
      "cubic Bernstein coefficients: b0 = B0 + (1−λ1)/3·B1, b1 = (2+λ1)/3·B1 + (2+λ2)/3·B2, b2 = (1−λ2)/3·B2 + B3")
print("   M =", show(M2), " (bidiagonal: row i supported on columns i, i+1)")
certify(gb2, t, 3, [l1, l2], [(-2, 1), (-2, 1)], "GB2 on [−2, 1]²")
mset2 = set(sp.factor(y) for y in minors(M2))
check(all(all(sp.Poly(f, l1, l2).total_degree() <= 1 for f, _ in sp.factor_list(y, l1, l2)[1]) for y in mset2),
      "  every minor is a constant times a product of the entries 1−λ1, 2+λ1, 2+λ2, 1−λ2 (linear factors)")
print("   Outside the box some function is negative (so the box is the exact TP set in R²):")
gb2_sides = [  # (function index, factorised form, parameter values just outside, end of [0, 1] where it is < 0)
    (0, (1 - t)**2 * ((1 - t) + (1 - l1) * t), {l1: R(11, 10), l2: 0}, 1),
    (1, t * (1 - t) * ((2 + l1) * (1 - t) + (2 + l2) * t), {l1: R(-21, 10), l2: 0}, 0),
    (1, t * (1 - t) * ((2 + l1) * (1 - t) + (2 + l2) * t), {l1: 0, l2: R(-21, 10)}, 1),
    (2, t**2 * ((1 - l2) * (1 - t) + t), {l1: 0, l2: R(11, 10)}, 0),
]
for i, form, env, end in gb2_sides:
    assert sp.expand(gb2[i] - form) == 0
    w = near_end_negative(gb2[i], t, end, env)
    check(w is not None, f"  {env}: b{i} = {form} < 0 near t = {end}; exact 1×1 minor b{i}({w[0]}) = {w[1]}")
print("   (in general λ1 > 1: b0 < 0 on (1/λ1, 1); λ1 < −2: b1 < 0 near 0; λ2 < −2: b1 < 0 near 1; λ2 > 1: b2 < 0 near 0)")

# =========================================================================================== 2. GB3
print()
print("2. GB3, t ∈ [0, 1], λ1 ∈ [−3, 1], λ2 ∈ [−3, 3], λ3 ∈ [−3, 1]")
gb3 = [(1 - t)**3 * (1 - l1 * t), t * (1 - t)**2 * (3 + l1 - l1 * t - l2 * t), t**2 * (1 - t) * (3 + l2 - l2 * t + l3 * t),
       t**3 * (1 - l3 + l3 * t)]
check(unity(gb3), "partition of unity")
M3 = bernstein_matrix(gb3, t, 4)
exp3 = sp.Matrix([[1, (1 - l1) / 4, 0, 0, 0], [0, (3 + l1) / 4, (3 - l2) / 6, 0, 0], [0, 0, (3 + l2) / 6, (3 + l3) / 4, 0],
                  [0, 0, 0, (1 - l3) / 4, 1]])
check(sp.simplify(M3 - exp3) == sp.zeros(4, 5),
      "quartic Bernstein coefficients: b0 = B0 + (1−λ1)/4·B1, b1 = (3+λ1)/4·B1 + (3−λ2)/6·B2, "
      "b2 = (3+λ2)/6·B2 + (3+λ3)/4·B3, b3 = (1−λ3)/4·B3 + B4")
print("   M =", show(M3), " (bidiagonal, all entries ≥ 0 on the box)")
certify(gb3, t, 4, [l1, l2, l3], [(-3, 1), (-3, 3), (-3, 1)], "GB3 on the box")
print("   (TP holds on the three dependence edges too: there some minors are 0, none negative.)")
print("   Outside the box some function is negative:")
gb3_sides = [
    (0, (1 - t)**3 * ((1 - t) + (1 - l1) * t), {l1: R(11, 10), l2: 0, l3: 0}, 1),
    (1, t * (1 - t)**2 * ((3 + l1) * (1 - t) + (3 - l2) * t), {l1: R(-31, 10), l2: 0, l3: 0}, 0),
    (1, t * (1 - t)**2 * ((3 + l1) * (1 - t) + (3 - l2) * t), {l1: 0, l2: R(31, 10), l3: 0}, 1),
    (2, t**2 * (1 - t) * ((3 + l2) * (1 - t) + (3 + l3) * t), {l1: 0, l2: R(-31, 10), l3: 0}, 0),
    (2, t**2 * (1 - t) * ((3 + l2) * (1 - t) + (3 + l3) * t), {l1: 0, l2: 0, l3: R(-31, 10)}, 1),
    (3, t**3 * ((1 - l3) * (1 - t) + t), {l1: 0, l2: 0, l3: R(11, 10)}, 0),
]
for i, form, env, end in gb3_sides:
    assert sp.expand(gb3[i] - form) == 0
    w = near_end_negative(gb3[i], t, end, env)
    check(w is not None, f"  {env}: b{i} = {form} < 0 near t = {end}; b{i}({w[0]}) = {w[1]}")

# =========================================================================================== 3. HMH trig
print()
print("3. Han–Ma–Huang trigonometric cubic (Appl. Math. Lett. 22 (2009) 226–231), t ∈ [0, π/2], (λ, μ) ∈ [−2, 1]²")
s, co = sp.sin(t), sp.cos(t)
hmh = [(1 - s)**2 * (1 - l * s), s * (1 - s) * (2 + l - l * s), co * (1 - co) * (2 + m - m * co), (1 - co)**2 * (1 - m * co)]
Nh = [numerator_posden(weierstrass(f, t, z), z) for f in hmh]
expN = [(1 - z)**4 * (1 + z**2 - 2 * l * z), 2 * z * (1 - z)**2 * ((2 + l) * (1 + z**2) - 2 * l * z),
        4 * z**2 * (1 - z**2) * (1 + (1 + m) * z**2), 4 * z**4 * ((1 - m) + (1 + m) * z**2)]
check(all(sp.expand(p - q) == 0 for p, q in zip(Nh, expN)) and sp.expand(sum(Nh) - (1 + z**2)**3) == 0,
      "z = tan(t/2) ∈ [0, 1] (increasing): b_i = N_i(z)/(1 + z²)³ with N0 = (1−z)⁴(1 + z² − 2λz), "
      "N1 = 2z(1−z)²((2+λ)(1+z²) − 2λz), N2 = 4z²(1−z²)(1 + (1+μ)z²), N3 = 4z⁴((1−μ) + (1+μ)z²); ΣN_i = (1+z²)³")
Mh, msh = certify(Nh, z, 6, [l, m], [(-2, 1), (-2, 1)], "HMH trig on [−2, 1]²")
print("   M (degree 6) =", show(Mh))
check(not all(minor_nonneg_on_box(y, [l, m], [(-2, 2), (-2, 1)]) for y in msh),
      "  control: the same test FAILS on [−2, 2] × [−2, 1] (the entry (1 − λ)/3 changes sign), so it is not vacuous")
import random
import mpmath as mpm
mpm.mp.dps = 40
random.seed(38)
fh = [sp.lambdify((t, l, m), f, "mpmath") for f in hmh]
worst = mpm.mpf(1)
for _ in range(300):
    lv, mv = mpm.mpf(random.uniform(-2, 1)), mpm.mpf(random.uniform(-2, 1))
    xs = sorted(mpm.mpf(random.uniform(0, float(mpm.pi / 2))) for _ in range(4))
    C = mpm.matrix([[f(x, lv, mv) for f in fh] for x in xs])
    for k in range(1, 5):
        for I in itertools.combinations(range(4), k):
            for J in itertools.combinations(range(4), k):
                worst = min(worst, mpm.det(mpm.matrix([[C[i, j] for j in J] for i in I])))
check(worst > -mpm.mpf(10)**-30, f"  mpmath cross-check (not a proof): 300 random (λ, μ, 4 points), all 69 minors each: min = {mpm.nstr(worst, 5)}")
print("   Outside the box (s = sin t, c = cos t): b0 = (1−s)²(1−λs) < 0 for s > 1/λ if λ > 1;")
print("   b1 = s(1−s)((2+λ)(1−s) + 2s) < 0 near s = 0 if λ < −2; b2 = c(1−c)((2+μ)(1−c) + 2c) < 0 near c = 0 if μ < −2;")
print("   b3 = (1−c)²(1−μc) < 0 for c > 1/μ if μ > 1. Exact witnesses (rational sin t, cos t):")
check(sp.expand(hmh[1] - s * (1 - s) * ((2 + l) * (1 - s) + 2 * s)) == 0 and
      sp.expand(hmh[2] - co * (1 - co) * ((2 + m) * (1 - co) + 2 * co)) == 0, "  factorised forms of b1, b2")
SC = {sp.sin(t): R(4, 5), sp.cos(t): R(3, 5)}
wit3 = [(0, {l: 2, m: 0}, SC), (1, {l: -3, m: 0}, {sp.sin(t): R(7, 25), sp.cos(t): R(24, 25)}),
        (2, {l: 0, m: -3}, {sp.sin(t): R(24, 25), sp.cos(t): R(7, 25)}), (3, {l: 0, m: 2}, {sp.sin(t): R(3, 5), sp.cos(t): R(4, 5)})]
for i, env, sc in wit3:
    v = sp.nsimplify(hmh[i].subs(env).subs(sc))
    check(v < 0, f"  {env}, (sin t, cos t) = ({sc[sp.sin(t)]}, {sc[sp.cos(t)]}): b{i} = {v}")

# =========================================================================================== 4. triangle
print()
print("4. 'triangle' quadratic, t ∈ [0, 1]: b0 = (1−t)² + 2a t(1−t), b1 = 2(1−a−b) t(1−t), b2 = t² + 2b t(1−t)")
tri = [(1 - t)**2 + 2 * a * t * (1 - t), 2 * (1 - a - b) * t * (1 - t), t**2 + 2 * b * t * (1 - t)]
check(unity(tri), "partition of unity")
Mt = bernstein_matrix(tri, t, 2)
check(Mt == sp.Matrix([[1, a, 0], [0, 1 - a - b, 0], [0, b, 1]]), "Bernstein matrix M = [1, a, 0; 0, 1−a−b, 0; 0, b, 1]")
mt = set(sp.factor(y) for y in minors(Mt))
check(mt == {sp.Integer(1), a, b, sp.factor(1 - a - b)},
      f"its nonzero minors are exactly {sorted(map(str, mt))}: all ≥ 0 ⇔ a ≥ 0, b ≥ 0, a + b ≤ 1 ⇒ TP on the triangle")
check(sp.factor(tri[0] - (1 - t) * ((1 - t) + 2 * a * t)) == 0 and sp.factor(tri[2] - t * (t + 2 * b * (1 - t))) == 0,
      "b0 = (1−t)((1−t) + 2a t) < 0 near t = 1 if a < 0; b2 = t(t + 2b(1−t)) < 0 near t = 0 if b < 0; "
      "b1 < 0 inside if a + b > 1 ⇒ NOT TP anywhere off the triangle (a negative 1×1 minor)")
for env, i, p, val in [({a: 1, b: 1}, 1, R(1, 2), R(-1, 2)), ({a: R(-1, 2), b: 0}, 0, R(3, 4), R(-1, 8)),
                       ({a: 0, b: R(-1, 2)}, 2, R(1, 4), R(-1, 8))]:
    v = tri[i].subs(env).subs(t, p)
    check(v == val, f"  (a, b) = ({env[a]}, {env[b]}): b{i}({p}) = {v}")

# =========================================================================================== 5. cubic triangle
print()
print("5. cubic version, t ∈ [0, 1]: b0 = B0 + aB1, b1 = (1−a)B1 + cB2, b2 = (1−b−c)B2, b3 = B3 + bB2 (B_i cubic Bernstein)")
B = [(1 - t)**3, 3 * t * (1 - t)**2, 3 * t**2 * (1 - t), t**3]
cub = [B[0] + a * B[1], (1 - a) * B[1] + c * B[2], (1 - b - c) * B[2], B[3] + b * B[2]]
check(unity(cub), "partition of unity")
Mc = bernstein_matrix(cub, t, 3)
print("   M =", show(Mc))
mc = set(sp.factor(y) for y in minors(Mc))
print("   its nonzero minors:", sorted(map(str, mc)))
check(all(all(f in (a, b, c, a - 1, b + c - 1) for f, _ in sp.factor_list(y, a, b, c)[1]) for y in mc),
      "every minor is ± a product of a, b, c, 1−a, 1−b−c")
# on the box [0,1]³ the only sign-changing factor is 1 − b − c; split it off: region b + c ≤ 1
ok = all(minor_nonneg_on_box(y.subs(c, (1 - b) * c), [a, b, c], [(0, 1), (0, 1), (0, 1)]) for y in mc)
check(ok, "all minors ≥ 0 on {0 ≤ a ≤ 1, b ≥ 0, c ≥ 0, b + c ≤ 1} (substituting c = (1 − b)·c', c' ∈ [0, 1], and Bernstein"
      " on [0, 1]³) ⇒ TP there")
check(all(minor_nonneg_on_box(y, [a, b, c], [(0, 1), (0, R(1, 2)), (0, R(1, 2))]) for y in mc),
      "in particular TP on a ∈ [0, 1], b, c ∈ [0, 1/2]")
check(sp.factor(Mc[2, 2]) == sp.factor(1 - b - c),
      "b2 = (1 − b − c)·3t²(1 − t) < 0 inside (0, 1) when b + c > 1 ⇒ inside the box TP ⇔ b + c ≤ 1")
for env, val in [({a: 0, b: 1, c: 1}, R(-3, 8)), ({a: R(1, 2), b: R(1, 2), c: 1}, R(-3, 16))]:
    v = cub[2].subs(env).subs(t, R(1, 2))
    check(v == val, f"  (a, b, c) = ({env[a]}, {env[b]}, {env[c]}): b2(1/2) = {v}")
print("   (off the box, in R³: a < 0 ⇒ b0 < 0 near 1; a > 1 ⇒ b1 < 0 near 0; c < 0 ⇒ b1 < 0 near 1; b < 0 ⇒ b3 < 0 near 0;")
print("   so the exact TP set in R³ is {0 ≤ a ≤ 1, b ≥ 0, c ≥ 0, b + c ≤ 1})")
for i, env, end in [(0, {a: R(-1, 10), b: 0, c: 0}, 1), (1, {a: R(11, 10), b: 0, c: 0}, 0), (1, {a: 0, b: 0, c: R(-1, 10)}, 1),
                    (3, {a: 0, b: R(-1, 10), c: 0}, 0)]:
    w = near_end_negative(cub[i], t, end, env)
    check(w is not None, f"  {env}: b{i}({w[0]}) = {w[1]}")

# =========================================================================================== 6. constructed
print()
print("6. CONSTRUCTED: nonnegative on its whole box, not TP on part of it. t ∈ [0, 1], (lambda, mu) ∈ [0, 2]²:")
print('   b0 = "(1 - t)^2*(1 - lambda*t)^2"')
print('   b1 = "1 - (1 - t)^2*(1 - lambda*t)^2 - t^2*(1 - mu*(1 - t))^2"')
print('   b2 = "t^2*(1 - mu*(1 - t))^2"')
q0 = (1 - t)**2 * (1 - l * t)**2
q2 = t**2 * (1 - m * (1 - t))**2
q1 = 1 - q0 - q2
cons = [q0, q1, q2]
Q = 2 + 2 * l * (1 - t) + 2 * m * t - (l**2 + m**2) * t * (1 - t)
check(sp.expand(q1 - t * (1 - t) * Q) == 0, "b1 = t(1−t)·Q, Q = 2 + 2λ(1−t) + 2μt − (λ² + μ²)t(1−t)")
check(sp.expand(Q - ((2 + 2 * l) * (1 - t)**2 + (6 - (l - 1)**2 - (m - 1)**2) * t * (1 - t) + (2 + 2 * m) * t**2)) == 0,
      "Q = (2+2λ)(1−t)² + (6 − (λ−1)² − (μ−1)²)·t(1−t) + (2+2μ)t²: on [0, 2]² the three coefficients are ≥ 2, ≥ 4, ≥ 2")
check(all(const_sign_on_box(f, [l, m], [(0, 2), (0, 2)]) == 1
          for f in (2 + 2 * l, 6 - (l - 1)**2 - (m - 1)**2, 2 + 2 * m)),
      "  (Bernstein-certified) ⇒ Q > 0 on [0,1]×[0,2]², so b1 ≥ 0; b0, b2 are squares: NONNEGATIVE on the whole box")
check(all(sp.expand(cons[i].subs({t: 1 - t, l: m, m: l}, simultaneous=True) - cons[2 - i]) == 0 for i in range(3)),
      "symmetry b_i(t; λ, μ) = b_{2−i}(1 − t; μ, λ)")
Mq, _ = certify(cons, t, 4, [l, m], [(0, 1), (0, 1)], "on [0, 1]²")
print("   M (degree 4) =", show(Mq))
# refutation: λ ∈ (1, 2]: b0 has a double zero at t1 = 1/λ ∈ (0, 1)
t2 = (1 / l + 1) / 2
check(q0.subs(t, 1 / l) == 0 and sp.factor(q0.subs(t, t2) - ((l - 1) / (2 * l))**2 * ((1 - l) / 2)**2) == 0,
      "λ > 1: b0(1/λ) = 0 and b0(t2) = ((λ−1)/(2λ))²((λ−1)/2)² > 0 at t2 = (1/λ + 1)/2 > 1/λ")
print("   with b1(t1) = t1(1−t1)Q > 0 at t1 = 1/λ: det[[b0(t1), b1(t1)], [b0(t2), b1(t2)]] = −b1(t1)·b0(t2) < 0 (every μ ∈ [0, 2]);")
check(q2.subs(t, 1 - 1 / m) == 0, "μ > 1 mirrors it: b2(1 − 1/μ) = 0, so columns (b1, b2) at t0 < 1 − 1/μ give −b2(t0)·b1(1 − 1/μ) < 0")
print("   ⇒ inside [0, 2]² TP holds EXACTLY on [0, 1]² (nonnegativity on all of [0, 2]²).")
for env, pts, val in [({l: 2, m: 0}, [R(1, 2), R(3, 4)], R(-3, 256)), ({l: 2, m: 2}, [R(1, 2), R(3, 4)], R(-1, 64)),
                      ({l: R(3, 2), m: 1}, [R(2, 3), R(5, 6)], None)]:
    C = colloc(cons, env, pts, [0, 1], [0, 1])
    d = C.det()
    check(d < 0 and (val is None or d == val),
          f"  (λ, μ) = ({env[l]}, {env[m]}), t = {pts[0]} < {pts[1]}, columns (b0, b1): {show(C)}, det = {d}")
C = colloc(cons, {l: 0, m: 2}, [R(1, 4), R(1, 2)], [0, 1], [1, 2])
check(C.det() == R(-3, 256), f"  mirror (λ, μ) = (0, 2), t = 1/4 < 1/2, columns (b1, b2): {show(C)}, det = {C.det()}")
C3 = colloc(cons, {l: 2, m: 0}, [R(1, 4), R(1, 2), R(3, 4)])
print(f"  full 3×3 collocation matrix at (2, 0), t = 1/4, 1/2, 3/4: {show(C3)} (det {C3.det()}; its minor on rows t = 1/2, 3/4 and columns b0, b1 is −3/256)")
assert all(v >= 0 for v in C3) and C3.extract([1, 2], [0, 1]).det() < 0

print(f"done in {time.time() - T0:.1f} s")
