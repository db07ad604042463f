#!/usr/bin/python3
"""Each level's touch time over a texture's map: the picture of `punchsweep.surface_map`.

Reads a map that punchsweep.surface_map() returned and .to_netcdf(engine="h5netcdf") wrote,
and draws, for every level below the tallest, its t* over the map's two remaining axes (the
pressure along x, log-scaled where it spans a decade), or along one axis as a line: log t*
in colour where the level touches late, grey where it touches at once (immediate), dark
where it never does. Axes beyond two are fixed by --at NAME=VALUE (the nearest value is used
and said); an axis of one value needs none.

Example:
  python3 -c 'import punchsweep; punchsweep.surface_map(lattice="hexagonal", l=1.2,
      dh=[0.04, 0.05, 0.06], dh2=0.09, s=2, pbar=[0.002, 0.005, 0.01, 0.02, 0.05],
      T=[2, 4, 8]).to_netcdf("hex.nc", engine="h5netcdf")'
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
    p.add_argument("map", metavar="MAP.nc", help="written by punchsweep.surface_map(...).to_netcdf(engine='h5netcdf')")
    p.add_argument("-o", "--output", required=True, help="picture to write (.png or .pdf)")
    p.add_argument("--at", nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                   help="fix an axis beyond the two drawn at its nearest value (said in the title)")
    return p.parse_args(argv)


def read_map(path: str):
    import xarray
    try:
        ds = xarray.open_dataset(path, engine="h5netcdf").load()
    except (OSError, ValueError) as e:
        raise pm.MapError(f"{path}: not a map surface_map wrote ({e})") from None
    for name in ("t_star", "regime"):
        if name not in ds or "level" not in ds[name].dims:
            raise pm.MapError(f"{path}: no '{name}' over a 'level' axis: not a map surface_map wrote")
    return ds


def select(ds, at: list[str]):
    """The map with every --at axis fixed at its nearest value, and the sentences saying so."""
    said = []
    for item in at:
        name, _, text = item.partition("=")
        if name not in ds.t_star.dims or name == "level":
            axes = ", ".join(d for d in ds.t_star.dims if d != "level")
            raise pm.MapError(f"--at {item}: no axis '{name}' (the map's: {axes})")
        try:
            value = float(text)
        except ValueError:
            raise pm.MapError(f"--at {item}: '{text}' is not a number") from None
        ds = ds.sel({name: value}, method="nearest")
        said.append(f"{name} = {float(ds[name]):.4g}")
    left = [d for d in ds.t_star.dims if d != "level" and ds.sizes[d] > 1]
    if len(left) > 2:
        raise pm.MapError(f"the map has {len(left)} axes of several values ({', '.join(left)}); fix all but two "
                          f"with --at NAME=VALUE")
    for d in [d for d in ds.t_star.dims if d != "level" and ds.sizes[d] == 1]:
        ds = ds.isel({d: 0})
    return ds, said


def render(ds, said: list[str]):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    axes = [d for d in ds.t_star.dims if d != "level"]
    # The pressure along x where it is one of the axes.
    axes.sort(key=lambda d: 0 if d in ("pbar", "pressure") else 1)
    levels = [int(v) for v in ds.level.values if int(v) > 0]
    fig, panels = plt.subplots(1, len(levels), figsize=(4.6 * len(levels) + 0.6, 4.0), layout="constrained",
                               squeeze=False)
    unit = ds.t_star.attrs.get("units", "")
    for panel, level in zip(panels[0], levels):
        t = ds.t_star.sel(level=level).transpose(*axes[::-1]) if axes else ds.t_star.sel(level=level)
        r = ds.regime.sel(level=level).transpose(*axes[::-1]) if axes else ds.regime.sel(level=level)
        x = ds[axes[0]].values.astype(float)
        if len(axes) == 2:
            y = ds[axes[1]].values.astype(float)
            shade = np.where(r.values == IMMEDIATE, 0, np.where(r.values == NEVER, 1, np.nan))
            panel.pcolormesh(x, y, shade, cmap=ListedColormap(["#d9d9d9", "#404040"]), vmin=0, vmax=1, shading="nearest")
            late = np.where(r.values == DELAYED, np.log10(np.maximum(t.values, 1e-300)), np.nan)
            mesh = panel.pcolormesh(x, y, late, cmap="viridis", shading="nearest")
            if np.isfinite(late).any():
                fig.colorbar(mesh, ax=panel, label=f"log10 t* ({unit})")
            panel.legend(handles=[Patch(color="#d9d9d9", label="touches at once"),
                                  Patch(color="#404040", label="never touches")], fontsize=7, loc="upper left")
            panel.set_ylabel(f"{axes[1]} ({ds[axes[1]].attrs.get('units', '')})")
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
        if x.size > 1 and x.min() > 0 and x.max() / x.min() >= 10:
            panel.set_xscale("log")
        panel.set_xlabel(f"{axes[0]} ({ds[axes[0]].attrs.get('units', '')})" if axes else "")
        panel.set_title(f"level {level}: X* = " + ", ".join(f"{v:.3g}" for v in np.atleast_1d(ds.X_star.sel(level=level).values))
                        + " E0*", fontsize=9)
    texture = json.loads(ds.attrs.get("texture", "{}"))
    words = ", ".join(f"{k} = {v}" for k, v in texture.items() if v not in ("None", ""))
    fig.suptitle(f"each level's touch time: {words}" + (f"; {', '.join(said)}" if said else ""), fontsize=9)
    return fig


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    out = pm.check_output(args.output, inputs=[args.map])
    ds, said = select(read_map(args.map), args.at)
    pm.save_figure(render(ds, said), out, dpi=FIG_DPI, inputs=[args.map])
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "surface_picture.py"))
