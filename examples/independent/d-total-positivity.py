"""Part D(d): total positivity (TP) and variation diminishing, decided exactly on bases outside the catalog.

Method (certificate): after an increasing change of variable (m = tan(t/2) ∈ [0, 1] on [0, π/2]; or the
variable itself on [0, 1]) a basis is b = N(x)/D(x) with D > 0 common to all functions. Write the numerators
in the Bernstein basis of degree d: N = M·B_d. Collocation matrices of N are M times collocation matrices of
B_d (TP), so if every minor of M is ≥ 0 (Cauchy–Binet) the basis is TP, hence variation diminishing, and a
normalised TP basis of planar curves is convexity preserving. The certificate can need degree elevation.
Refutation: a collocation matrix at exact points with a negative minor (1×1 = a negative value).
"""

import sympy as sp
from _exact import (check, describe_alg, numerator_posden, pyth, show_intervals, tp_certificate_set, trig_at,
                    trig_zero, weierstrass)

t, lam, m, x = sp.symbols("t lambda m x", real=True)
R = sp.Rational
s, c = sp.sin(t), sp.cos(t)


def show(iv):
    return " ∪ ".join(f"[{describe_alg(a)}, {describe_alg(b)}]" for a, b in iv) if iv else "∅"


# ---------------- Han 2002 quadratic (A1)
han = [(1 - s) * (1 - lam * s), (1 + lam) * (s + c - 1), (1 - c) * (1 - lam * c)]
N = [numerator_posden(weierstrass(f, t, m), m) for f in han]
iv, M = tp_certificate_set(N, m, lam, 4)
print("Han 2002 quadratic, m = tan(t/2), numerators over (1 + m²)², Bernstein degree 4:")
print("  M =", M.tolist())
check(iv == [(-1, 1)], "TP certificate set (all minors of M ≥ 0) = [−1, 1] = the nonnegativity range ⇒ TP exactly for λ ∈ [−1, 1]")
check(trig_at(han[0].subs(lam, 2), t, R(1, 2)) == R(-3, 25), "outside: λ = 2 at (sin, cos) = (4/5, 3/5): b0 = −3/25 (a negative 1×1 minor)")

# ---------------- Yan & Liang 2011 cubic (A2)
yl = [(1 - lam * x) * (1 - x) ** 3, x * (1 - x) ** 2 * (3 + lam * (1 - x)), x**2 * (1 - x) * (3 + lam * x), (1 - lam + lam * x) * x**3]
iv, M = tp_certificate_set(yl, x, lam, 4)
print("Yan & Liang cubic, Bernstein degree 4: M =", M.tolist())
check(iv == [(-3, 1)], "TP certificate set = [−3, 1] = the nonnegativity range ⇒ TP exactly for λ ∈ [−3, 1]")
check(yl[0].subs({lam: 2, x: R(3, 4)}) == R(-1, 128), "outside: λ = 2, t = 3/4: b0 = −1/128")

# ---------------- irrational-end (A7): degree elevation needed
k = (lam**2 - 4 * lam) / 4
u = x * (1 - x)
ie = [(1 - x) ** 2 * (1 - k * x**2), 2 * u * (1 + k * u), x**2 * (1 - k * (1 - x) ** 2)]
iv4, M4 = tp_certificate_set(ie, x, lam, 4)
iv6, _ = tp_certificate_set(ie, x, lam, 5)
print("irrational-end: certificate at degree 4:", show(iv4))
print("                certificate at degree 5:", show(iv6))
check(len(iv4) == 2 and sp.simplify(iv4[0][1] - (2 - sp.sqrt(2))) == 0 and sp.simplify(iv4[1][0] - (2 + sp.sqrt(2))) == 0,
      "degree 4 certifies only [2 − 2√2, 2 − √2] ∪ [2 + √2, 2 + 2√2]")
mnr = sp.factor(M4.extract([0, 1, 2], [1, 2, 3]).det())
check(sp.expand(mnr - (lam**2 - 4 * lam + 2) / 24) == 0,
      "  the failing minor: rows 0–2, columns 1–3 of the degree-4 matrix = (λ² − 4λ + 2)/24 < 0 on (2 − √2, 2 + √2)")
check(len(iv6) == 1 and sp.simplify(iv6[0][0] - (2 - 2 * sp.sqrt(2))) == 0 and sp.simplify(iv6[0][1] - (2 + 2 * sp.sqrt(2))) == 0,
      "after one degree elevation (degree 5): [2 − 2√2, 2 + 2√2] = the nonnegativity range ⇒ TP exactly there")
print("  degree-4 matrix:", M4.tolist())

# ---------------- squared Han basis (C7): nonnegative on [−1, 2 + 2√2], TP only on [−1, 1]
sq = [(1 - s) ** 2 * (1 - lam * s) ** 2, 1 - (1 - s) ** 2 * (1 - lam * s) ** 2 - (1 - c) ** 2 * (1 - lam * c) ** 2,
      (1 - c) ** 2 * (1 - lam * c) ** 2]
N = [numerator_posden(weierstrass(f, t, m), m) for f in sq]
iv, _ = tp_certificate_set(N, m, lam, 8)
print("squares-han, numerators over (1 + m²)⁴, Bernstein degree 8:", show(iv))
check(iv == [(-1, 1)], "TP certificate set = [−1, 1] (strictly inside the nonnegativity range [−1, 2 + 2√2])")
# refutation for λ ∈ (1, 2 + 2√2]: b0 vanishes at sin t1 = 1/λ inside (0, π/2) and is > 0 after it
l0 = R(5, 4)
m1, m2 = R(1, 2), R(3, 4)          # (sin, cos) = (4/5, 3/5): sin t1 = 4/5 = 1/λ;  (24/25, 7/25) later
v = [[trig_at(sq[i].subs(lam, l0), t, mm) for i in (0, 1)] for mm in (m1, m2)]
minor = v[0][0] * v[1][1] - v[0][1] * v[1][0]
print(f"  λ = 5/4: collocation rows (b0, b1) at (sin, cos) = (4/5, 3/5) and (24/25, 7/25): {v}")
check(v[0][0] == 0 and minor < 0, f"  2×2 minor det[[b0(t1), b1(t1)], [b0(t2), b1(t2)]] = {minor} < 0 with t1 < t2: NOT TP at λ = 5/4")
print("  general λ ∈ (1, 2 + 2√2]: b0(t1) = 0 at sin t1 = 1/λ, b0(t2) > 0 for t2 ∈ (t1, π/2), b1(t1) > 0 (F1, F2 > 0 there)")
print("  ⇒ that minor is −b1(t1)b0(t2) < 0: TP holds exactly for λ ∈ [−1, 1] (nonnegativity: [−1, 2 + 2√2]).")
check(sp.simplify(sq[0].subs({lam: 2, t: sp.pi / 6})) == 0 and
      sp.simplify(sq[0].subs({lam: 2, t: sp.pi / 3}) - (1 - sp.sqrt(3) / 2) ** 2 * (1 - sp.sqrt(3)) ** 2) == 0,
      "  λ = 2: b0(π/6) = 0 (sin = 1/2) while b0(π/3) = (1 − √3/2)²(1 − √3)² > 0: same mechanism")

# ---------------- quadratic C-Bézier (B4): a rational Bernstein basis with w = cos(α/2)
print("quadratic C-Bézier: b_i = rational quadratic Bernstein in u = sin(t/2)/(sin(t/2) + sin((α − t)/2)) with w = cos(α/2)")
a, xx, yy = sp.symbols("alpha xx yy")
uu = sp.sin(t / 2) / (sp.sin(t / 2) + sp.sin((a - t) / 2))
du = sp.diff(uu, t)
check(trig_zero((du - sp.sin(a / 2) / (2 * (sp.sin(t / 2) + sp.sin((a - t) / 2)) ** 2)).subs({t: 2 * xx, a: 2 * yy}), [xx, yy]),
      "u'(t) = sin(α/2)/(2(sin(t/2) + sin((α − t)/2))²) > 0: increasing from 0 to 1")
print("  numerators (1 − u)², 2w u(1 − u), u² in the Bernstein basis of degree 2: M = diag(1, w, 1):")
print("  all minors ≥ 0 ⇔ w = cos(α/2) ≥ 0 ⇔ α ∈ (0, π]: TP (and VD) exactly on the nonnegativity range.")
print("quartic trigonometric B-basis (C4): b_i = C_i (x + y)⁴ · (1 − u)^{4−i} u^i with u = y/(x + y) increasing,")
print("  C = (1, 4c, 2 + 4c², 4c, 1)/sin⁴(α/2)·(binomials removed): M = diag(1, c, (1 + 2c²)/3, c, 1) ⇒ TP ⇔ c = cos(α/2) ≥ 0.")
cc, X, Y = sp.symbols("c X Y", positive=True)
Cq = [1, 4 * cc, 2 + 4 * cc**2, 4 * cc, 1]
Uq = Y / (X + Y)
check(all(sp.simplify(Cq[i] * X ** (4 - i) * Y**i - (X + Y) ** 4 * Cq[i] / sp.binomial(4, i) * sp.binomial(4, i) * (1 - Uq) ** (4 - i) * Uq**i) == 0
          for i in range(5)), "  b_i·sin⁴(α/2) = (x + y)⁴·[C_i/C(4, i)]·C(4, i)(1 − u)^{4−i}u^i, u = y/(x + y) (the same u as above)")
print("Consequences: where TP holds the basis is variation diminishing (a curve crosses a line no more often than its")
print("control polygon), and, being normalised, convexity preserving for planar curves.")
print("done")
