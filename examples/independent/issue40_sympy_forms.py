"""Issue 40: every SymPy form of the JSON audit parses to the expression it
stands for.

For every spec in examples/, examples/catalog/ and examples/independent/issue40/
(parameters named `lambda` beside `lamda`, `in`, `None`, `I`, `S`, `N`),
`trig-audit audit --spec F --format json` is read and every expression
(an object with `sympy` and `symbols`) is checked:

1. its `sympy` form (and its factored one) parses with
   `parse_expr(sympy, local_dict={n: Symbol(n) for n in symbols})`, and its
   free symbols are among `symbols`;
2. where its plain form is a formula (not a decimal or a bracket), the
   plain form read independently here — every name its own symbol, `s`, `c`
   as sin θ, cos θ, `^` as `**` — equals the SymPy form with its symbols
   named back by the documented rule (strip one trailing `_`; `lamda…` is
   `lambda…`), compared at random rational points to 40 digits; so a merge
   of two names (or a residual that parses to 0) is found;
3. the factored form equals the expanded one the same way;
4. an enclosure parses to a SymPy `Interval`, never `Float('[…]')`;
5. a witness point's `symbol = sympy` pairs parse.

Run from the repository root:  python3 examples/independent/issue40_sympy_forms.py
(needs SymPy; builds nothing: uses target/debug/trig-audit, or $TRIG_AUDIT).
Prints the counts and exits nonzero on any failure.
"""

import glob
import json
import os
import random
import re
import subprocess
import sys

from sympy import Interval, Symbol, cos, pi, sin, Rational, Max, Min, exp, sqrt, atan2, asin, acos
from sympy.parsing.sympy_parser import parse_expr

BIN = os.environ.get("TRIG_AUDIT", "target/debug/trig-audit")
THETA = Symbol("theta")


def specs():
    files = sorted(glob.glob("examples/*.toml"))
    files += sorted(glob.glob("examples/catalog/*.toml"))
    files += sorted(glob.glob("examples/independent/issue40/*.toml"))
    return files


def unname(sym):
    """The ring's name of a SymPy symbol, by the documented rule."""
    if sym.endswith("_"):
        return sym[:-1]
    m = re.fullmatch(r"lamda(\d*)", sym)
    if m:
        return "lambda" + m.group(1)
    return sym


def parse_sympy(text, symbols):
    return parse_expr(text, local_dict={n: Symbol(n) for n in symbols})


NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
FUNCS = {"sin": sin, "cos": cos, "exp": exp, "sqrt": sqrt, "max": Max, "min": Min,
         "atan2": atan2, "asin": asin, "acos": acos}


def parse_plain(text):
    """The plain form, read without the program's SymPy names: every
    variable is the symbol `v:<its name>`."""
    out, names, i = [], {}, 0
    for m in NAME.finditer(text):
        out.append(text[i:m.start()])
        n = m.group(0)
        after = text[m.end():m.end() + 1]
        if n in FUNCS and after == "(":
            key = "F_" + n
            names[key] = FUNCS[n]
        elif n == "pi":
            key = "K_pi"
            names[key] = pi
        elif n in ("s", "c"):
            key = "K_" + n
            names[key] = sin(THETA) if n == "s" else cos(THETA)
        else:
            key = "V_" + str(len(names))
            names[key] = Symbol("v:" + n)
        out.append(key)
        i = m.end()
    out.append(text[i:])
    return parse_expr("".join(out).replace("^", "**"), local_dict=names)


def named_back(expr):
    return expr.subs({s: Symbol("v:" + unname(s.name)) for s in expr.free_symbols if s != THETA},
                     simultaneous=True)


def same(a, b, rng):
    """a == b at three random rational points (40 digits)."""
    free = sorted(a.free_symbols | b.free_symbols, key=lambda s: s.name)
    for _ in range(3):
        point = {s: Rational(rng.randint(1, 97), rng.randint(1, 89)) for s in free}
        x = (a - b).subs(point)
        try:
            v = x.evalf(40)
        except Exception:
            return False
        if v.is_number and v == 0:
            continue
        ref = abs(a.subs(point).evalf(40)) + 1
        if not v.is_number or abs(v) > ref * 1e-30:
            return False
    return True


def is_formula(plain):
    return not plain.startswith("[") and "Float" not in plain and NAME.search(plain) is not None \
        and not re.fullmatch(r"[-0-9.e+ ]*", plain)


def check(path, data, counts, failures, rng):
    def walk(o, where):
        if isinstance(o, dict):
            if "sympy" in o and "symbols" in o:
                expr(o, where)
            if "symbol" in o and "sympy" in o and "name" in o:
                point(o, where)
            for k, v in o.items():
                walk(v, f"{where}/{k}")
        elif isinstance(o, list):
            for i, v in enumerate(o):
                walk(v, f"{where}[{i}]")

    def fail(where, why):
        failures.append(f"{path}{where}: {why}")

    def expr(o, where):
        counts["forms"] += 1
        text, symbols = o["sympy"], o["symbols"]
        if "Float('[" in text:
            fail(where, f"interval as Float: {text}")
            return
        try:
            e = parse_sympy(text, symbols)
        except Exception as err:  # noqa: BLE001
            fail(where, f"does not parse: {text!r}: {err}")
            return
        counts["parsed"] += 1
        if isinstance(e, Interval):
            counts["intervals"] += 1
        extra = {s.name for s in getattr(e, "free_symbols", set())} - set(symbols)
        if extra:
            fail(where, f"free symbols {extra} not in symbols {symbols}")
        if len(set(symbols)) != len(symbols):
            fail(where, f"symbols repeated: {symbols}")
        f = o.get("factored")
        if f:
            counts["forms"] += 1
            try:
                g = parse_sympy(f["sympy"], symbols)
                counts["parsed"] += 1
                counts["factored_equal"] += 1 if same(e, g, rng) else 0
                if not same(e, g, rng):
                    fail(where, f"factored {f['sympy']} differs from {text}")
            except Exception as err:  # noqa: BLE001
                fail(where, f"factored does not parse: {f['sympy']!r}: {err}")
        plain = o.get("plain", "")
        if is_formula(plain):
            try:
                p = parse_plain(plain)
            except Exception:  # noqa: BLE001
                counts["plain_unread"] += 1
                return
            if same(named_back(e), p, rng):
                counts["plain_equal"] += 1
            else:
                fail(where, f"SymPy form {text!r} is not the plain {plain!r}")

    def point(o, where):
        counts["point_pairs"] += 1
        try:
            Symbol(o["symbol"])
            parse_expr(o["sympy"])
        except Exception as err:  # noqa: BLE001
            fail(where, f"point {o['symbol']} = {o['sympy']}: {err}")

    walk(data, "")


def main():
    rng = random.Random(40)
    counts = {k: 0 for k in ["specs", "forms", "parsed", "plain_equal", "plain_unread",
                             "factored_equal", "intervals", "point_pairs"]}
    failures = []
    for path in specs():
        run = subprocess.run([BIN, "audit", "--spec", path, "--format", "json"],
                             capture_output=True, text=True, check=False)
        if run.returncode != 0:
            failures.append(f"{path}: audit failed: {run.stderr.strip()}")
            continue
        counts["specs"] += 1
        check(path, json.loads(run.stdout), counts, failures, rng)
    # the residual lambda - lamda stays nonzero, with two symbols
    names = json.loads(subprocess.run(
        [BIN, "audit", "--spec", "examples/independent/issue40/names.toml", "--format", "json"],
        capture_output=True, text=True, check=True).stdout)
    unity = next(c for c in names["claims"] if c["id"] == "N-unity")
    residual = unity["evidence"][0]["exprs"][0]["expr"]
    try:
        r = parse_sympy(residual["sympy"], residual["symbols"])
    except Exception:  # noqa: BLE001
        r = None
    wanted = {"lamda", "lamda_", "in_", "None_", "I_", "S_", "N_", "t"}
    got = {s.name for s in r.free_symbols} if r is not None else set()
    if r is None or r == 0 or got != wanted:
        failures.append(f"names.toml: residual {residual['sympy']} has symbols {got}, not {wanted}")
    for k, v in counts.items():
        print(f"{k}: {v}")
    print(f"names.toml residual: {r} (symbols {sorted(got)}, nonzero: {r != 0})")
    print(f"failures: {len(failures)}")
    for f in failures[:40]:
        print("  " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
