"""Part C1 (and C8): the uniform C-B-spline of span{1, t, sin t, cos t}, knot spacing α.

Source: J. Zhang, "C-curves: an extension of cubic curves", CAGD 13 (1996) 199-217 (the C-B-spline
section), also J. Zhang, "Two different forms of C-B-splines", CAGD 14 (1997) 31-41. The print was NOT
retrieved; the segment functions below are DERIVED here from the definition (the uniform B-spline of
the space: C² at the knots, support of four knot intervals, partition of unity) and agree with the form
recalled from Zhang, b3 = (t − sin t)/(2α(1 − cos α)). The printed range, as recalled, is α ∈ (0, π).

Segment t ∈ [0, α] of the curve r(t) = Σ b_i(t) P_{j+i}, with k = 1/(2α(1 − cos α)):
  b3(t) = k (t − sin t)
  b2(t) = k [(α − sin α) + (1 − cos α) t + sin α (1 − cos t) − (2 + cos α)(t − sin t)]
  b1(t) = b2(α − t),   b0(t) = b3(α − t).
The B-spline N on [0, 4α] is b3, b2, b1, b0 on the knot intervals 0, 1, 2, 3 (piece j = b_{3−j}), as in B6.
Derivatives w.r.t. t.
"""

import sympy as sp
import mpmath as mpm
from _exact import check, iv_digits, iv_sign, root_enclosure, trig_zero

t, a, x = sp.symbols("t alpha x", positive=True)
S, C = sp.sin, sp.cos
k = 1 / (2 * a * (1 - C(a)))
b3 = k * (t - S(t))
b2 = k * ((a - S(a)) + (1 - C(a)) * t + S(a) * (1 - C(t)) - (2 + C(a)) * (t - S(t)))
b1 = b2.subs(t, a - t)
b0 = b3.subs(t, a - t)
b = [b0, b1, b2, b3]
print("c-bspline: uniform C-B-spline of span{1, t, sin t, cos t}, spacing α; k = 1/(2α(1 − cos α))")
for i, f in enumerate(b):
    print(f"  b{i}(t) =", f)

# ---- derivation: the B-spline conditions determine these functions
c0, c1, c2, c3, K = sp.symbols("c0:4 K")
p0 = K * (t - S(t))                       # first piece: triple zero at the support start (C²)
p1 = c0 + c1 * t + c2 * C(t) + c3 * S(t)  # second piece; third = p1(α − t), fourth = p0(α − t) (symmetry)
eqs = [sp.diff(p1, t, j).subs(t, 0) - sp.diff(p0, t, j).subs(t, a) for j in range(3)] + [sp.diff(p1, t).subs(t, a)]
sol = sp.solve(eqs, [c0, c1, c2, c3], dict=True)[0]
P1 = p1.subs(sol)
Ksol = sp.solve(sp.simplify(sp.expand_trig(p0 + P1 + P1.subs(t, a - t) + p0.subs(t, a - t))) - 1, K)
check(len(Ksol) == 1 and trig_zero(Ksol[0] - k, [a]),
      "C² at the knots + symmetry + unity force K = 1/(2α(1 − cos α)) (the normalising divisor 2α(1 − cos α))")
check(trig_zero(P1.subs(K, k) - b2, [t, a]), "… and the second piece is b2 as written above")
check(trig_zero(sum(b) - 1, [t, a]), "unity Σ b_i = 1 (exact)")
check(all(trig_zero(b[i].subs(t, a - t) - b[3 - i], [t, a]) for i in range(4)), "symmetry b_i(t) = b_{3−i}(α − t)")
check(all(sp.expand(sp.limit(f.subs(t, a * x), a, 0) - g) == 0 for f, g in
          zip(b, [(1 - x) ** 3 / 6, (3 * x**3 - 6 * x**2 + 4) / 6, (-3 * x**3 + 3 * x**2 + 3 * x + 1) / 6, x**3 / 6])),
      "α → 0 (t = αx): the uniform cubic B-spline segment ((1−x)³, 3x³−6x²+4, −3x³+3x²+3x+1, x³)/6")

# ---- continuity of the B-spline: jumps at the knots, orders 0..3
print("  jumps of N^(k) at the knots 0, α, 2α, 3α, 4α: J_j = b_{3−j}^(k)(0) − b_{4−j}^(k)(α)  (b_4 = b_{−1} = 0)")
pieces = [b3, b2, b1, b0]
J = []
for j in range(5):
    row = []
    for kk in range(4):
        right = sp.diff(pieces[j], t, kk).subs(t, 0) if j < 4 else 0
        left = sp.diff(pieces[j - 1], t, kk).subs(t, a) if j > 0 else 0
        row.append(right - left)
    J.append(row)
check(all(trig_zero(J[j][kk], [a]) for j in range(5) for kk in range(3)), "jumps of orders 0, 1, 2 vanish at every knot: C²")
third = [k, -2 * k * (1 + C(a)), 2 * k * (1 + 2 * C(a)), -2 * k * (1 + C(a)), k]
check(all(trig_zero(J[j][3] - third[j], [a]) for j in range(5)),
      "third-derivative jumps = k·(1, −2(1 + cos α), 2(1 + 2cos α), −2(1 + cos α), 1) at knots 0..4α")
print("  (α → 0: α³·jumps → (1, −4, 6, −4, 1), the cubic B-spline's.) The support-end jump k never vanishes,")
print("  so the B-spline is exactly C² for every α (inner jumps vanish only at α = π, resp. α = 2π/3).")

# ---- nonnegativity in α (exact chain of arguments; each identity checked)
h = S(a) - a * C(a)
print("  nonnegativity for α ∈ (0, 2π) (k > 0 there):")
print("   * b3 = k(t − sin t) ≥ 0 and b0 = b3(α − t) ≥ 0.")
db2 = sp.diff(b2, t)
check(trig_zero(db2 - k * ((1 - C(a)) + S(a) * S(t) - (2 + C(a)) * (1 - C(t))), [t, a]) and
      trig_zero(db2.subs(t, 0) - 1 / (2 * a), [a]) and trig_zero(db2.subs(t, a), [a]),
      "   * b2' ∈ span{1, cos t, sin t}, b2'(0) = 1/(2α) > 0, b2'(α) = 0")
print("     span{1, cos, sin} is a Chebyshev space on intervals of length < 2π (≤ 2 zeros with multiplicity):")
print("     b2' has at most one more zero in (0, α), where it changes sign ⇒ b2 increases then decreases,")
print("     so min_[0,α] b2 = min(b2(0), b2(α)).")
check(trig_zero(b2.subs(t, 0) - k * (a - S(a)), [a]), "   * b2(0) = k(α − sin α) > 0")
check(trig_zero(b2.subs(t, a) - 2 * k * h, [a]) and trig_zero(b1.subs(t, 0) - 2 * k * h, [a]),
      "   * b2(α) = b1(0) = 2k·(sin α − α cos α) = (sin α − α cos α)/(α(1 − cos α))")
check(sp.simplify(sp.diff(h, a) - a * S(a)) == 0 and h.subs(a, sp.pi) == sp.pi and h.subs(a, 3 * sp.pi / 2) == -1,
      "   * H(α) = sin α − α cos α: H(0) = 0, H' = α sin α (> 0 on (0, π), < 0 on (π, 2π)), H(π) = π, H(3π/2) = −1")
print("     ⇒ H > 0 on (0, α*), H(α*) = 0, H < 0 on (α*, 2π], for a unique α* ∈ (π, 3π/2): tan α* = α*.")
print("  ⇒ MAXIMAL RANGE (the component containing the printed (0, π)): α ∈ (0, α*], α* = the first positive root")
print("    of tan α = α (equivalently sin α − α cos α = 0). At α* itself b1(0) = b2(α) = 0 (N(2α) = 0).")
print("    α* is transcendental: for algebraic α ≠ 0, tan α is transcendental (Lindemann–Weierstrass), so tan α ≠ α.")

# ---- certified enclosure of α*
mpm.mp.dps = 50
astar = mpm.findroot(lambda y: mpm.sin(y) - y * mpm.cos(y), 4.4934)
print("  α* ≈", mpm.nstr(astar, 40))
lo = sp.Rational("4.493409457909064175307880927280")
hi = sp.Rational("4.493409457909064175307880927281")
check(root_enclosure(h, a, lo, hi) == (1, -1),
      "certified (interval arithmetic, 60 digits): H(4.493409457909064175307880927280) > 0 > H(…281), so"
      " α* ∈ [4.493409457909064175307880927280, 4.493409457909064175307880927281]")
check(root_enclosure(h, a, sp.Rational(4493, 1000), sp.Rational(4494, 1000)) == (1, -1),
      "coarse bracket: α* ∈ (4493/1000, 4494/1000)  (H(4.493) > 0 > H(4.494))")

# ---- witnesses
w_out = sp.Rational(8987, 2000)  # 4.4935
v = iv_digits(b1.subs(t, 0), {a: w_out})
check(iv_sign(b1.subs(t, 0), {a: w_out}) < 0, f"just outside: α = 8987/2000 = 4.4935, t = 0: b1(0) = {v} < 0 (30 certified digits)")
v = iv_digits(b1.subs(t, 0), {a: sp.Rational(4493, 1000)})
check(iv_sign(b1.subs(t, 0), {a: sp.Rational(4493, 1000)}) > 0,
      f"just inside: α = 4493/1000, t = 0: b1(0) = {v} > 0 (the minimum over [0, α], by the unimodality argument)")
wv = sp.simplify(b1.subs(t, 0).subs(a, 3 * sp.pi / 2))
check(wv == -2 / (3 * sp.pi), "exact witness: α = 3π/2, t = 0: b1(0) = −2/(3π) ≈ −0.2122 (H(3π/2) = −1, k = 1/(3π))")
check(sp.simplify(b1.subs(t, 0).subs(a, sp.pi)) == sp.Rational(1, 2) and sp.simplify(b0.subs(t, 0).subs(a, sp.pi)) == sp.Rational(1, 4),
      "α = π: b(0) = (1/4, 1/2, 1/4, 0)")
print("  α = 2π: k = 1/(2α(1 − cos α)) is undefined (no B-spline).")

# grid cross-check (not a proof): the component beyond 2π
mpm.mp.dps = 30
fb2 = sp.lambdify((t, a), b2, "mpmath")


def gmin(al, n=800):
    al = mpm.mpf(al)
    return min(fb2(al * j / n, al) for j in range(n + 1))


print("  grid minima of b2 (= min of all four, by symmetry and b0, b3 ≥ 0), 800 points, 30 digits:")
for al in ["0.1", "1", "3.14159", "4.4", "4.4933", "4.4935", "5", "6.2", "7.83", "7.84", "9", "10.9", "10.91"]:
    print(f"    α = {al}: {mpm.nstr(gmin(al), 8)}")
tw = sp.Rational(565, 100)
check(iv_sign(b2, {a: sp.Rational(783, 100), t: tw}) < 0,
      f"beyond 2π (outside every printed range): α = 783/100, t = 565/100: b2 = {iv_digits(b2, {a: sp.Rational(783, 100), t: tw})} < 0")
print("  Remark (grid only, NOT certified): the nonnegativity set continues beyond 2π with further components,")
print("  [β1, α3] ≈ [7.837, 10.904], [β2, α5] ≈ [14.13, 17.22], …, whose right ends are the 3rd, 5th, … positive roots")
print("  of tan α = α (b1(0) = 0 again) and whose left ends are interior double zeros of b2 (β1 ∈ (7.83, 7.84)).")

# ---- endpoint derivatives (orders 0..3)
forms0 = [  # (b0, b1, b2, b3) at t = 0
    [k * (a - S(a)), 2 * k * h, k * (a - S(a)), 0],
    [-k * (1 - C(a)), 0, k * (1 - C(a)), 0],
    [k * S(a), -2 * k * S(a), k * S(a), 0],
    [-k * C(a), k * (1 + 2 * C(a)), -k * (2 + C(a)), k],
]
txt0 = ["(k(α − sin α), 2k(sin α − α cos α), k(α − sin α), 0)",
        "(−k(1 − cos α), 0, k(1 − cos α), 0) = (−1, 0, 1, 0)/(2α)",
        "(k sin α, −2k sin α, k sin α, 0)",
        "(−k cos α, k(1 + 2cos α), −k(2 + cos α), k)"]
for kk in range(4):
    at0 = [sp.diff(f, t, kk).subs(t, 0) for f in b]
    atA = [sp.diff(f, t, kk).subs(t, a) for f in b]
    check(all(trig_zero(p - q, [a]) for p, q in zip(at0, forms0[kk])), f"order {kk} at t = 0: {txt0[kk]}")
    check(all(trig_zero(atA[i] - (-1) ** kk * forms0[kk][3 - i], [a]) for i in range(4)),
          f"order {kk} at t = α: b_i^({kk})(α) = (−1)^{kk} b_(3−i)^({kk})(0)")
P = sp.symbols("P0:4")
r = sum(f * p for f, p in zip(b, P))
check(trig_zero(sp.diff(r, t).subs(t, 0) - (P[2] - P[0]) / (2 * a), [a]), "r'(0) = (P2 − P0)/(2α)")
check(trig_zero(sp.diff(r, t, 2).subs(t, 0) - k * S(a) * (P[0] - 2 * P[1] + P[2]), [a]),
      "r''(0) = k sin α (P0 − 2P1 + P2) = sin α/(2α(1 − cos α))·(P0 − 2P1 + P2)")
print("done")
