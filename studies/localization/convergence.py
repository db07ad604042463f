#!/usr/bin/python3
"""Issue 12: how the engine's localization models converge to the periodic BEM at the
paper's six points (SLS T = 2.5, s = 2, C = 0.5; docs/model.md, section 11).

For each point, `punchsweep point --localization L --times 0,5` gives t*, a1 and a2 at
t = 0 and t = 5 T_eps, for L = paper (D = 2, point loads, radii frozen at t = 0 by eq 9.18)
and shells:D (the punches of both levels within D distances, spread over their own spots,
radii that follow the loads) for growing D; `refined` is shells:200. The reference is
`punchsweep reference --bem-grid 512` at the same point, cached in bem_paper_points.json
with its commands (N = 256 -> 512 moves these figures by 0.07-0.2%, 1.4% for a2 at l = 1;
t* is bracketed to 1e-3).

The last column is the observed order p of the self-convergence |x_D - x_Dmax| ~ D^(-p)
between the two D below the largest (the family's own limit, not the BEM, is what D -> infinity
approaches).

Usage: convergence.py [--binary build/src/app/punchsweep] [--D 2,6,20,60,200,1000]
                      [--refresh]   (recompute the BEM cache: about 5 minutes)
"""
import argparse
import json
import math
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parents[1] / "postprocess"))
from localization_shells import T_CREEP, print_table  # noqa: E402
from punchsweep_point import find_binary  # noqa: E402

CACHE = HERE / "bem_paper_points.json"
# The paper's six points (docs/accuracy.md, "How accurate is the localization method?"): (l, dh, pbar0).
POINTS = [(0.75, 0.05, 0.06), (0.75, 0.075, 0.06), (0.75, 0.1, 0.06), (0.75, 0.05, 0.025), (1.0, 0.05, 0.025),
          (1.25, 0.05, 0.025)]
TIMES = "0,5"
QUANTITIES = [("t*", None, None), ("a1(0)", "a1", 0), ("a2(0)", "a2", 0), ("a1(5)", "a1", 1), ("a2(5)", "a2", 1)]


def values(out):
    """t* and the radii at t = 0 and 5 from a point or reference JSON (t* None for never)."""
    series = out["series"]
    return {"t*": out["t_star"] if out["regime"] != "never" else None,
            **{name: series[key][i] for name, key, i in QUANTITIES if key}}


def point(binary, l, dh, pbar, localization):
    cmd = [binary, "point", "--l", str(l), "--dh", str(dh), "--T", str(T_CREEP), "--pbar", str(pbar), "--s", "2",
           "--times", TIMES, "--localization", localization, "--format", "json"]
    return values(json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout))


def bem_cache(binary, refresh):
    if refresh or not CACHE.exists():
        rows = []
        for l, dh, pbar in POINTS:
            command = ["reference", "--l", str(l), "--dh", str(dh), "--T", str(T_CREEP), "--pbar", str(pbar), "--s",
                       "2", "--bem-grid", "512", "--times", TIMES, "--format", "json"]
            out = json.loads(subprocess.run([binary, *command], check=True, capture_output=True, text=True).stdout)
            rows.append({"l": l, "dh": dh, "pbar": pbar, "N": 512, **values(out), "command": " ".join(command)})
        CACHE.write_text(json.dumps(rows, indent=1) + "\n")
    return json.loads(CACHE.read_text())


def relative(value, ref):
    """value/ref - 1, or None where either is missing or the reference is 0."""
    if value is None or ref is None or ref == 0:
        return None
    return value / ref - 1


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", default=os.environ.get("PUNCHSWEEP"), help="punchsweep binary")
    p.add_argument("--D", default="2,6,20,60,200,1000", help="distance counts of the distributed family")
    p.add_argument("--refresh", action="store_true", help="recompute the BEM cache")
    args = p.parse_args(argv)
    binary = find_binary(args.binary)
    Ds = [int(d) for d in args.D.split(",")]
    models = ["paper"] + [f"shells:{d}" for d in Ds]
    results = {}

    def rows():
        for ref in bem_cache(binary, args.refresh):
            l, dh, pbar = ref["l"], ref["dh"], ref["pbar"]
            runs = [point(binary, l, dh, pbar, m) for m in models]
            results[(l, dh, pbar)] = (ref, runs)
            for name, _, _ in QUANTITIES:
                if not ref[name]:  # t* of an immediate or never point, a2 before touchdown
                    continue
                cells = []
                for r in runs:
                    e = relative(r[name], ref[name])
                    cells.append("-" if e is None else f"{100 * e:+.2f}%")
                x = [r[name] for r in runs[-3:]]
                order = "-"
                if None not in x and x[0] != x[2] and x[1] != x[2]:
                    order = f"{math.log(abs(x[0] - x[2]) / abs(x[1] - x[2])) / math.log(Ds[-2] / Ds[-3]):.2f}"
                yield [f"{l:g}, {dh:g}, {pbar:g}", name, "-" if ref[name] is None else f"{ref[name]:.4f}"], cells + [order]

    print_table(f"The engine's `point` against the BEM at N = 512 (SLS T = {T_CREEP:g}, s = 2), error relative to "
                "the BEM:", ["point (l, dh, pbar0)", "quantity", "BEM"] + [m if m != "paper" else "paper (D = 2, point "
                "loads, frozen radii)" for m in models] + [f"order p ({Ds[-3]} -> {Ds[-2]}, against {Ds[-1]})"], rows())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
