#!/usr/bin/python3
"""Contact radii, loads and area fraction against time for one parameter point.

Draws a1, a2 (R), P1, P2 (R^2 E0/(1-nu^2)) and the area fraction against t (T_eps),
marking t*. Two sources:

  point mode:  runs `punchsweep point --format json` (never parses the text table) at
               --l --dh --T --pbar --s, sampled at --samples times up to --t-max;
  map mode:    reads the series stored in a regime map made with `--quantities full`
               (--map MAP.h5 --at l=.. dh=.. T=.. pbar=.. s=.., one value per axis of the
               map, whichever axes it has), at the map's snapshot times.

Examples:
  postprocess/evolution.py --l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 2 -o evolution.png
  postprocess/evolution.py --map map.h5 --at l=0.75 dh=0.075 T=2.5 pbar=0.06 s=2 -o evo.png
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402
from punchsweep_point import find_binary, run_point  # noqa: E402

POINT_OPTIONS = ("l", "dh", "T", "pbar", "s")  # the options of `punchsweep point`, not map axes
POINT_DEFAULTS = {"C": 0.5, "t_max": 5.0, "samples": 101}


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="evolution.py", description=__doc__,
                  formatter_class=argparse.RawDescriptionHelpFormatter)
    point = p.add_argument_group("point mode (runs punchsweep point)")
    point.add_argument("--l", type=float, help="lattice pitch, in R (> 0)")
    point.add_argument("--dh", type=float, help="height difference, in R (>= 0)")
    point.add_argument("--T", type=float, help="creep ratio T_eps/T_sigma (>= 1)")
    point.add_argument("--pbar", type=float, help="nominal pressure, in E0/(1-nu^2) (> 0)")
    point.add_argument("--s", type=int, help="shape exponent, integer in [1, 32]")
    point.add_argument("--C", type=float, help="shape constant (> 0; default 0.5)")
    point.add_argument("--t-max", type=float, help="last time, in T_eps (default 5)")
    point.add_argument("--samples", type=int, help="number of times (default 101)")
    point.add_argument("--localization", help="periodic, paper, refined, shells:D or point-shells:D (default: "
                                              "the engine's, periodic)")
    point.add_argument("--binary", help="punchsweep executable (default: $PUNCHSWEEP, PATH or build/)")
    from_map = p.add_argument_group("map mode (reads a --quantities full regime map)")
    from_map.add_argument("--map", metavar="MAP.h5",
                          help="regime map written by `punchsweep sweep --quantities full`")
    pm.add_at_option(from_map, "the point: a value for each axis of the map (e.g. l=.. dh=.. "
                               "T=.. pbar=.. s=..)")
    p.add_argument("-o", "--output", required=True, help="picture to write (.png or .pdf)")
    p.add_argument("--json", help="also write the result here, as `punchsweep point --format json`"
                                  " does (in map mode: the map's values in the same layout)")
    args = p.parse_args(argv)
    point_given = [f"--{n.replace('_', '-')}" for n in (*POINT_OPTIONS, "C", "t_max", "samples",
                                                        "binary") if getattr(args, n) is not None]
    if args.map is not None:
        if point_given:
            p.error(f"--map reads the point from the map: use --at, not {', '.join(point_given)}")
    else:
        if args.at:
            p.error("--at needs --map MAP.h5 (in point mode give --l --dh --T --pbar --s)")
        missing = [f"--{n}" for n in POINT_OPTIONS if getattr(args, n) is None]
        if missing:
            p.error(f"give --l --dh --T --pbar --s (missing {' '.join(missing)}), "
                    f"or read a map with --map MAP.h5 --at AXIS=VALUE ...")
        for name, value in POINT_DEFAULTS.items():
            if getattr(args, name) is None:
                setattr(args, name, value)
        if args.samples < 2 or not args.t_max > 0:
            p.error("--samples must be >= 2 and --t-max > 0")
    return args


def from_engine(args: argparse.Namespace) -> tuple[dict, str]:
    """The engine's JSON result at the point given on the command line, and its title."""
    import numpy as np

    times = list(np.linspace(0.0, args.t_max, args.samples))
    try:
        result = run_point(find_binary(args.binary), args.l, args.dh, args.T, args.pbar, args.s,
                           args.C, times, args.localization)
    except (ValueError, FileNotFoundError) as e:
        raise pm.MapError(str(e)) from None
    title = f"l = {args.l} R, dh = {args.dh} R, T = {args.T}, pbar0 = {args.pbar}, s = {args.s}"
    return result, title


def _number(x) -> float | None:
    x = float(x)
    return None if math.isnan(x) else x


def from_map(args: argparse.Namespace) -> tuple[dict, str]:
    """The map's values at the nearest grid point, in the layout of the engine's JSON."""
    with pm.open_map(args.map) as ds:
        if not pm.has_series(ds):
            raise pm.MapError(f"'{args.map}' has no time series (it was swept with --quantities "
                              f"regime): re-run the sweep with --quantities full, or use the point "
                              f"mode (--l --dh --T --pbar --s)")
        at = pm.parse_at(args.at, ds)
        fixed = pm.resolve_at(ds, at, free=[])
        for f in fixed.values():
            print(f.message)
        cell = ds.isel({name: f.index for name, f in fixed.items()}).load()
        regime = pm.flags(ds, "regime").meaning(int(cell["regime"]))
        where = ", ".join(pm.format_value(ds, n, f.value) for n, f in fixed.items())
        if regime not in pm.DRAWN_REGIMES:
            raise pm.MapError(f"the point {where} was not computed (interrupted map): resume the "
                              f"sweep first")
        valid = pm.flags(ds, "valid").meaning(int(cell["valid"]))
        result = {"regime": regime,
                  "t_star": _number(cell["t_star"]),
                  "h_0": _number(cell["h_0"]), "h_inf": _number(cell["h_inf"]),
                  "valid": valid == pm.VALID, "reason": "" if valid == pm.VALID else valid,
                  "a1_inf": _number(cell["a1_inf"]), "a2_inf": _number(cell["a2_inf"]),
                  "area_fraction_inf": _number(cell["area_fraction_inf"]),
                  "series": {"t": [float(t) for t in cell["time"].values],
                             **{k: [_number(v) for v in cell[k].values] for k in pm.SERIES}}}
    return result, f"{where} (from {Path(args.map).name})"


def draw(result: dict, title: str, output: Path, markers: bool, inputs=()) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    series = {k: np.array([np.nan if v is None else v for v in vals])
              for k, vals in result["series"].items()}
    style = {"marker": "o", "ms": 3.5} if markers else {}
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8), constrained_layout=True)
    t = series["t"]
    axes[0].plot(t, series["a1"], label="$a_1$", **style)
    axes[0].plot(t, series["a2"], label="$a_2$", **style)
    axes[0].set_ylabel("contact radius [R]")
    axes[1].plot(t, series["P1"], label="$P_1$", **style)
    axes[1].plot(t, series["P2"], label="$P_2$", **style)
    axes[1].set_ylabel("load per punch [$R^2 E_0/(1-\\nu^2)$]")
    axes[2].plot(t, series["area_fraction"], color="k", **style)
    axes[2].set_ylabel("area fraction $\\lambda$ [-]")
    for ax in axes:
        ax.set_xlabel("t [$T_\\varepsilon$]")
        if result["t_star"] is not None and result["t_star"] > 0:
            ax.axvline(result["t_star"], color="grey", ls=":", label="$t^*$")
        ax.grid(alpha=0.3)
    axes[0].legend()
    axes[1].legend()
    valid = "" if result["valid"] else "  [FLAGGED: " + result["reason"] + "]"
    fig.suptitle(f"{title}: {result['regime']}, {t_star_text(result)}{valid}", fontsize=10)
    pm.save_figure(fig, output, dpi=120, inputs=inputs)


def t_star_text(result: dict) -> str:
    return "never" if result["t_star"] is None else f"t* = {result['t_star']:.4g} T_eps"


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    inputs = [args.map] if args.map else []
    output = pm.check_output(args.output, inputs=inputs)
    if args.json:
        pm.check_output(args.json, suffixes=(), inputs=inputs + [output])
    result, title = from_map(args) if args.map else from_engine(args)
    if args.json:
        pm.write_whole(args.json, lambda tmp: Path(tmp).write_text(json.dumps(result, indent=2)), inputs)
    draw(result, title, output, markers=bool(args.map), inputs=inputs)
    print(f"evolution.py: wrote {output} ({result['regime']}, {t_star_text(result)})")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "evolution.py"))
