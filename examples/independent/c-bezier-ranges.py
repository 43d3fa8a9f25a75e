"""Part C2: maximal ranges of the quadratic and cubic C-Bézier bases on [0, α], with certified witnesses.

Quadratic (B4; BVP 2022 eq. (2), printed α ∈ (0, π]):
  b0 = (1 − cos(α − t))/(1 − cos α),  b1 = −(1 − cos t + cos α − cos(α − t))/(1 − cos α),  b2 = (1 − cos t)/(1 − cos α)
     = 2 cos(α/2) sin(t/2) sin((α − t)/2)/sin²(α/2)  (middle function, proved in trig-quadratic-bbasis.py).
Cubic (B1; Zhang 1996, Chen & Wang 2003), A = α − sin α, g = 2 − 2cos α − α sin α,
  N(τ) = A(1 − cos τ) − (1 − cos α)(τ − sin τ):  b3 = (t − sin t)/A, b2 = (1 − cos α)N(t)/(A g), b1 = b2(α − t), b0 = b3(α − t).
The maximal sets themselves are proved in trig-quadratic-bbasis.py (quadratic: (0, π]) and c-bezier-cubic.py
(cubic: (0, 2π)); this script adds the certified witnesses on both sides of each end, for the spec files
c-bezier-quadratic.toml and c-bezier-cubic-2pi.toml. Derivatives w.r.t. t.
"""

import sympy as sp
from _exact import check, iv_digits, iv_sign, trig_zero

t, a = sp.symbols("t alpha", positive=True)
S, C = sp.sin, sp.cos
R = sp.Rational

# ---------------- quadratic
q = [(1 - C(a - t)) / (1 - C(a)), -(1 - C(t) + C(a) - C(a - t)) / (1 - C(a)), (1 - C(t)) / (1 - C(a))]
q1 = 2 * C(a / 2) * S(t / 2) * S((a - t) / 2) / S(a / 2) ** 2
x, y = sp.symbols("x y")
check(trig_zero((q[1] - q1).subs({t: 2 * x, a: 2 * y}), [x, y]), "quadratic: b1 = 2 cos(α/2) sin(t/2) sin((α − t)/2)/sin²(α/2)")
print("quadratic C-Bézier: nonnegative exactly for α ∈ (0, π] (closed at π, where b1 ≡ 0: not a basis there).")
v = iv_digits(q[1], {a: R(315, 100), t: R(315, 200)})
check(iv_sign(q[1], {a: R(315, 100), t: R(315, 200)}) < 0, f"  just outside: α = 63/20 = 3.15 > π, t = α/2 = 63/40: b1 = {v} < 0")
check(iv_sign(C(a / 2), {a: R(314, 100)}) > 0,
      "  just inside: α = 157/50 = 3.14 < π: cos(α/2) > 0, so b1 ≥ 0 on [0, α] (sin(t/2), sin((α−t)/2) ≥ 0)")
check(sp.simplify(q1.subs({a: 4 * sp.pi / 3, t: 2 * sp.pi / 3})) == -1, "  exact witness: α = 4π/3, t = 2π/3: b1 = −1")
check(sp.simplify(q[1].subs(a, sp.pi)) == 0, "  α = π: b1 ≡ 0 (the printed closed end is nonnegative but degenerate)")
print("  α ≥ 2π: α = 2kπ undefined (1 − cos α = 0); otherwise sin(t/2) sin((α−t)/2) takes both signs on [0, α].")

# ---------------- cubic
A = a - S(a)
g = 2 - 2 * C(a) - a * S(a)
N = lambda u: A * (1 - C(u)) - (1 - C(a)) * (u - S(u))   # noqa: E731
b2 = (1 - C(a)) * N(t) / (A * g)
b1 = b2.subs(t, a - t)
print("cubic C-Bézier: nonnegative exactly for α ∈ (0, 2π) (open: at 2π, 1 − cos α = g = 0).")
v = iv_digits(b2, {a: R(63, 10), t: R(1, 10)})
check(iv_sign(b2, {a: R(63, 10), t: R(1, 10)}) < 0,
      f"  just outside: α = 63/10 = 6.3 > 2π, t = 1/10: b2 = {v} < 0  (g(6.3) < 0, N > 0 near 0)")
check(iv_sign(g, {a: R(63, 10)}) < 0 and iv_sign(N(t), {a: R(63, 10), t: R(1, 10)}) > 0, "  … with g(63/10) < 0 and N(1/10) > 0 certified")
v = iv_digits(b1, {a: R(63, 10), t: R(1, 10)})
print(f"    (b1 at the same point: {v}; b1(t) = b2(α − t))")
check(iv_sign(g, {a: R(628, 100)}) > 0 and iv_sign(A, {a: R(628, 100)}) > 0 and iv_sign(1 - C(a), {a: R(628, 100)}) > 0,
      "  just inside: α = 157/25 = 6.28 < 2π: A, g, 1 − cos α > 0 (certified), so all b_i ≥ 0 by the proof in c-bezier-cubic.py")
print("  α > 2π, cos α ≠ 1: N(2π) = −2π(1 − cos α) < 0 while N > 0 near 0: b2 takes both signs (see B1).")
print("  α = 3π (exact): b1(π) = −2/3 (c-bezier-cubic.py).")
check(sp.simplify(b1.subs(a, 3 * sp.pi).subs(t, sp.pi)) == R(-2, 3), "  exact witness: α = 3π, t = π: b1 = −2/3")
print("done")
