#!/usr/bin/python3
"""Contact radii, loads and area fraction against time for one parameter point.

Runs `punchsweep point --format json` (never parses the text table) and draws a1, a2 (R),
P1, P2 (R^2 E0/(1-nu^2)) and the area fraction against t (T_eps), marking t*.

Example:
  postprocess/evolution.py --l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 2 -o evolution.png
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from punchsweep_point import find_binary, run_point  # noqa: E402


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--l", type=float, required=True, help="lattice pitch, in R (> 0)")
    p.add_argument("--dh", type=float, required=True, help="height difference, in R (>= 0)")
    p.add_argument("--T", type=float, required=True, help="creep ratio T_eps/T_sigma (>= 1)")
    p.add_argument("--pbar", type=float, required=True, help="nominal pressure, in E0/(1-nu^2) (> 0)")
    p.add_argument("--s", type=int, required=True, help="shape exponent, integer in [1, 32]")
    p.add_argument("--C", type=float, default=0.5, help="shape constant (> 0; default 0.5)")
    p.add_argument("--t-max", type=float, default=5.0, help="last time, in T_eps (default 5)")
    p.add_argument("--samples", type=int, default=101, help="number of times (default 101)")
    p.add_argument("-o", "--output", required=True, help="picture to write (.png or .pdf)")
    p.add_argument("--json", help="also write the engine's JSON result here")
    p.add_argument("--binary", help="punchsweep executable (default: PATH or build/)")
    args = p.parse_args(argv)
    if args.samples < 2 or not args.t_max > 0:
        p.error("--samples must be >= 2 and --t-max > 0")
    return args


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    times = list(np.linspace(0.0, args.t_max, args.samples))
    try:
        result = run_point(find_binary(args.binary), args.l, args.dh, args.T, args.pbar, args.s,
                           args.C, times)
    except (ValueError, FileNotFoundError) as e:
        print(f"evolution.py: {e}", file=sys.stderr)
        return 2
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=2))

    series = {k: np.array([np.nan if v is None else v for v in vals])
              for k, vals in result["series"].items()}
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8), constrained_layout=True)
    t = series["t"]
    axes[0].plot(t, series["a1"], label="$a_1$")
    axes[0].plot(t, series["a2"], label="$a_2$")
    axes[0].set_ylabel("contact radius [R]")
    axes[1].plot(t, series["P1"], label="$P_1$")
    axes[1].plot(t, series["P2"], label="$P_2$")
    axes[1].set_ylabel("load per punch [$R^2 E_0/(1-\\nu^2)$]")
    axes[2].plot(t, series["area_fraction"], color="k")
    axes[2].set_ylabel("area fraction $\\lambda$ [-]")
    for ax in axes:
        ax.set_xlabel("t [$T_\\varepsilon$]")
        if result["t_star"] is not None and result["t_star"] > 0:
            ax.axvline(result["t_star"], color="grey", ls=":", label="$t^*$")
        ax.grid(alpha=0.3)
    axes[0].legend()
    axes[1].legend()
    valid = "" if result["valid"] else "  [FLAGGED: " + result["reason"] + "]"
    t_star = "never" if result["t_star"] is None else f"t* = {result['t_star']:.4g} T_eps"
    fig.suptitle(f"l = {args.l} R, dh = {args.dh} R, T = {args.T}, pbar0 = {args.pbar}, s = {args.s}: "
                 f"{result['regime']}, {t_star}{valid}", fontsize=10)
    fig.savefig(args.output, dpi=120)
    print(f"evolution.py: wrote {args.output} ({result['regime']}, {t_star})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
