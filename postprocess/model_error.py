#!/usr/bin/python3
"""How far the localization model is from the periodic BEM reference, from one map.

Reads a regime map written with `punchsweep sweep --reference bem` (variables bem_regime,
bem_t_star, bem_a1, bem_a2, ...) and compares the model with the reference at every point
where the reference was computed:
  - regime agreement: the confusion table model x BEM, and the share of points that agree;
  - t*: relative error |t*_model - t*_BEM| / t*_BEM where both are delayed, median and worst,
    overall and per value of each axis;
  - contact radii a1, a2: relative errors at every snapshot time, median and worst.
Optionally draws the errors against each axis (--errors-plot) and a regime-map slice with
the BEM regimes drawn over the localization colours (--slice-plot): markers at the sampled
cells and, where a slice is fully sampled, the BEM regime boundaries as lines.

The map's axes, their units and the codes of regime, valid and bem_regime are read from
the file (the dimensions of `regime`, the coordinates' attributes, flag_values/flag_meanings).

Units: t* in T_eps, radii in R; errors are relative (dimensionless).
Example:
  model_error.py map.h5 --errors-plot errors.png --slice-plot slice.png --x pbar --y dh --at l=0.75 T=5 s=2
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

BEM_VARIABLES = ("bem_regime", "bem_t_star")
NAMES = pm.DRAWN_REGIMES  # the confusion table's rows and columns, by flag meaning


def require_reference(ds) -> None:
    missing = [v for v in BEM_VARIABLES if v not in ds]
    if missing:
        raise pm.MapError("this map has no BEM reference (missing " + ", ".join(missing) +
                          "): make it with `punchsweep sweep --reference bem`")


def relative_error(model: np.ndarray, bem: np.ndarray) -> np.ndarray:
    """|model - bem| / |bem|, NaN where either is NaN or the reference is 0."""
    model = np.asarray(model, dtype=float)
    bem = np.asarray(bem, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        err = np.abs(model - bem) / np.abs(bem)
    err[~np.isfinite(err) | (bem == 0)] = np.nan
    return err


def stats(values: np.ndarray) -> dict:
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return {"count": 0, "median": float("nan"), "worst": float("nan")}
    return {"count": int(v.size), "median": float(np.median(v)), "worst": float(np.max(v))}


def compare(ds, valid_only: bool = False) -> dict:
    """Every comparison figure of a map with a BEM reference (pure: no printing, no files).

    Returns {"sampled", "confusion" (3x3 counts, rows model, columns BEM), "agreement"
    (share of sampled points with the same regime), "t_star" (stats), "t_star_by_axis"
    ({axis: [(value, stats)]}), "radii" ({"a1": stats, "a2": stats} over all snapshot
    times, where both radii are > 0)}."""
    require_reference(ds)
    axes = pm.axes(ds)
    model_codes, bem_codes = pm.flags(ds, "regime"), pm.flags(ds, "bem_regime")
    regime = ds.regime.values
    bem = ds.bem_regime.transpose(*axes).values
    mask = np.isin(bem, [bem_codes.code(n) for n in NAMES])  # the reference's sample
    if valid_only:
        mask &= ds.valid.transpose(*axes).values == pm.flags(ds, "valid").code(pm.VALID)
    model_is = [regime == model_codes.code(n) for n in NAMES]
    bem_is = [bem == bem_codes.code(n) for n in NAMES]
    confusion = np.zeros((3, 3), dtype=int)
    for m in range(3):
        for b in range(3):
            confusion[m, b] = int(np.sum(mask & model_is[m] & bem_is[b]))
    sampled = int(mask.sum())
    agreement = float(np.trace(confusion)) / sampled if sampled else float("nan")

    delayed = NAMES.index("delayed")
    both_delayed = mask & model_is[delayed] & bem_is[delayed]
    t_err = np.where(both_delayed, relative_error(ds.t_star.transpose(*axes).values,
                                                  ds.bem_t_star.transpose(*axes).values), np.nan)
    by_axis = {}
    for axis_index, name in enumerate(axes):
        rows = []
        for i, value in enumerate(pm.grid_values(ds, name)):
            rows.append((value, stats(np.take(t_err, i, axis=axis_index))))
        by_axis[name] = rows

    radii = {}
    for name in ("a1", "a2"):
        bem_name = "bem_" + name
        if bem_name not in ds or name not in ds:
            continue
        model_r = ds[name].transpose(*axes, ...).values
        bem_r = ds[bem_name].transpose(*axes, ...).values
        ok = mask[..., None] & (model_r > 0) & (bem_r > 0)
        radii[name] = stats(np.where(ok, relative_error(model_r, bem_r), np.nan))
    return {"sampled": sampled, "confusion": confusion, "agreement": agreement,
            "t_star": stats(t_err), "t_star_by_axis": by_axis, "radii": radii,
            "t_star_errors": t_err}


def report(ds, result: dict, valid_result: dict) -> str:
    lines = []
    attrs = ds.attrs
    lines.append(f"BEM reference: {int(attrs.get('bem_sample', result['sampled']))} sampled points, grid "
                 f"{attrs.get('bem_grid', '?')} x {attrs.get('bem_grid', '?')}, CG tolerance {attrs.get('bem_tolerance', '?')}")
    lines.append("")
    lines.append("regime (rows: localization model, columns: BEM reference)")
    lines.append(f"{'':12s}" + "".join(f"{n:>11s}" for n in NAMES))
    for m in range(3):
        lines.append(f"{NAMES[m]:12s}" + "".join(f"{result['confusion'][m, b]:11d}" for b in range(3)))
    lines.append(f"agreement: {100 * result['agreement']:.1f}% of {result['sampled']} points "
                 f"({100 * valid_result['agreement']:.1f}% of the {valid_result['sampled']} the model flags valid)")
    lines.append("")
    t, tv = result["t_star"], valid_result["t_star"]
    lines.append(f"t* relative error where both are delayed: median {100 * t['median']:.1f}%, worst "
                 f"{100 * t['worst']:.1f}% over {t['count']} points (t* in T_eps); where the model is valid: median "
                 f"{100 * tv['median']:.1f}%, worst {100 * tv['worst']:.1f}% over {tv['count']}")
    for name, stat in result["radii"].items():
        sv = valid_result["radii"][name]
        lines.append(f"{name} relative error at the snapshot times: median {100 * stat['median']:.1f}%, worst "
                     f"{100 * stat['worst']:.1f}% over {stat['count']} values (radii in R); where the model is "
                     f"valid: median {100 * sv['median']:.1f}%, worst {100 * sv['worst']:.1f}% over {sv['count']}")
    lines.append("")
    lines.append("t* relative error by axis value (median / worst, points):")
    for name, rows in result["t_star_by_axis"].items():
        cells = [f"{pm.value_text(value)}: {100 * s['median']:.1f}%/{100 * s['worst']:.1f}% ({s['count']})"
                 for value, s in rows if s["count"]]
        lines.append(f"  {name}{pm.unit_suffix(ds, name)}: " + ("; ".join(cells) if cells else "no delayed pairs"))
    return "\n".join(lines)


def errors_plot(ds, result: dict, valid_result: dict, path: Path) -> None:
    """t* errors against each axis: points the model flags (hollow, grey) and valid ones
    (filled), with the valid points' median."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t_err = result["t_star_errors"]
    names = pm.axes(ds)
    fig, axes = plt.subplots(1, len(names), figsize=(3.2 * len(names), 3.4), constrained_layout=True,
                             sharey=True, squeeze=False)
    axes = axes[0]
    for axis_index, (ax, name) in enumerate(zip(axes, names)):
        categorical = pm.is_categorical(ds, name)
        values = np.arange(ds.sizes[name]) if categorical else ds[name].values.astype(float)
        shape = [1] * t_err.ndim
        shape[axis_index] = len(values)
        x = np.broadcast_to(values.reshape(shape), t_err.shape)
        valid = np.isfinite(valid_result["t_star_errors"])
        flagged = np.isfinite(t_err) & ~valid
        ax.scatter(x[flagged], 100 * t_err[flagged], s=10, facecolors="none", edgecolors="0.55", linewidths=0.7,
                   label="flagged by the model")
        ax.scatter(x[valid], 100 * t_err[valid], s=8, alpha=0.6, color="tab:blue", label="valid")
        medians = [s["median"] for _, s in valid_result["t_star_by_axis"][name]]
        ax.plot(values, 100 * np.array(medians), color="k", marker="o", ms=3, label="median (valid)")
        if pm.is_log(ds, name):
            ax.set_xscale("log")
        if categorical:  # one column per label
            ax.set_xticks(values, pm.labels(ds, name))
        ax.set_xlabel(pm.axis_label(ds, name))
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("|t*$_{model}$ - t*$_{BEM}$| / t*$_{BEM}$ [%]")
    axes[0].legend()
    fig.suptitle(f"t* of the localization model ({ds.attrs.get('localization', 'paper')}) against the periodic BEM "
                 "(points delayed in both)")
    pm.save_figure(fig, path)


def slice_plot(ds, x: str, y: str, at: dict, path: Path) -> list[str]:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    if x == y:
        raise pm.MapError("--x and --y must differ")
    pm.require_numeric(ds, x, "--x")
    pm.require_numeric(ds, y, "--y")
    fixed = pm.resolve_at(ds, at, free=[x, y], reserved={x: "the x axis", y: "the y axis"})
    cut = ds.isel({name: f.index for name, f in fixed.items()}).transpose(y, x, ...)
    xv, yv = ds[x].values, ds[y].values
    xe, ye = pm.cell_edges(xv, pm.is_log(ds, x)), pm.cell_edges(yv, pm.is_log(ds, y))
    cat = pm.categories(ds, cut.regime.values, cut.valid.values)
    colours = pm.category_colours()
    fig, ax = plt.subplots(figsize=(7.5, 5), constrained_layout=True)
    ax.pcolormesh(xe, ye, cat, cmap=ListedColormap(colours), norm=BoundaryNorm(np.arange(-0.5, 7.5), 7),
                  shading="flat", antialiased=False)
    bem_codes = pm.flags(ds, "bem_regime")
    bem = np.full(cut.bem_regime.shape, -1)  # index into NAMES; -1 outside the sample
    for k, name in enumerate(NAMES):
        bem[cut.bem_regime.values == bem_codes.code(name)] = k
    sampled = bem >= 0
    xx, yy = np.meshgrid(xv, yv)
    for k, name in enumerate(NAMES):
        sel = sampled & (bem == k)
        ax.scatter(xx[sel], yy[sel], s=28, color=pm.REGIME_COLOURS[name], edgecolors="k", linewidths=0.8, zorder=3)
    if sampled.all() and len(xv) > 1 and len(yv) > 1:
        ax.contour(xv, yv, bem, levels=[0.5, 1.5], colors="k", linewidths=1.6, linestyles="--", zorder=2)
    if pm.is_log(ds, x):
        ax.set_xscale("log")
        pm.style_log_axis(ax.xaxis)
    if pm.is_log(ds, y):
        ax.set_yscale("log")
        pm.style_log_axis(ax.yaxis)
    ax.set_xlabel(pm.axis_label(ds, x))
    ax.set_ylabel(pm.axis_label(ds, y))
    handles = [Patch(color=colours[c], label=f"model: {NAMES[c]}") for c in range(3)]
    handles += [Line2D([], [], marker="o", ls="", color=pm.REGIME_COLOURS[NAMES[c]], markeredgecolor="k",
                       label=f"BEM: {NAMES[c]}") for c in range(3)]
    if sampled.all():
        handles.append(Line2D([], [], color="k", ls="--", label="BEM regime boundaries"))
    ax.legend(handles=handles, loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    title = ", ".join(pm.format_value(ds, n, f.value, tex=True) for n, f in fixed.items())
    ax.set_title(f"localization model (cells) vs periodic BEM (markers){': ' + title if title else ''}", fontsize=10)
    pm.save_figure(fig, path)
    return [f.message for f in fixed.values()]


def main(argv: list[str]) -> int:
    p = pm.Parser(prog="model_error.py", description=__doc__,
                  formatter_class=__import__("argparse").RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.h5", help="regime map written by `punchsweep sweep --reference bem`")
    p.add_argument("--errors-plot", metavar="OUT.png", help="draw the t* errors against each axis (.png or .pdf)")
    p.add_argument("--slice-plot", metavar="OUT.png", help="draw a regime-map slice with the BEM regimes over it")
    p.add_argument("--x", default="pbar", metavar="AXIS", help="slice axis across (default pbar)")
    p.add_argument("--y", default="dh", metavar="AXIS", help="slice axis up (default dh)")
    pm.add_at_option(p, "fix the other axes of the slice")
    args = p.parse_args(argv)
    outputs = [pm.check_output(o, inputs=[args.map]) for o in (args.errors_plot, args.slice_plot) if o]
    with pm.open_map(args.map) as ds:
        x = pm.parse_axis(ds, args.x, "--x")
        y = pm.parse_axis(ds, args.y, "--y")
        at = pm.parse_at(args.at, ds)
        result = compare(ds)
        valid_result = compare(ds, valid_only=True)
        print(report(ds, result, valid_result))
        if args.errors_plot:
            errors_plot(ds, result, valid_result, outputs[0])
            print(f"model_error.py: wrote {outputs[0]}")
        if args.slice_plot:
            for message in slice_plot(ds, x, y, at, outputs[-1]):
                print(message)
            print(f"model_error.py: wrote {outputs[-1]}")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "model_error.py"))
