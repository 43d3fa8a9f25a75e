"""Issue 41: an independent check of the spec-language options added in session 5
(identity `curves`, `diff(EXPR, NAME)`, `let`, `change`; join `factors` and
`orientation = "reversed"`; the checks `surface-join`, `same-basis`, `fourier-span`)
on two published bases with two shape parameters each, neither in examples/catalog/:

  GB2  X.-A. Han, Y.-C. Ma, X.-L. Huang, "A novel generalization of Bézier curve and
       surface", J. Comput. Appl. Math. 217 (2008) 180–193, as quoted in Hu, Bo & Qin,
       J. Inequal. Appl. 2017:115, Def. 1, n = 2 (examples/gb2-independence.toml):
         b0 = (1 − t)²(1 − λ1 t), b1 = t(1 − t)(2 + λ1 − λ1 t + λ2 t),
         b2 = t²(1 − λ2 + λ2 t),  t ∈ [0, 1], λ1, λ2 ∈ [−2, 1];

  HMH  X.-A. Han, Y. Ma, X. Huang, "The cubic trigonometric Bézier curve with two shape
       parameters", Appl. Math. Lett. 22 (2009) 226–231 (examples/han-ma-huang-cubic.toml):
         b0 = (1 − s)²(1 − λs), b1 = s(1 − s)(2 + λ − λs),
         b2 = c(1 − c)(2 + μ − μc), b3 = (1 − c)²(1 − μc),
         s = sin t, c = cos t, t ∈ [0, π/2], λ, μ ∈ [−2, 1].

Expected verdicts and values for examples/two-shape-options/ (document.toml, the
listing surface-nets.txt, the copies hmh-shifted.toml and hmh-garbled.toml), asserted
by tests/tests/options_independent.rs. SymPy only, no project code:
    python3 examples/independent/two_shape_options.py
"""

import sympy as sp
from sympy import Rational as R

t, x, x_i, h = sp.symbols("t x x_i h")
l1, l2, lam, mu = sp.symbols("lambda1 lambda2 lambda mu")
lam1, mu1, lam2, mu2, omega, kappa = sp.symbols("lambda1 mu1 lambda2 mu2 omega kappa")
V0, V1, V2, Y, y0, y1, d0, d1, f0, f1 = sp.symbols("V0 V1 V2 Y y0 y1 d0 d1 f0 f1")
P = sp.symbols("P0:4")
Q = sp.symbols("Q0:4")


def check(ok, what):
    assert ok, what
    print("  ok  " + what)


def zero(e):
    return sp.simplify(sp.expand(e)) == 0


def gb2(a, b, v=t):
    return [(1 - v) ** 2 * (1 - a * v), v * (1 - v) * (2 + a - a * v + b * v), v**2 * (1 - b + b * v)]


def hmh(a, b, v=t):
    s, c = sp.sin(v), sp.cos(v)
    return [(1 - s) ** 2 * (1 - a * s), s * (1 - s) * (2 + a - a * s),
            c * (1 - c) * (2 + b - b * c), (1 - c) ** 2 * (1 - b * c)]


G = gb2(l1, l2)
H = hmh(lam, mu)
print("GB2 and HMH")
check(zero(sum(G) - 1) and zero(sum(H) - 1), "both are partitions of unity")

# ------------------------------------------------------------------ diff (GB2)
print("diff(EXPR, NAME): the least-squares normal equation (TS-diff, TS-diff-sign)")
r = V0 * G[0] + V1 * G[1] + V2 * G[2] - Y
check(zero(sp.diff(r**2, V1) / 2 - G[1] * r), "∂/∂V1 (r²)/2 = b1·r, r = V0b0 + V1b1 + V2b2 − Y")
check(zero(sp.diff(r**2, Y) + 2 * r), "∂/∂Y r² = −2r")
# the deliberate wrong sign: ∂/∂V2 r² printed −2·b2·r
res = sp.expand(sp.diff(r**2, V2) - (-2 * G[2] * r))
check(zero(res - 4 * G[2] * r), "the print ∂/∂V2 r² = −2 b2 r fails: residual 4 b2 r (value 2 b2 r, target −2 b2 r)")

# ------------------------------------------------------------------ let (GB2)
print("let: names of the claim (TS-let)")
S1, S2 = 2 + l1, 2 + l2
K = G[1] - G[0]
E = G[0] + G[1]
check(zero(sp.diff(K, t).subs(t, 0) - 2 * S1), "K = b1 − b0: K'(0) = 2·S1, S1 = 2 + λ1")
check(zero(sp.diff(E, t).subs(t, 1) + S2), "E = b0 + b1: E'(1) = −S2, S2 = 2 + λ2")
k_half = sp.expand(K.subs(t, R(1, 2)))
print("  K(1/2) =", k_half)
check(zero(k_half - (2 + 2 * l1 + l2) / 8), "K(1/2) = (2 + 2λ1 + λ2)/8")
check(zero(E + G[2] - 1), "E + b2 = 1 (a bare name: the function at the variable)")
e_half = sp.expand(E.subs(t, R(1, 2)))
print("  E(1/2) =", e_half)
check(zero(e_half - (R(3, 4) + l2 / 8)), "E(1/2) = 3/4 + λ2/8 (b2(1/2) = (2 − λ2)/8 = 1/4 − λ2/8)")

# ------------------------------------------------------------------ change (GB2)
print("change = { x = (x − x_i)/h } with a curve of printed points (TS-change, TS-change-sign)")
Gx = gb2(l1, l2, (x - x_i) / h)
Hc = y0 * Gx[0] + (y0 + h * d0 / (2 + l1)) * Gx[1] + y1 * Gx[2]
check(zero(Hc.subs(x, x_i) - y0), "H(x_i) = y0")
check(zero(Hc.subs(x, x_i + h) - y1), "H(x_i + h) = y1")
check(zero(sp.diff(Hc, x).subs(x, x_i) - d0), "H'(x_i) = d0 (derivative in x)")
check(zero(sp.diff(Gx[2], x).subs(x, x_i + h) - (2 + l2) / h), "b2'(x_i + h) = (2 + λ2)/h")
check(zero(sp.diff(Gx[0], x, 2).subs(x, x_i) - 2 * (1 + 2 * l1) / h**2), "b0''(x_i) = 2(1 + 2λ1)/h²")
b1end = sp.factor(sp.diff(Gx[1], x).subs(x, x_i + h))
print("  b1'(x_i + h) =", b1end)
check(zero(b1end + (2 + l2) / h), "b1'(x_i + h) = −(2 + λ2)/h: the print (2 + λ2)/h fails, residual −2(2 + λ2)/h")
check(b1end.subs({h: 1, l2: 0}) == -2, "  at h = 1, λ2 = 0: value −2, target 2")

# ------------------------------------------------------------------ curves (HMH)
print("curves: a Hermite-type curve of printed points (TS-curves, TS-curves-sign)")
pts = [f0, f0 + d0 / (2 + lam), f1 - d1 / (2 + mu), f1]
rc = sum(b * p for b, p in zip(H, pts))
check(zero(rc.subs(t, 0) - f0) and zero(rc.subs(t, sp.pi / 2) - f1), "r(0) = f0, r(π/2) = f1")
check(zero(sp.diff(rc, t).subs(t, 0) - d0), "r'(0) = d0")
check(zero(sp.diff(rc, t).subs(t, sp.pi / 2) - d1), "r'(π/2) = d1")
r2_0 = sp.expand(sp.simplify(sp.diff(rc, t, 2).subs(t, 0)))
print("  r''(0) =", sp.collect(r2_0, [d0, d1, f0, f1]))
check(zero(r2_0 - (2 * (f1 - f0) - 4 * (1 + lam) * d0 / (2 + lam) - 2 * d1 / (2 + mu))),
      "r''(0) = 2(f1 − f0) − 4(1 + λ)d0/(2 + λ) − 2d1/(2 + μ)")
# garbled: the sign of the d1 term flipped
wrong = 2 * (f1 - f0) - 4 * (1 + lam) * d0 / (2 + lam) + 2 * d1 / (2 + mu)
check(zero(r2_0 - wrong + 4 * d1 / (2 + mu)), "the print with + 2d1/(2 + μ) fails: residual −4d1/(2 + μ)")
b_end = [sp.simplify(sp.diff(b, t, k).subs(t, e)) for k in (1, 2) for e in (0, sp.pi / 2) for b in H]
print("  b_i'(0), b_i'(π/2), b_i''(0), b_i''(π/2):", b_end)

# ------------------------------------------------------------------ joins (HMH, different)
print("join factors and orientation (TS-G1-reversed, TS-G1-forward, TS-G1-sign, TS-G1-mismatch, TS-G2-reversed)")
Pc = sum(b * p for b, p in zip(hmh(lam1, mu1), P))
Qc = sum(b * p for b, p in zip(hmh(lam2, mu2), Q))
P1e = sp.simplify(sp.diff(Pc, t).subs(t, sp.pi / 2))
P2e = sp.simplify(sp.diff(Pc, t, 2).subs(t, sp.pi / 2))
Q1s = sp.simplify(sp.diff(Qc, t).subs(t, 0))
Q2s = sp.simplify(sp.diff(Qc, t, 2).subs(t, 0))
check(zero(P1e - (2 + mu1) * (P[3] - P[2])), "P'(π/2) = (2 + μ1)(P3 − P2)")
check(zero(Q1s - (2 + lam2) * (Q[1] - Q[0])), "Q'(0) = (2 + λ2)(Q1 − Q0)")
print("  P''(π/2) =", sp.collect(sp.expand(P2e), P))
print("  Q''(0) =", sp.collect(sp.expand(Q2s), Q))
# reversed G1: P'(π/2) = ω Q'(0)
q1_rev = P[3] + (2 + mu1) * (P[3] - P[2]) / (omega * (2 + lam2))
check(zero(P1e - omega * Q1s.subs({Q[0]: P[3], Q[1]: q1_rev})), "reversed: Q1 = P3 + (2 + μ1)(P3 − P2)/(ω(2 + λ2)) gives P' = ωQ'")
q1_fwd = P[3] + omega * (2 + mu1) * (P[3] - P[2]) / (2 + lam2)
check(zero(Q1s.subs({Q[0]: P[3], Q[1]: q1_fwd}) - omega * P1e), "forward: Q1 = P3 + ω(2 + μ1)(P3 − P2)/(2 + λ2) gives Q' = ωP'")
# the reversed formula read forward: residual Q'(0) − ωP'(π/2)
mism = sp.factor(Q1s.subs({Q[0]: P[3], Q[1]: q1_rev}) - omega * P1e)
print("  reversed print read forward, Q'(0) − ωP'(π/2) =", mism)
check(zero(mism - (1 - omega**2) * (2 + mu1) * (P[3] - P[2]) / omega), "= (1 − ω²)(2 + μ1)(P3 − P2)/ω: fails unless ω = 1")
q1_sign = P[3] - (2 + mu1) * (P[3] - P[2]) / (omega * (2 + lam2))
check(not zero(P1e - omega * Q1s.subs({Q[0]: P[3], Q[1]: q1_sign})), "the print with − fails (reversed)")
# reversed G2: P''(π/2) = ω² Q''(0) + κ Q'(0); solve for Q2
Q2sym = sp.Symbol("Q2")
eq = sp.expand(P2e - omega**2 * Q2s.subs({Q[0]: P[3], Q[1]: q1_rev}) - kappa * Q1s.subs({Q[0]: P[3], Q[1]: q1_rev}))
q2_rev = sp.solve(eq, Q2sym)[0]
q2_rev = sp.collect(sp.expand(q2_rev), P, sp.factor)
print("  reversed G2: Q2 =", q2_rev)
# as the document prints it: Q2 = P3 + P''(π/2)/(2ω²) + (2(1 + λ2)/(ω(2 + λ2)) − κ/(2ω³))(2 + μ1)(P3 − P2)
q2_print = (P[3] + (2 * P[1] - 4 * (1 + mu1) * P[2] + (4 * mu1 + 2) * P[3]) / (2 * omega**2)
            + (2 * (1 + lam2) / (omega * (2 + lam2)) - kappa / (2 * omega**3)) * (2 + mu1) * (P[3] - P[2]))
print("  printed Q2 − solved =", sp.simplify(q2_print - q2_rev))
check(zero(q2_print - q2_rev), "the printed Q2 (document TS-G2-reversed) is the solved one")

# ------------------------------------------------------------------ surface join (HMH at λ = 1/2, μ = −1)
print("surface-join over the nets of surface-nets.txt (TS-surface-C1, TS-surface-C2, TS-surface-sign)")
at = {lam: R(1, 2), mu: -1}
Hs = [b.subs(at) for b in H]
k = (2 + mu) / (2 + lam)
k = k.subs(at)
check(k == R(2, 5), "C1 factor (2 + μ)/(2 + λ) = 2/5 at λ = 1/2, μ = −1")
# the listing: P the 4 × 4 net P0..P15, point Pn = (n mod 4, n div 4, (n mod 4)·(n div 4) mod 3)
def pnt(n):
    return sp.Matrix([n % 4, n // 4, ((n % 4) * (n // 4)) % 3])
Pn = [pnt(n) for n in range(16)]
rows = [[Pn[4 * r + j] for j in range(4)] for r in range(4)]
def qrow(row, sign):
    a, b = row[3], row[3] + sign * k * (row[3] - row[2])
    return [a, b, b + sp.Matrix([1, 0, 0]), b + sp.Matrix([2, 1, 0])]
Qrows = [qrow(rw, 1) for rw in rows]
Rrows = [qrow(rw, -1) for rw in rows]
def line(pts, k_, e):
    return sp.simplify(sum((sp.diff(b, t, k_).subs(t, e) * p for b, p in zip(Hs, pts)), sp.zeros(3, 1)))
jumps1 = [line(Qrows[r], 1, 0) - line(rows[r], 1, sp.pi / 2) for r in range(4)]
jumps0 = [line(Qrows[r], 0, 0) - line(rows[r], 0, sp.pi / 2) for r in range(4)]
check(all(j == sp.zeros(3, 1) for j in jumps0 + jumps1), "seam P | Q: every row joins C1")
jumps2 = [sp.simplify(line(Qrows[r], 2, 0) - line(rows[r], 2, sp.pi / 2)) for r in range(4)]
print("  seam P | Q, order-2 jumps of the rows:", [list(j) for j in jumps2])
check(any(j != sp.zeros(3, 1) for j in jumps2), "seam P | Q is not C2")
rj = [sp.simplify(line(Rrows[r], 1, 0) - line(rows[r], 1, sp.pi / 2)) for r in range(4)]
print("  seam P | R, order-1 jumps of the rows:", [list(j) for j in rj])
check(all(j == -2 * (2 + mu).subs(at) * (rows[r][3] - rows[r][2]) for r, j in enumerate(rj)),
      "seam P | R (sign flipped): order-1 jump of row r = −2(2 + μ)(P_{4r+3} − P_{4r+2}) = −2(P_{4r+3} − P_{4r+2})")
# row seam P ; T: T's first row = P's last row, second row = P's last + k·(last − third)
Trows = [rows[3], [rows[3][j] + k * (rows[3][j] - rows[2][j]) for j in range(4)],
         [rows[3][j] + sp.Matrix([0, 0, 1]) for j in range(4)], [rows[3][j] + sp.Matrix([0, 0, 2]) for j in range(4)]]
cols = lambda net: [[net[i][j] for i in range(4)] for j in range(4)]
cj = [line(cols(Trows)[j], 1, 0) - line(cols(rows)[j], 1, sp.pi / 2) for j in range(4)]
cj0 = [line(cols(Trows)[j], 0, 0) - line(cols(rows)[j], 0, sp.pi / 2) for j in range(4)]
check(all(j == sp.zeros(3, 1) for j in cj + cj0), "seam P ; T: every column joins C1")

# ------------------------------------------------------------------ same-basis (HMH copies)
print("same-basis (TS-same, TS-same-wrong-map, TS-same-garbled)")
u, p, q = sp.symbols("u p q")
S_, C_ = sp.sin(sp.pi * u / 2), sp.cos(sp.pi * u / 2)
shifted = [(1 - S_) ** 2 * (1 + 2 * S_ - p * S_), S_ * (1 - S_) * (p + 2 * S_ - p * S_),
           C_ * (1 - C_) * (3 - q - C_ + q * C_), (1 - C_) ** 2 * (1 - C_ + q * C_)]
Hu = hmh(lam, mu, sp.pi * u / 2)
check(all(zero(a - b.subs({lam: p - 2, mu: 1 - q})) for a, b in zip(shifted, Hu)),
      "the copy in u ∈ [0, 1], θ = πu/2, is HMH with λ = p − 2, μ = 1 − q; λ ∈ [−2, 1] ⇔ p ∈ [0, 3], μ ∈ [−2, 1] ⇔ q ∈ [0, 3]")
wrong_map = [sp.factor(a - b.subs({lam: p - 2, mu: q - 1})) for a, b in zip(shifted, Hu)]
print("  with μ = q − 1:", wrong_map)
check(zero(wrong_map[0]) and zero(wrong_map[1]) and zero(wrong_map[2] + 2 * C_ * (q - 1) * (1 - C_) ** 2)
      and zero(wrong_map[3] - 2 * C_ * (q - 1) * (1 - C_) ** 2),
      "μ = q − 1: b0, b1 agree; b2, b3 differ by ∓2c(q − 1)(1 − c)²")
wpt = {u: R(1, 2), p: 0, q: 0}
check(zero(shifted[2].subs(wpt) - (R(7, 4) * sp.sqrt(2) - 2)) and zero(Hu[2].subs({lam: -2, mu: -1}).subs(wpt) - sp.sqrt(2) / 4),
      "  witness at u = 1/2, p = q = 0: b2 = 7√2/4 − 2, the other's b2 = √2/4")
garbled = list(shifted)
garbled[2] = C_ * (1 - C_) * (3 - q + C_ + q * C_)   # the sign of the middle c flipped
gres = [sp.factor(a - b.subs({lam: p - 2, mu: 1 - q})) for a, b in zip(garbled, Hu)]
print("  garbled copy (b2 with + c):", gres)
check(zero(gres[2] - 2 * C_**2 * (1 - C_)) and all(zero(g) for i, g in enumerate(gres) if i != 2),
      "garbled copy: only b2 differs, residual 2c²(1 − c)")
check(zero(gres[2].subs(wpt) - (1 - sp.sqrt(2) / 2)), "  at u = 1/2: residual 1 − √2/2")

# ------------------------------------------------------------------ fourier-span (HMH at λ = 1, μ = −2)
print("fourier-span (TS-span, TS-span-missing, TS-span-free)")
at2 = {lam: 1, mu: -2}
def fourier(f):
    f = sp.expand(sp.expand_trig(f))
    c0 = sp.integrate(f, (t, -sp.pi, sp.pi)) / (2 * sp.pi)
    out = {"1": sp.simplify(c0)}
    for n in range(1, 5):
        out[f"cos {n}t"] = sp.simplify(sp.integrate(f * sp.cos(n * t), (t, -sp.pi, sp.pi)) / sp.pi)
        out[f"sin {n}t"] = sp.simplify(sp.integrate(f * sp.sin(n * t), (t, -sp.pi, sp.pi)) / sp.pi)
    return {kk: v for kk, v in out.items() if v != 0}
F = [fourier(b.subs(at2)) for b in H]
for i, f in enumerate(F):
    print(f"  b{i} at λ = 1, μ = −2:", f)
check(F[0] == {"1": R(5, 2), "cos 2t": R(-3, 2), "sin 1t": R(-15, 4), "sin 3t": R(1, 4)}, "b0 = 5/2 − 15/4 sin t − 3/2 cos 2t + 1/4 sin 3t")
check(F[1] == {"1": -2, "cos 2t": 2, "sin 1t": R(15, 4), "sin 3t": R(-1, 4)}, "b1 = −2 + 15/4 sin t + 2 cos 2t − 1/4 sin 3t")
check(F[2] == {"1": 1, "cos 1t": R(-3, 2), "cos 2t": 1, "cos 3t": R(-1, 2)}, "b2 = 1 − 3/2 cos t + cos 2t − 1/2 cos 3t")
check(F[3] == {"1": R(-1, 2), "cos 1t": R(3, 2), "cos 2t": R(-3, 2), "cos 3t": R(1, 2)}, "b3 = −1/2 + 3/2 cos t − 3/2 cos 2t + 1/2 cos 3t")
check(all("sin 2t" not in f for f in F), "no function has sin 2t: the span {1, sin t, cos t, cos 2t, sin 3t, cos 3t} holds (sin 2t omitted)")
check([f.get("cos 2t") for f in F] == [R(-3, 2), 2, 1, R(-3, 2)], "without cos 2t it fails: coefficients −3/2, 2, 1, −3/2")
Ffree = [fourier(b) for b in H]
check(all("sin 2t" not in f for f in Ffree), "for every λ, μ no sin 2t either (b0, b1 in s only, b2, b3 in c only)")
# ------------------------------------------------------------ shape-effect (session 6)
print("shape-effect: parameters (concurrent), onto, either (SE-*)")
l1, l2 = sp.symbols("lambda1 lambda2")
s_, c_ = sp.symbols("s c")
G12 = gb2(l1, l2)
total = [sp.factor(sp.diff(b, l1) + sp.diff(b, l2)) for b in G12]
check(sp.simplify(total[0] + t * (1 - t) ** 2) == 0 and sp.simplify(total[1] - t * (1 - t)) == 0
      and sp.simplify(total[2] + t**2 * (1 - t)) == 0,
      "GB2 total derivatives in λ1 + λ2: −t(1 − t)², t(1 − t), −t²(1 − t) (b1 has both parameters)")
grid = [R(k, 20) for k in range(21)]
check(all(total[0].subs(t, x) <= 0 <= total[1].subs(t, x) and total[2].subs(t, x) <= 0 for x in grid),
      "  ends fall, inner rises on [0, 1] (the factors' signs; checked on a grid too): SE-both holds, SE-both-away fails")
check(total[0].subs(t, R(1, 2)) == R(-1, 8), "  SE-both-away witness at t = 1/2: ∂b0/∂λ1 + ∂b0/∂λ2 = −1/8")
Hs = [(1 - s_) ** 2 * (1 - lam * s_), s_ * (1 - s_) * (2 + lam - lam * s_),
      c_ * (1 - c_) * (2 + mu - mu * c_), (1 - c_) ** 2 * (1 - mu * c_)]
dmu = [sp.factor(sp.diff(b, mu)) for b in Hs]
check(dmu[0] == 0 and dmu[1] == 0 and sp.simplify(dmu[2] - c_ * (1 - c_) ** 2) == 0
      and sp.simplify(dmu[3] + c_ * (1 - c_) ** 2) == 0,
      "HMH ∂/∂μ: 0, 0, c(1 − c)², −c(1 − c)²: weight moves onto P2 as μ grows (SE-onto holds)")
check(dmu[2].subs(c_, R(3, 5)) == R(12, 125),
      "  onto P3 fails (SE-onto-wrong): ∂b2/∂μ = 12/125 > 0 at c = 3/5; as μ decreases it holds (SE-onto-either)")
print("all expected values derived")
