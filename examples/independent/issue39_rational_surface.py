"""Issue 39: the exact corner table of the rational surface
`table --surface --net FILE` (a net with weights) checked by an independent
derivation in SymPy (a helper, not a project dependency).

For S(u, v) = sum_ij w_ij P_ij B_i(u) B_j(v) / sum_ij w_ij B_i(u) B_j(v)
the corner entry d^(a+b)S/du^a dv^b is derived here by SymPy's own diff of
the quotient (no Leibniz rule, no jets), with
  * the thesis cubic basis (5.2) = (3.7) of the thesis (seed 001,
    001_cf6c2ede0355a863.txt), typed from the thesis, in both directions
    with one symbolic m, derivatives in the angles theta = pi*u/2 (the
    table's default);
  * the weights read from examples/surfaces/thesis-net-weighted.txt by this
    script's own parser, the points kept as symbols P_ij;
and compared cell by cell with `trig-audit table --surface --net ... --format csv`
(every difference cancels to 0).

Run from the repository root:  python3 examples/independent/issue39_rational_surface.py
"""

import csv
import io
import os
import subprocess

import sympy as sp

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NET = "examples/surfaces/thesis-net-weighted.txt"
ORDER = 2
m, tu, tv = sp.symbols("m theta_u theta_v")


def thesis(th):
    s, c = sp.sin(th), sp.cos(th)  # thesis (5.2)
    return [
        (1 - s) ** 2 * (1 - m * s),
        m * s * (1 - s) ** 2 - 2 * s * (s - 1),
        m * c * (1 - c) ** 2 - 2 * c * (c - 1),
        (1 - c) ** 2 * (1 - m * c),
    ]


def weights(path):
    """[i][j] weights: net rows separated by blank lines, `x y z w` per line."""
    rows, row = [], []
    for line in open(os.path.join(ROOT, path)):
        line = line.strip()
        if line.startswith("#"):
            continue
        if not line:
            if row:
                rows.append(row)
            row = []
            continue
        row.append(sp.Rational(line.split()[3]))
    if row:
        rows.append(row)
    return rows


def cli(args):
    binary = os.path.join(ROOT, "target", "debug", "trig-audit")
    cmd = [binary] if os.path.exists(binary) else ["cargo", "run", "-q", "-p", "trig-audit", "--"]
    return subprocess.run(cmd + args, cwd=ROOT, capture_output=True, text=True, check=True).stdout


w = weights(NET)
bu, bv = thesis(tu), thesis(tv)
num = sum(w[i][j] * sp.Symbol(f"P{i}{j}") * bu[i] * bv[j] for i in range(4) for j in range(4))
den = sum(w[i][j] * bu[i] * bv[j] for i in range(4) for j in range(4))
surface = num / den
corners = {
    "corner u at its start, v at its start": (0, 0),
    "corner u at its start, v at its end": (0, sp.pi / 2),
    "corner u at its end, v at its start": (sp.pi / 2, 0),
    "corner u at its end, v at its end": (sp.pi / 2, sp.pi / 2),
}
text = cli(["table", "thesis-cubic", "--surface", "--net", NET, "--order", str(ORDER), "--format", "csv"])
checked = 0
for row in csv.DictReader(io.StringIO(text)):
    at_u, at_v = corners[row["table"]]
    a, b = int(row["row"]), int(row["column"])
    want = sp.diff(surface, tu, a, tv, b) if a + b else surface
    want = want.subs({tu: at_u, tv: at_v})
    got = sp.sympify(row["value"].replace("^", "**"))
    assert sp.cancel(sp.together(got - want)) == 0, (row, sp.factor(want))
    checked += 1
assert checked == 4 * (ORDER + 1) ** 2, checked
print(f"[ok] rational thesis cubic surface, weights of {NET}: {checked} entries (4 corners, a, b = 0..{ORDER}) agree")
print("     the weights, by net row:", [[str(x) for x in r] for r in w])
sample = [r for r in csv.DictReader(io.StringIO(text)) if r["row"] == "1" and r["column"] == "1"][0]
print("     e.g. d2S/du dv at (0, 0) =", sample["value"])
