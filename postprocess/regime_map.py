#!/usr/bin/python3
"""A 2-D slice of a punchsweep regime map: where level 2 touches immediately, after a delay
t*, or never.

Each grid point is one cell. Immediate cells are blue and never cells green (fixed colours);
a delayed cell is coloured by log10 t* on a sequential yellow-to-red scale, with a colour
bar (log10 t* in the map's time unit: T_eps, the creep time, or a material's unit). Points
the localization method flags as invalid (valid != 0: spots overlap, or no solution) are
drawn in a paler shade of their colour and hatched, unless the map holds the periodic BEM's
answer there (sweep --reference bem, e.g. --reference.sample invalid): then the BEM's regime
is drawn, in full colour and dotted; points never computed (an interrupted map) are dark
grey. Contour lines of t* run over the delayed region at whole decades (1-2-5 steps when
the delayed t* span less than two), labelled where their labels keep apart from each other.
A log-spaced axis (attribute spacing = "log") is drawn on a log scale.

--touch-within X draws the designer's question instead: which cells touch within X
(immediate, or delayed with t* <= X; blue), which touch later (t* > X; orange) and which
never (green).

The title names the material (or the creep law), its temperature, and the load: the
pressure where it is fixed, its range where it is an axis of the picture.

Any axes of the map can be drawn, fixed or faceted: the map's axes, their units and the
regime codes are read from the file. Units: l and dh in R (the punch size),
pbar in E0/(1-nu^2), T and s dimensionless, t* in T_eps; for a material map (sweep
[model] material) pbar in kPa (pbar E0* of the material) and times in its file's unit;
with model.R, lengths in R's unit (um).

Example:
  postprocess/regime_map.py map.h5 --x pbar --y dh --at l=0.75 T=2.5 s=2 -o map.png
  postprocess/regime_map.py map.h5 --x pbar --y dh --at l=0.75 s=2 --facet T -o map.pdf
  postprocess/regime_map.py silicone.h5 --x pbar --y dh --at l=150um s=2 --touch-within 1min -o t.png
"""
from __future__ import annotations

import argparse
import math
import sys
import textwrap
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

FIG_DPI = 150
PANEL_SIZE = (4.6, 3.6)  # inches per panel
LEGEND_WIDTH = 2.2  # inches
MAX_COLUMNS = 3
MOST_LEVELS = 7  # t* contour levels at most
LABEL_FONTSIZE = 8
LABEL_GAP = 3.0  # pixels kept free at least between contour labels, and between a label and the frame
LABEL_SPREAD = 30.0  # pixels kept free between contour labels where the line allows it
LABEL_TRIES = 80  # candidate spots per level along its line
FEW_VALUES = 6  # a linear axis with at most this many values is ticked at its grid values
T_STAR_LABEL = "log10 t*"  # the colour bar's label, before its unit
BAR_HEIGHT = 1.6  # inches of the colour bar, where the legend leaves room


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="regime_map.py", description=__doc__,
                  formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.h5", help="regime map written by `punchsweep sweep`")
    p.add_argument("--x", required=True, metavar="AXIS",
                   help="axis across the picture: a numeric axis of the map, e.g. pbar (l, dh "
                        "in R; pbar in E0/(1-nu^2); T, s dimensionless)")
    p.add_argument("--y", required=True, metavar="AXIS", help="axis up the picture (as --x)")
    pm.add_at_option(p, "fix each axis that is not --x, --y or --facet, e.g. l=0.75 T=2.5 s=2; a list "
                        "(temperature=20,30,40) draws a panel at each of those values of that axis")
    p.add_argument("--facet", metavar="AXIS",
                   help="draw one panel per grid value of this axis (shared legend); with --at AXIS=a,b,c "
                        "only at those")
    p.add_argument("--no-contours", action="store_true",
                   help="leave out the t* contour lines (t* in T_eps, or the material's time unit)")
    p.add_argument("--touch-within", metavar="TIME",
                   help="threshold view: colour the cells that touch within TIME (immediate, or "
                        "delayed with t* <= TIME), those that touch later, and those that never "
                        "touch. With a unit (60s, 1min, 2h) on a material map; a bare number is in "
                        "the map's time unit (T_eps, or the material's)")
    p.add_argument("--floor", metavar="TIME",
                   help="a delay shorter than this reads as immediate in practice: such cells are drawn as "
                        "immediate (the legend says so) and the colour bar starts there. Default on a "
                        "step-loaded material map 1 ms (under a ramp the immediate regime already runs to "
                        "the end of the rise); none on a map in T_eps; 0 turns it off")
    p.add_argument("-o", "--output", required=True,
                   help="picture to write; the format follows the suffix: .png or .pdf")
    return p.parse_args(argv)


@dataclass
class Panel:
    """One drawn slice: its axes, the cell-centre coordinates, the fill colours, its title,
    the t* contour labels drawn on it and the colour scale of the delayed cells (a
    ScalarMappable of log10 t*; None in the --touch-within view)."""
    ax: object
    x: np.ndarray
    y: np.ndarray
    colours: np.ndarray  # (ny, nx, 4) RGBA
    title: str
    labels: list = field(default_factory=list)
    scale: object = None


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


def contour_levels(t_star: np.ndarray, most: int = MOST_LEVELS) -> list[float]:
    """t* contour levels spread evenly in log t* over the delayed t* values (strictly between
    the smallest and the largest): the densest of 1-2-5 steps, 1-3 steps, whole decades, or
    every 2, 3, 5, 10 or 20 decades that gives at most `most` levels."""
    t = t_star[np.isfinite(t_star) & (t_star > 0)]
    if t.size == 0:
        return []
    lo, hi = math.log10(float(t.min())), math.log10(float(t.max()))
    exponents = range(math.floor(lo), math.ceil(hi) + 1)
    ladders = [[m * 10.0 ** e for e in exponents for m in mantissas] for mantissas in ((1, 2, 5), (1, 3))]
    ladders += [[10.0 ** e for e in exponents if e % every == 0] for every in (1, 2, 3, 5, 10, 20)]
    levels = []
    for ladder in ladders:
        levels = [v for v in ladder if lo < math.log10(v) < hi]
        if len(levels) <= most:
            break
    return levels


def level_texts(levels: list[float]) -> list[str]:
    """The contour labels: numbers as %g where every level lies from 0.001 to 1000, else
    every level as a power of ten, 10^k, or m 10^k (mathtext)."""
    if all(1e-3 <= v < 1e4 for v in levels):
        return [f"{v:g}" for v in levels]
    texts = []
    for v in levels:
        k = math.floor(math.log10(v) + 1e-9)
        m = v / 10.0 ** k
        texts.append(f"$10^{{{k}}}$" if abs(m - 1) < 1e-9 else f"${m:g} \\times 10^{{{k}}}$")
    return texts


def draw_contours(ax, xv, yv, regime, t_star, levels, codes: pm.Flags):
    """t* contour lines over the delayed cells; the ContourSet, or None if no line is drawn.

    The field is log10 t* at the delayed cell centres only (masked elsewhere), so each line
    runs where neighbouring delayed cells' t* bracket its level; none is pushed to the edge
    of the immediate or never region, where t* leaves the grid's range within one cell.
    `codes` are the map's regime flags.
    """
    delayed = regime == codes.code("delayed")
    if not delayed.any() or regime.shape[0] < 2 or regime.shape[1] < 2:
        return None
    with np.errstate(divide="ignore", invalid="ignore"):
        z = np.ma.masked_invalid(np.where(delayed & (t_star > 0), np.log10(t_star), np.nan))
    if z.count() < 4:
        return None
    cs = ax.contour(xv, yv, z, levels=np.log10(levels), colors="black", linewidths=0.7,
                    linestyles="solid")
    if not any(len(seg) > 1 for segs in cs.allsegs for seg in segs):
        return None
    return cs


def label_spots(ax, segs, fraction: float) -> list[tuple[float, float]]:
    """Candidate label spots (data coordinates) along one level's line pieces: the longest
    piece first, from the spot at `fraction` of its length outward, then the other pieces."""
    to_px = ax.transData
    pieces = []
    for seg in segs:
        if len(seg) < 2:
            continue
        px = to_px.transform(seg)
        step = np.hypot(*np.diff(px, axis=0).T)
        arc = np.concatenate([[0.0], np.cumsum(step)])
        if arc[-1] <= 0 or not np.all(np.isfinite(arc)):
            continue
        pieces.append((arc[-1], seg, arc))
    pieces.sort(key=lambda p: -p[0])
    spots = []
    for length, seg, arc in pieces:
        n = max(2, min(LABEL_TRIES, int(length / 4)))
        where = np.linspace(0, length, n)
        order = np.argsort(np.abs(where - fraction * length), kind="stable")
        xs = np.interp(where[order], arc, seg[:, 0])
        ys = np.interp(where[order], arc, seg[:, 1])
        spots += list(zip(xs, ys))
    return spots


def place_labels(fig, drawn: list) -> None:
    """Labels the t* contours of every panel: one label per level, on its line, where its box
    overlaps no label placed before and stays inside the panel (checked on the renderer's
    window extents after the figure is laid out). A level whose line offers no such spot is
    left unlabelled. `drawn` holds (panel, ContourSet, levels)."""
    fig.canvas.draw()  # the layout, so that extents are those of the saved picture
    renderer = fig.canvas.get_renderer()
    taken = []  # the placed labels' boxes (pixels)
    for panel, cs, levels in drawn:
        ax = panel.ax
        frame = ax.get_window_extent(renderer).padded(-LABEL_GAP)
        n = len(levels)
        for k, (label, segs) in enumerate(zip(level_texts(levels), cs.allsegs)):
            spots = label_spots(ax, segs, (k + 1) / (n + 1))
            text = ax.text(0, 0, label, fontsize=LABEL_FONTSIZE, ha="center", va="center",
                           zorder=4, bbox=dict(boxstyle="round,pad=0.15", facecolor="white", alpha=0.85,
                                               edgecolor="none"))
            text.set_in_layout(False)
            # Well apart from the other labels if the line has such a spot, else just apart.
            for gap in (LABEL_SPREAD, LABEL_SPREAD / 2, LABEL_GAP):
                spot = next((xy for xy in spots if fits(text, xy, renderer, frame, taken, gap)), None)
                if spot is not None:
                    break
            if spot is None:
                text.remove()
                continue
            text.set_position(spot)
            taken.append(text.get_window_extent(renderer))
            panel.labels.append(text)


def fits(text, xy, renderer, frame, taken, gap: float) -> bool:
    """Whether `text` moved to `xy` (data coordinates) lies inside `frame` and at least `gap`
    pixels from every box in `taken` (all in pixels)."""
    text.set_position(xy)
    box = text.get_window_extent(renderer)
    if not (frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0 and box.y1 <= frame.y1):
        return False
    wide = box.padded(gap)
    return not any(wide.overlaps(other) for other in taken)


def few_and_apart(values: np.ndarray, edges: np.ndarray) -> bool:
    """Whether a linear axis is better ticked at its grid values than by matplotlib:
    few values, none closer to the next than 8 % of the drawn range."""
    if len(values) > FEW_VALUES:
        return False
    return len(values) == 1 or np.min(np.diff(values)) >= 0.08 * (edges[-1] - edges[0])


@dataclass
class Slice:
    """One panel's arrays, shaped (ny, nx): the model's regime, validity and t*, and the BEM's
    regime and t* (not_computed / NaN outside its sample, or in a map without it)."""
    value: object  # the facet value (a float, or a label on a categorical axis), or None
    regime: np.ndarray
    valid: np.ndarray
    t_star: np.ndarray
    bem: np.ndarray
    bem_t_star: np.ndarray
    # Over the map's box of tolerances (output.tolerance), where it has one: the regimes and
    # t* at the box's ends (else None).
    regime_low: np.ndarray | None = None
    regime_high: np.ndarray | None = None
    t_star_low: np.ndarray | None = None
    t_star_high: np.ndarray | None = None


def slices(ds, x: str, y: str, facet: str | None, fixed: dict[str, pm.Fixed],
           panels: list[int] | None = None) -> list[Slice]:
    """The panels' arrays (Slice), one per facet value (those at `panels`, grid indices, where
    given) or one without --facet."""
    sel = {name: f.index for name, f in fixed.items()}
    order = ([facet] if facet else []) + [y, x]

    def take(name, fill):
        if name not in ds:
            return np.full(ds["regime"].isel(sel).transpose(*order).shape, fill)
        return ds[name].isel(sel).transpose(*order).values

    regime = take("regime", None)
    valid = take("valid", None)
    t_star = take("t_star", np.nan).astype(float)
    bem = take("bem_regime", pm.flags(ds, "regime").code(pm.NOT_COMPUTED))
    bem_t = take("bem_t_star", np.nan).astype(float)
    box = [take(name, None) if name in ds else None for name in ("regime_low", "regime_high")] + \
          [take(name, np.nan).astype(float) if name in ds else None for name in ("t_star_low", "t_star_high")]
    if facet is None:
        return [Slice(None, regime, valid, t_star, bem, bem_t, *box)]
    values = pm.grid_values(ds, facet)
    return [Slice(values[k], regime[k], valid[k], t_star[k], bem[k], bem_t[k],
                  *[None if b is None else b[k] for b in box])
            for k in (range(len(values)) if panels is None else panels)]


def below_floor(ds, regime: np.ndarray, t_star: np.ndarray, floor: tuple[float, str]):
    """A delay below the floor reads as immediate in practice: (the regimes with such cells
    made immediate, which cells they are)."""
    codes = pm.flags(ds, "regime")
    practical = (np.asarray(regime) == codes.code("delayed")) & (np.asarray(t_star) < floor[0])
    return np.where(practical, codes.code("immediate"), regime), practical


def tolerance_band(ds, d: Slice, within: tuple[float, str] | None,
                   floor: tuple[float, str] | None = None) -> np.ndarray | None:
    """Cells whose regime (or --touch-within class) differs between the ends of the map's box
    of tolerances: the answer there depends on where in the box the part falls (a delay below
    `floor` counting as immediate, as the picture draws it). None for a map without a box."""
    if d.regime_low is None:
        return None
    low, high = np.asarray(d.regime_low), np.asarray(d.regime_high)
    if within is not None:
        low, high = touch_within(ds, low, d.t_star_low, within[0]), touch_within(ds, high, d.t_star_high, within[0])
    elif floor is not None:
        low, high = (below_floor(ds, r, t, floor)[0] for r, t in ((low, d.t_star_low), (high, d.t_star_high)))
    computed = (low != pm.flags(ds, "regime").code(pm.NOT_COMPUTED)) & \
               (high != pm.flags(ds, "regime").code(pm.NOT_COMPUTED))
    return computed & (low != high)


def bem_answers(ds, valid: np.ndarray, bem: np.ndarray) -> np.ndarray:
    """Cells the model cannot answer (flagged invalid) where the map has the BEM's regime."""
    ok = np.asarray(valid) == pm.flags(ds, "valid").code(pm.VALID)
    return ~ok & (np.asarray(bem) != pm.flags(ds, "regime").code(pm.NOT_COMPUTED))


def touch_within(ds, regime: np.ndarray, t_star: np.ndarray, limit: float) -> np.ndarray:
    """The --touch-within classes as regime codes of the map: cells that touch within `limit`
    (immediate, or delayed with t* <= limit) get the immediate code, those that touch later
    (t* > limit) the delayed code, never stays never. A delayed cell without a finite t* (the
    BEM's beyond its last snapshot time) touches later if `limit` is before that time, else it
    is not known: not_computed."""
    codes = pm.flags(ds, "regime")
    regime = np.asarray(regime)
    delayed = regime == codes.code("delayed")
    t = np.asarray(t_star, dtype=float)
    last = float(np.nanmax(ds["time"].values)) if "time" in ds.variables and ds["time"].size else -np.inf
    within = delayed & np.isfinite(t) & (t <= limit)
    later = delayed & ((np.isfinite(t) & (t > limit)) | (~np.isfinite(t) & (limit < last)))
    out = regime.copy()
    out[within] = codes.code("immediate")
    out[delayed & ~within & ~later] = codes.code(pm.NOT_COMPUTED)
    return out


def load_text(ds, x: str, y: str, facet: str | None, fixed: dict[str, pm.Fixed]) -> str:
    """The load for the title: the load's kind and the pressure, fixed ('pbar0 = 2 kPa'), or its
    range on the axis that shows it."""
    _, _, load = pm.map_parts(ds)
    if "pbar" not in pm.axes(ds):
        return load
    if "pbar" in fixed:
        return f"{load}, {pm.format_value(ds, 'pbar', fixed['pbar'].value, tex=True)}"
    values = pm.grid_values(ds, "pbar")
    unit = pm.unit_tex(pm.units(ds, "pbar"))
    where = {x: "x axis", y: "y axis", facet: "one a panel"}["pbar"] if "pbar" in (x, y, facet) else ""
    span = f"{min(values):.3g} to {max(values):.3g}" + ("" if unit in ("", "-") else f" {unit}")
    return f"{load}, nominal pressure {pm.symbol_tex('pbar')} from {span} ({where})"


def title_lines(ds, x: str, y: str, facet: str | None, fixed: dict[str, pm.Fixed],
                within: str | None = None) -> str:
    """The figure's title: what it shows and of which material (or creep law) at which
    temperature; the load; the other fixed axes and the model."""
    law, model, _ = pm.map_parts(ds)
    names = pm.material_names(ds)
    if "material" in fixed:
        label = str(fixed["material"].value)
        law = names.get(label, label)
    elif facet == "material":
        law = "one material a panel"
    what = f"Level 2 touching within {within}: " if within else "Regime map: "
    first = what + law
    if "temperature" in pm.axes(ds):
        if "temperature" in fixed:
            first += ", " + pm.format_value(ds, "temperature", fixed["temperature"].value, tex=True)
        else:
            first += ", temperature on the " + {x: "x axis", y: "y axis", facet: "panels"}["temperature"]
    others = [pm.format_value(ds, name, f.value, tex=True) for name, f in fixed.items()
              if name not in ("pbar", "temperature", "material")]
    incomplete = " (incomplete map)" if not pm.is_completed(ds) else ""
    last = ("at " + ", ".join(others) + "; " if others else "") + model + incomplete
    return "\n".join([first, load_text(ds, x, y, facet, fixed), last])


def default_floor(ds) -> tuple[float, str] | None:
    """The --floor a map gets when none is given: 1 ms on a step-loaded map in physical time
    (a material map), in the map's time unit; None otherwise."""
    if pm.map_parts(ds)[2] != "step load":
        return None  # under a ramp or a table the immediate regime runs to the end of the rise already
    try:
        return pm.parse_time(ds, "0.001s", "--floor")[0], "1 ms"
    except pm.MapError:
        return None  # T_eps: no physical floor


def render(ds, x: str, y: str, fixed: dict[str, pm.Fixed], facet: str | None = None,
           contours: bool = True, within: tuple[float, str] | None = None, panels: list[int] | None = None,
           floor: tuple[float, str] | None = None):
    """Draws the map; returns (figure, panels). The figure size and dpi are fixed.

    `within` = (time in the map's time unit, its text) draws the --touch-within view (no
    t* colours or contours)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.cm import ScalarMappable
    from matplotlib.collections import PatchCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch, Rectangle
    from matplotlib.ticker import MaxNLocator

    data = slices(ds, x, y, facet, fixed, panels)
    codes, valid_code = pm.flags(ds, "regime"), pm.flags(ds, "valid").code(pm.VALID)
    xv, yv = ds[x].values.astype(float), ds[y].values.astype(float)
    xlog, ylog = pm.is_log(ds, x), pm.is_log(ds, y)
    xe, ye = pm.cell_edges(xv, xlog), pm.cell_edges(yv, ylog)
    time_unit = pm.unit_tex(pm.units(ds, "t_star")) if "t_star" in ds else ""

    # What each panel shows: the regime (the BEM's where it answers for the model) and its t*.
    shown = []
    any_practical = False
    for d in data:
        answered = bem_answers(ds, d.valid, d.bem)
        regime = np.where(answered, d.bem, d.regime)
        valid = np.where(answered, valid_code, d.valid)
        t_star = np.where(answered, d.bem_t_star, d.t_star)
        if within is not None:
            regime = touch_within(ds, regime, t_star, within[0])
        elif floor is not None:  # drawn as immediate, and said so
            regime, practical = below_floor(ds, regime, t_star, floor)
            any_practical |= bool(practical.any())
        shown.append((answered, regime, valid, t_star))
    norm = None
    if within is None:
        norm = pm.t_star_norm(np.concatenate([np.where(r == codes.code("delayed"), t, np.nan).ravel()
                                              for _, r, _, t in shown]))
    scale = ScalarMappable(norm=norm, cmap=pm.t_star_colormap()) if norm is not None else None
    all_t = np.concatenate([np.where(r == codes.code("delayed"), t, np.nan).ravel() for _, r, _, t in shown])
    levels = contour_levels(all_t) if contours and within is None else []

    n = len(data)
    ncols = min(n, MAX_COLUMNS)
    nrows = math.ceil(n / ncols)
    fig = plt.figure(figsize=(PANEL_SIZE[0] * ncols + LEGEND_WIDTH, PANEL_SIZE[1] * nrows + 0.75),
                     dpi=FIG_DPI, constrained_layout=True)
    grid = fig.add_gridspec(nrows, ncols + 1,
                            width_ratios=[PANEL_SIZE[0]] * ncols + [LEGEND_WIDTH])
    panels: list[Panel] = []
    with_contours = []
    any_invalid = any_missing = any_bem = any_band = False
    first = None
    for k, (d, (answered, regime, valid, t_star)) in enumerate(zip(data, shown)):
        row, col = divmod(k, ncols)
        ax = fig.add_subplot(grid[row, col], sharex=first, sharey=first)
        first = first or ax
        # Where the model has no answer and the BEM has one, the BEM's regime, drawn as a
        # valid one (full colour), dotted (the model's pale hatched cell is not drawn there).
        any_bem |= bool(answered.any())
        colours = pm.regime_colour_grid(ds, regime, valid, t_star, norm)
        mesh = ax.pcolormesh(xe, ye, np.zeros(regime.shape), shading="flat", antialiased=False,
                             edgecolors="none")
        mesh.set_array(None)  # each cell its own RGBA
        mesh.set_facecolor(colours.reshape(-1, 4))
        if answered.any():
            rects = [Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j])
                     for j, i in zip(*np.nonzero(answered))]
            ax.add_collection(PatchCollection(rects, facecolor="none", edgecolor="0.15",
                                              hatch="..", linewidth=0))
        cat = pm.categories(ds, regime, valid)
        bad = (cat >= 3) & (cat < pm.CATEGORY_NOT_COMPUTED)
        any_invalid |= bool(bad.any())
        any_missing |= bool((cat == pm.CATEGORY_NOT_COMPUTED).any())
        if bad.any():
            rects = [Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j])
                     for j, i in zip(*np.nonzero(bad))]
            ax.add_collection(PatchCollection(rects, facecolor="none", edgecolor="0.35",
                                              hatch="///", linewidth=0))
        band = tolerance_band(ds, d, within, floor)
        if band is not None and band.any():
            any_band = True
            rects = [Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j])
                     for j, i in zip(*np.nonzero(band))]
            ax.add_collection(PatchCollection(rects, facecolor="none", edgecolor="black",
                                              hatch="xx", linewidth=0))
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
        if row == nrows - 1 or k + ncols >= n:
            ax.set_xlabel(pm.axis_label(ds, x))
        if col == 0:
            ax.set_ylabel(pm.axis_label(ds, y))
        title = pm.format_value(ds, facet, d.value, tex=True) if facet else ""
        if title:
            ax.set_title(title, fontsize=10)
        panel = Panel(ax, xv, yv, colours, title, scale=scale)
        panels.append(panel)
        cs = draw_contours(ax, xv, yv, regime if floor is not None else d.regime, d.t_star, levels, codes) \
            if levels else None
        if cs is not None:
            with_contours.append((panel, cs, levels))

    if within is None:
        delayed_label = "delayed: colour\nis $t^*$ (bar)" if scale is not None else "delayed"
        mid = pm.t_star_colormap()(0.5) if scale is not None else pm.REGIME_COLOURS["delayed"]
        immediate_label = (f"immediate, or within\n{floor[1]} (immediate\nin practice)" if any_practical
                           else "immediate")
        handles = [Patch(facecolor=pm.REGIME_COLOURS["immediate"], label=immediate_label),
                   Patch(facecolor=mid, label=delayed_label),
                   Patch(facecolor=pm.REGIME_COLOURS["never"], label="never")]
    else:
        handles = [Patch(facecolor=pm.REGIME_COLOURS["immediate"],
                         label=f"touches within\n{within[1]}"),
                   Patch(facecolor=pm.REGIME_COLOURS["delayed"], label="touches later"),
                   Patch(facecolor=pm.REGIME_COLOURS["never"], label="never")]
    if any_invalid:
        handles.append(Patch(facecolor=pm.invalid_colour("delayed"), edgecolor="0.35", hatch="///",
                             linewidth=0, label="invalid (overlap or\nno solution): paler,\nhatched"))
    if any_bem:
        handles.append(Patch(facecolor=pm.REGIME_COLOURS["delayed"], edgecolor="0.15", hatch="..",
                             linewidth=0, label="model invalid, the\nBEM's regime: full\ncolour, dotted"))
    if any_band:
        box = "\n".join(textwrap.wrap(str(ds.attrs.get("tolerance", "")), 22))
        handles.append(Patch(facecolor="white", edgecolor="black", hatch="xx", linewidth=0,
                             label=f"depends on where in\nthe tolerance box:\n{box}"))
    if any_missing:
        handles.append(Patch(facecolor=pm.REGIME_COLOURS[pm.NOT_COMPUTED],
                             label="not computed" if within is None else "not computed,\nor $t^*$ unknown"))
    if with_contours:
        handles.append(Line2D([], [], color="black", lw=0.7, label=f"$t^*$ contours,\nlabels in {time_unit}"))
    legend_ax = fig.add_subplot(grid[:, ncols])
    legend_ax.axis("off")
    legend = legend_ax.legend(handles=handles, loc="upper left", title="level-2 contact", frameon=False,
                              fontsize=9, title_fontsize=9, borderaxespad=0)
    fig.suptitle(title_lines(ds, x, y, facet, fixed, within[1] if within else None), fontsize=10)
    if scale is not None:
        # The colour bar under the legend, in the room the laid-out legend leaves.
        fig.canvas.draw()
        below = legend.get_window_extent().transformed(legend_ax.transAxes.inverted()).y0
        top = below - 0.06
        height = min(BAR_HEIGHT / (legend_ax.get_window_extent().height / fig.dpi), top - 0.02)
        cax = legend_ax.inset_axes([0.04, top - max(height, 0.1), 0.09, max(height, 0.1)])
        bar = fig.colorbar(scale, cax=cax)
        bar.set_label(f"{T_STAR_LABEL} [{time_unit}]", fontsize=9)
        bar.ax.yaxis.set_major_locator(MaxNLocator(integer=True, nbins=8))
        bar.ax.tick_params(labelsize=8)
    if with_contours:
        place_labels(fig, with_contours)
    return fig, panels


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    out = pm.check_output(args.output, inputs=[args.map])
    with pm.open_map(args.map) as ds:
        at = pm.parse_at(args.at, ds, lists=True)
        # --at AXIS=a,b,c: those values of AXIS, a panel each (AXIS is then the facet).
        listed = [name for name, v in at.items() if isinstance(v, list)]
        if len(listed) > 1 or (listed and args.facet and listed[0] != args.facet):
            raise pm.MapError(f"--at {listed[-1]}=...: a list of values picks the panels of the facet axis, "
                              f"{'which is ' + args.facet if args.facet and listed[-1] != args.facet else 'one axis'}; "
                              f"give the other axes one value each")
        panels = None
        if listed:
            args.facet = listed[0]
            panels = list(dict.fromkeys(pm.nearest_index(ds, args.facet, v) for v in at.pop(args.facet)))
        check_axes(ds, args.x, args.y, args.facet)
        within = None
        if args.touch_within is not None:
            if "t_star" not in ds:
                raise pm.MapError(f"'{args.map}' has no t_star variable (needed by --touch-within)")
            within = pm.parse_time(ds, args.touch_within, "--touch-within")
        reserved = {args.x: "the x axis", args.y: "the y axis"}
        if args.facet:
            reserved[args.facet] = "the facet axis"
        fixed = pm.resolve_at(ds, at, free=[], reserved=reserved)
        for f in fixed.values():
            print(f.message)
        floor = default_floor(ds) if args.floor is None else \
            (None if args.floor.strip() in ("0", "0s") else pm.parse_time(ds, args.floor, "--floor"))
        fig, _ = render(ds, args.x, args.y, fixed, args.facet, contours=not args.no_contours,
                        within=within, panels=panels, floor=floor)
        pm.save_figure(fig, out, dpi=FIG_DPI, inputs=[args.map])
    print(f"regime_map.py: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "regime_map.py"))
