#!/usr/bin/python3
"""A 2-D slice of a punchsweep regime map: where level 2 touches immediately, after a delay
t*, or never.

Each grid point is one cell, coloured by its regime (fixed colours: immediate blue, delayed
orange, never green). Points the localization method flags as invalid (valid != 0: spots
overlap, or no solution) are drawn in a paler shade of their regime colour and hatched,
unless the map holds the periodic BEM's answer there (sweep --reference bem, e.g.
--reference.sample invalid): then the BEM's regime is drawn, in full colour and dotted;
points never computed (an interrupted map) are dark grey. Contour lines of t* (in T_eps,
the creep time) run over the delayed region. A log-spaced axis (attribute spacing = "log")
is drawn on a log scale.

Any axes of the map can be drawn, fixed or faceted: the map's axes, their units and the
regime codes are read from the file. Units: l and dh in R (the punch size),
pbar in E0/(1-nu^2), T and s dimensionless, t* in T_eps; for a material map (sweep
[model] material) pbar in kPa (pbar E0* of the material) and times in its file's unit.

Example:
  postprocess/regime_map.py map.h5 --x pbar --y dh --at l=0.75 T=2.5 s=2 -o map.png
  postprocess/regime_map.py map.h5 --x pbar --y dh --at l=0.75 s=2 --facet T -o map.pdf
"""
from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

FIG_DPI = 150
PANEL_SIZE = (4.6, 3.6)  # inches per panel
LEGEND_WIDTH = 2.2  # inches
MAX_COLUMNS = 3
LABEL_SPACING = 0.35  # inches between contour labels
LABEL_MARGIN = 0.15  # inches from a contour label to the frame
FEW_VALUES = 6  # a linear axis with at most this many values is ticked at its grid values


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="regime_map.py", description=__doc__,
                  formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.h5", help="regime map written by `punchsweep sweep`")
    p.add_argument("--x", required=True, metavar="AXIS",
                   help="axis across the picture: a numeric axis of the map, e.g. pbar (l, dh "
                        "in R; pbar in E0/(1-nu^2); T, s dimensionless)")
    p.add_argument("--y", required=True, metavar="AXIS", help="axis up the picture (as --x)")
    pm.add_at_option(p, "fix each axis that is not --x, --y or --facet, e.g. l=0.75 T=2.5 s=2")
    p.add_argument("--facet", metavar="AXIS",
                   help="draw one panel per grid value of this axis (shared legend)")
    p.add_argument("--no-contours", action="store_true",
                   help="leave out the t* contour lines (t* in T_eps)")
    p.add_argument("-o", "--output", required=True,
                   help="picture to write; the format follows the suffix: .png or .pdf")
    return p.parse_args(argv)


@dataclass
class Panel:
    """One drawn slice: its axes, the cell-centre coordinates and the fill colours."""
    ax: object
    x: np.ndarray
    y: np.ndarray
    colours: np.ndarray  # (ny, nx, 4) RGBA
    title: str


def check_axes(ds, x: str, y: str, facet: str | None) -> None:
    """--x, --y (numeric) and --facet must be different axes of the map."""
    axes = pm.axes(ds)
    pm.parse_axis(ds, x, "--x")
    pm.parse_axis(ds, y, "--y")
    if x == y:
        raise pm.MapError(f"--x and --y are both '{x}'; choose two different axes of "
                          f"{', '.join(axes)}")
    pm.require_numeric(ds, x, "--x")
    pm.require_numeric(ds, y, "--y")
    if facet is not None:
        pm.parse_axis(ds, facet, "--facet")
        if facet in (x, y):
            raise pm.MapError(f"--facet {facet} is already the {'x' if facet == x else 'y'} axis; "
                              f"choose one of {', '.join(a for a in axes if a not in (x, y))}")


def contour_levels(t_star: np.ndarray, most: int = 8, decades: float = 2.5) -> list[float]:
    """1-2-5 levels (T_eps) spanning the delayed t* values, at most `most` of them.

    Levels more than `decades` below the largest t* are left out: t* falls to 0 steeply at the
    immediate boundary, where such lines would crowd into one.
    """
    t = t_star[np.isfinite(t_star) & (t_star > 0)]
    if t.size == 0:
        return []
    hi = float(t.max())
    lo = max(float(t.min()), hi * 10.0**-decades)
    levels = [m * 10.0**e for e in range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)
              for m in (1, 2, 5)]
    levels = [v for v in levels if lo < v < hi]
    step = max(1, math.ceil(len(levels) / most))
    return levels[::step]


def inside(mask: np.ndarray, xe: np.ndarray, ye: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Whether each point (x, y) lies in a cell where mask[j, i] is true."""
    i = np.searchsorted(xe, pts[:, 0]) - 1
    j = np.searchsorted(ye, pts[:, 1]) - 1
    ok = (i >= 0) & (i < mask.shape[1]) & (j >= 0) & (j < mask.shape[0])
    hit = np.zeros(len(pts), dtype=bool)
    hit[ok] = mask[j[ok], i[ok]]
    return hit


def draw_contours(ax, xv, yv, xe, ye, regime, t_star, levels, codes: pm.Flags) -> bool:
    """t* contour lines (T_eps) clipped to the delayed cells; True if any line is drawn.

    The field is log10 t* at the delayed cell centres. Immediate cells stand for t* = 0 and
    never cells for t* = infinity (t* -> 0 and -> infinity at those boundaries), both as
    values a decade beyond the levels, so that lines run up to the delayed cells' edges.
    `codes` are the map's regime flags.
    """
    from matplotlib.artist import Artist
    from matplotlib.path import Path as MplPath

    delayed = regime == codes.code("delayed")
    if not delayed.any() or regime.shape[0] < 2 or regime.shape[1] < 2:
        return False
    lo, hi = math.log10(levels[0]) - 1, math.log10(levels[-1]) + 1
    with np.errstate(divide="ignore", invalid="ignore"):
        z = np.where(delayed, np.log10(t_star), np.nan)
    z = np.where(regime == codes.code("immediate"), lo,
                 np.where(regime == codes.code("never"), hi, z))
    z = np.ma.masked_invalid(z)
    cs = ax.contour(xv, yv, z, levels=np.log10(levels), colors="black", linewidths=0.8,
                    linestyles="solid")
    clip = MplPath.make_compound_path(*[
        MplPath([(xe[i], ye[j]), (xe[i + 1], ye[j]), (xe[i + 1], ye[j + 1]), (xe[i], ye[j + 1]),
                 (xe[i], ye[j])], closed=True)
        for j, i in zip(*np.nonzero(delayed))])
    for artist in ([cs] if isinstance(cs, Artist) else cs.collections):
        artist.set_clip_path(clip, ax.transData)
    # One label per level, on its longest stretch inside the delayed cells, preferring
    # successive fractions along it for successive levels. A spot too close to a label
    # already placed or to the frame is skipped (distances in inches of the panel).
    to_inches = ax.transData + ax.transAxes.inverted()
    manual, drawn = [], False
    n = len(cs.allsegs)
    for k, segs in enumerate(cs.allsegs):
        best = None
        for seg in segs:
            hit = np.flatnonzero(inside(delayed, xe, ye, seg))
            if hit.size and (best is None or hit.size > best.size):
                best = seg[hit]
        if best is None:
            continue
        drawn = True
        where = to_inches.transform(best) * np.array(PANEL_SIZE)
        prefer = (k + 1) / (n + 1) * (len(best) - 1)
        for idx in np.argsort(np.abs(np.arange(len(best)) - prefer), kind="stable"):
            x_in, y_in = where[idx]
            clear = all(math.hypot(x_in - px, y_in - py) >= LABEL_SPACING for px, py, _ in manual)
            framed = (LABEL_MARGIN <= x_in <= PANEL_SIZE[0] - LABEL_MARGIN
                      and LABEL_MARGIN <= y_in <= PANEL_SIZE[1] - LABEL_MARGIN)
            if clear and framed:
                manual.append((x_in, y_in, tuple(best[idx])))
                break
    manual = [point for _, _, point in manual]
    if manual:
        ax.clabel(cs, manual=manual, fmt=lambda v: f"{10 ** v:.3g}", fontsize=7, inline=True)
    return drawn


def few_and_apart(values: np.ndarray, edges: np.ndarray) -> bool:
    """Whether a linear axis is better ticked at its grid values than by matplotlib:
    few values, none closer to the next than 8 % of the drawn range."""
    if len(values) > FEW_VALUES:
        return False
    return len(values) == 1 or np.min(np.diff(values)) >= 0.08 * (edges[-1] - edges[0])


def slices(ds, x: str, y: str, facet: str | None, fixed: dict[str, pm.Fixed]):
    """(facet value or None, regime, valid, t*, BEM regime) with arrays shaped (ny, nx); a
    facet value is a float, or a label on a categorical axis. The BEM regime is the map's
    bem_regime (not_computed outside its sample), all not_computed in a map without it."""
    sel = {name: f.index for name, f in fixed.items()}
    order = ([facet] if facet else []) + [y, x]
    regime = ds["regime"].isel(sel).transpose(*order).values
    valid = ds["valid"].isel(sel).transpose(*order).values
    t_star = (ds["t_star"].isel(sel).transpose(*order).values if "t_star" in ds
              else np.full(regime.shape, np.nan))
    bem = (ds["bem_regime"].isel(sel).transpose(*order).values if "bem_regime" in ds
           else np.full(regime.shape, pm.flags(ds, "regime").code(pm.NOT_COMPUTED)))
    if facet is None:
        return [(None, regime, valid, t_star, bem)]
    return [(v, regime[k], valid[k], t_star[k], bem[k]) for k, v in enumerate(pm.grid_values(ds, facet))]


def bem_answers(ds, valid: np.ndarray, bem: np.ndarray) -> np.ndarray:
    """Cells the model cannot answer (flagged invalid) where the map has the BEM's regime."""
    ok = np.asarray(valid) == pm.flags(ds, "valid").code(pm.VALID)
    return ~ok & (np.asarray(bem) != pm.flags(ds, "regime").code(pm.NOT_COMPUTED))


def render(ds, x: str, y: str, fixed: dict[str, pm.Fixed], facet: str | None = None,
           contours: bool = True):
    """Draws the map; returns (figure, panels). The figure size and dpi are fixed."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PatchCollection
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch, Rectangle

    data = slices(ds, x, y, facet, fixed)
    codes = pm.flags(ds, "regime")
    xv, yv = ds[x].values.astype(float), ds[y].values.astype(float)
    xlog, ylog = pm.is_log(ds, x), pm.is_log(ds, y)
    xe, ye = pm.cell_edges(xv, xlog), pm.cell_edges(yv, ylog)
    colours = pm.category_colours()
    cmap = ListedColormap(colours)
    norm = BoundaryNorm(np.arange(len(colours) + 1) - 0.5, len(colours))
    all_t = np.concatenate([np.where(r == codes.code("delayed"), t, np.nan).ravel()
                            for _, r, _, t, _ in data])
    levels = contour_levels(all_t) if contours else []

    n = len(data)
    ncols = min(n, MAX_COLUMNS)
    nrows = math.ceil(n / ncols)
    fig = plt.figure(figsize=(PANEL_SIZE[0] * ncols + LEGEND_WIDTH, PANEL_SIZE[1] * nrows + 0.5),
                     dpi=FIG_DPI, constrained_layout=True)
    grid = fig.add_gridspec(nrows, ncols + 1,
                            width_ratios=[PANEL_SIZE[0]] * ncols + [LEGEND_WIDTH])
    panels: list[Panel] = []
    any_invalid = any_missing = any_contour = any_bem = False
    first = None
    for k, (fval, regime, valid, t_star, bem) in enumerate(data):
        row, col = divmod(k, ncols)
        ax = fig.add_subplot(grid[row, col], sharex=first, sharey=first)
        first = first or ax
        # Where the model has no answer and the BEM has one, the BEM's regime, drawn as a
        # valid one (full colour), dotted (the model's pale hatched cell is not drawn there).
        answered = bem_answers(ds, valid, bem)
        any_bem |= bool(answered.any())
        shown_regime = np.where(answered, bem, regime)
        shown_valid = np.where(answered, pm.flags(ds, "valid").code(pm.VALID), valid)
        cat = pm.categories(ds, shown_regime, shown_valid)
        ax.pcolormesh(xe, ye, cat, cmap=cmap, norm=norm, shading="flat", antialiased=False,
                      edgecolors="none")
        if answered.any():
            rects = [Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j])
                     for j, i in zip(*np.nonzero(answered))]
            ax.add_collection(PatchCollection(rects, facecolor="none", edgecolor="0.15",
                                              hatch="..", linewidth=0))
        bad = (cat >= 3) & (cat < pm.CATEGORY_NOT_COMPUTED)
        any_invalid |= bool(bad.any())
        any_missing |= bool((cat == pm.CATEGORY_NOT_COMPUTED).any())
        if bad.any():
            rects = [Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j])
                     for j, i in zip(*np.nonzero(bad))]
            ax.add_collection(PatchCollection(rects, facecolor="none", edgecolor="0.35",
                                              hatch="///", linewidth=0))
        ax.set_xlim(xe[0], xe[-1])
        ax.set_ylim(ye[0], ye[-1])
        if xlog:
            ax.set_xscale("log")
            pm.style_log_axis(ax.xaxis)
        elif few_and_apart(xv, xe):
            ax.set_xticks(xv, [f"{v:g}" for v in xv])
        if ylog:
            ax.set_yscale("log")
            pm.style_log_axis(ax.yaxis)
        elif few_and_apart(yv, ye):
            ax.set_yticks(yv, [f"{v:g}" for v in yv])
        if levels and draw_contours(ax, xv, yv, xe, ye, regime, t_star, levels, codes):
            any_contour = True
        if row == nrows - 1 or k + ncols >= n:
            ax.set_xlabel(pm.axis_label(ds, x))
        if col == 0:
            ax.set_ylabel(pm.axis_label(ds, y))
        title = pm.format_value(ds, facet, fval, tex=True) if facet else ""
        if title:
            ax.set_title(title, fontsize=10)
        panels.append(Panel(ax, xv, yv, pm.regime_colour_grid(ds, shown_regime, shown_valid), title))

    handles = [Patch(facecolor=pm.REGIME_COLOURS[m], label=m) for m in pm.DRAWN_REGIMES]
    if any_invalid:
        handles.append(Patch(facecolor=pm.invalid_colour("delayed"), edgecolor="0.35", hatch="///",
                             linewidth=0, label="invalid (overlap or\nno solution): paler,\nhatched"))
    if any_bem:
        handles.append(Patch(facecolor=pm.REGIME_COLOURS["delayed"], edgecolor="0.15", hatch="..",
                             linewidth=0, label="model invalid, the\nBEM's regime: full\ncolour, dotted"))
    if any_missing:
        handles.append(Patch(facecolor=pm.REGIME_COLOURS[pm.NOT_COMPUTED], label="not computed"))
    if any_contour:
        handles.append(Line2D([], [], color="black", lw=0.8, label="$t^*$ contours,\n"
                                                                     f"labels in {pm.unit_tex(pm.units(ds, 't_star'))}"))
    legend_ax = fig.add_subplot(grid[:, ncols])
    legend_ax.axis("off")
    legend_ax.legend(handles=handles, loc="upper left", title="level-2 contact", frameon=False,
                     fontsize=9, title_fontsize=9, borderaxespad=0)

    fixed_text = ", ".join(pm.format_value(ds, name, f.value, tex=True)
                           for name, f in fixed.items())
    incomplete = "" if pm.is_completed(ds) else " (incomplete map)"
    fig.suptitle((f"Regime map at {fixed_text}{incomplete}" if fixed_text else f"Regime map{incomplete}")
                 + f"\n{pm.map_context(ds)}", fontsize=11)
    return fig, panels


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    out = pm.check_output(args.output)
    with pm.open_map(args.map) as ds:
        check_axes(ds, args.x, args.y, args.facet)
        at = pm.parse_at(args.at, ds)
        reserved = {args.x: "the x axis", args.y: "the y axis"}
        if args.facet:
            reserved[args.facet] = "the facet axis"
        fixed = pm.resolve_at(ds, at, free=[], reserved=reserved)
        for f in fixed.values():
            print(f.message)
        fig, _ = render(ds, args.x, args.y, fixed, args.facet, contours=not args.no_contours)
        pm.save_figure(fig, out, dpi=FIG_DPI)
    print(f"regime_map.py: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "regime_map.py"))
