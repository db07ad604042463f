#!/usr/bin/python3
"""The job scripts' pictures of a run folder's map (a texture's map: texture.png, each
level's regime and t* by surface_picture.py, and explore.html): regime_map.png (pbar across, dh up,
a panel per s; on a material map a delay under 1 ms drawn as immediate in practice),
critical_dh.png (against pbar; on a material map with the dh that touches by 1 s, 1 min
and 1 h), for whatever axes the map has, and
explore.html, the interactive page (explore.py; coarsened on its longest axis, every K-th
value, K chosen once from the page's estimated size so that it fits explore.py's limit).

Every axis that a picture does not show is fixed at a value that fits the map: l at 0.75 R
and T at 5 where the map has them (the README's default picture), any other axis (a
material's temperature, a categorical material, a ramp time) at its middle grid value (the
first label of a categorical one), and an axis with one value at that value. What was fixed
is printed, as regime_map.py and critical_dh.py print it.

  postprocess/run_pictures.py RUN/map.h5 RUN
"""
from __future__ import annotations

import sys
from pathlib import Path

import critical_dh
import explore
import punchsweep_maps as pm
import regime_map
import surface_picture

PREFERRED = {"l": 0.75, "T": 5.0}
# The touch-by curves of a material map's design chart: the times a user thinks in.
USER_TIMES = "1s,1min,1h"


def fixed_values(ds, shown: set[str]) -> list[str]:
    """--at items for every axis of the map with several values that is not in `shown`."""
    items = []
    for name in pm.axes(ds):
        grid = pm.grid_values(ds, name)
        if name in shown or len(grid) == 1:
            continue
        if pm.is_categorical(ds, name):
            value = pm.labels(ds, name)[0]
        elif name in PREFERRED:
            value = PREFERRED[name]
        else:
            value = grid[len(grid) // 2]
        items.append(f"{name}={value}")
    return items


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        raise pm.MapError("usage: run_pictures.py MAP.h5 FOLDER")
    path, folder = argv[0], Path(argv[1])
    with pm.open_map(path) as ds:
        texture = "level" in ds["regime"].dims
    if texture:
        code = texture_picture(path, folder)
        return code if code != 0 else explore_page(path, folder)
    with pm.open_map(path) as ds:
        pm.require_axes(ds, ("pbar", "dh"), "run_pictures.py")
        s_values = len(pm.grid_values(ds, "s")) if "s" in pm.axes(ds) else 1
        facet = ["--facet", "s"] if s_values > 1 else []
        regime_at = fixed_values(ds, {"pbar", "dh", "s"} if facet else {"pbar", "dh"})
        chart_at = fixed_values(ds, {"pbar", "dh", critical_dh.CURVE_AXIS, critical_dh.PANEL_AXIS})
        # A map in physical time marks the times a user thinks in.
        physical = pm.units(ds, "t_star") in ("s", "ms", "min", "h")
        touch_by = ["--touch-by", USER_TIMES] if physical else []
    code = regime_map.main([path, "--x", "pbar", "--y", "dh", *(["--at", *regime_at] if regime_at else []), *facet,
                            "-o", str(folder / "regime_map.png")])
    if code != 0:
        return code
    code = critical_dh.main([path, "--against", "pbar", *(["--at", *chart_at] if chart_at else []), *touch_by,
                             "-o", str(folder / "critical_dh.png")])
    if code != 0:
        return code
    return explore_page(path, folder)


def texture_picture(path: str, folder: Path) -> int:
    """texture.png (surface_picture.py): each level's regime and t* over two axes, pbar
    across and dh up where the map has several of each, else its first axes of several
    values; every other axis fixed as fixed_values fixes it."""
    with pm.open_map(path) as ds:
        several = [a for a in pm.axes(ds) if a != "level" and len(pm.grid_values(ds, a)) > 1]
        shown = [a for a in ("pbar", "dh") if a in several]
        shown += [a for a in several if a not in shown][:2 - len(shown)]
        at = fixed_values(ds, set(shown) | {"level"})
    return surface_picture.main([path, *(["--at", *at] if at else []), "-o", str(folder / "texture.png")])


def explore_page(path: str, folder: Path) -> int:
    """explore.html, coarsened on the map's longest axis as far as it must be to fit."""
    # The coarsening chosen once, from the page's estimated size; built again (one step
    # coarser) only where the estimate fell short.
    with pm.open_map(path) as ds:
        longest = max(pm.axes(ds), key=lambda n: ds.sizes[n])
        every = explore.every_that_fits(ds, longest, explore.DEFAULT_MAX_MB)
        if every == 0:
            raise pm.MapError(f"explore.html would stay above {explore.DEFAULT_MAX_MB:g} MB even with every "
                              f"{ds.sizes[longest]}th {longest}; draw it with explore.py --every on several axes")
    for k in (every, every + 1):
        try:
            return explore.main([path, "-o", str(folder / "explore.html"),
                                 *(["--every", f"{longest}={k}"] if k > 1 else [])])
        except pm.MapError as e:
            if "above --max-mb" not in str(e):
                raise
    raise pm.MapError(f"explore.html stays above the size limit even with every {every + 1}th {longest}")


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "run_pictures.py"))
