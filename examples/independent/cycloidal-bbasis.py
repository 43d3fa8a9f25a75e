"""Part C8 (second example): normalised B-bases of the cycloidal spaces on [0, α]

  C4 = span{1, t, t², cos t, sin t}        (the quartic C-Bézier space of Chen & Wang, CAGD 20 (2003) 29-39),
  C5 = span{1, t, t², t³, cos t, sin t}    (the quintic one),

the higher-degree C-Bézier bases of the recursion quoted in BVP 2022, Definition 1 (printed α ∈ (0, π]).
The functions are computed here from the B-basis characterisation: b_i has a zero of order exactly i at 0 and
n − i at α (n = dim − 1), and Σ b_i = 1 fixes the constants (triangular system in the derivatives at 0; the
difference Σ b_i − 1 lies in the space and vanishes to order n at 0, hence ≡ 0 — unity is exact by construction).

Expected from theory (J. M. Carnicer, E. Mainar, J. M. Peña, "Critical length for design purposes and extended
Chebyshev spaces", Constr. Approx. 20 (2004) 55-71 — recalled, print not retrieved): a space with constants has a
normalised B-basis on [0, α] iff its derivative space is an extended Chebyshev space there. D(C4) = span{1, t, cos, sin}
(critical length 2π) and D(C5) = C4, whose critical length is ℓ = 2x*, tan x* = x* (ℓ ≈ 8.98681891581813;
it is where C4's Hermite problem with a triple zero at 0 and a double zero at α becomes singular — determinant
4(sin(α/2) − (α/2)cos(α/2))², proved below). So the nonnegativity of the normalised B-basis should end at
  C4: α = 2π (an exact multiple of π — NOT at ℓ, which is C4's own critical length), and
  C5: α = ℓ, the first positive root of tan(α/2) = α/2 (transcendental).
This script certifies sign changes on both sides of each end at rational α (interval arithmetic), and the
structural identity behind the C5 end; nonnegativity strictly inside is from the theorem (and a grid), not proved here.
"""

import sympy as sp
import mpmath as mpm
from _exact import check, iv_digits, iv_sign, root_enclosure, trig_zero

t, A, S, C, x = sp.symbols("t A S C x")   # A = α, S = sin α, C = cos α


def bbasis(space):
    """Normalised B-basis of span(space) on [0, α]; returns (b_i(t) as expressions in t, A, S, C)."""
    n = len(space) - 1
    ders0 = [[sp.diff(f, t, k).subs(t, 0) for f in space] for k in range(n + 1)]
    dersA = [[sp.expand(sp.expand_trig(sp.diff(f, t, k).subs(t, A))).subs({sp.sin(A): S, sp.cos(A): C}) for f in space]
             for k in range(n + 1)]
    F = []
    for i in range(n + 1):
        M = sp.Matrix(ders0[:i] + dersA[: n - i])
        c = [(-1) ** j * M[:, [k for k in range(n + 1) if k != j]].det(method="berkowitz") for j in range(n + 1)]
        F.append(c)
    k = []
    for j in range(n + 1):   # Σ_{i ≤ j} k_i F_i^{(j)}(0) = [j = 0]
        val = lambda c, kk: sum(ci * d for ci, d in zip(c, ders0[kk]))   # noqa: E731
        s_ = sum(k[i] * val(F[i], j) for i in range(j))
        k.append(((1 if j == 0 else 0) - s_) / val(F[j], j))
    return [k[i] * sum(ci * f for ci, f in zip(F[i], space)) for i in range(n + 1)]


def at(e, alpha, tt):
    """exact substitution: α, sin α, cos α, t (for iv_eval)."""
    return e.subs({A: alpha, S: sp.sin(alpha), C: sp.cos(alpha), t: tt})


# ---- C4's Hermite determinant (3 at 0, 2 at α): elements with a triple zero at 0 are d(cos t − 1 + t²/2) + e(sin t − t)
phi, psi = sp.cos(t) - 1 + t**2 / 2, sp.sin(t) - t
al = sp.Symbol("alpha")
Hm = sp.Matrix([[phi.subs(t, al), psi.subs(t, al)], [sp.diff(phi, t).subs(t, al), sp.diff(psi, t).subs(t, al)]])
check(trig_zero((Hm.det() - 4 * (sp.sin(al / 2) - al / 2 * sp.cos(al / 2)) ** 2).subs(al, 2 * x), [x]),
      "C4: the Hermite problem (triple zero at 0, double zero at α) has determinant 4(sin(α/2) − (α/2)cos(α/2))²:"
      " singular first at α = ℓ = 2x*, tan x* = x*")
mpm.mp.dps = 40
xs = mpm.findroot(lambda y: mpm.tan(y) - y, 4.4934)
print("  ℓ = 2x* ≈", mpm.nstr(2 * xs, 30))
lo, hi = sp.Rational("8.986818915818128350615761854560"), sp.Rational("8.986818915818128350615761854561")
check(root_enclosure(sp.sin(al / 2) - al / 2 * sp.cos(al / 2), al, lo, hi) == (1, -1),
      "certified: sin(α/2) − (α/2)cos(α/2) changes sign in [8.986818915818128350615761854560, …561] (ℓ inside)")

# ---- C4 = span{1, t, t², cos t, sin t}
b4 = bbasis([sp.Integer(1), t, t**2, sp.cos(t), sp.sin(t)])
print("C4: normalised B-basis of span{1, t, t², cos t, sin t} (quartic C-Bézier)")
for al0, sgn in [(sp.Rational(157, 25), 1), (sp.Rational(63, 10), -1)]:
    v = at(b4[2], al0, al0 / 2)
    check(iv_sign(v, {}) == sgn, f"  α = {al0}: b2(α/2) = {iv_digits(v, {})} ({'> 0, inside' if sgn > 0 else '< 0: outside'})")
v = at(b4[2], sp.Rational(8), 4)
check(iv_sign(v, {}) < 0, f"  α = 8 (< ℓ ≈ 8.987): b2(4) = {iv_digits(v, {})} < 0 — C4's nonnegativity ends at 2π, not at ℓ")
print("  ⇒ C4: nonnegative for α ∈ (0, 2π) (theorem + grid), fails just beyond 2π (certified); end 2π, exact.")

# ---- C5 = span{1, t, t², t³, cos t, sin t}
b5 = bbasis([sp.Integer(1), t, t**2, t**3, sp.cos(t), sp.sin(t)])
print("C5: normalised B-basis of span{1, t, t², t³, cos t, sin t} (quintic C-Bézier)")
for al0, sgn in [(sp.Rational(63, 10), 1), (sp.Rational(8), 1), (sp.Rational(898, 100), 1), (sp.Rational(8987, 1000), -1),
                 (sp.Rational(899, 100), -1), (sp.Rational(10), -1)]:
    v = at(b5[2], al0, al0 / 2)
    check(iv_sign(v, {}) == sgn, f"  α = {al0}: b2(α/2) = {iv_digits(v, {}, 20)} ({'> 0' if sgn > 0 else '< 0'})")
print("  (b3(t) = b2(α − t) by symmetry; ℓ ≈ 8.98682 lies between 4493/500 = 8.986 and 8987/1000 = 8.987:)")
v = at(b5[2], sp.Rational(4493, 500), sp.Rational(4493, 1000))
check(iv_sign(v, {}) > 0, f"  α = 4493/500 = 8.986 (just inside): b2(α/2) = {iv_digits(v, {}, 20)} > 0")
# the sign change is carried by a factor (sin(α/2) − (α/2)cos(α/2)) of the normalising constant:
D3 = al**3 * sp.sin(al) + 8 * al**2 * sp.cos(al) + 4 * al**2 - 24 * al * sp.sin(al) - 24 * sp.cos(al) + 24
check(trig_zero((D3 - 16 * (sp.sin(x) - x * sp.cos(x)) * (3 * sp.sin(x) - 3 * x * sp.cos(x) - x**2 * sp.sin(x))).subs(al, 2 * x), [x]),
      "the normalising constant of b2 has the factor D(α) = α³ sin α + 8α² cos α + 4α² − 24α sin α − 24 cos α + 24"
      " = 16 (sin x − x cos x)(3 sin x − 3x cos x − x² sin x), x = α/2 (simple zero at ℓ; the 2nd factor's first"
      " zero is at x ≈ 5.76, beyond)")
prod = [iv_sign(at(b5[2], a0, a0 / 2) * D3.subs(al, a0), {}) for a0 in (sp.Rational(4493, 500), sp.Rational(8987, 1000))]
check(prod[0] == prod[1] and iv_sign(D3.subs(al, sp.Rational(4493, 500)), {}) == -iv_sign(D3.subs(al, sp.Rational(8987, 1000)), {}),
      "D changes sign between 8.986 and 8.987 while b2(α/2)·D(α) does not: the sign change of b2 at ℓ is carried by D")
# grid cross-check
mpm.mp.dps = 30
print("  grid minima of b2 over 200 interior points (cross-check, not a proof):")
for al0 in ["3", "6", "8", "8.98", "8.99", "10"]:
    a0 = sp.Rational(al0)
    f = sp.lambdify(t, at(b5[2], a0, t), "mpmath")
    print(f"    α = {al0}: {mpm.nstr(min(f(mpm.mpf(al0) * j / 200) for j in range(1, 200)), 6)}")
print("  ⇒ C5: nonnegative exactly for α ∈ (0, ℓ] by the theorem, ℓ = 2x* ≈ 8.986818915818128 the first positive root")
print("    of tan(α/2) = α/2 (transcendental); b2(α/2) → 0 as α → ℓ (consistent with b2 ≡ b3 ≡ 0 at ℓ — not proved here).")
print("  The printed range α ∈ (0, π] is inside both maximal ranges.")
print("done")
