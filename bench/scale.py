#!/usr/bin/env python3
"""Cost of a spec audit against the number of functions and of parameters.

Writes spec files into a temporary folder and times `trig-audit audit --spec
FILE --format json` (the standard battery plus the claims `independent`,
`total-positivity` and `convex-hull`), the median of three runs, wall time.
The bases:

* functions: the Bernstein basis of degree n − 1 on [0, 1] and
  C(m, i) sin²ⁱt cos²⁽ᵐ⁻ⁱ⁾t on [0, π/2] (m = n − 1), n = 4, 7, 11, 16, 21;
* parameters: the generalized Bernstein basis of degree 3 (Han, Ma & Huang,
  JCAM 217 (2008) 180–193) with 1, 2 or 3 of its parameters free (the
  others 0), on its printed box.

Usage (from the checkout, after a build): python3 bench/scale.py
[path/to/trig-audit]. Standard library only. Prints a Markdown table and
each audit's verdict counts.
"""

import json
import statistics
import subprocess
import sys
import tempfile
import time
from math import comb
from pathlib import Path

BINARY = sys.argv[1] if len(sys.argv) > 1 else "target/debug/trig-audit"
CLAIMS = [("IND", "independent"), ("TP", "total-positivity"), ("HULL", "convex-hull")]


def spec(ident, variable, params, functions):
    lines = [f'id = "{ident}"', 'citation = "bench/scale.py"', f'variable = "{variable}"']
    for name, rng in params:
        lines += ["[[parameters]]", f'name = "{name}"', f'range = "{rng}"']
    for i, f in enumerate(functions):
        lines += ["[[functions]]", f'name = "b{i}"', f'formula = "{f}"']
    for cid, check in CLAIMS:
        lines += ["[[claims]]", f'id = "{cid}"', 'source = "bench"', 'statement = "x"',
                  f'check = "{check}"']
    return "\n".join(lines) + "\n"


def bases():
    for n in [4, 7, 11, 16, 21]:
        m = n - 1
        yield (f"Bernstein, {n} functions", 0,
               spec(f"bernstein{n}", "polynomial", [],
                    [f"{comb(m, i)}*t^{i}*(1 - t)^{m - i}" for i in range(n)]))
        yield (f"sin² Bernstein, {n} functions", 0,
               spec(f"sin2-bernstein{n}", "angle", [],
                    [f"{comb(m, i)}*s^{2 * i}*c^{2 * (m - i)}" for i in range(n)]))
    gb3 = ["(1 - t)^3*(1 - lambda1*t)",
           "t*(1 - t)^2*(3 + lambda1 - lambda1*t - lambda2*t)",
           "t^2*(1 - t)*(3 + lambda2 - lambda2*t + lambda3*t)",
           "t^3*(1 - lambda3 + lambda3*t)"]
    ranges = [("lambda1", "[-3, 1]"), ("lambda2", "[-3, 3]"), ("lambda3", "[-3, 1]")]
    for k in [1, 2, 3]:
        fs = gb3
        for name, _ in ranges[k:]:
            fs = [f.replace(name, "0") for f in fs]
        yield (f"generalized Bernstein, 4 functions", k, spec(f"gb3-{k}", "polynomial", ranges[:k], fs))


def main():
    print("| basis | parameters | wall (median of 3) | verdicts |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for label, params, text in bases():
            path = Path(tmp) / "basis.toml"
            path.write_text(text)
            times, out = [], ""
            for _ in range(3):
                start = time.perf_counter()
                out = subprocess.run([BINARY, "audit", "--spec", str(path), "--format", "json",
                                      "--time-limit", "60"], capture_output=True, text=True,
                                     check=True).stdout
                times.append(time.perf_counter() - start)
            verdicts = [c["verdict"] for c in json.loads(out)["claims"]]
            counts = {v: verdicts.count(v) for v in sorted(set(verdicts))}
            shown = ", ".join(f"{n} {v}" for v, n in counts.items())
            print(f"| {label} | {params} | {statistics.median(times):.2f} s | {shown} |")


if __name__ == "__main__":
    main()
