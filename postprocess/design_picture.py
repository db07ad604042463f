#!/usr/bin/python3
"""The design window against temperature: the picture `punchsweep design` promises.

Reads the JSON of `punchsweep design ... --format json` (or `punchsweep.design(...).to_dict()` written
with json.dump) and draws, against temperature, each requirement's bound on dh (or, with
--find l or --find pressure, on the pitch or the pressure): the tightest over the tolerance
box's corners at that temperature, the quantity's own tolerance taken off. For dh a "touch
within ..." requirement is an upper bound (dh at most the line), a "never" or "no touch
within ..." one a lower bound; for the pitch and the pressure the other way round. Where every lower line lies under every upper
one, the band between is shaded; the window that holds at every temperature (the design's
answer) is the hatched band, its centre dashed, and the edge each requirement sets is
marked where it binds. With one temperature (or a law without temperature) the bounds are
drawn as levels. The title says the window, or "no design meets this" with the nearest miss.

Units: dh and l in the unit of the design's R (um where --R 80um was given), the pressure in
kPa (or Pa, MPa) where the material gives a modulus, temperature in C.

Example:
  punchsweep design --material examples/dma_exports/tpe_a_truth.ini --R 80um --l 250um --s 2 \\
      --temperature 20..40C --require "touch within 1s at 30kPa" --require "never at 5kPa" \\
      --tolerance "dh=0.5um, pressure=10%" --format json > window.json
  postprocess/design_picture.py window.json -o window.png
"""
from __future__ import annotations

import argparse
import math
import sys
import textwrap
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

FIG_DPI = 150


def parse_args(argv: list[str]) -> argparse.Namespace:
    return pm.picture_args(argv, "design_picture.py", __doc__, "window", "WINDOW.json",
                           "`punchsweep design --format json`")


def _unit(text: str) -> str:
    return "µm" if text == "um" else text


def _number(v) -> float:
    return math.nan if v is None else float(v)


def bound_curves(d: dict) -> list[tuple[dict, np.ndarray, np.ndarray]]:
    """Per requirement: (requirement, temperatures, the edge it sets there in the physical
    unit): the tightest of its corners' edges (each bound less the quantity's own tolerance,
    as the engine wrote it) at each temperature."""
    scale = d["physical"]["scale"]  # the quantity's scaled unit (R, E0*) in its physical one
    curves = []
    for r in d["requirements"]:
        upper = r["side"] == "upper"
        by_T: dict[float, float] = {}
        for b in r["bounds"]:
            T = _number(b["temperature"])
            key = 0.0 if math.isnan(T) else T
            edge = _number(b["edge"])
            by_T[key] = min(by_T.get(key, math.inf), edge) if upper else max(by_T.get(key, -math.inf), edge)
        Ts = np.array(sorted(by_T))
        curves.append((r, Ts, np.array([by_T[T] for T in Ts]) * scale))
    return curves


def render(d: dict):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    unit, length = _unit(d["physical"]["unit"]), _unit(d["physical"]["length_unit"])
    q = pm.design_quantity(d)
    curves = bound_curves(d)
    has_T = len(d["temperatures"]) > 1
    fig, ax = plt.subplots(figsize=(7.5, 4.8), layout="constrained")
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    x_span = (min(d["temperatures"]), max(d["temperatures"])) if has_T else (0.0, 1.0)
    for k, (r, Ts, edge) in enumerate(curves):
        upper = r["side"] == "upper"
        label = f"{r['text']}: {q} {'≤' if upper else '≥'} line"
        colour = colours[k % len(colours)]
        if has_T:
            ax.plot(Ts, edge, color=colour, lw=2, label=label, marker="o", ms=3)
            bind = _number(r["binds_at"]["temperature"])
            ax.plot([bind], [_number(r["edge_physical"])], marker="*", ms=14, color=colour, mec="black", zorder=5)
        else:
            ax.hlines(edge[0], *x_span, color=colour, lw=2, label=label)
    if has_T and curves:
        grid = np.linspace(*x_span, 200)
        lower = np.zeros_like(grid)
        upper = np.full_like(grid, np.inf)
        for r, Ts, edge in curves:
            line = np.interp(grid, Ts, edge)
            if r["side"] == "upper":
                upper = np.minimum(upper, line)
            else:
                lower = np.maximum(lower, line)
        top = np.where(np.isfinite(upper), upper, np.nanmax(lower) * 1.5 + 1e-30)
        ax.fill_between(grid, lower, top, where=top > lower, color="tab:green", alpha=0.15,
                        label="meets every requirement at that temperature")
    lo, hi = d["physical"]["lower"], d["physical"]["upper"]
    if not d["empty"]:
        top = hi if hi is not None and math.isfinite(_number(hi)) else None
        if top is not None:
            ax.axhspan(lo, top, facecolor="none", edgecolor="tab:green", hatch="///", lw=0,
                       label="the window: every temperature and corner")
            ax.axhline(d["physical"]["centre"], color="tab:green", ls="--", lw=1.2, label="its centre")
        else:
            ax.axhline(lo, color="tab:green", ls="--", lw=1.2, label="the window's lower edge")
        title = (f"{q} window {lo:.4g} to {top:.4g} {unit} (centre {d['physical']['centre']:.4g}, margin "
                 f"± {d['physical']['margin']:.3g} {unit})" if top is not None else f"{q} ≥ {lo:.4g} {unit}")
    else:
        title = "no design meets this"
    box = []
    if d["tolerance"]["dh"]:
        box.append(f"dh ± {d['physical']['dh_tolerance']:.3g} {length}")
    if d["tolerance"]["pressure"]:
        pa = d["physical"].get("E0_star_Pa")
        box.append(f"pressure ± {100 * d['tolerance']['pressure']:.3g}%" if d["tolerance"]["pressure_is"] == "relative"
                   else f"pressure ± {d['tolerance']['pressure'] * pa / 1e3:.4g} kPa" if pa
                   else f"pressure ± {d['tolerance']['pressure']:.4g} E0*")
    if d["tolerance"]["l"]:
        box.append(f"l ± {d['tolerance']['l'] * d['physical']['R']:.3g} {length}" if d["tolerance"]["l_is"] != "relative"
                   else f"l ± {100 * d['tolerance']['l']:.3g}%")
    subtitle = d["point"] + (f"; tolerance {', '.join(box)}" if box else "")
    ax.set_title(title + "\n" + "\n".join(textwrap.wrap(subtitle.replace(" um", " µm"), 110)), fontsize=9)
    ax.set_xlabel("temperature (°C)" if has_T else "")
    if not has_T:
        ax.set_xticks([])
    ax.set_ylabel(f"{pm.DESIGN_QUANTITIES[d['quantity']]} ({unit})")
    ax.set_xlim(*x_span)
    ax.legend(fontsize=7.5, loc="best")
    if d["empty"] and d.get("miss"):
        fig.text(0.01, 0.005, d["miss"], fontsize=7, wrap=True)
    return fig


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    pm.picture_of(args.window, args.output, pm.read_design_window, render, FIG_DPI)
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "design_picture.py"))
