#!/usr/bin/env python3
"""Re-check every witness of the claims that do not hold, from the JSON
audit report alone (`trig-audit audit --format json`), with SymPy.

No name mapping: each coordinate of a witness point names its SymPy
`symbol` (the names the expressions' `sympy` forms use: `P0`, `lamda`,
`theta`) and its value in SymPy syntax. A value that records the expression
it is the value of (`of`, or an expression of its item with the value's
label) is re-computed by substituting the point; a
witness whose item has a residual and two values is checked as
residual(point) = first − second. Exact values must agree exactly, numeric
ones to the digits shown. What the check states of the values (`stated`:
the first against the second, or against 0 when there is one value; absent:
they are equal; `differ`: the values in pairs, some pair differs) must be
false at the point. Not a project dependency (CI has no Python).

Usage: trig-audit audit --format json > report.json
       python3 scripts/recheck_witnesses.py report.json
"""
import json
import sys

import sympy


def parse(text, names):
    local = {n: sympy.Symbol(n) for n in names}
    local.update({"atan2": sympy.atan2, "asin": sympy.asin, "acos": sympy.acos, "pi": sympy.pi})
    return sympy.parse_expr(text, local_dict=local)


def point_of(w):
    """The point as SymPy substitutions, or the coordinates without a symbol."""
    subs, names = {}, []
    for a in w["point"]:
        if "symbol" in a and "sympy" in a:
            names.append(a["symbol"])
    for a in w["point"]:
        if "symbol" in a and "sympy" in a:
            subs[sympy.Symbol(a["symbol"])] = parse(a["sympy"], names)
    return subs


def same(value, expected, exact):
    if exact:
        return sympy.simplify(value - expected) == 0
    # numeric: agree to the digits shown (30 significant)
    v, e = sympy.N(value, 40), sympy.N(expected, 40)
    return abs(v - e) <= abs(e) * sympy.Float("1e-28") + sympy.Float("1e-40")


def value_of(expr):
    text = expr["sympy"]
    if text.startswith("Float("):
        return sympy.Float(text[7:text.index("'", 7)], 40)
    return parse(text, expr.get("symbols", []))


# the order a witness's check states, on first − second
STATED = {
    "less": lambda d: d < 0,
    "at-most": lambda d: d <= 0,
    "greater": lambda d: d > 0,
    "at-least": lambda d: d >= 0,
}


def stated_fails(w):
    """None when the stated relation is false at the point, else why not."""
    stated = w.get("stated", "equal")
    values = [value_of(v["value"]) for v in w["values"]]
    if stated == "differ":  # pairs in order; every pair agrees at the point
        pairs = list(zip(values[0::2], values[1::2]))
        if len(values) % 2 or any(not same(a, b, w["exact"]) for a, b in pairs):
            return "the stated difference holds at the point"
        return None
    if len(values) > 2:
        return None if stated == "equal" else f"{stated} of {len(values)} values"
    first, second = values[0], (values[1] if len(values) > 1 else sympy.Integer(0))
    if stated == "equal":
        return "the two values are equal" if len(values) == 2 and same(first, second, w["exact"]) else None
    d = sympy.simplify(first - second) if w["exact"] else sympy.N(first - second, 40)
    return f"the stated relation ({stated}) holds at the point" if bool(STATED[stated](d)) else None


def check(item):
    """'ok', or why the witness cannot be re-checked / is wrong."""
    w = item["witness"]
    subs = point_of(w)
    values = w["values"]
    checked = 0
    # an expression of the item labelled as a value is that value's expression
    labelled = {x["label"]: x["expr"] for x in item.get("exprs", [])}
    for v in values:
        of = v.get("of") or labelled.get(v["label"])
        if of is None:
            continue
        e = parse(of["sympy"], of.get("symbols", []) + [str(s) for s in subs])
        got = sympy.simplify(e.subs(subs))
        # symbols the point leaves free (control points) must be those of the value
        missing = got.free_symbols - {sympy.Symbol(n) for n in v["value"].get("symbols", [])}
        if missing:
            return f"the point does not give {sorted(map(str, missing))}"
        if not same(got, value_of(v["value"]), w["exact"]):
            return f"{v['label']}: substituted {got}, stated {v['value']['sympy']}"
        checked += 1
    if checked:
        return stated_fails(w) or "ok"
    residual = next((x for x in item.get("exprs", []) if "residual" in x["label"] or "jump" in x["label"]), None)
    if residual is None and len(item.get("exprs", [])) == 1 and len(values) == 1:
        residual = item["exprs"][0]
    if residual is None:
        return "no expression to substitute into (the item gives values only)"
    e = parse(residual["expr"]["sympy"], residual["expr"]["symbols"])
    missing = e.free_symbols - set(subs)
    if missing:
        return f"the point does not give {sorted(map(str, missing))}"
    got = sympy.simplify(e.subs(subs))
    want = value_of(values[0]["value"]) - (value_of(values[1]["value"]) if len(values) > 1 else 0)
    if not same(got, want, w["exact"]):
        return f"residual at the point is {got}, the values give {want}"
    if got == 0:
        return "the residual vanishes at the point"
    return "ok"


def main(path):
    report = json.load(open(path))
    total, ok, problems = 0, 0, []
    for claim in report["claims"]:
        if claim["verdict"] == "holds":
            continue
        for item in claim.get("evidence", []):
            if not item.get("witness"):
                continue
            total += 1
            try:
                result = check(item)
            except Exception as e:  # a form SymPy cannot read is a finding too
                result = f"cannot parse: {e}"
            if result == "ok":
                ok += 1
            else:
                problems.append((claim["id"], item.get("subject") or item["text"][:60], result))
    for cid, subject, why in problems:
        print(f"{cid}: {subject}: {why}")
    print(f"re-checked {ok} of {total} witnesses of the claims that do not hold; {len(problems)} not re-checked")
    return 0 if ok == total else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "/dev/stdin"))
