"""Issue 38, part 4: total positivity on parameter-dependent domains [0, α] by consecutive Wronskians.

Derived independently (SymPy / mpmath); the Rust crates were not read. Every printed statement marked [ok]
is asserted.

TP: every collocation matrix (b_j(x_i)), x_0 < … < x_m in [0, α], has all minors ≥ 0.
Criterion (Karlin; Carnicer–Mainar–Peña, Constr. Approx. 20 (2004)): if every Wronskian of CONSECUTIVE
functions W(b_j, …, b_l)(t) > 0 for all t in the OPEN interval (0, α), the system is strictly TP on (0, α),
hence TP on [0, α]. Refutation: a negative collocation minor (a negative value is a 1×1 minor).

Method. Each basis is written as b = C·f over a fixed spanning system f (1, t, cos t, sin t / 1, t, cosh t,
sinh t); then W(b_S) = Σ_T det C[S, T] · W(f_T) (Cauchy–Binet for the derivative matrix), and each of these
is proved equal to a short closed form by an exact identity (sin/cos reduced modulo s² + c² = 1,
sinh/cosh through exp). Signs of the closed forms are proved by hand-checkable factorisations that are
themselves asserted as identities. End behaviour: the h-derivatives of W at t = h (left end) and at
t = α − h (right end), h → 0, are computed exactly; the first one not identically 0 in α gives the order
and the leading coefficient (positive ⇔ W > 0 next to that end). The t-derivative at the right end is
(−1)^k times the h-derivative.

  1. cubic C-Bézier, span{1, t, sin t, cos t} on [0, α]          (examples/c-bezier-cubic.toml)
  2. cubic H-Bézier, span{1, t, sinh t, cosh t} on [0, α]        (examples/h-bezier-cubic.toml)
  3. quadratic trigonometric Bernstein (Sánchez-Reyes 1998) on [0, α]
  4. quadratic C-Bézier span{1, cos t, sin t} (c-bezier-quadratic.toml) and its α = π/2 instance
     (trig-bbasis-half-angle.toml)
  5. exponential Bernstein, span{1, e^t, e^2t, e^3t} on [0, α]   (examples/exp-bernstein-cubic.toml)
"""

import itertools
import random
import time

import mpmath as mpm
import sympy as sp
from _exact import check, hyp_zero, iv_digits, iv_sign, root_enclosure, trig_zero

T0 = time.time()
R = sp.Rational
t, a, h = sp.symbols("t alpha h", real=True)
x, y = sp.symbols("x y", real=True)  # half angles for basis 4: t = 2x, α = 2y
Ct, St = sp.symbols("Ct St")
pi = sp.pi


# --------------------------------------------------------------------------- tools
def wronskian(fs, var=t):
    n = len(fs)
    return sp.Matrix(n, n, lambda i, j: sp.diff(fs[j], var, i)).det()


def runs(n):
    """Consecutive runs (j, l), 0 ≤ j ≤ l ≤ n, by length."""
    return [(j, j + k - 1) for k in range(1, n + 2) for j in range(0, n + 2 - k)]


def name(r):
    return "W(" + ", ".join(f"b{i}" for i in range(r[0], r[1] + 1)) + ")"


def coeff_matrix(bs, cf, sf):
    """Rows: coefficients of b_i over (1, t, cf, sf); b_i must be linear in t, cf, sf after expand_trig."""
    rows = []
    for b in bs:
        e = sp.expand(sp.expand_trig(b)).subs({cf: Ct, sf: St})
        P = sp.Poly(e, t, Ct, St)
        assert P.total_degree() <= 1, b
        rows.append([P.coeff_monomial(m) for m in (1, t, Ct, St)])
    return sp.Matrix(rows)


def cauchy_binet_wronskians(C, f, scale, par_atoms):
    """W(b_S) for b_i = scale_i·(C·f)_i: Π scale_S · Σ_T det C[S, T]·W(f_T). The entries of C are polynomials in α and
    par_atoms (e.g. sin α, cos α), replaced by plain symbols while the minors are expanded."""
    m = len(f)
    P = [sp.Symbol(f"P{i}") for i in range(len(par_atoms))]
    Cs = C.subs(dict(zip(par_atoms, P)))
    back = dict(zip(P, par_atoms))
    Wf = {T: wronskian([f[i] for i in T]) for k in range(1, m + 1) for T in itertools.combinations(range(m), k)}
    out = {}
    for j, l in runs(C.rows - 1):
        S = list(range(j, l + 1))
        sc = sp.Mul(*[scale[i] for i in S])
        tot = sum(sp.expand(Cs.extract(S, list(T)).det(method="berkowitz")).subs(back) * Wf[T]
                  for T in itertools.combinations(range(m), len(S)))
        out[(j, l)] = sc * tot
    return out


def end_data(W, zero, right=a, maxk=8):
    """[(order, leading h-derivative) at t = 0 + h, (order, leading h-derivative) at t = right − h]."""
    res = []
    for end in (0, right):
        e = W.subs(t, h) if end == 0 else W.subs(t, right - h)
        for k in range(maxk + 1):
            d = sp.diff(e, h, k).subs(h, 0)
            if not zero(d):
                break
        else:
            raise AssertionError("vanishes to order > maxk")
        res.append((k, d))
    return res


def check_ends(label, Ws, zero, expected, n, right=a):
    """expected[(j, l)] = ((k0, lead0), (kα, leadα)); orders must also be the generic k·j and k·(n − l)."""
    print(f"   end behaviour of {label} (order in t, leading coefficient L of h^order/order!, h = distance from the end):")
    for r, W in Ws.items():
        (k0, d0), (k1, d1) = end_data(W, zero, right)
        (e0, L0), (e1, L1) = expected[r]
        k = r[1] - r[0] + 1
        ok = (k0, k1) == (e0, e1) == (k * r[0], k * (n - r[1])) and zero(d0 - L0) and zero(d1 - L1)
        check(ok, f"  {name(r)}: at t = 0 order {k0}, L = {L0};  at t = {right} order {k1}, L = {L1}"
                  f"  [t-derivative there: (−1)^{k1}·L]")


def iv_positive(f, dps=50):
    """Certified f > 0 for f built from mpmath.iv operations (outward rounding)."""
    from mpmath import iv

    iv.dps = dps
    v = f(iv)
    return v.a > 0


def spot(forms, alphas, fracs, sign=1):
    """Certified (interval arithmetic) sign of every form at α in alphas, t = f·α for f in fracs."""
    return all(iv_sign(F, {a: av, t: fr * av}) == sign for F in forms for av in alphas for fr in fracs)


def show(M):
    return "[" + "; ".join(", ".join(str(v) for v in row) for row in M.tolist()) + "]"


def mp_colloc_min(fs, env, lo, hi, npts, trials, seed, dps=50):
    """mpmath cross-check (NOT a proof): min over random increasing point sets of all collocation minors."""
    mpm.mp.dps = dps
    random.seed(seed)
    fl = [sp.lambdify(t, f.subs(env), "mpmath") for f in fs]
    lo, hi = mpm.mpf(str(sp.N(lo, dps + 5))), mpm.mpf(str(sp.N(hi, dps + 5)))
    worst = mpm.mpf(10)
    n = len(fs)
    for _ in range(trials):
        xs = sorted(lo + (hi - lo) * mpm.mpf(random.random()) for _ in range(npts))
        Cm = mpm.matrix([[g(xx) for g in fl] for xx in xs])
        for k in range(1, min(npts, n) + 1):
            for I in itertools.combinations(range(npts), k):
                for J in itertools.combinations(range(n), k):
                    worst = min(worst, mpm.det(mpm.matrix([[Cm[i, j] for j in J] for i in I])))
    return worst


tz = lambda e: trig_zero(e, [t, a])  # noqa: E731
tza = lambda e: trig_zero(e, [a])  # noqa: E731
def exp_zero(expr, xs):
    """e ≡ 0: sinh z, cosh z -> (e^z ∓ e^−z)/2, each exp(c0 + Σ c_i x_i) -> e^c0·Π X_i^c_i (X_i = e^{x_i}); the numerator must
    expand to 0 in Q(x, X). (Like _exact.hyp_zero, but without rewriting powers such as α² into exp(2 log α).)"""
    e = sp.sympify(expr).replace(sp.sinh, lambda z: (sp.exp(z) - sp.exp(-z)) / 2)
    e = e.replace(sp.cosh, lambda z: (sp.exp(z) + sp.exp(-z)) / 2)
    Xs = {v: sp.Symbol(f"X_{v}", positive=True) for v in xs}
    reps = {}
    for ex in e.atoms(sp.exp):
        P = sp.Poly(sp.expand(ex.args[0]), *xs)
        assert P.total_degree() <= 1, ex
        val = sp.exp(P.coeff_monomial(1))
        for v in xs:
            val *= Xs[v] ** P.coeff_monomial(v)
        reps[ex] = val
    e = e.xreplace(reps)
    num, _den = sp.fraction(sp.together(e))
    return sp.expand(num) == 0


hz = lambda e: exp_zero(e, [t, a])  # noqa: E731
hza = lambda e: exp_zero(e, [a])  # noqa: E731

# =========================================================================================== 1. C-Bézier cubic
print("1. cubic C-Bézier, span{1, t, sin t, cos t} on [0, α] (examples/c-bezier-cubic.toml)")
s = a - t  # the mirrored variable
A = a - sp.sin(a)
c = 1 - sp.cos(a)
g = 2 - 2 * sp.cos(a) - a * sp.sin(a)
D = c**2 / (A**2 * g)
G = lambda u: 2 - 2 * sp.cos(u) - u * sp.sin(u)  # noqa: E731
Nf = lambda u: A * (1 - sp.cos(u)) - c * (u - sp.sin(u))  # noqa: E731
cb = [(a - t - sp.sin(a - t)) / A, c * Nf(a - t) / (A * g), c * Nf(t) / (A * g), (t - sp.sin(t)) / A]
print("   A = α − sin α, c = 1 − cos α, g = 2 − 2cos α − α sin α = G(α), G(τ) = 2 − 2cos τ − τ sin τ,")
print("   N(τ) = A(1 − cos τ) − c(τ − sin τ), D = c²/(A²g), s = α − t")
check(tz(sum(cb) - 1), "unity Σ b_i = 1")
check(all(tz(cb[i].subs(t, a - t) - cb[3 - i]) for i in range(4)), "symmetry b_i(t) = b_{3−i}(α − t)")
sc_cb = [1 / A, c / (A * g), c / (A * g), 1 / A]
pc = [a - t - sp.sin(a - t), Nf(a - t), Nf(t), t - sp.sin(t)]
check(all(sp.simplify(cb[i] - sc_cb[i] * pc[i]) == 0 for i in range(4)), "b = (1/A, c/(Ag), c/(Ag), 1/A)·(s − sin s, N(s), N(t), t − sin t)")
Ccb = coeff_matrix(pc, sp.cos(t), sp.sin(t))
check(all(tz(pc[i] - (Ccb[i, 0] + Ccb[i, 1] * t + Ccb[i, 2] * sp.cos(t) + Ccb[i, 3] * sp.sin(t))) for i in range(4)),
      "these numerators = C·(1, t, cos t, sin t), C(α) a 4×4 matrix polynomial in α, sin α, cos α")
check(sp.simplify(wronskian([1, t, sp.cos(t), sp.sin(t)])) == 1, "W(1, t, cos t, sin t) = 1")
Wcb = cauchy_binet_wronskians(Ccb, [sp.Integer(1), t, sp.cos(t), sp.sin(t)], sc_cb, [sp.sin(a), sp.cos(a)])
H = (t - sp.sin(t)) * (1 - sp.cos(s)) + (s - sp.sin(s)) * (1 - sp.cos(t))
closed_cb = {
    (0, 0): ((s - sp.sin(s)) / A, "(s − sin s)/A"),
    (1, 1): (c * Nf(s) / (A * g), "c·N(s)/(A g)"),
    (2, 2): (c * Nf(t) / (A * g), "c·N(t)/(A g)"),
    (3, 3): ((t - sp.sin(t)) / A, "(t − sin t)/A"),
    (0, 1): (c * G(s) / (A * g), "c·G(s)/(A g)"),
    (1, 2): (D * H, "D·[(t − sin t)(1 − cos s) + (s − sin s)(1 − cos t)]"),
    (2, 3): (c * G(t) / (A * g), "c·G(t)/(A g)"),
    (0, 2): (D * (s - sp.sin(s)), "D·(s − sin s)"),
    (1, 3): (D * (t - sp.sin(t)), "D·(t − sin t)"),
    (0, 3): (D, "D = (1 − cos α)²/((α − sin α)²(2 − 2cos α − α sin α))"),
}
print("   Consecutive Wronskians (Cauchy–Binet over C, each proved equal to the closed form):")
for r in runs(3):
    check(tz(Wcb[r] - closed_cb[r][0]), f"  {name(r)} = {closed_cb[r][1]}")
# The 2-Wronskian W(b1, b2) also written out in t, α:
check(tz(H - (a + sp.sin(a) - sp.sin(t) - sp.sin(s) - t * sp.cos(s) - s * sp.cos(t))),
      "  (the bracket of W(b1, b2) = α + sin α − sin t − sin(α − t) − t cos(α − t) − (α − t) cos t; symmetric in t ↔ α − t)")
check(tz(Wcb[(1, 2)] * A**2 * g / c**2 - ((a + sp.sin(a)) * (1 - sp.cos(t)) - c * (sp.sin(t) - t * sp.cos(t))
                                           - t * sp.sin(a) * sp.sin(t))),
      "  equivalently W(b1, b2) = D·[(α + sin α)(1 − cos t) − (1 − cos α)(sin t − t cos t) − t sin α sin t]")

print("   Signs (exact arguments, the identities asserted):")
hh = lambda u: 2 * sp.sin(u / 2) - u * sp.cos(u / 2)  # noqa: E731
u_ = sp.Symbol("u", real=True)
check(trig_zero((G(u_) - 2 * sp.sin(u_ / 2) * hh(u_)).subs(u_, 2 * x), [x])
      and sp.simplify(sp.diff(hh(u_), u_) - u_ / 2 * sp.sin(u_ / 2)) == 0 and hh(u_).subs(u_, 0) == 0,
      "  G(τ) = 2 sin(τ/2)·h(τ), h(τ) = 2 sin(τ/2) − τ cos(τ/2), h(0) = 0, h'(τ) = (τ/2) sin(τ/2) > 0 on (0, 2π) "
      "⇒ G > 0 on (0, 2π)")
check(sp.simplify(sp.diff(a - sp.sin(a), a) - (1 - sp.cos(a))) == 0 and trig_zero((c - 2 * sp.sin(a / 2)**2).subs(a, 2 * y), [y]),
      "  A = α − sin α > 0 (A(0) = 0, A' = 1 − cos α ≥ 0, = 0 only at isolated points); c = 2 sin²(α/2) > 0 on (0, 2π); "
      "g = G(α) > 0 on (0, 2π) ⇒ D > 0")
phi = (u_ - sp.sin(u_)) / (1 - sp.cos(u_))
check(tz(Nf(t) - (1 - sp.cos(t)) * c * (phi.subs(u_, a) - phi.subs(u_, t)))
      and trig_zero(sp.diff(phi, u_) - G(u_) / (1 - sp.cos(u_))**2, [u_]),
      "  N(τ) = (1 − cos τ)(1 − cos α)(φ(α) − φ(τ)), φ(τ) = (τ − sin τ)/(1 − cos τ), φ' = G/(1 − cos τ)² > 0 on (0, 2π) "
      "⇒ N(τ) > 0 for τ ∈ (0, α)")
print("   ⇒ for every α ∈ (0, 2π) and t ∈ (0, α) (so t, s ∈ (0, 2π)): b0, b3 > 0 (τ − sin τ > 0); b1, b2 > 0 (N > 0);")
print("     W(b0,b1), W(b2,b3) > 0 (G > 0); W(b1,b2) = D·[(t − sin t)(1 − cos s) + (s − sin s)(1 − cos t)] > 0 (both terms ≥ 0,")
print("     not both 0 as cos t = 1 = cos s is impossible); W(b0,b1,b2), W(b1,b2,b3), W(b0..b3) > 0 (D > 0).")
check(spot([closed_cb[r][0] for r in runs(3)], [R(1, 100), R(1, 2), R(3), R(31, 10), R(6), R(157, 25)], [R(1, 100), R(1, 2), R(99, 100)]),
      "  ALL 10 consecutive Wronskians are > 0 on (0, α) for EVERY α ∈ (0, 2π) ⇒ strictly TP on (0, α), TP on [0, α]"
      " (certified spot values > 0 at α ∈ {1/100, 1/2, 3, 31/10, 6, 157/25}, t/α ∈ {1/100, 1/2, 99/100})")
check(R(3) < pi and R(31, 10) < pi and pi < 2 * pi,
      "  (a) yes for every α ∈ [1/2, 3] and for every α ∈ [1/2, 3.1] (both inside (0, 2π)); the spec range (0, π) is not maximal")
# certified spot values (interval arithmetic), a cross-check of signs at α = 31/10, t = α/3
spot_ok = all(iv_sign(closed_cb[r][0], {a: R(31, 10), t: R(31, 30)}) == 1 for r in runs(3))
check(spot_ok, "  interval-arithmetic cross-check: all 10 closed forms > 0 at α = 31/10, t = 31/30")
# limit α → 2π: the basis degenerates
eps = sp.Symbol("epsilon", positive=True)
lim_cg = sp.limit((c / g).subs(a, 2 * pi - eps), eps, 0)
lim_D = sp.limit(D.subs(a, 2 * pi - eps), eps, 0)
check(lim_cg == 0 and lim_D == 0 and sp.simplify(g.subs(a, 2 * pi)) == 0 and c.subs(a, 2 * pi) == 0,
      "  (b) α* = 2π exactly: at α = 2π, c = g = 0 (b1, b2 are 0/0); as α → 2π⁻, c/g → 0 so b1, b2 → 0 and "
      "D = W(b0..b3) → 0 (the limit system b0 + b3 = 1 has rank 2)")
print("   (c) (α*, 2π) is empty. Beyond 2π the formulas stop being nonnegative (so not TP):")
v1 = sp.nsimplify(sp.simplify(cb[2].subs({a: 5 * pi / 2, t: pi / 2})))
check(sp.simplify(v1 + 8 * pi / ((5 * pi - 2) * (5 * pi - 4))) == 0 and v1 < 0,
      f"  α = 5π/2, t = π/2: b2 = {v1} = −8π/((5π − 2)(5π − 4)) < 0 (exact; 1×1 minor)")
v2 = sp.simplify(cb[1].subs({a: 3 * pi, t: pi}))
check(v2 == R(-2, 3), f"  α = 3π, t = π: b1 = {v2} (exact)")
mpm.mp.dps = 100  # iv_digits converts the interval ends with mpmath.mpf: keep the working precision high
val = iv_digits(cb[2], {a: R(13, 2), t: 1}, digits=50, dps=90)
check(iv_sign(cb[2], {a: R(13, 2), t: 1}) == -1,
      f"  α = 13/2 (rational, in (2π, α1)), t = 1: b2 = {val}  (numeric, mpmath interval arithmetic, 50 certified digits)")
hal = 2 * sp.sin(a / 2) - a * sp.cos(a / 2)
root_enclosure(hal, a, R(898681891581, 10**11), R(898681891582, 10**11))
check(iv_sign(g, {a: R(13, 2)}) == -1 and iv_sign(g, {a: R(898681891581, 10**11)}) == -1 and iv_sign(g, {a: 9}) == 1
      and iv_sign(hal, {a: 2 * pi}) == 1,
      "  g = 2 sin(α/2)·h(α) < 0 on (2π, α1) (sin(α/2) < 0, h(2π) = 2π, h' < 0), α1 ∈ (8.98681891581, 8.98681891582) the root of tan(α/2) = α/2 "
            "(certified sign change of h); there b2 ~ c t²/(2g) < 0 near t = 0; at α1 the formulas are undefined")

closed_cb_ends = {
    (0, 0): ((0, 1), (3, 1 / A)),
    (1, 1): ((1, c / A), (2, c / g)),
    (2, 2): ((2, c / g), (1, c / A)),
    (3, 3): ((3, 1 / A), (0, 1)),
    (0, 1): ((0, c / A), (4, 2 * c / (A * g))),
    (1, 2): ((2, c**2 / (A * g)), (2, c**2 / (A * g))),
    (2, 3): ((4, 2 * c / (A * g)), (0, c / A)),
    (0, 2): ((0, c**2 / (A * g)), (3, D)),
    (1, 3): ((3, D), (0, c**2 / (A * g))),
    (0, 3): ((0, D), (0, D)),
}
check_ends("C-Bézier", {r: closed_cb[r][0] for r in runs(3)}, tza, closed_cb_ends, 3)
print("   every leading coefficient is a product of powers of c, A, g > 0: positive for α ∈ (0, 2π)")
print("   degenerate parameters: α = 0 (domain), α = 2π (c = g = 0, basis undefined, limit rank 2); no consecutive")
print("   Wronskian vanishes identically for α ∈ (0, 2π). Outside: g = 0 at α1 ≈ 8.98681891582 (formulas undefined).")
for av in (R(1, 2), R(3), R(31, 10), R(6), R(25, 4)):
    w = mp_colloc_min(cb, {a: av}, 0, av, 4, 15, 7)
    check(w > -mpm.mpf(10)**-40, f"  mpmath cross-check (not a proof), α = {av}: min of all collocation minors over "
                                  f"15 random 4-point sets = {mpm.nstr(w, 5)}")

# =========================================================================================== 2. H-Bézier cubic
print()
print("2. cubic H-Bézier, span{1, t, sinh t, cosh t} on [0, α] (examples/h-bezier-cubic.toml)")
Ah = sp.sinh(a) - a
ch = sp.cosh(a) - 1
gh = a * sp.sinh(a) - 2 * sp.cosh(a) + 2
Dh = ch**2 / (Ah**2 * gh)
Gh = lambda u: u * sp.sinh(u) - 2 * sp.cosh(u) + 2  # noqa: E731
Nh = lambda u: Ah * (sp.cosh(u) - 1) - ch * (sp.sinh(u) - u)  # noqa: E731
hb = [(sp.sinh(a - t) - (a - t)) / Ah, ch * Nh(a - t) / (Ah * gh), ch * Nh(t) / (Ah * gh), (sp.sinh(t) - t) / Ah]
print("   A = sinh α − α, c = cosh α − 1, g = α sinh α − 2cosh α + 2 = G(α), G(τ) = τ sinh τ − 2cosh τ + 2,")
print("   N(τ) = A(cosh τ − 1) − c(sinh τ − τ), D = c²/(A²g), s = α − t")
check(hz(sum(hb) - 1), "unity")
check(all(hz(hb[i].subs(t, a - t) - hb[3 - i]) for i in range(4)), "symmetry b_i(t) = b_{3−i}(α − t)")
sc_hb = [1 / Ah, ch / (Ah * gh), ch / (Ah * gh), 1 / Ah]
ph = [sp.sinh(a - t) - (a - t), Nh(a - t), Nh(t), sp.sinh(t) - t]
check(all(sp.simplify(hb[i] - sc_hb[i] * ph[i]) == 0 for i in range(4)), "b = (1/A, c/(Ag), c/(Ag), 1/A)·(sinh s − s, N(s), N(t), sinh t − t)")
Chb = coeff_matrix(ph, sp.cosh(t), sp.sinh(t))
check(all(hz(ph[i] - (Chb[i, 0] + Chb[i, 1] * t + Chb[i, 2] * sp.cosh(t) + Chb[i, 3] * sp.sinh(t))) for i in range(4)),
      "these numerators = C·(1, t, cosh t, sinh t)")
check(hz(wronskian([1, t, sp.cosh(t), sp.sinh(t)]) - 1), "W(1, t, cosh t, sinh t) = 1")
Whb = cauchy_binet_wronskians(Chb, [sp.Integer(1), t, sp.cosh(t), sp.sinh(t)], sc_hb, [sp.sinh(a), sp.cosh(a)])
Hh = (sp.sinh(t) - t) * (sp.cosh(s) - 1) + (sp.sinh(s) - s) * (sp.cosh(t) - 1)
closed_hb = {
    (0, 0): ((sp.sinh(s) - s) / Ah, "(sinh s − s)/A"),
    (1, 1): (ch * Nh(s) / (Ah * gh), "c·N(s)/(A g)"),
    (2, 2): (ch * Nh(t) / (Ah * gh), "c·N(t)/(A g)"),
    (3, 3): ((sp.sinh(t) - t) / Ah, "(sinh t − t)/A"),
    (0, 1): (ch * Gh(s) / (Ah * gh), "c·G(s)/(A g)"),
    (1, 2): (Dh * Hh, "D·[(sinh t − t)(cosh s − 1) + (sinh s − s)(cosh t − 1)]"),
    (2, 3): (ch * Gh(t) / (Ah * gh), "c·G(t)/(A g)"),
    (0, 2): (Dh * (sp.sinh(s) - s), "D·(sinh s − s)"),
    (1, 3): (Dh * (sp.sinh(t) - t), "D·(sinh t − t)"),
    (0, 3): (Dh, "D = (cosh α − 1)²/((sinh α − α)²(α sinh α − 2cosh α + 2))"),
}
print("   Consecutive Wronskians:")
for r in runs(3):
    check(hz(Whb[r] - closed_hb[r][0]), f"  {name(r)} = {closed_hb[r][1]}")
hhh = lambda u: u * sp.cosh(u / 2) - 2 * sp.sinh(u / 2)  # noqa: E731
check(hyp_zero((Gh(u_) - 2 * sp.sinh(u_ / 2) * hhh(u_)), [u_]) and hyp_zero(sp.diff(hhh(u_), u_) - u_ / 2 * sp.sinh(u_ / 2), [u_])
      and hhh(u_).subs(u_, 0) == 0,
      "  G(τ) = 2 sinh(τ/2)·(τ cosh(τ/2) − 2 sinh(τ/2)), the bracket is 0 at 0 with derivative (τ/2) sinh(τ/2) > 0 "
      "⇒ G > 0 for τ > 0; c > 0, A > 0 (A' = cosh α − 1 > 0), g = G(α) > 0 ⇒ D > 0")
phih = (sp.sinh(u_) - u_) / (sp.cosh(u_) - 1)
check(hz(Nh(t) - (sp.cosh(t) - 1) * ch * (phih.subs(u_, a) - phih.subs(u_, t)))
      and hyp_zero(sp.diff(phih, u_) - Gh(u_) / (sp.cosh(u_) - 1)**2, [u_]),
      "  N(τ) = (cosh τ − 1)(cosh α − 1)(ψ(α) − ψ(τ)), ψ = (sinh τ − τ)/(cosh τ − 1), ψ' = G/(cosh τ − 1)² > 0 ⇒ N > 0 on (0, α)")
check(spot([closed_hb[r][0] for r in runs(3)], [R(1, 100), R(1), R(3), R(10)], [R(1, 100), R(1, 2), R(99, 100)]),
      "  ALL 10 consecutive Wronskians are > 0 on (0, α) for EVERY α > 0 (so on the spec range (0, 3]); "
      "α* = +∞ (sup of the set; no finite bound); TP for every α > 0 (certified spot values > 0 at α ∈ {1/100, 1, 3, 10}, "
      "t/α ∈ {1/100, 1/2, 99/100})")
closed_hb_ends = {
    (0, 0): ((0, 1), (3, 1 / Ah)),
    (1, 1): ((1, ch / Ah), (2, ch / gh)),
    (2, 2): ((2, ch / gh), (1, ch / Ah)),
    (3, 3): ((3, 1 / Ah), (0, 1)),
    (0, 1): ((0, ch / Ah), (4, 2 * ch / (Ah * gh))),
    (1, 2): ((2, ch**2 / (Ah * gh)), (2, ch**2 / (Ah * gh))),
    (2, 3): ((4, 2 * ch / (Ah * gh)), (0, ch / Ah)),
    (0, 2): ((0, ch**2 / (Ah * gh)), (3, Dh)),
    (1, 3): ((3, Dh), (0, ch**2 / (Ah * gh))),
    (0, 3): ((0, Dh), (0, Dh)),
}
check_ends("H-Bézier", {r: closed_hb[r][0] for r in runs(3)}, hza, closed_hb_ends, 3)
print("   degenerate parameters: only α = 0 (domain; A = c = g = 0); no Wronskian vanishes identically for α > 0")
w = mp_colloc_min(hb, {a: R(3)}, 0, 3, 4, 40, 8)
check(w > -mpm.mpf(10)**-40, f"  mpmath cross-check (not a proof), α = 3: min collocation minor over 40 random 4-point sets = {mpm.nstr(w, 5)}")

# =========================================================================================== 3. trig Bernstein quadratic
print()
print("3. quadratic trigonometric Bernstein (Sánchez-Reyes, CAGD 15 (1998)) on [0, α], α ∈ (0, π)")
sa = sp.sin(a)
tb = [sp.sin(a - t)**2 / sa**2, 2 * sp.cos(a) * sp.sin(a - t) * sp.sin(t) / sa**2, sp.sin(t)**2 / sa**2]
check(tz(sum(tb) - 1), "unity: sin²(α−t) + 2cos α sin(α−t) sin t + sin²t = sin²α")
closed_tb = {
    (0, 0): (tb[0], "sin²(α−t)/sin²α"),
    (1, 1): (tb[1], "2cos α sin(α−t) sin t/sin²α"),
    (2, 2): (tb[2], "sin²t/sin²α"),
    (0, 1): (2 * sp.cos(a) * sp.sin(a - t)**2 / sa**3, "2cos α sin²(α−t)/sin³α"),
    (1, 2): (2 * sp.cos(a) * sp.sin(t)**2 / sa**3, "2cos α sin²t/sin³α"),
    (0, 2): (4 * sp.cos(a) / sa**3, "4cos α/sin³α"),
}
for r in runs(2):
    check(tz(wronskian(tb[r[0]:r[1] + 1]) - closed_tb[r][0]), f"  {name(r)} = {closed_tb[r][1]}")
print("   On (0, α) ⊂ (0, π): sin t, sin(α − t), sin α > 0, so b0, b2 > 0 and the other five have the sign of cos α:")
check(spot([closed_tb[r][0] for r in runs(2)], [R(1, 100), R(1), R(157, 100)], [R(1, 100), R(1, 2), R(99, 100)])
      and spot([closed_tb[r][0] for r in [(1, 1), (0, 1), (1, 2), (0, 2)]], [R(158, 100), R(2), R(314, 100)], [R(1, 100), R(1, 2), R(99, 100)], -1),
      "  all consecutive Wronskians > 0 on (0, α) ⇔ α ∈ (0, π/2) ⇒ TP there (certified spot signs: all > 0 at α = 1/100, 1, 157/100;"
      " the four with cos α < 0 at α = 158/100, 2, 314/100)")
check(sp.simplify(tb[1].subs(a, pi / 2)) == 0 and all(sp.simplify(closed_tb[r][0].subs(a, pi / 2)) == 0 for r in [(0, 1), (1, 2), (0, 2)]),
      "  α = π/2: b1 ≡ 0 and W(b0,b1), W(b1,b2), W(b0,b1,b2) ≡ 0 (criterion not applicable)")
x0, x1 = sp.symbols("x0 x1", real=True)
m2 = sp.Matrix([[sp.cos(x0)**2, sp.sin(x0)**2], [sp.cos(x1)**2, sp.sin(x1)**2]]).det()
check(trig_zero(m2 - sp.sin(x1 - x0) * sp.sin(x1 + x0), [x0, x1]) and tz(tb[0].subs(a, pi / 2) - sp.cos(t)**2),
      "  but TP at α = π/2: b = (cos²t, 0, sin²t); the only nonzero minors are entries ≥ 0 and "
      "det[[cos²x0, sin²x0], [cos²x1, sin²x1]] = sin(x1 − x0) sin(x1 + x0) ≥ 0 for 0 ≤ x0 < x1 ≤ π/2 (a rank-2 system, not a basis)")
v = sp.simplify(tb[1].subs({a: 2 * pi / 3, t: pi / 3}))
check(v == -1, f"  refutation α = 2π/3, t = π/3: b1 = {v} (exact, 1×1 minor)")
# rational witness: tan(α/2) = 2 ⇒ (sin α, cos α) = (4/5, −3/5); tan(t/2) = 1/2 ⇒ (sin t, cos t) = (4/5, 3/5)
tbe = sp.expand(sp.expand_trig(tb[1]))
v = tbe.subs({sp.sin(a): R(4, 5), sp.cos(a): R(-3, 5), sp.sin(t): R(4, 5), sp.cos(t): R(3, 5)})
check(v == R(-36, 25) and iv_positive(lambda m: 2 * m.atan2(2, 1) - m.pi / 2) and iv_positive(lambda m: m.pi - 2 * m.atan2(2, 1)),
      f"  rational refutation α = 2 atan 2 ∈ (π/2, π) (sin α = 4/5, cos α = −3/5), t = 2 atan(1/2) (sin t = 4/5, cos t = 3/5): "
      f"b1 = {v}")
check(tz(tb[1] - sp.cos(a) * 2 * sp.sin(a - t) * sp.sin(t) / sa**2),
      "  for every α ∈ (π/2, π), b1 = cos α·(2 sin(α−t) sin t/sin²α) < 0 on all of (0, α) ⇒ NOT TP. Exact TP set in (0, π): (0, π/2]")
closed_tb_ends = {
    (0, 0): ((0, 1), (2, 2 / sa**2)),
    (1, 1): ((1, 2 * sp.cos(a) / sa), (1, 2 * sp.cos(a) / sa)),
    (2, 2): ((2, 2 / sa**2), (0, 1)),
    (0, 1): ((0, 2 * sp.cos(a) / sa), (2, 4 * sp.cos(a) / sa**3)),
    (1, 2): ((2, 4 * sp.cos(a) / sa**3), (0, 2 * sp.cos(a) / sa)),
    (0, 2): ((0, 4 * sp.cos(a) / sa**3), (0, 4 * sp.cos(a) / sa**3)),
}
check_ends("trig Bernstein (α ≠ π/2)", {r: closed_tb[r][0] for r in runs(2)}, tza, closed_tb_ends, 2)
print("   degenerate parameters: α = 0; α = π/2 (b1 ≡ 0, three Wronskians ≡ 0); α = π (sin α = 0: undefined)")

# =========================================================================================== 4. quadratic C-Bézier
print()
print("4. quadratic C-Bézier, span{1, cos t, sin t} on [0, α] (examples/c-bezier-quadratic.toml; printed α ∈ (0, π])")
ca = 1 - sp.cos(a)
cq = [(1 - sp.cos(a - t)) / ca, -(1 - sp.cos(t) + sp.cos(a) - sp.cos(a - t)) / ca, (1 - sp.cos(t)) / ca]
check(tz(sum(cq) - 1), "unity")
half = lambda e: trig_zero(sp.expand(e).subs({t: 2 * x, a: 2 * y}), [x, y])  # noqa: E731
check(half(cq[1] - 2 * sp.cos(a / 2) * sp.sin(t / 2) * sp.sin((a - t) / 2) / sp.sin(a / 2)**2)
      and half(cq[0] - sp.sin((a - t) / 2)**2 / sp.sin(a / 2)**2) and half(cq[2] - sp.sin(t / 2)**2 / sp.sin(a / 2)**2),
      "b_i(t; α) = (basis 3)_i(t/2; α/2): b1 = 2cos(α/2) sin(t/2) sin((α−t)/2)/sin²(α/2)")
closed_cq = {
    (0, 0): (cq[0], "(1 − cos(α−t))/(1 − cos α)"),
    (1, 1): (cq[1], "2cos(α/2) sin(t/2) sin((α−t)/2)/sin²(α/2)"),
    (2, 2): (cq[2], "(1 − cos t)/(1 − cos α)"),
    (0, 1): (sp.sin(a) * (1 - sp.cos(a - t)) / ca**2, "sin α (1 − cos(α−t))/(1 − cos α)²"),
    (1, 2): (sp.sin(a) * (1 - sp.cos(t)) / ca**2, "sin α (1 − cos t)/(1 − cos α)²"),
    (0, 2): (sp.sin(a) / ca**2, "sin α/(1 − cos α)² = cos(α/2)/(2 sin³(α/2))"),
}
for r in runs(2):
    check(tz(wronskian(cq[r[0]:r[1] + 1]) - closed_cq[r][0]), f"  {name(r)} = {closed_cq[r][1]}")
check(half(closed_cq[(0, 2)][0] - sp.cos(a / 2) / (2 * sp.sin(a / 2)**3)), "  (half-angle form of the constant)")
print("   On (0, α), α ∈ (0, 2π): 1 − cos t, 1 − cos(α−t), 1 − cos α > 0, sin(t/2), sin((α−t)/2) > 0; the rest has the sign")
print("   of cos(α/2), i.e. of sin α:")
check(spot([closed_cq[r][0] for r in runs(2)], [R(1, 100), R(2), R(314, 100)], [R(1, 100), R(1, 2), R(99, 100)])
      and spot([closed_cq[r][0] for r in [(1, 1), (0, 1), (1, 2), (0, 2)]], [R(315, 100), R(4), R(628, 100)], [R(1, 100), R(1, 2), R(99, 100)], -1),
      "  all consecutive Wronskians > 0 on (0, α) ⇔ α ∈ (0, π) ⇒ TP there (certified spot signs at α = 1/100, 2, 314/100 and,"
      " negative, at 315/100, 4, 628/100)")
check(sp.simplify(cq[1].subs(a, pi)) == 0, "  α = π: b1 ≡ 0, W(b0,b1), W(b1,b2), W(b0,b1,b2) ≡ 0; still TP (b = ((1+cos t)/2, 0, "
                                           "(1−cos t)/2) = (cos²(t/2), 0, sin²(t/2)): basis 3 at π/2 with t/2)")
v = sp.simplify(cq[1].subs({a: 4 * pi / 3, t: 2 * pi / 3}))
check(v == -1, f"  refutation α = 4π/3, t = 2π/3: b1 = {v} (exact)")
cqe = sp.expand(sp.expand_trig(cq[1]))
v = cqe.subs({sp.sin(a): R(-24, 25), sp.cos(a): R(-7, 25), sp.sin(t): R(24, 25), sp.cos(t): R(-7, 25)})
check(v == R(-36, 25) and iv_positive(lambda m: 4 * m.atan2(2, 1) - m.pi) and iv_positive(lambda m: 2 * m.pi - 4 * m.atan2(2, 1))
      and iv_positive(lambda m: 4 * m.atan2(2, 1) - 4 * m.atan2(1, 2)),
      f"  rational refutation α = 4 atan 2 ∈ (π, 2π) (cos α, sin α) = (−7/25, −24/25), t = 4 atan(1/2) < α "
      f"(cos t, sin t) = (−7/25, 24/25): b1 = {v}")
check(half(cq[1] - sp.cos(a / 2) * 2 * sp.sin(t / 2) * sp.sin((a - t) / 2) / sp.sin(a / 2)**2),
      "  α ∈ (π, 2π): b1 = cos(α/2)·(positive) < 0 on all of (0, α) ⇒ NOT TP. Exact TP set in (0, 2π): (0, π] (the printed range is exact)")
closed_cq_ends = {
    (0, 0): ((0, 1), (2, 1 / ca)),
    (1, 1): ((1, sp.sin(a) / ca), (1, sp.sin(a) / ca)),
    (2, 2): ((2, 1 / ca), (0, 1)),
    (0, 1): ((0, sp.sin(a) / ca), (2, sp.sin(a) / ca**2)),
    (1, 2): ((2, sp.sin(a) / ca**2), (0, sp.sin(a) / ca)),
    (0, 2): ((0, sp.sin(a) / ca**2), (0, sp.sin(a) / ca**2)),
}
check_ends("quadratic C-Bézier (α ≠ π)", {r: closed_cq[r][0] for r in runs(2)}, tza, closed_cq_ends, 2)
print("   degenerate parameters: α = 0; α = π (b1 ≡ 0); α = 2π (1 − cos α = 0: undefined)")

print()
print("4'. trig-bbasis-half-angle.toml: b0 = sin²(π/4 − t/2)/sin²(π/4), b2 = sin²(t/2)/sin²(π/4), b1 = 1 − b0 − b2, t ∈ [0, π/2]")
hb0 = sp.sin(pi / 4 - t / 2)**2 / sp.sin(pi / 4)**2
hb2 = sp.sin(t / 2)**2 / sp.sin(pi / 4)**2
hbb = [hb0, 1 - hb0 - hb2, hb2]
han = [1 - sp.sin(t), sp.sin(t) + sp.cos(t) - 1, 1 - sp.cos(t)]
hz2 = lambda e: trig_zero(sp.expand(e).subs(t, 2 * x), [x])  # noqa: E731
check(all(hz2(p - q) for p, q in zip(hbb, han)) and all(trig_zero(cq[i].subs(a, pi / 2) - han[i], [t]) for i in range(3)),
      "b = (1 − sin t, sin t + cos t − 1, 1 − cos t) = the quadratic C-Bézier basis at α = π/2")
closed_h = {(0, 0): han[0], (1, 1): han[1], (2, 2): han[2], (0, 1): 1 - sp.sin(t), (1, 2): 1 - sp.cos(t), (0, 2): sp.Integer(1)}
check(all(trig_zero(wronskian(han[r[0]:r[1] + 1]) - closed_h[r], [t]) for r in runs(2)),
      "  W(b0) = 1 − sin t, W(b1) = sin t + cos t − 1, W(b2) = 1 − cos t, W(b0,b1) = 1 − sin t, W(b1,b2) = 1 − cos t, "
      "W(b0,b1,b2) = 1: all > 0 on (0, π/2) ⇒ TP")
closed_h_ends = {(0, 0): ((0, 1), (2, 1)), (1, 1): ((1, 1), (1, 1)), (2, 2): ((2, 1), (0, 1)), (0, 1): ((0, 1), (2, 1)),
                 (1, 2): ((2, 1), (0, 1)), (0, 2): ((0, 1), (0, 1))}
check_ends("half-angle basis", closed_h, lambda e: sp.simplify(e) == 0, closed_h_ends, 2, right=pi / 2)

# =========================================================================================== 5. exp Bernstein
print()
print("5. exponential Bernstein, span{1, e^t, e^2t, e^3t} on [0, α] (examples/exp-bernstein-cubic.toml, range [1/2, 4])")
E = sp.exp(a)
wv = (sp.exp(t) - 1) / (E - 1)
X = sp.Symbol("X", real=True)
Bx = [sp.binomial(3, i) * X**i * (1 - X)**(3 - i) for i in range(4)]
eb = [B.subs(X, wv) for B in Bx]
check(hz(sum(eb) - 1), "unity")
Wx = {r: sp.factor(wronskian(Bx[r[0]:r[1] + 1], X)) for r in runs(3)}
expWx = {(0, 0): (1 - X)**3, (1, 1): 3 * X * (1 - X)**2, (2, 2): 3 * X**2 * (1 - X), (3, 3): X**3,
         (0, 1): 3 * (1 - X)**4, (1, 2): 9 * X**2 * (1 - X)**2, (2, 3): 3 * X**4,
         (0, 2): 18 * (1 - X)**3, (1, 3): 18 * X**3, (0, 3): sp.Integer(108)}
check(all(sp.expand(Wx[r] - expWx[r]) == 0 for r in runs(3)),
      "Bernstein Wronskians in x: (1−x)³, 3x(1−x)², 3x²(1−x), x³; W(B0,B1) = 3(1−x)⁴, W(B1,B2) = 9x²(1−x)², W(B2,B3) = 3x⁴; "
      "W(B0,B1,B2) = 18(1−x)³, W(B1,B2,B3) = 18x³; W(B0..B3) = 108: all > 0 on (0, 1)")
wp = sp.exp(t) / (E - 1)
closed_eb = {r: wp**((r[1] - r[0] + 1) * (r[1] - r[0]) // 2) * expWx[r].subs(X, wv) for r in runs(3)}
# exact check of the chain rule through u = e^t: d/dt f(e^t) = (θf)(e^t) with θ = u·d/du; κ = 1/(e^α − 1) kept as a symbol,
# so every entry is a polynomial in (u, κ)
u = sp.Symbol("u", positive=True)
kap = sp.Symbol("kappa", positive=True)
bu = [sp.expand(B.subs(X, kap * (u - 1))) for B in Bx]


def theta_wronskian(fs):
    rows = [list(fs)]
    for _ in range(1, len(fs)):
        rows.append([sp.expand(u * sp.diff(f, u)) for f in rows[-1]])
    return sp.expand(sp.Matrix(rows).det(method="berkowitz"))


check(all(theta_wronskian(bu[r[0]:r[1] + 1]) - sp.expand((u * kap)**((r[1] - r[0] + 1) * (r[1] - r[0]) // 2)
                                                          * expWx[r].subs(X, kap * (u - 1))) == 0 for r in runs(3))
      and all(hz(eb[i] - bu[i].subs({u: sp.exp(t), kap: 1 / (E - 1)})) for i in range(4)),
      "chain rule: W_t(b_j..b_l)(t) = (w')^{k(k−1)/2}·W_x(B_j..B_l)(w(t)), w = (e^t − 1)/(e^α − 1), w' = e^t/(e^α − 1) > 0"
      " (checked exactly in u = e^t, d/dt = u·d/du)")
check(wv.subs(t, 0) == 0 and sp.simplify(wv.subs(t, a) - 1) == 0 and sp.simplify(sp.diff(wv, t) - wp) == 0,
      "  w(0) = 0, w(α) = 1, w' > 0: w maps (0, α) increasingly onto (0, 1) ⇒ every consecutive Wronskian > 0 on (0, α) for EVERY α > 0 ⇒ TP on "
            "the range [1/2, 4] and beyond; α* = +∞")
print("   end behaviour (order in t, leading h-derivative L; E = e^α): orders are those of the Bernstein case")
Es = sp.Symbol("E", positive=True)
q = sp.Symbol("q", positive=True)
for r in runs(3):
    (k0, d0), (k1, d1) = end_data(closed_eb[r], hza)
    k = r[1] - r[0] + 1
    L0 = sp.factor(sp.simplify(d0.subs(sp.exp(a), Es)))
    L1 = sp.factor(sp.simplify(d1.subs(sp.exp(a), Es)))
    pos = True
    for L in (L0, L1):
        nu, de = sp.fraction(sp.factor(L.subs(Es, 1 + q)))
        pos &= all(co > 0 for co in sp.Poly(sp.expand(nu), q).coeffs()) and all(co > 0 for co in sp.Poly(sp.expand(de), q).coeffs())
    check((k0, k1) == (k * r[0], k * (3 - r[1])) and pos,
          f"  {name(r)}: at t = 0 order {k0}, L = {L0};  at t = α order {k1}, L = {L1}  (L > 0: E = 1 + q, q > 0, "
          f"all coefficients positive)")
print("   degenerate parameters: only α = 0")

print()
print(f"done in {time.time() - T0:.1f} s")
