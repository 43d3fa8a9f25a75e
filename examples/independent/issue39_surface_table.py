"""Issue 39: the exact corner table of `table --surface` checked by an
independent derivation in SymPy (a helper, not a project dependency).

For S(u, v) = sum_i sum_j P_ij B_i(u) B_j(v) the corner entry
d^(a+b)S/du^a dv^b at (u0, v0) is sum_ij P_ij B_i^(a)(u0) B_j^(b)(v0).
Derived here with SymPy's own diff for
  1. the thesis cubic surface, basis (5.2) = (3.7) of the thesis (seed 001,
     001_cf6c2ede0355a863.txt), typed from the thesis, in both directions,
     derivatives in the angle theta = pi*u/2 (the table's default);
  2. the thesis cubic in u and the spec file examples/han-quadratic.toml in v
     (its formulas read from the TOML text and parsed by SymPy), the v
     parameter lambda called lambda_v as the table names it;
and compared cell by cell with `trig-audit table --surface --format csv`
(every difference simplifies to 0).

Run from the repository root:  python3 examples/independent/issue39_surface_table.py
"""

import csv
import io
import os
import re
import subprocess
import tomllib

import sympy as sp

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ORDER = 3
th, m, t = sp.symbols("theta m t")
s, c = sp.sin(th), sp.cos(th)
# thesis (5.2), in s = sin(pi u/2), c = cos(pi u/2)
THESIS = [
    (1 - s) ** 2 * (1 - m * s),
    m * s * (1 - s) ** 2 - 2 * s * (s - 1),
    m * c * (1 - c) ** 2 - 2 * c * (c - 1),
    (1 - c) ** 2 * (1 - m * c),
]


def spec_functions(path, suffix):
    """The functions of a spec file, in its variable t, parameters renamed."""
    with open(path, "rb") as f:
        spec = tomllib.load(f)
    names = [p["name"] for p in spec.get("parameters", [])]
    local = {"t": t, **{n + suffix: sp.Symbol(n + suffix) for n in names}}

    def read(formula):
        for n in names:  # `lambda` is a Python word: renamed before parsing
            formula = re.sub(rf"\b{n}\b", n + suffix, formula)
        return sp.sympify(formula.replace("^", "**"), locals=local)

    return [read(f["formula"]) for f in spec["functions"]]


def ends(functions, var, a, b):
    """[end][function][order] derivatives at var = a and var = b."""
    return [
        [[sp.diff(f, var, k).subs(var, x) for k in range(ORDER + 1)] for f in functions]
        for x in (a, b)
    ]


def expected(du, dv, corner, a, b):
    eu, ev = corner
    total = 0
    for i, bi in enumerate(du[eu]):
        for j, bj in enumerate(dv[ev]):
            total += sp.Symbol(f"P{i}{j}") * bi[a] * bj[b]
    return total


def cli(args):
    binary = os.path.join(ROOT, "target", "debug", "trig-audit")
    cmd = [binary] if os.path.exists(binary) else ["cargo", "run", "-q", "-p", "trig-audit", "--"]
    out = subprocess.run(cmd + args, cwd=ROOT, capture_output=True, text=True, check=True)
    return out.stdout


def compare(title, du, dv, args):
    text = cli(["table", "--surface", "--order", str(ORDER), "--format", "csv"] + args)
    rows = list(csv.DictReader(io.StringIO(text)))
    corners = {
        "corner u at its start, v at its start": (0, 0),
        "corner u at its start, v at its end": (0, 1),
        "corner u at its end, v at its start": (1, 0),
        "corner u at its end, v at its end": (1, 1),
    }
    checked = 0
    for row in rows:
        corner = corners[row["table"]]
        a, b = int(row["row"]), int(row["column"])
        got = sp.sympify(row["value"].replace("^", "**"), locals={"lambda_v": sp.Symbol("lambda_v"), "pi": sp.pi})
        want = expected(du, dv, corner, a, b)
        assert sp.simplify(sp.expand(got - want)) == 0, (title, row, want)
        checked += 1
    assert checked == 4 * (ORDER + 1) ** 2, checked
    print(f"[ok] {title}: {checked} entries (4 corners, orders a, b = 0..{ORDER}) agree")
    return rows


thesis = ends(THESIS, th, 0, sp.pi / 2)
rows = compare("thesis cubic x thesis cubic (same m)", thesis, thesis, ["thesis-cubic"])
sample = next(r for r in rows if r["table"].endswith("start, v at its start") and r["row"] == "1" and r["column"] == "1")
print("     e.g. d2S/du dv at (0, 0) =", sample["value"])
han = spec_functions(os.path.join(ROOT, "examples", "han-quadratic.toml"), "_v")
han_ends = ends([f.subs(t, th) for f in han], th, 0, sp.pi / 2)
compare(
    "thesis cubic x examples/han-quadratic.toml",
    thesis,
    han_ends,
    ["thesis-cubic", "--v-spec", "examples/han-quadratic.toml"],
)
