#!/usr/bin/python3
"""Each level's touch time over a texture's map: the picture of `punchsweep.surface_map`.

Reads a map `punchsweep surface-map --output MAP.nc` (or punchsweep.surface_map(output=...))
wrote, or a Dataset surface_map returned saved by .to_netcdf(engine="h5netcdf"), and draws, for every level below the tallest, its t* over the map's two remaining axes (the
pressure along x, log-scaled where it spans a decade), or along one axis as a line: log t*
in colour where the level touches late, grey where it touches at once (immediate), dark
where it never does; and, where the map has them, the share of caps in contact at one of
its times (--time, default the last), blank where that snapshot is flagged. A map with a box
of tolerances (surface-map --tolerance) has the cells whose regime differs between the box's
ends hatched: there the answer depends on where in the box the part falls. Axes beyond two are fixed by --at NAME=VALUE (the nearest value is used
and said); an axis of one value needs none. A map of a scattered supercell with a seed axis
(one draw per seed) is drawn over its draws with --over-seeds: each level's median t* over
them (its regime: at once where the median is 0, never where it is infinite), the mean
share of caps in contact (blank where any draw's snapshot is flagged), and hatched the
cells where the draws' regimes differ.

Example:
  mpirun -n 2 punchsweep surface-map --lattice hexagonal --l 1.2 --dh 0.04,0.05,0.06 --dh2 0.09 \
      --s 2 --pbar 0.002,0.005,0.01,0.02,0.05 --T 2,4,8 --output hex.nc
  postprocess/surface_picture.py hex.nc --at T=4 -o hex.png
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

FIG_DPI = 150
#: The map's regime codes (a regime map's: punchsweep.REGIMES).
IMMEDIATE, DELAYED, NEVER = 0, 1, 2


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="surface_picture.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.nc", help="written by punchsweep surface-map (or punchsweep.surface_map)")
    p.add_argument("-o", "--output", required=True, help="picture to write (.png or .pdf)")
    p.add_argument("--over-seeds", action="store_true",
                   help="draw a scattered map over its seed axis: median t*, mean share, cells whose draws differ hatched")
    p.add_argument("--at", nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                   help="fix an axis beyond the two drawn at its nearest value (said in the title)")
    p.add_argument("--time", type=float, default=None, metavar="T",
                   help="the time of the caps-in-contact panel (the map's nearest; default its last)")
    return p.parse_args(argv)


def read_map(path: str):
    """The map by the one reader every map goes through (pm.open_map: its checks; lengths in
    R's unit, pressures in kPa and times in the material's where the map has them)."""
    ds = pm.open_map(path)
    for name in ("t_star", "regime"):
        if name not in ds or "level" not in ds[name].dims:
            raise pm.MapError(f"{path}: no '{name}' over a 'level' axis: not a map surface_map wrote (a regime map "
                              f"of punchsweep sweep is drawn by regime_map.py)")
    return ds.load()


def over_seeds(ds):
    """The map's draws (its `seed` axis, two values or more) as one: each level's median t*
    over them and its regime (immediate where the median is 0, never where it is +inf,
    delayed otherwise), `regime_spread` (1 where the draws' regimes differ), the mean share of
    caps in contact, and `valid` 0 only where every draw's snapshot is."""
    if "seed" not in ds.t_star.dims or ds.sizes["seed"] < 2:
        raise pm.MapError("--over-seeds: the map has no seed axis of two values or more (surface-map --supercell K "
                          "--scatter normal:SD --seed 1:8)")
    n = ds.sizes["seed"]
    out = ds.isel(seed=0, drop=True)
    t = ds.t_star.median("seed", skipna=False, keep_attrs=True)
    out["t_star"] = t
    out["X_star"] = ds.X_star.median("seed", skipna=False, keep_attrs=True)
    out["regime"] = t.copy(data=np.where(t.values == 0, IMMEDIATE, np.where(np.isinf(t.values), NEVER, DELAYED)))
    out["regime_spread"] = (ds.regime.min("seed") != ds.regime.max("seed")).astype(np.int8)
    if "touched" in ds:
        out["touched"] = ds.touched.mean("seed", keep_attrs=True)
        out["valid"] = ds.valid.max("seed", keep_attrs=True)
    for name in ("regime_low", "regime_high"):  # (a box of tolerances: per draw, not drawn over them)
        if name in out:
            out = out.drop_vars(name)
    out.attrs["over_seeds"] = f"{n} draws, seeds {', '.join(str(int(v)) for v in ds.seed.values)}"
    return out


def select(ds, at: list[str]):
    """The map with every --at axis fixed at its nearest value, and the sentences saying so."""
    said = []
    for item in at:
        name, _, text = item.partition("=")
        if name not in ds.t_star.dims or name == "level":
            axes = ", ".join(d for d in ds.t_star.dims if d != "level")
            raise pm.MapError(f"--at {item}: no axis '{name}' (the map's: {axes})")
        # (A number with a unit, 20kPa, is converted to the axis's unit; a bare one is in the
        # axis's scale, R or E0*, as on every command line.)
        ds = ds.sel({name: pm.at_number(ds, name, text)}, method="nearest")
        unit = pm.units(ds, name)
        said.append(f"{name} = {float(ds[name]):.4g}" + (f" {unit}" if unit not in ("", "1") else ""))
    left = [d for d in ds.t_star.dims if d != "level" and ds.sizes[d] > 1]
    if len(left) > 2:
        raise pm.MapError(f"the map has {len(left)} axes of several values ({', '.join(left)}); fix all but two "
                          f"with --at NAME=VALUE")
    for d in [d for d in ds.t_star.dims if d != "level" and ds.sizes[d] == 1]:
        ds = ds.isel({d: 0})
    return ds, said


def edges(values: np.ndarray, log: bool) -> np.ndarray:
    """Cell edges about each value: midway between neighbours (geometrically where the axis
    is drawn log-scaled, so that each value's cell is centred on it there)."""
    v = np.log10(values) if log else values.astype(float)
    if v.size == 1:
        middle = np.array([v[0] - 0.5, v[0] + 0.5]) if not log else np.array([v[0] - 0.05, v[0] + 0.05])
    else:
        inner = 0.5 * (v[1:] + v[:-1])
        middle = np.concatenate([[2 * v[0] - inner[0]], inner, [2 * v[-1] - inner[-1]]])
    return 10 ** middle if log else middle


def log_scaled(values: np.ndarray) -> bool:
    """An axis drawn log-scaled: positive values over a decade or more."""
    return values.size > 1 and values.min() > 0 and values.max() / values.min() >= 10


def tolerance_band(ds, level: int, order: list[str]) -> np.ndarray | None:
    """Level `level`'s cells (dimensions `order`) whose regime differs between the ends of the
    map's box of tolerances (regime_low, regime_high; both computed): None without a box."""
    if "regime_low" not in ds:
        return None
    low = ds.regime_low.sel(level=level).transpose(*order).values
    high = ds.regime_high.sel(level=level).transpose(*order).values
    return (low >= 0) & (high >= 0) & (low != high)


def render(ds, said: list[str], time: float | None = None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PatchCollection
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch, Rectangle

    axes = [d for d in ds.t_star.dims if d != "level"]
    # The pressure along x where it is one of the axes.
    axes.sort(key=lambda d: 0 if d in ("pbar", "pressure") else 1)
    levels = [int(v) for v in ds.level.values if int(v) > 0]
    # The share of caps in contact at one time (a map surface-map wrote has it), one panel more.
    touched = "touched" in ds and "t" in ds.touched.dims and ds.sizes["t"] > 0
    fig, panels = plt.subplots(1, len(levels) + touched, figsize=(4.6 * (len(levels) + touched) + 0.6, 4.0),
                               layout="constrained", squeeze=False)
    unit = pm.units(ds, "t_star")
    for panel, level in zip(panels[0], levels):
        t = ds.t_star.sel(level=level).transpose(*axes[::-1]) if axes else ds.t_star.sel(level=level)
        r = ds.regime.sel(level=level).transpose(*axes[::-1]) if axes else ds.regime.sel(level=level)
        x = ds[axes[0]].values.astype(float)
        if len(axes) == 2:
            y = ds[axes[1]].values.astype(float)
            shade = np.where(r.values == IMMEDIATE, 0, np.where(r.values == NEVER, 1, np.nan))
            xe, ye = edges(x, log_scaled(x)), edges(y, log_scaled(y))
            panel.pcolormesh(xe, ye, shade, cmap=ListedColormap(["#d9d9d9", "#404040"]), vmin=0, vmax=1, shading="flat")
            late = np.where(r.values == DELAYED, np.log10(np.maximum(t.values, 1e-300)), np.nan)
            mesh = panel.pcolormesh(xe, ye, late, cmap="viridis", shading="flat")
            if log_scaled(y):
                panel.set_yscale("log")
            if np.isfinite(late).any():
                fig.colorbar(mesh, ax=panel, label=f"log10 t* ({unit})")
            handles = [Patch(color="#d9d9d9", label="touches at once"), Patch(color="#404040", label="never touches")]
            band = tolerance_band(ds, level, axes[::-1])
            label = f"regime depends on\nthe tolerance ({ds.attrs.get('tolerance', '')})"
            if "regime_spread" in ds:
                band = ds.regime_spread.sel(level=level).transpose(*axes[::-1]).values != 0
                label = f"regime differs\nbetween the draws ({ds.attrs['over_seeds'].split(',')[0]})"
            if band is not None and band.any():
                rects = [Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j])
                         for j, i in zip(*np.nonzero(band))]
                panel.add_collection(PatchCollection(rects, facecolor="none", edgecolor="0.5", hatch="xx", linewidth=0))
                handles.append(Patch(facecolor="white", edgecolor="0.5", hatch="xx", linewidth=0, label=label))
            panel.legend(handles=handles, fontsize=7, loc="upper left")
            panel.set_ylabel(f"{axes[1]} ({pm.units(ds, axes[1])})")
        else:
            late = np.where(r.values == DELAYED, t.values, np.nan)
            panel.plot(x, late, marker="o", label="delayed: t*")
            for code, colour, text in ((IMMEDIATE, "#a0a0a0", "immediate"), (NEVER, "#404040", "never")):
                where = r.values == code
                if where.any():
                    panel.plot(x[where], np.full(where.sum(), np.nanmin(late) if np.isfinite(late).any() else 1.0),
                               ls="none", marker="s", color=colour, label=text)
            panel.set_yscale("log")
            panel.set_ylabel(f"t* ({unit})")
            panel.legend(fontsize=7)
        if log_scaled(x):
            panel.set_xscale("log")
        panel.set_xlabel(f"{axes[0]} ({pm.units(ds, axes[0])})" if axes else "")
        x_unit = pm.units(ds, "X_star")
        panel.set_title(f"level {level}: X* = " + ", ".join(f"{v:.3g}" for v in np.atleast_1d(ds.X_star.sel(level=level).values))
                        + (" E0*" if x_unit == "E0/(1-nu^2)" else f" {x_unit}"), fontsize=9)
    if touched:
        panel = panels[0][-1]
        at = ds.t.values[-1] if time is None else float(ds.t.sel(t=time, method="nearest"))
        share = ds.touched.sel(t=at).transpose(*axes[::-1]) if axes else ds.touched.sel(t=at)
        # A snapshot the curve cannot vouch for (below its resolution, past its top,
        # unloading) is left blank, not drawn.
        trusted = np.where(ds.valid.sel(t=at).transpose(*axes[::-1]).values == 0, share.values, np.nan)
        x = ds[axes[0]].values.astype(float)
        if len(axes) == 2:
            y = ds[axes[1]].values.astype(float)
            mesh = panel.pcolormesh(edges(x, log_scaled(x)), edges(y, log_scaled(y)), trusted, cmap="magma",
                                    vmin=0, vmax=1, shading="flat")
            fig.colorbar(mesh, ax=panel, label="share of caps in contact")
            if log_scaled(y):
                panel.set_yscale("log")
            panel.set_ylabel(f"{axes[1]} ({pm.units(ds, axes[1])})")
        else:
            panel.plot(x, trusted, marker="o")
            panel.set_ylim(-0.02, 1.02)
            panel.set_ylabel("share of caps in contact")
        if log_scaled(x):
            panel.set_xscale("log")
        panel.set_xlabel(f"{axes[0]} ({pm.units(ds, axes[0])})")
        blank = " (blank: flagged)" if np.isnan(trusted).any() else ""
        mean = "mean share of " if "over_seeds" in ds.attrs else ""
        panel.set_title(f"{mean}caps in contact at t = {at:.4g} {pm.units(ds, 't')}{blank}", fontsize=9)
    texture = json.loads(ds.attrs.get("texture", "{}"))
    words = ", ".join(f"{k} = {v}" for k, v in texture.items() if v not in ("None", ""))
    over = f"; median over {ds.attrs['over_seeds']}" if "over_seeds" in ds.attrs else ""
    fig.suptitle(f"each level's touch time: {words}" + (f"; {', '.join(said)}" if said else "") + over, fontsize=9)
    return fig


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    out = pm.check_output(args.output, inputs=[args.map])
    ds = read_map(args.map)
    ds, said = select(over_seeds(ds) if args.over_seeds else ds, args.at)
    pm.save_figure(render(ds, said, args.time), out, dpi=FIG_DPI, inputs=[args.map])
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "surface_picture.py"))
