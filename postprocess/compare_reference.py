#!/usr/bin/python3
"""Localization model against the periodic BEM reference at the paper's points.

For the Table 9.1 case and the Fig. 9.5 cases (T = 2.5, s = 2, C = 0.5) it runs
`punchsweep point` (the localization model) and `punchsweep reference` (the full periodic
contact problem on an N x N grid, and on 2N x 2N to show the BEM figures are converged) and
prints a Markdown table: regime, t* (T_eps), a1 and a2 (R) at t = 0 and t = 5 T_eps, the
model's relative difference from the BEM, and the BEM's largest relative change N -> 2N.

Example:  postprocess/compare_reference.py --bem-grid 256 > comparison.md
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from punchsweep_point import find_binary, run_command  # noqa: E402

# (label, l, dh, pbar): Table 9.1 is the first Fig. 9.5b case.
CASES = [
    ("Table 9.1 / Fig. 9.5b", 0.75, 0.05, 0.06),
    ("Fig. 9.5b", 0.75, 0.075, 0.06),
    ("Fig. 9.5b", 0.75, 0.1, 0.06),
    ("Fig. 9.4b / 9.5a", 0.75, 0.05, 0.025),
    ("Fig. 9.5a", 1.0, 0.05, 0.025),
    ("Fig. 9.5a", 1.25, 0.05, 0.025),
]


def run(binary: str, command: str, l: float, dh: float, pbar: float, extra: dict) -> dict:
    return run_command(binary, command, dict(l=l, dh=dh, T=2.5, pbar=pbar, s=2, times=[0.0, 5.0], **extra))


def quantities(r: dict) -> dict:
    s = r["series"]
    return {"t_star": r["t_star"], "a1_0": s["a1"][0], "a2_0": s["a2"][0], "a1_5": s["a1"][1], "a2_5": s["a2"][1]}


def rel(a, b):
    if a is None or b is None:
        return None
    return abs(a - b) / max(abs(b), 1e-12)


def fmt(v, digits=4):
    return "-" if v is None else f"{v:.{digits}f}"


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--bem-grid", type=int, default=256, help="BEM grid nodes per side N (even; default 256)")
    p.add_argument("--no-convergence", action="store_true", help="skip the 2N x 2N runs")
    p.add_argument("--localization", help="the model: periodic, paper, refined, shells:D or point-shells:D "
                                          "(default: the engine's, periodic)")
    p.add_argument("--binary", help="punchsweep executable (default: PATH or build/)")
    args = p.parse_args(argv)
    if args.bem_grid < 16 or args.bem_grid % 2:
        print("compare_reference.py: --bem-grid must be an even integer >= 16", file=sys.stderr)
        return 2
    binary = find_binary(args.binary)
    n = args.bem_grid
    print(f"| case | l [R] | dh [R] | pbar0 | regime model / BEM | t* [T_eps] model / BEM | a1(0) [R] model / BEM "
          f"| a2(0) | a1(5) | a2(5) | largest model-BEM difference | BEM change {n} -> {2 * n} |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for label, l, dh, pbar in CASES:
        model = run(binary, "point", l, dh, pbar, {"localization": args.localization})
        bem = run(binary, "reference", l, dh, pbar, {"bem_grid": n})
        m, b = quantities(model), quantities(bem)
        diffs = [rel(m[k], b[k]) for k in m if b[k] not in (None, 0.0) and m[k] not in (None, 0.0)]
        change = "-"
        if not args.no_convergence:
            fine = quantities(run(binary, "reference", l, dh, pbar, {"bem_grid": 2 * n}))
            changes = [rel(b[k], fine[k]) for k in b if fine[k] not in (None, 0.0) and b[k] is not None]
            change = f"{100 * max(changes):.2f}%"
        cells = [f"{fmt(m[k])} / {fmt(b[k])}" for k in ("t_star", "a1_0", "a2_0", "a1_5", "a2_5")]
        print(f"| {label} | {l:g} | {dh:g} | {pbar:g} | {model['regime']} / {bem['regime']} | " + " | ".join(cells)
              + f" | {100 * max(diffs):.1f}% | {change} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
