"""Shared exact tools for the independent checks (SymPy only; mpmath for cross-checks).

Nothing here knows about any particular basis. Every "proof" helper either returns an
exact object or raises AssertionError; nothing is decided by floating point.

  trig_zero(e, angles)      e ≡ 0 as a function of the angles (sin/cos reduced modulo s²+c²=1)
  hyp_zero(e, vars)         e ≡ 0 with sinh/cosh/exp rewritten through X = exp(x)
  weierstrass(e, t, m)      sin t, cos t -> 2m/(1+m²), (1-m²)/(1+m²)   (t ∈ [0, π/2] <-> m ∈ [0, 1])
  nonneg_on(f, x, lo, hi)   exact decision of f(x) ≥ 0 on [lo, hi] for a rational univariate f
  param_set(F, x, lam, ...) the exact set of λ with F(x, λ) ≥ 0 for all x in [lo, hi]
  iv_eval(e, env)           rigorous enclosure (mpmath.iv, outward rounding) of e at exact/interval values
  iv_sign(e, env)           certified sign (+1/−1) of e, from iv_eval; AssertionError if the enclosure contains 0
  root_enclosure(F, x, lo, hi)   certified sign change of F between two rationals (a root inside)
  bernstein_matrix(N, x, d) coefficient matrix of polynomials N_i(x) in the Bernstein basis of degree d on [0, 1]
  minors(M)                 all nonzero minors of M (every order)
  tp_certificate_set(N, x, lam, d)  exact set of λ where every minor of the degree-d Bernstein matrix is ≥ 0
"""

import sympy as sp
from sympy import Rational as R

TRIG = (sp.sin, sp.cos, sp.tan, sp.sinh, sp.cosh, sp.tanh, sp.exp)


# --------------------------------------------------------------------------- identities
def trig_zero(expr, angles):
    """Return True iff expr reduces to 0 after expand_trig and s²+c²=1 for each angle.

    expr may contain sin/cos of integer-linear combinations of `angles` and polynomials
    in any symbols. A zero remainder is a proof of the identity (wherever the
    denominators are nonzero)."""
    e = sp.expand_trig(sp.expand(expr))
    reps, gens, rels = {}, [], []
    for a in angles:
        s, c = sp.Symbol(f"S_{a}"), sp.Symbol(f"C_{a}")
        reps[sp.sin(a)] = s
        reps[sp.cos(a)] = c
        gens += [s]
        rels.append(s**2 + c**2 - 1)
    e = e.xreplace(reps)
    assert not e.has(*TRIG), f"trig left after reduction: {e}"
    num, _den = sp.fraction(sp.together(e))
    num = sp.expand(num)
    if num == 0:
        return True
    others = sorted(num.free_symbols - set(gens), key=str)
    _, rem = sp.reduced(num, rels, *gens, *others, order="lex")
    return sp.expand(rem) == 0


def hyp_zero(expr, xs):
    """True iff expr ≡ 0 after rewriting sinh/cosh through exp and X_i = exp(x_i).

    Each exp(c0 + Σ c_i x_i) (rational c) becomes exp(c0)·Π X_i^{c_i}; x_i themselves stay as
    independent polynomial variables (an identity in Q(x, X) is an identity of functions)."""
    e = expr.rewrite(sp.exp)
    Xs = {x: sp.Symbol(f"X_{x}", positive=True) for x in xs}
    reps = {}
    for ex in e.atoms(sp.exp):
        arg = sp.expand(ex.args[0])
        P = sp.Poly(arg, *xs)
        assert P.total_degree() <= 1, f"non-linear exponent {arg}"
        val = sp.exp(P.coeff_monomial(1))
        for x in xs:
            val *= Xs[x] ** P.coeff_monomial(x)
        reps[ex] = val
    e = e.xreplace(reps)
    assert not e.has(sp.exp) or all(a.args[0].is_number for a in e.atoms(sp.exp)), f"exp left: {e}"
    num, _den = sp.fraction(sp.together(e))
    return sp.expand(num) == 0


def weierstrass(expr, t, m):
    """sin t -> 2m/(1+m²), cos t -> (1-m²)/(1+m²); returns a rational function of m."""
    return sp.cancel(expr.subs({sp.sin(t): 2 * m / (1 + m**2), sp.cos(t): (1 - m**2) / (1 + m**2)}))


def pyth(m):
    """(sin t, cos t) at t = 2·atan(m): rational for rational m."""
    m = sp.nsimplify(m)
    return (2 * m / (1 + m**2), (1 - m**2) / (1 + m**2))


# --------------------------------------------------------------------------- rationals
def simplest_between(a, b):
    """Simplest rational strictly inside (a, b); a < b exact sympy numbers (may be algebraic)."""
    a, b = sp.nsimplify(a), sp.nsimplify(b)
    assert a < b
    lo = sp.Rational(str(sp.N(a, 60)))
    hi = sp.Rational(str(sp.N(b, 60)))
    # shrink a hair so the rational is strictly inside the exact interval
    eps = (hi - lo) / 10**6
    lo, hi = lo + eps, hi - eps
    return _stern_brocot(lo, hi)


def _stern_brocot(lo, hi):
    # simplest rational in the closed interval [lo, hi] (lo <= hi, rationals)
    if lo <= 0 <= hi:
        return sp.Integer(0)
    if hi < 0:
        return -_stern_brocot(-hi, -lo)
    fl = sp.floor(lo)
    if fl == lo:
        return fl
    if fl + 1 <= hi:
        return fl + 1
    # lo, hi in (fl, fl+1)
    return fl + 1 / _stern_brocot(1 / (hi - fl), 1 / (lo - fl))


# --------------------------------------------------------------------------- univariate sign
def _odd_interior_roots(f, x, lo, hi):
    P = sp.Poly(f, x)
    n = 0
    for g, e in P.factor_list()[1]:
        if e % 2 == 1 and g.degree() > 0:
            k = g.count_roots(lo, hi)
            k -= int(g.eval(lo) == 0) + int(g.eval(hi) == 0)
            n += k
    return n


def nonneg_on(f, x, lo, hi, prefer=()):
    """Exact: is the rational polynomial f(x) ≥ 0 on [lo, hi]?

    Returns (True, None) or (False, x0) with a rational witness x0 in [lo, hi], f(x0) < 0.
    `prefer` lists rational points tried first for a nice witness."""
    f = sp.expand(f)
    if f == 0:
        return True, None
    P = sp.Poly(f, x)
    for p in prefer:
        if lo <= p <= hi and P.eval(p) < 0:
            return False, sp.nsimplify(p)
    if _odd_interior_roots(f, x, lo, hi) == 0:
        # constant sign on (lo, hi): test a nonzero interior point
        k = 2
        while True:
            for j in range(1, k):
                p = lo + (hi - lo) * R(j, k)
                v = P.eval(p)
                if v != 0:
                    if v > 0:
                        return True, None
                    return False, p
            k += 1
    # sign change: the root-separating rationals contain a negative one
    roots = sorted({lo, hi} | {r for r in P.real_roots() if lo < r < hi}, key=lambda r: sp.N(r, 50))
    cands = [simplest_between(roots[i], roots[i + 1]) for i in range(len(roots) - 1)]
    for p in sorted(cands, key=lambda q: (sp.denom(q), abs(sp.numer(q)))):
        if P.eval(p) < 0:
            return False, p
    raise AssertionError("no witness found although a sign change exists")


# --------------------------------------------------------------------------- one-parameter sets
def critical_values(F, x, lam, lo, hi):
    """Real λ where the sign pattern of F(·, λ) on [lo, hi] can change (exact algebraic numbers)."""
    crit = set()
    _, facs = sp.factor_list(sp.expand(F), x, lam)
    # roots of two different factors may meet (F can become ≥ 0 at an isolated λ there)
    xf = [g for g, _e in facs if g.has(x)]
    for i in range(len(xf)):
        for j in range(i + 1, len(xf)):
            if xf[i].has(lam) or xf[j].has(lam):
                r = sp.expand(sp.resultant(xf[i], xf[j], x))
                if r.has(lam):
                    crit |= set(sp.Poly(r, lam).real_roots())
    for g, _e in facs:
        if not g.has(lam):
            continue
        G = sp.Poly(g, x)
        cands = []
        if G.degree() == 0:
            cands.append(g)
        else:
            cands += [g.subs(x, lo), g.subs(x, hi), G.LC()]
            if G.degree() >= 2:
                cands.append(sp.discriminant(g, x))
        for p in cands:
            p = sp.expand(p)
            if p.has(lam):
                crit |= set(sp.Poly(p, lam).real_roots())
    return sorted(crit, key=lambda r: sp.N(r, 50))


def param_set(Fs, x, lam, lo, hi, prefer=()):
    """Exact set {λ : F(x, λ) ≥ 0 for all x ∈ [lo, hi], for every F in Fs}.

    Returns (intervals, samples): intervals is a list of (a, b) closed intervals with exact
    algebraic ends (±oo allowed, then open there); samples is a list of
    (λ0, ok, witness) for the rational test points used (witness = (F index, x0))."""
    crit = sorted({r for F in Fs for r in critical_values(F, x, lam, lo, hi)}, key=lambda r: sp.N(r, 50))
    pts = []
    if not crit:
        pts = [sp.Integer(0)]
    else:
        pts.append(simplest_between(crit[0] - 1, crit[0]))
        for i in range(len(crit) - 1):
            pts.append(simplest_between(crit[i], crit[i + 1]))
        pts.append(simplest_between(crit[-1], crit[-1] + 1))

    def test(l0):
        for i, F in enumerate(Fs):
            ok, w = nonneg_on(F.subs(lam, l0), x, lo, hi, prefer)
            if not ok:
                return False, (i, w)
        return True, None

    samples = [(p, *test(p)) for p in pts]
    cell_ok = [s[1] for s in samples]
    # decide critical values: closed set, so a value next to a good cell is in; else test if rational
    crit_ok = []
    for i, r in enumerate(crit):
        if cell_ok[i] or cell_ok[i + 1]:
            crit_ok.append(True)
        elif r.is_Rational:
            crit_ok.append(test(r)[0])
        else:
            # both neighbours fail: look for an exact negative value at the neighbours' witness points
            found = False
            for s_ in (samples[i], samples[i + 1]):
                k, x0 = s_[2]
                val = sp.nsimplify(Fs[k].subs({x: x0})).subs(lam, r)
                if _alg_sign(val) < 0:
                    found = True
                    break
            if not found:
                raise AssertionError(f"isolated irrational critical value {r}: decide by hand")
            crit_ok.append(False)
    # assemble maximal closed intervals
    bounds = [-sp.oo] + crit + [sp.oo]
    intervals, cur = [], None
    for i, ok in enumerate(cell_ok):
        if ok:
            if cur is None:
                cur = [bounds[i], bounds[i + 1]]
            else:
                cur[1] = bounds[i + 1]
        else:
            if cur is not None:
                intervals.append(tuple(cur))
                cur = None
        if i < len(crit):
            if crit_ok[i] and cur is None:
                cur = [crit[i], crit[i]]
            elif not crit_ok[i] and cur is not None:
                intervals.append(tuple(cur))
                cur = None
    if cur is not None:
        intervals.append(tuple(cur))
    return intervals, samples, crit


def _alg_sign(val):
    """Sign of a real algebraic number: zero decided exactly (minimal polynomial), else 60 digits."""
    z = sp.Symbol("z")
    if sp.minimal_polynomial(val, z) == z:
        return 0
    return int(sp.sign(sp.N(val, 60)))


def describe_alg(r, digits=12):
    """Exact description of a real algebraic number: value, minimal polynomial, isolating interval."""
    if r in (sp.oo, -sp.oo) or r.is_Rational:
        return str(r)
    z = sp.Symbol("z")
    mp = sp.minimal_polynomial(r, z)
    # isolating interval with rational ends from the minimal polynomial's real-root isolation
    P = sp.Poly(mp, z)
    rv = sp.N(r, 40)
    for (a, b), _k in P.intervals(eps=R(1, 10**6)):
        if a <= rv <= b:
            iv = (a, b)
            break
    return f"{sp.nsimplify(r)} ≈ {sp.N(r, digits)} (min. poly {mp} = 0, isolating interval [{iv[0]}, {iv[1]}])"


def show_intervals(intervals):
    out = []
    for a, b in intervals:
        l = "(" if a == -sp.oo else "["
        rr = ")" if b == sp.oo else "]"
        out.append(f"{l}{sp.nsimplify(a) if a != -sp.oo else '-oo'}, {sp.nsimplify(b) if b != sp.oo else 'oo'}{rr}")
    return " ∪ ".join(out) if out else "∅"


def check(cond, msg):
    """assert with a printed line."""
    assert cond, msg
    print("  [ok]", msg)


# --------------------------------------------------------------------------- small conveniences
PYTH_M = [R(1, 2), R(1, 3), R(2, 3), R(1, 4), R(3, 4), R(1, 5), R(4, 5), R(1, 8), R(7, 8), R(1, 10), R(9, 10)]


def trig_at(expr, t, m):
    """Exact value of expr at t = 2·atan(m) (rational m gives rational sin, cos)."""
    s, c = pyth(m)
    return sp.nsimplify(sp.simplify(expr.subs({sp.sin(t): s, sp.cos(t): c})))


def numerator_posden(expr, x, lo=0, hi=1):
    """Numerator N of a rational function whose denominator has constant positive sign on [lo, hi]
    and no parameter in it; returns N with the sign of the denominator folded in."""
    num, den = sp.fraction(sp.together(sp.cancel(expr)))
    den = sp.expand(den)
    assert den.free_symbols <= {x}, f"denominator depends on a parameter: {den}"
    D = sp.Poly(den, x)
    assert D.count_roots(lo, hi) == 0, f"denominator vanishes on [{lo},{hi}]"
    sgn = sp.sign(D.eval(sp.Rational(lo + hi, 2)))
    return sp.expand(sgn * num)


def range_contains(intervals, a, b):
    """Exact: is [a, b] inside the union of closed intervals?"""
    return any((lo == -sp.oo or lo <= a) and (hi == sp.oo or b <= hi) for lo, hi in intervals)


def mp_min(fns, var, lo, hi, n=400, dps=100):
    """mpmath cross-check (not a proof): min over an n-point grid of each function, at dps digits."""
    import mpmath as mpm

    mpm.mp.dps = dps
    a, b = mpm.mpf(str(sp.N(lo, dps + 10))), mpm.mpf(str(sp.N(hi, dps + 10)))
    out = []
    for f in fns:
        g = sp.lambdify(var, f, "mpmath")
        out.append(min(g(a + (b - a) * k / n) for k in range(n + 1)))
    return out


# --------------------------------------------------------------------------- certified numerics
def iv_eval(expr, env, dps=60):
    """Rigorous interval enclosure of a SymPy expression (mpmath.iv, outward rounding).

    env maps symbols to exact SymPy numbers (rationals, multiples of π, ...) or to (lo, hi) pairs of
    exact numbers (then the symbol ranges over [lo, hi]). Rationals are entered as exact quotients,
    π as iv.pi, sin/cos/tan/exp directly, sinh/cosh through exp. Nothing is rounded before the
    interval arithmetic starts."""
    from mpmath import iv

    iv.dps = dps

    def num(v):
        v = sp.nsimplify(v)
        if v.is_Rational:
            return iv.mpf(int(v.p)) / int(v.q)
        return go(v)

    def go(e):
        if e.is_Symbol:
            v = env[e]
            if isinstance(v, tuple):
                lo, hi = num(v[0]), num(v[1])
                return iv.mpf([lo.a, hi.b])
            return num(v)
        if e.is_Rational:
            return iv.mpf(int(e.p)) / int(e.q)
        if e is sp.pi:
            return iv.pi
        if e is sp.E:
            return iv.exp(iv.mpf(1))
        if e.is_Add:
            out = iv.mpf(0)
            for a in e.args:
                out = out + go(a)
            return out
        if e.is_Mul:
            out = iv.mpf(1)
            for a in e.args:
                out = out * go(a)
            return out
        if e.is_Pow:
            b, x = e.args
            if x.is_Integer:
                n = int(x)
                base = go(b)
                if n >= 0:
                    out = iv.mpf(1)
                    for _ in range(n):
                        out = out * base
                    return out
                out = iv.mpf(1)
                for _ in range(-n):
                    out = out * base
                return 1 / out
            if x == sp.Rational(1, 2):
                return iv.sqrt(go(b))
            raise AssertionError(f"iv_eval: exponent {x}")
        f = e.func
        if f in (sp.sin, sp.cos, sp.tan, sp.exp):
            return getattr(iv, f.__name__)(go(e.args[0]))
        if f is sp.sinh:
            y = go(e.args[0])
            return (iv.exp(y) - iv.exp(-y)) / 2
        if f is sp.cosh:
            y = go(e.args[0])
            return (iv.exp(y) + iv.exp(-y)) / 2
        raise AssertionError(f"iv_eval: cannot evaluate {e}")

    return go(sp.sympify(expr))


def iv_sign(expr, env, dps=60):
    """Certified sign of expr at env: +1 or −1 (the enclosure excludes 0), else AssertionError."""
    v = iv_eval(expr, env, dps)
    if v.a > 0:
        return 1
    if v.b < 0:
        return -1
    raise AssertionError(f"sign not certified: enclosure {v} contains 0")


def iv_digits(expr, env, digits=30, dps=60):
    """The value of expr at env to `digits` significant digits, certified: both ends of the interval
    enclosure round to the same string (AssertionError otherwise)."""
    import mpmath

    v = iv_eval(expr, env, dps)
    # the ends are converted at the enclosure's own precision: at mpmath's
    # default 15 digits both would be rounded to doubles first
    with mpmath.workdps(dps):
        lo = mpmath.nstr(mpmath.mpf(v.a), digits)
        hi = mpmath.nstr(mpmath.mpf(v.b), digits)
    assert lo == hi, f"not {digits} certified digits: [{lo}, {hi}]"
    return lo


def root_enclosure(F, x, lo, hi, env=None, dps=60):
    """Certified: F(lo) and F(hi) have opposite signs (interval arithmetic at dps digits), so F (continuous
    on [lo, hi]) has a root in (lo, hi). Returns (sign at lo, sign at hi)."""
    env = dict(env or {})
    slo = iv_sign(F, {**env, x: lo}, dps)
    shi = iv_sign(F, {**env, x: hi}, dps)
    assert slo * shi < 0, f"no sign change of {F} on [{lo}, {hi}]"
    return slo, shi


# --------------------------------------------------------------------------- total positivity
def bernstein_matrix(N, x, d):
    """Rows: the coefficients of N_i(x) in the Bernstein basis C(d, j) x^j (1 − x)^{d−j} of degree d on [0, 1].

    A degree below d is elevated exactly (the power-to-Bernstein formula of degree d)."""
    rows = []
    for f in N:
        P = sp.Poly(sp.expand(f), x)
        assert P.degree() <= d, f"degree {P.degree()} > {d}"
        a = [P.coeff_monomial(x**k) for k in range(d + 1)]
        rows.append([sp.factor(sum(sp.binomial(j, k) / sp.binomial(d, k) * a[k] for k in range(j + 1))) for j in range(d + 1)])
    return sp.Matrix(rows)


def minors(M):
    """All nonzero minors of M, every order (factored)."""
    import itertools

    r, c = M.shape
    out = []
    for k in range(1, min(r, c) + 1):
        for I in itertools.combinations(range(r), k):
            for J in itertools.combinations(range(c), k):
                v = sp.factor(M.extract(list(I), list(J)).det())
                if v != 0:
                    out.append(v)
    return out


def tp_certificate_set(N, x, lam, d):
    """Exact set of λ (closed intervals, exact algebraic ends) where every minor of the degree-d Bernstein
    matrix of N is ≥ 0. On that set the basis N (hence b = N/(positive common factor), composed with an
    increasing change of variable) is totally positive: its collocation matrices are the Bernstein ones
    (TP) times M (Cauchy–Binet). Decided cell by cell between consecutive real roots of the minors."""
    M = bernstein_matrix(N, x, d)
    ms = minors(M)
    crit = set()
    for y in ms:
        if y.has(lam):
            crit |= set(sp.Poly(y, lam).real_roots())
    crit = sorted(crit, key=lambda r: sp.N(r, 50))
    if not crit:
        ok = all(sp.sign(y) >= 0 for y in ms)
        return ([(-sp.oo, sp.oo)] if ok else []), M
    cells = [simplest_between(crit[0] - 1, crit[0])]
    cells += [simplest_between(crit[i], crit[i + 1]) for i in range(len(crit) - 1)]
    cells += [simplest_between(crit[-1], crit[-1] + 1)]

    def good(v):
        return all(_alg_sign(sp.nsimplify(y.subs(lam, v))) >= 0 if not v.is_Rational else sp.sign(y.subs(lam, v)) >= 0
                   for y in ms)

    cell_ok = [good(p) for p in cells]
    crit_ok = [cell_ok[i] or cell_ok[i + 1] or good(r) for i, r in enumerate(crit)]
    bounds = [-sp.oo] + crit + [sp.oo]
    out, cur = [], None
    for i, ok in enumerate(cell_ok):
        if ok:
            cur = [bounds[i], bounds[i + 1]] if cur is None else [cur[0], bounds[i + 1]]
        elif cur is not None:
            out.append(tuple(cur))
            cur = None
        if i < len(crit):
            if crit_ok[i] and cur is None:
                cur = [crit[i], crit[i]]
            elif not crit_ok[i] and cur is not None:
                out.append(tuple(cur))
                cur = None
    if cur is not None:
        out.append(tuple(cur))
    return out, M
