#!/usr/bin/python3
"""Design chart from a punchsweep regime map: the critical height differences against the
lattice pitch l or the nominal pressure pbar0.

  dh <= h_0:          level 2 touches immediately (h_0 is the tip-to-centre displacement
                      difference at t = 0; it does not depend on T);
  h_0 < dh < h_inf:   level 2 touches after a delay t*;
  dh >= h_inf:        level 2 never touches (h_inf: the same difference as t -> infinity).

One panel per shape exponent s. In each, h_0 is drawn once (blue, the immediate region
below it shaded) and h_inf once per creep ratio T (one colour per T). The values come
from the map's h_0 and h_inf variables, which do not depend on dh; the script checks that
they agree across the dh axis (and h_0 across T) and says so on stderr if they do not.

With --touch-by t1,t2,...: also the height difference below which level 2 touches by each
time t_k (one dash pattern each; on a map made with a tolerance box, `sweep --tolerance`, a
shaded band about it from where it touches by t_k at every corner of the box to where at
some), interpolated along the dh axis of the map's t_star in
log t* (from h_0, where t* leaves 0, never below it); where even the grid's largest dh
touches by t_k the curve stops, marked ^ on that dh. Against
the temperature of a material map (--against temperature) this is the chart that moves:
h_0 and h_inf do not depend on the temperature (a time shift changes neither J(0) nor
J(inf)), the touch-by curves rise with it.

The dh axis is logarithmic (in every panel) when the values drawn in some panel (h_0, h_inf,
the touch-by curves) span more than a factor LOG_DH_SPAN (10), so that h_0 and the touch-by
curves are not pressed against the bottom by an h_inf many times larger (a material that
creeps far: h_inf/h_0 follows J(inf)/J(0)); else linear from 0. --log-dh or --linear-dh
forces one. The title names the material (or the creep law), the
temperature (its value, or "against temperature"), the load with the pressure in its unit
(kPa on a material map), the other fixed axes and the model.

The map must have the axes dh and --against (pbar, l or temperature); a map without a T
or an s axis gets one curve or one panel. Every other axis of the map (read from the file, like the units)
is fixed with --at, or has a single value.

Units: dh, h_0, h_inf and l in R (the punch size); pbar in E0/(1-nu^2) (kPa for a material
map; drawn on a log axis when the map's pbar axis is log-spaced); T and s dimensionless;
temperature in degC; --touch-by times in the map's time unit (T_eps, or the material's).

Example:
  postprocess/critical_dh.py map.h5 --against pbar --at l=0.75 -o chart.png
  postprocess/critical_dh.py map.h5 --against l --at pbar=0.04 T=2.5 -o chart.pdf
  postprocess/critical_dh.py wlf_map.h5 --against temperature --at l=0.75 pbar=47 \\
      --touch-by 1,60,3600 -o chart.png
  postprocess/critical_dh.py map.h5 --at l=0.75 --linear-dh -o chart.png
"""
from __future__ import annotations

import argparse
import math
import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

FIG_DPI = 150
PANEL_SIZE = (4.6, 3.6)  # inches per panel
LEGEND_WIDTH = 2.2  # inches
RELATIVE_TOLERANCE = 1e-12  # for "does not depend on dh / T"
AGAINST = ("pbar", "l", "temperature")  # the horizontal axes the chart is drawn against
CURVE_AXIS = "T"  # one h_inf curve per value (h_0 does not depend on it), if the map has it
PANEL_AXIS = "s"  # one panel per value, if the map has it
LOG_DH_SPAN = 10.0  # the dh axis is logarithmic when the drawn values span more than this factor
LOG_MARGIN = 1.25  # a log dh axis reaches this factor below the smallest and above the largest value


# Dash patterns of the touch-by curves, told apart at a glance: long dashes, dots, dash-dot,
# short dashes.
TOUCH_STYLES = [(0, (6, 2)), (0, (1, 1.5)), (0, (6, 2, 1, 2)), (0, (3, 1.5))]


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="critical_dh.py", description=__doc__,
                  formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.h5", help="regime map written by `punchsweep sweep`")
    p.add_argument("--against", default="pbar", metavar="AXIS",
                   help="horizontal axis: pbar (nominal pressure, E0/(1-nu^2); the default), "
                        "l (lattice pitch, R) or temperature (a material map with a [shift])")
    pm.add_at_option(p, "fix the other of l / pbar and any further axis of the map; "
                        "optionally also T and/or s to draw only those curves and panels",
                     "dh cannot be fixed: it is the chart's vertical axis.")
    p.add_argument("--touch-by", default="", metavar="TIMES",
                   help="comma-separated times: also draw the dh below which level 2 touches by "
                        "each (from t_star): 1s,1min,1h on a material map, or bare numbers in the "
                        "map's time unit")
    scale = p.add_mutually_exclusive_group()
    scale.add_argument("--log-dh", dest="dh_scale", action="store_const", const="log", default="auto",
                       help="draw dh on a log axis (the default when the drawn values span more than "
                            f"a factor {LOG_DH_SPAN:g})")
    scale.add_argument("--linear-dh", dest="dh_scale", action="store_const", const="linear",
                       help="draw dh on a linear axis from 0 (the default otherwise)")
    p.add_argument("-o", "--output", required=True,
                   help="picture to write; the format follows the suffix: .png or .pdf")
    return p.parse_args(argv)


def along_dh(values: np.ndarray, name: str, dh_axis: int, unit: str = "") -> np.ndarray:
    """Collapses the dh axis of h_0 or h_inf, warning on stderr if the values differ (`unit`:
    the suffix for the spread, e.g. ' R')."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # all-NaN columns stay NaN
        mid = np.nanmedian(values, axis=dh_axis)
        spread = np.nanmax(np.abs(values - np.expand_dims(mid, dh_axis)))
        scale = np.nanmax(np.abs(mid)) if np.isfinite(mid).any() else 1.0
    if np.isfinite(spread) and spread > RELATIVE_TOLERANCE * max(scale, 1e-300):
        print(f"critical_dh.py: warning: {name} varies along dh by up to {spread:.3g}{unit}; "
              f"drawing its median over dh", file=sys.stderr)
    return mid


def touch_by_curve(dh: np.ndarray, t_star: np.ndarray, t_target: float, h0: float = float("nan")) -> float:
    """The dh below which level 2 touches by t_target along one dh line of t* (0 immediate,
    NaN never; t* grows with dh): linear in log t* between the bracketing grid points (in t*
    from an immediate one, t* = 0, and from h0 there when h0, the line's h_0, lies between the
    two: t* leaves 0 at h_0, not at the grid point below it, so the curve never dips below
    h_0); the last grid dh that touches when the next never does; NaN when none does; +inf
    when even the grid's largest dh touches (the answer lies above the grid, which a curve
    must not pretend to know)."""
    t = np.where(np.isnan(t_star), np.inf, t_star)
    touched = t <= t_target
    if not touched.any():
        return float("nan")
    k = int(np.nonzero(touched)[0][-1])
    if k + 1 >= len(dh):
        return float("inf")
    if not np.isfinite(t[k + 1]):
        return float(dh[k])
    lo, hi = t[k], t[k + 1]
    start = float(dh[k])
    if lo == 0.0:
        w = t_target / hi
        if dh[k] < h0 < dh[k + 1]:
            start = float(h0)
    else:
        w = (np.log(t_target) - np.log(lo)) / (np.log(hi) - np.log(lo)) if hi > lo else 0.0
    return float(start + w * (dh[k + 1] - start))


def touch_by_curves(ds, against: str, fixed: dict[str, pm.Fixed], times: list[float],
                    variable: str = "t_star") -> np.ndarray:
    """(time, T, s, x): touch_by_curve over the map's dh axis for each target time (from the
    map's h_0 at each point, its median over dh, where t* leaves 0). `variable`: t_star, or
    the ends of a map's tolerance box, t_star_high (touches by then at every corner of the
    box) and t_star_low (at some corner), which start from their own last 0."""
    sel = {name: f.index for name, f in fixed.items()}
    for name in (CURVE_AXIS, PANEL_AXIS):
        if name in sel:
            sel[name] = [sel[name]]
    names = [variable] + (["h_0"] if "h_0" in ds.variables and variable == "t_star" else [])
    cut = ds[names].isel(sel)
    for name in (CURVE_AXIS, PANEL_AXIS):
        if name not in cut.dims:
            cut = cut.expand_dims(name)
    order = ("dh", CURVE_AXIS, PANEL_AXIS, against)
    t = cut[variable].transpose(*order).values
    h0 = np.full(t.shape[1:], np.nan)
    if "h_0" in cut:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # all-NaN lines stay NaN
            h0 = np.nanmedian(cut["h_0"].transpose(*order).values, axis=0)
    dh = ds["dh"].values.astype(float)
    out = np.full((len(times),) + t.shape[1:], np.nan)
    for i, target in enumerate(times):
        for idx in np.ndindex(*t.shape[1:]):
            out[(i,) + idx] = touch_by_curve(dh, t[(slice(None),) + idx], target, h0[idx])
    return out


def critical_curves(ds, against: str, fixed: dict[str, pm.Fixed]):
    """h_0 as (s, x) and h_inf as (T, s, x), with the T, s and x grid values drawn.

    T and s stand for CURVE_AXIS and PANEL_AXIS; for one the map does not have, its values
    are [nan] (one curve or one panel)."""
    sel = {name: f.index for name, f in fixed.items()}
    for name in (CURVE_AXIS, PANEL_AXIS):
        if name in sel:  # keep the axis, one value long
            sel[name] = [sel[name]]
    cut = ds[["h_0", "h_inf"]].isel(sel)
    for name in (CURVE_AXIS, PANEL_AXIS):
        if name not in cut.dims:
            cut = cut.expand_dims(name)
    order = ("dh", CURVE_AXIS, PANEL_AXIS, against)
    h0 = cut["h_0"].transpose(*order).values
    hinf = cut["h_inf"].transpose(*order).values
    unit = pm.unit_suffix(ds, "dh")
    h0, hinf = along_dh(h0, "h_0", 0, unit), along_dh(hinf, "h_inf", 0, unit)  # (T, s, x)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        h0_s = np.nanmedian(h0, axis=0)
        spread = np.nanmax(np.abs(h0 - h0_s[None]))
    if np.isfinite(spread) and spread > RELATIVE_TOLERANCE * max(np.nanmax(np.abs(h0_s)), 1e-300):
        print(f"critical_dh.py: warning: h_0 varies with {CURVE_AXIS} by up to {spread:.3g}{unit}; "
              f"drawing its median over {CURVE_AXIS}", file=sys.stderr)

    def drawn(name: str) -> np.ndarray:
        if name not in pm.axes(ds):
            return np.array([np.nan])
        return ds[name].isel({name: sel.get(name, slice(None))}).values.astype(float)

    x = ds[against].values.astype(float)
    return x, drawn(CURVE_AXIS), drawn(PANEL_AXIS), h0_s, hinf


def dh_scale(panels, choice: str = "auto") -> str:
    """'log' or 'linear': the scale of the dh axis (one for every panel) for the values drawn
    in each panel (a list of arrays; NaN and inf are not drawn). `choice` 'auto' is 'log' when
    the values are all > 0 and in some panel the largest is more than LOG_DH_SPAN times the
    smallest; 'log' with a value <= 0 is a MapError."""
    finite = [v[np.isfinite(v)] for v in (np.asarray(p, dtype=float).ravel() for p in panels)]
    every = np.concatenate(finite) if finite else np.array([])
    if choice == "log" and (every <= 0).any():
        raise pm.MapError(f"--log-dh: the chart has critical dh values <= 0 (down to {every.min():.3g}), "
                          f"which a log axis cannot show; use --linear-dh")
    if choice != "auto":
        return choice
    if every.size == 0 or (every <= 0).any():
        return "linear"
    return "log" if any(v.size and v.max() > LOG_DH_SPAN * v.min() for v in finite) else "linear"


def title_lines(ds, against: str, fixed: dict[str, pm.Fixed]) -> str:
    """The figure's title, worded as regime_map.py's: the material (or creep law) and its
    temperature (the fixed value, or 'against temperature'); the load with the pressure (fixed:
    its value in its unit); the other fixed axes and the model."""
    law, model, load = pm.map_parts(ds)
    if "material" in fixed:
        label = str(fixed["material"].value)
        law = pm.material_names(ds).get(label, label)
    first = "Critical height differences: " + law
    if "temperature" in pm.axes(ds):
        first += (", " + pm.format_value(ds, "temperature", fixed["temperature"].value, tex=True)
                  if "temperature" in fixed else ", against temperature")
    if "pbar" in fixed:
        load += ", " + pm.format_value(ds, "pbar", fixed["pbar"].value, tex=True)
    elif against == "pbar":
        load += ", against the nominal pressure " + pm.symbol_tex("pbar")
    others = [pm.format_value(ds, name, f.value, tex=True) for name, f in fixed.items()
              if name not in ("pbar", "temperature", "material")]
    incomplete = " (incomplete map)" if not pm.is_completed(ds) else ""
    last = ("at " + ", ".join(others) + "; " if others else "") + model + incomplete
    return "\n".join([first, load, last])


def render(ds, against: str, fixed: dict[str, pm.Fixed], times: list[float] | None = None,
           scale: str = "auto", labels: list[str] | None = None):
    """The chart; `scale` is that of the dh axis: 'auto' (dh_scale), 'log' or 'linear';
    `labels` how the touch-by times are written (as given: '1 min'; default in the map's
    time unit)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    x, T, s, h0, hinf = critical_curves(ds, against, fixed)
    times = times or []
    touch = touch_by_curves(ds, against, fixed, times) if times else None
    # Over a map's tolerance box: from touching by t at every corner to at some corner.
    band = ((touch_by_curves(ds, against, fixed, times, "t_star_high"),
             touch_by_curves(ds, against, fixed, times, "t_star_low"))
            if times and "t_star_high" in ds.variables else None)
    time_unit = pm.unit_tex(pm.units(ds, "t_star"))
    has_curves, has_panels = CURVE_AXIS in pm.axes(ds), PANEL_AXIS in pm.axes(ds)
    n = len(s)
    ncols = min(n, 3)
    nrows = math.ceil(n / ncols)
    fig = plt.figure(figsize=(PANEL_SIZE[0] * ncols + LEGEND_WIDTH, PANEL_SIZE[1] * nrows + 0.5),
                     dpi=FIG_DPI, constrained_layout=True)
    grid = fig.add_gridspec(nrows, ncols + 1, width_ratios=[PANEL_SIZE[0]] * ncols + [LEGEND_WIDTH])
    cmap = plt.get_cmap("viridis")
    t_colours = [cmap(0.85 * k / max(len(T) - 1, 1)) for k in range(len(T))]
    immediate = pm.REGIME_COLOURS["immediate"]
    dh_unit = pm.unit_tex(pm.units(ds, "dh")) if pm.units(ds, "dh") else "-"
    dh_top = float(ds["dh"].values[-1])
    # Everything drawn, per panel (last axis of each: x): h_0, h_inf, the touch-by curves where
    # they are inside the grid, and the ^ marks on the grid's largest dh where they are not.
    drawn = [np.concatenate([h0[k][None], hinf[:, k]]
                            + ([np.where(np.isinf(touch[:, :, k]), dh_top, touch[:, :, k]).reshape(-1, len(x))]
                               if touch is not None else []))
             for k in range(len(s))]
    scale = dh_scale(drawn, scale)
    if touch is not None and np.isinf(touch).any():
        beyond = [f"{t:g}" for i, t in enumerate(times) if np.isinf(touch[i]).any()]
        print(f"critical_dh.py: warning: by t = {', '.join(beyond)} {pm.units(ds, 't_star')} level 2 touches even at "
              f"the grid's largest dh = {dh_top:.6g}{pm.unit_suffix(ds, 'dh')} at some points; those touch-by "
              f"curves stop there (marked ^): extend grid.dh to draw them", file=sys.stderr)
    for k in range(n):
        row, col = divmod(k, ncols)
        ax = fig.add_subplot(grid[row, col], sharex=fig.axes[0] if k else None)
        values = drawn[k][np.isfinite(drawn[k])]
        if scale == "log":
            values = values[values > 0]
            lo, hi = (values.min() / LOG_MARGIN, values.max() * LOG_MARGIN) if values.size else (0.1, 1.0)
        else:
            lo, hi = 0.0, 1.05 * values.max() if values.size and values.max() > 0 else 1.0
        ax.fill_between(x, lo, h0[k], color=immediate, alpha=0.15, lw=0)
        ax.plot(x, h0[k], color=immediate, lw=2.2, marker="o", ms=3)
        for j in range(len(T)):
            ax.plot(x, hinf[j, k], color=t_colours[j], lw=1.4, marker="o", ms=2.5)
            for i in range(len(times)):
                curve = touch[i, j, k]
                # Beyond the grid's largest dh the curve stops, with a mark on the top edge.
                ax.plot(x, np.where(np.isinf(curve), np.nan, curve), color=t_colours[j], lw=1.6,
                        ls=TOUCH_STYLES[i % len(TOUCH_STYLES)])
                if band is not None:
                    every, some = (np.where(np.isinf(b[i, j, k]), dh_top, b[i, j, k]) for b in band)
                    ax.fill_between(x, every, some, color=t_colours[j], alpha=0.2, lw=0)
                above = np.isinf(curve)
                if above.any():
                    ax.plot(x[above], np.full(above.sum(), dh_top), ls="none", marker="^", ms=6,
                            color=t_colours[j], clip_on=False)
        if scale == "log":
            ax.set_yscale("log")
            ax.set_ylim(lo, hi)
            pm.style_log_axis(ax.yaxis)
        else:
            ax.set_ylim(lo, hi)
        if len(x) > 1:
            ax.set_xlim(x[0], x[-1])
        if pm.is_log(ds, against):
            ax.set_xscale("log")
            pm.style_log_axis(ax.xaxis)
        ax.grid(alpha=0.3)
        if has_panels:
            ax.set_title(pm.format_value(ds, PANEL_AXIS, float(s[k]), tex=True), fontsize=10)
        if row == nrows - 1 or k + ncols >= n:
            ax.set_xlabel(pm.axis_label(ds, against))
        if col == 0:
            ax.set_ylabel(f"critical height difference $\\Delta h$ [{dh_unit}]")

    handles = [Line2D([], [], color=immediate, lw=2.2, marker="o", ms=3,
                      label="$h_0$: below it, level 2\ntouches immediately"),
               Patch(facecolor=immediate, alpha=0.15, label="immediate region")]
    handles += [Line2D([], [], color=c, lw=1.4, marker="o", ms=2.5,
                       label=f"$h_\\infty$, {pm.format_value(ds, CURVE_AXIS, float(t), tex=True)}"
                       if has_curves else "$h_\\infty$")
                for t, c in zip(T, t_colours)]
    # The touch-by lines in their own dash pattern, in the colour they are drawn in when there
    # is one T curve (black beside several T colours).
    legend_colour = t_colours[0] if len(T) == 1 else "black"
    # A time whose curve lies nowhere inside the grid (above its largest dh everywhere, or
    # not reached) is not in the legend as a line: said in a note instead.
    labels = labels or [f"{t:g} {time_unit}" for t in times]
    drawn_any = [touch is not None and bool(np.isfinite(touch[i]).any()) for i in range(len(times))]
    handles += [Line2D([], [], color=legend_colour, lw=1.6, ls=TOUCH_STYLES[i % len(TOUCH_STYLES)],
                       label=f"touches by t = {labels[i]}") for i in range(len(times)) if drawn_any[i]]
    for i in range(len(times)):
        if not drawn_any[i]:
            where = ("even the grid's largest\n$\\Delta h$ touches by then" if np.isinf(touch[i]).all()
                     else "no dh of the grid\ntouches by then")
            handles.append(Line2D([], [], ls="none", label=f"by t = {labels[i]}: {where}"))
    if band is not None:
        handles.append(Patch(facecolor=legend_colour, alpha=0.2,
                             label="touches by then at some\nbut not every corner of the\ntolerance box: "
                                   + str(ds.attrs.get("tolerance", ""))))
    if touch is not None and np.isinf(touch).any():
        handles.append(Line2D([], [], color=legend_colour, ls="none", marker="^", ms=6,
                              label="touches by then even at the grid's\nlargest "
                                    f"{pm.format_value(ds, 'dh', dh_top, tex=True)}; the\n"
                                    "curve stops there: extend grid.dh"))
    legend_ax = fig.add_subplot(grid[:, ncols])
    legend_ax.axis("off")
    legend_ax.legend(handles=handles, loc="upper left", frameon=False, fontsize=9, borderaxespad=0,
                     title="between $h_0$ and $h_\\infty$:\ndelayed; above $h_\\infty$: never",
                     title_fontsize=9)
    fig.suptitle(title_lines(ds, against, fixed), fontsize=11)
    return fig


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    if args.against not in AGAINST:
        raise pm.MapError(f"--against '{args.against}' is not a valid choice; use l, pbar or temperature")
    out = pm.check_output(args.output, inputs=[args.map])
    with pm.open_map(args.map) as ds:
        parsed = [pm.parse_time(ds, v, f"--touch-by '{args.touch_by}':") for v in args.touch_by.split(",")
                  if v.strip()]
        times, labels = [t for t, _ in parsed], [text for _, text in parsed]
        pm.require_axes(ds, ("dh", args.against), f"critical_dh.py --against {args.against}")
        at = pm.parse_at(args.at, ds)
        missing = [n for n in ("h_0", "h_inf") if n not in ds.variables]
        if missing:
            raise pm.MapError(f"'{args.map}' has no {' or '.join(missing)} variable")
        reserved = {args.against: "the horizontal axis",
                    "dh": "the chart's vertical axis (h_0 and h_inf do not depend on dh)"}
        series = (CURVE_AXIS, PANEL_AXIS)
        fixed = pm.resolve_at(ds, at, free=list(series), optional=series, reserved=reserved)
        for f in fixed.values():
            print(f.message)
        if times and "t_star" not in ds.variables:
            raise pm.MapError(f"'{args.map}' has no t_star variable (needed by --touch-by)")
        fig = render(ds, args.against, fixed, times, args.dh_scale, labels)
        pm.save_figure(fig, out, dpi=FIG_DPI, inputs=[args.map])
    print(f"critical_dh.py: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "critical_dh.py"))
