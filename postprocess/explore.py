#!/usr/bin/python3
"""An interactive explorer of a punchsweep regime map: one self-contained HTML page.

  postprocess/explore.py MAP.h5 -o map.html

A map `punchsweep surface-map` wrote is drawn the same way: its axes (level a slider,
level 1 first), each level's regime and t* and X*, the caps in contact and the area
fraction per time (colour by, with the time slider; flagged snapshots blank), and a click
gives the `punchsweep surface` command of the cell.

The page works offline from file:// (no server, no network): plotly.js is embedded from
Debian's python3-plotly (/usr/share/python3-plotly/plotly.js, plotly.js 2.6.3, MIT
licence) and the map's data with it, each variable deflate-compressed and decoded in the
browser (DecompressionStream). On it:

  - a heat map over two chosen axes (default dh up, pbar across), a slider for every other
    axis (a material map's temperature, a creep law's T, s, l, ...);
  - the regime in the project's colours, delayed cells shaded by log10 t*; where the map
    has a BEM reference, its answer and the answer's source;
  - hovering a cell reads every per-point quantity with its unit (physical where the map
    has them: um, kPa, s); clicking it shows the `punchsweep point` command for that point;
  - on a full map, a colour-by choice of a1, a2, P1, P2, area_fraction with a time slider;
  - the critical height differences h_0 and h_inf over the slice, where dh is the vertical
    axis.

Size: the page holds plotly.js (8.7 MB, embedded deflate-compressed: 2.5 MB, inflated by the
browser) and the data (compressed; the area fractions computed by the page from the radii
where the map's equal pi (a1^2 + a2^2) / l^2); above --max-mb (default 40) the
script stops and says by how much, and --every AXIS=K keeps every K-th value of an axis
(repeatable) to make it fit.

Exit codes: 0 written, 2 bad input (one line on stderr), nothing written then.
"""
from __future__ import annotations

import argparse
import base64
import functools
import html
import json
import math
import re
import sys
import zlib
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

PLOTLY_JS = Path("/usr/share/python3-plotly/plotly.js")
"""plotly.js as Debian's python3-plotly ships it (cmake/install-deps.sh installs it)."""
DEFAULT_MAX_MB = 40.0


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="explore.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.h5", help="regime map written by `punchsweep sweep`")
    p.add_argument("-o", "--output", required=True, help="the page to write (.html)")
    p.add_argument("--x", default=None, metavar="AXIS", help="the axis across (default pbar)")
    p.add_argument("--y", default=None, metavar="AXIS",
                   help="the axis up (default dh; on a surface map the first geometry axis of several values)")
    p.add_argument("--every", nargs="+", action="extend", default=[], metavar="AXIS=K",
                   help="keep every K-th value of AXIS (its first and then each K-th), to fit --max-mb")
    p.add_argument("--design", metavar="WINDOW.json",
                   help="draw a design window (`punchsweep design --format json`) on the page: its edges as "
                        "lines across wherever its quantity (dh or l) is an axis of the picture")
    p.add_argument("--max-mb", type=float, default=DEFAULT_MAX_MB,
                   help=f"the largest page written, in MB (default {DEFAULT_MAX_MB:g})")
    args = p.parse_args(argv)
    args.x_given, args.y_given = args.x is not None, args.y is not None
    args.x = args.x or "pbar"
    args.y = args.y or "dh"
    return args


def packed(values: np.ndarray, dtype: str) -> str:
    """An array's little-endian bytes, deflate (zlib) compressed, base64. (Byte-shuffling,
    XOR or delta coding first made the default map's arrays 8-20% larger: their mantissas
    are noise to deflate.)"""
    raw = np.ascontiguousarray(values, dtype=dtype).tobytes()
    return base64.b64encode(zlib.compress(raw, 9)).decode("ascii")


@functools.lru_cache(maxsize=1)
def plotly_packed() -> str:
    """plotly.js as the page embeds it: deflate compressed, base64 (2.5 MB of its 8.7 MB);
    the page inflates it with the browser's DecompressionStream before its first plot."""
    return base64.b64encode(zlib.compress(PLOTLY_JS.read_bytes(), 9)).decode("ascii")


def plotly_mb() -> float:
    return len(plotly_packed()) / 1e6


def coarsening(ds, items: list[str], thinned: tuple[str, ...] | None = None) -> dict[str, int]:
    """--every's steps by axis, each axis one of `thinned` (default the map's axes; a surface
    map's level is not thinned: its levels are the answer, not a grid)."""
    thinned = tuple(pm.axes(ds)) if thinned is None else thinned
    steps = {}
    for item in items:
        name, _, k = item.partition("=")
        if name not in thinned and name in pm.axes(ds):
            raise pm.MapError(f"--every {item}: the levels are the map's answer, not a grid; thin one of "
                              f"{', '.join(thinned)}")
        if name not in thinned:
            raise pm.MapError(f"--every {item}: '{name}' is not an axis of the map (axes: {', '.join(thinned)})")
        try:
            steps[name] = int(k)
        except ValueError:
            steps[name] = 0
        if steps[name] < 1:
            raise pm.MapError(f"--every {item}: K must be a whole number >= 1")
    return steps


def point_variables(ds, over=None) -> tuple[list[str], list[str]]:
    """The map's per-point variables, as the file declares them (the engine writes one per
    map::kQuantities entry it stores, in that order): the reals and the flags (those with
    flag_meanings) over the grid's axes, or over the dimensions `over(dims)` accepts. A
    quantity the engine gains reaches the page with no change here."""
    grid = ds["regime"].dims
    chosen = [v for v in ds.data_vars if (over(ds[v].dims) if over else ds[v].dims == grid)]
    flags = [v for v in chosen if "flag_meanings" in ds[v].attrs]
    reals = [v for v in chosen if v not in flags and ds[v].dtype.kind == "f"]
    return reals, flags


# The area fractions a page computes from the radii instead of carrying (the model's
# definition, docs/model.md: pi (a1^2 + a2^2) / l^2), where the map's equal it: the default
# map's page is 4 MB smaller.
DERIVED = {"area_fraction_inf": ("a1_inf", "a2_inf"), "area_fraction": ("a1", "a2")}


def derivable(ds, name: str) -> bool:
    """Whether the map's `name` (an area fraction) is pi (a1^2 + a2^2) / l^2 of its radii to
    1e-12 (NaN where they are NaN), so the page may compute it."""
    if name not in DERIVED or name not in ds.variables or any(r not in ds.variables for r in DERIVED[name]):
        return False
    a1, a2 = (ds[r] for r in DERIVED[name])
    with np.errstate(invalid="ignore"):
        computed = (np.pi * (a1 ** 2 + a2 ** 2) / ds["l"] ** 2).transpose(*ds[name].dims).values
        stored = ds[name].values
        same = np.where(np.isnan(stored), np.isnan(computed), np.abs(computed - stored) <= 1e-12 * np.abs(stored))
    return bool(same.all())


def embedded(ds) -> list[tuple[str, str]]:
    """The map's arrays the page embeds, with their types: what payload packs (for the
    estimate, the area fractions taken as computed by the page where the map has the radii;
    payload checks each before leaving it out)."""
    reals, flags = point_variables(ds)
    computed = {v for v, radii in DERIVED.items() if all(r in ds.variables for r in radii)}
    names = [(v, "<f8") for v in reals if v not in computed] + [(v, "<i1") for v in flags]
    if pm.has_series(ds):
        names += [(v, "<f8") for v in pm.SERIES if v not in computed]
    return names


PAGE_OVERHEAD = 200_000
"""Bytes of the page besides plotly.js and the arrays: its own code and the axes' values."""


def estimate_mb(ds, steps: dict[str, int], samples: int = 8, block: int = 1 << 14) -> float:
    """The page's size in MB, estimated before it is built, from the map's metadata and a few
    blocks of each array: plotly.js, and per array its size (after `steps`) times the
    deflate ratio of `samples` blocks of `block` values spread over it, times base64's 4/3.
    Reads about samples x block values per array, whatever the map's size."""
    sel = {n: slice(None, None, k) for n, k in steps.items()}
    ds = ds.isel(sel) if sel else ds
    total = len(plotly_packed()) + PAGE_OVERHEAD
    for name, dtype in embedded(ds):
        da = ds[name]
        size = int(np.prod(da.shape))
        if size == 0:
            continue
        # Blocks of about `block` consecutive values (C order): the trailing axes whole, a run
        # of the next one, at `samples` places spread over the leading ones.
        shape, k, tail = da.shape, da.ndim, 1
        while k > 0 and tail * shape[k - 1] <= block:
            tail *= shape[k - 1]
            k -= 1
        raw = compressed = 0
        if k == 0:
            places, rows = [()], 0
        else:
            rows = max(1, block // tail)
            lead = int(np.prod(shape[:k - 1])) if k > 1 else 1
            places = [np.unravel_index(int(i), shape[:k - 1]) if k > 1 else ()
                      for i in np.unique(np.linspace(0, lead - 1, min(samples, lead)).astype(int))]
        for j, place in enumerate(places):
            index = {da.dims[d]: int(place[d]) for d in range(len(place))}
            if k > 0:
                start = (j * 7919) % max(1, shape[k - 1] - rows + 1)  # spread the runs too
                index[da.dims[k - 1]] = slice(start, start + rows)
            values = np.ascontiguousarray(da.isel(index).values, dtype=dtype)
            raw += values.nbytes
            compressed += len(zlib.compress(values.tobytes(), 9))
        total += size * np.dtype(dtype).itemsize * (compressed / raw) * 4 / 3
    return total / 1e6


def every_that_fits(ds, axis: str, max_mb: float, estimate=None) -> int:
    """The smallest K for which `--every AXIS=K` gives a page estimated within max_mb (with
    10% to spare for the estimate), 0 if none does; `estimate(ds, steps)` is the page's
    estimate (estimate_mb, or surface_estimate_mb for a surface map)."""
    estimate = estimate or estimate_mb
    plotly = plotly_mb()
    whole = estimate(ds, {})
    if whole <= 0.9 * max_mb:
        return 1
    n = ds.sizes[axis]
    k = max(2, int(np.ceil((whole - plotly) / max(0.9 * max_mb - plotly, 1e-9))))
    while k <= n:
        if estimate(ds, {axis: k}) <= 0.9 * max_mb:
            return k
        k += 1
    return 0


def refuse_if_far_too_large(ds, steps: dict[str, int], max_mb: float, thinned: tuple[str, ...],
                            estimate=None, slack: float = 1.5) -> None:
    """MapError, before the page is built, where its estimate is above slack x max_mb (a
    regime map's estimate runs up to 25% high, a surface map's up to 12%: docs/maps.md),
    naming the estimate, the limit and the --every on the longest of the `thinned` axes that
    fits (an 8e6-point map took 49 s and 1.5 GB to be refused when the page was built first)."""
    estimate = estimate or estimate_mb
    size = estimate(ds, steps)
    if size > slack * max_mb:
        biggest = max(thinned, key=lambda n: ds.sizes[n])
        k = every_that_fits(ds, biggest, max_mb, estimate)
        hint = f"--every {biggest}={k}" if k else f"--every on more than one axis (even every {biggest} alone is too much)"
        raise pm.MapError(f"the page would be about {size:.0f} MB (estimated), above --max-mb {max_mb:g} "
                          f"(plotly.js is {plotly_mb():.1f} MB of it): coarsen the map, e.g. {hint}, or raise --max-mb")


def attr_text(value) -> str:
    return value.decode() if isinstance(value, bytes) else str(value)


def design_window(path: str | None) -> dict | None:
    """A design window to draw (`punchsweep design --format json`): its quantity and its
    finite edges (in R), each named for the legend; None without one."""
    if path is None:
        return None
    try:
        d = pm.read_design_window(path)
    except pm.MapError as e:
        raise pm.MapError(f"--design {e}") from None
    physical = d.get("physical")
    if not isinstance(physical, dict):
        raise pm.MapError(f"--design {path}: physical = {json.dumps(physical)} is not an object (the window in the "
                          f"quantity's physical unit: lower, upper, unit)")
    if not isinstance(d.get("empty"), bool):
        raise pm.MapError(f"--design {path}: empty = {json.dumps(d.get('empty'))} is not true or false")
    if not isinstance(physical.get("unit"), str):
        raise pm.MapError(f"--design {path}: physical.unit = {json.dumps(physical.get('unit'))} is not a unit's name")
    q, name, unit = d["quantity"], pm.design_quantity(d), physical["unit"]

    def number(where: dict, key: str, field: str, meaning: str) -> float | None:
        value = where.get(key)
        if value is None or (isinstance(value, (int, float)) and not isinstance(value, bool)):
            return value
        raise pm.MapError(f"--design {path}: {field} = {json.dumps(value)} is not a number or null ({meaning})")

    scale = d["unit"] if isinstance(d.get("unit"), str) else "the map's scale"
    edges = []
    for side in ("lower", "upper"):
        value = number(d, side, side, f"the window's {side} edge in {scale}")
        shown = number(physical, side, f"physical.{side}", f"the window's {side} edge in {unit}")
        if value is not None and math.isfinite(value) and not d["empty"]:
            if shown is None or not math.isfinite(shown):
                raise pm.MapError(f"--design {path}: physical.{side} = {json.dumps(shown)} is not a finite number "
                                  f"(the window's {side} edge in {unit}; {side} is {value:g})")
            edges.append((f"design window: {name} {side} edge {shown:.4g} {unit}", float(value)))
    return {"quantity": q, "edges": edges, "empty": d["empty"]}


def payload(ds, x: str, y: str, steps: dict[str, int], map_path: str) -> dict:
    """What the page needs, its arrays packed: axes (values as shown, in physical units where
    known, and the file's scaled values for the point command), variables flattened in the
    map's axis order (C order), flags with their meanings, series over time."""
    names = list(pm.axes(ds))
    for name, option in ((x, "--x"), (y, "--y")):
        if name not in names:
            raise pm.MapError(f"{option} {name}: not an axis of the map (axes: {', '.join(names)})")
    if x == y:
        raise pm.MapError(f"--x and --y are both {x}; choose two axes")
    sel = {n: slice(None, None, steps[n]) for n in steps}
    ds = ds.isel(sel) if sel else ds
    axes = []
    for n in names:
        coord = ds[n]
        labels = pm.labels(ds, n)
        if labels is not None:  # a categorical axis (material): drawn at its indices, shown by its labels
            values = scaled = np.arange(len(labels), dtype=float)
        else:
            values = coord.values
            scaled = values * (1.0 / float(coord.attrs["per_scaled"])) if "per_scaled" in coord.attrs else values
        axes.append({
            "name": n, "values": [float(v) for v in values],
            "scaled": [float(v) for v in np.asarray(scaled, dtype=float)],
            "unit": pm.units(ds, n), "log": bool(pm.is_log(ds, n)),
            "label": f"{n}: {attr_text(coord.attrs.get('long_name', n))}" + (
                f" [{pm.units(ds, n)}]" if pm.units(ds, n) not in ("", "1") else ""),
            "labels": labels,
        })
    variables = {}
    reals, flag_names = point_variables(ds)
    for v in reals:
        if v in ds.variables:
            da = ds[v].transpose(*names)
            variables[v] = {"unit": pm.units(ds, v), "long_name": attr_text(ds[v].attrs.get("long_name", v))}
            if derivable(ds, v):
                variables[v]["derived"] = DERIVED[v]
            else:
                variables[v]["data"] = packed(da.values, "<f8")
    flags = {}
    for v in flag_names:
        if v in ds.variables:
            f = pm.flags(ds, v)
            values = ds[v].transpose(*names).values
            unknown = np.setdiff1d(np.unique(values), np.asarray(f.codes))
            if unknown.size:  # the page would show them as bare numbers
                raise pm.MapError(f"{v} holds the codes {[int(c) for c in unknown[:5]]}, which its flag_values "
                                  f"({', '.join(f'{c} {m}' for c, m in zip(f.codes, f.meanings))}) do not name")
            flags[v] = {"data": packed(values, "<i1"),
                        "codes": {str(c): m for c, m in zip(f.codes, f.meanings)}}
    series = {}
    if pm.has_series(ds):
        for v in pm.SERIES:
            da = ds[v].transpose(*names, "time")
            series[v] = {"unit": pm.units(ds, v), "long_name": attr_text(ds[v].attrs.get("long_name", v))}
            if derivable(ds, v):
                series[v]["derived"] = DERIVED[v]
            else:
                series[v]["data"] = packed(da.values, "<f8")
    attrs = ds.attrs
    material = "; ".join(pm.material_names(ds).values())
    # The material file as the sweep was given it (the resolved config's model.material):
    # the clicked point's command names it; several files are the material axis's labels.
    given = [line.partition("=")[2].strip() for line in attr_text(attrs.get("config", "")).splitlines()
             if line.partition("=")[0].strip() == "material" and line.partition("=")[1]]
    material_path = given[0] if given and "," not in given[0] else ""
    return {
        "source": Path(map_path).name,
        "title": pm.map_context(ds),
        "material": material, "material_path": material_path,
        "localization": attr_text(attrs.get("localization", "paper")),
        "creep_law": attr_text(attrs.get("creep_law", "")),
        "C": float(attrs.get("C", 0.5)),
        "R": attr_text(attrs.get("R", "")),
        "time_unit": attr_text(attrs.get("time_unit", "T_eps")),
        "axes": axes, "x": x, "y": y,
        "shape": [len(a["values"]) for a in axes],
        "variables": variables, "flags": flags,
        "series": series, "time": [float(t) for t in ds["time"].values] if series else [],
        "colours": pm.REGIME_COLOURS,
        "coarsened": {n: k for n, k in steps.items() if k > 1},
    }


def is_surface_map(path: str) -> bool:
    """Whether `path` is a map `punchsweep surface-map` wrote (regime over a level axis, each
    level's touchdown load; with full quantities the caps touched over time), not a regime
    map."""
    import os

    import h5py
    if not os.path.isfile(path):  # not a file (a pipe would block h5py): open_map says what it is
        return False
    try:
        with h5py.File(path, "r") as f:
            return "regime" in f and "level" in f and "X_star" in f
    except OSError:
        return False


def open_surface_map(path: str):
    """A surface map as an xarray Dataset by the one reader every map goes through (pm.open_map:
    lengths in R's unit, pressures in kPa where the map has a material and R), read lazily:
    the size of its page is estimated (surface_estimate_mb) before its arrays are read."""
    return pm.open_map(path)


def movable_axes(ds) -> tuple[str, ...]:
    """A surface map's axes but level: the geometry's and the load's (those --every thins)."""
    return tuple(n for n in ds["regime"].dims if n != "level")


def surface_axes(ds, x: str | None, y: str | None) -> tuple[str, str]:
    """The page's axes across and up: as given, else pbar across (or the first axis of several
    values) and up the first other axis of several values. A map with one axis besides level
    (a height map's texture over the pressure) has it across and level up: a heat map needs
    two axes, and each level's answer over that one is the picture."""
    names = list(ds["regime"].dims)
    movable = movable_axes(ds)
    if not movable:
        raise pm.MapError("the surface map has no axis but level: the page draws a heat map over an axis of the "
                          "geometry or the load (make the map over --pbar, say)")
    several = [n for n in movable if ds.sizes[n] > 1]
    x = x or ("pbar" if "pbar" in movable else (several or list(movable))[0])
    y = y or next((n for n in several if n != x), next((n for n in movable if n != x), "level"))
    for name, option in ((x, "--x"), (y, "--y")):
        if name not in names:
            raise pm.MapError(f"{option} {name}: not an axis of the map (axes: {', '.join(names)})")
    if x == y:
        raise pm.MapError(f"--x and --y are both {x}; choose two axes")
    return x, y


OPTION_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.-]*")
"""A texture keyword as `punchsweep surface` takes it (--lattice, --height-map, --C)."""


def surface_texture(ds) -> dict:
    """The texture's keywords (the map's `texture` attribute, JSON), each a plain option name:
    a clicked cell's command is pasted into a shell, so a key such as `lattice; touch x; #`
    (a forged attribute) is refused, not written into it."""
    text = attr_text(ds.attrs.get("texture", "{}"))
    try:
        texture = json.loads(text)
    except ValueError:
        texture = None
    if not isinstance(texture, dict):
        raise pm.MapError(f"the map's texture attribute is not a JSON object of the texture's keywords: {text[:80]!r}")
    for key in texture:
        if not OPTION_NAME.fullmatch(key):
            raise pm.MapError(f"the map's texture names the keyword {key!r}, which is no option of punchsweep "
                              f"surface (letters, digits, '-', '_' and '.')")
    scatter = attr_text(ds.attrs.get("scatter_kind", ""))
    if scatter and not OPTION_NAME.fullmatch(scatter):
        raise pm.MapError(f"the map's scatter_kind {scatter!r} is no scatter of punchsweep surface (normal, uniform)")
    return texture


def surface_arrays(ds) -> list[tuple[str, str, str]]:
    """What a surface map's page embeds, as (kind, variable, type): every per-level variable
    over (some of) the map's axes, as the file declares them: the flags (regime; with a box of
    tolerances regime_low, regime_high) and the reals (t*, X*; t_star_low, t_star_high), so
    that one the command gains reaches the page unchanged; and the series over time (the caps
    touched, the area fraction; a map of regime quantities has none)."""
    names = list(ds["regime"].dims)
    reals, flag_names = point_variables(ds, over=lambda dims: "level" in dims and set(dims) <= set(names))
    return ([("flags", v, "<i1") for v in flag_names] + [("variables", v, "<f8") for v in reals]
            + [("series", v, "<f8") for v in ("touched", "area_fraction") if v in ds])


def surface_array(ds, kind: str, name: str) -> np.ndarray:
    """One array of a surface map's page, over the map's axes in its order (C order), the
    series with time last: the reals broadcast over every axis; the series NaN where the
    snapshot is flagged (`valid` not 0: not valid is never shown as a number)."""
    names = list(ds["regime"].dims)
    if kind == "flags":
        return ds[name].transpose(*names).values
    if kind == "variables":
        return ds[name].broadcast_like(ds["regime"]).transpose(*names).values
    return ds[name].where(ds["valid"] == 0).broadcast_like(ds["regime"]).transpose(*names, "t").values


SERIES_DEFLATE = 1.25
"""A trusted snapshot's series take up to 1.25 times their bytes in the file on the page
(deflated alone; the file shuffles their bytes first): 0.91 to 1.25 measured over five maps."""


def surface_estimate_mb(ds, steps: dict[str, int]) -> float:
    """A surface map's page size in MB, estimated before any of its arrays is read: each page
    array's values counted from the axes' lengths (after `steps`), at the bytes its source
    variable takes in the file (deflated, a metadata query; the writer stores each variable as
    one compressed chunk, so reading even a block of it would inflate it whole); the series
    only where a snapshot is trusted (the int8 `valid` flags, the one array read: the page
    blanks the rest), a broadcast array at least 1/300 of its raw size (deflate codes a
    repeat in matches of at most 258 bytes), and base64's 4/3. Measured 2% to 12% above the
    page (docs/maps.md)."""
    sel = {n: slice(None, None, k) for n, k in steps.items()}
    thinned = ds.isel(sel) if sel else ds
    names = tuple(thinned["regime"].dims)
    valid = thinned["valid"].values if "valid" in thinned else np.empty(0)
    trusted = float(np.mean(valid == 0)) if valid.size else 1.0
    arrays = surface_arrays(thinned)
    stored = stored_bytes(ds, [name for _, name, _ in arrays])
    total = len(plotly_packed()) + PAGE_OVERHEAD
    for kind, name, dtype in arrays:
        kept = stored[name] * thinned[name].size / max(ds[name].size, 1)
        dims = names + (("t",) if kind == "series" else ())
        raw = np.dtype(dtype).itemsize * int(np.prod([thinned.sizes[d] for d in dims]))
        deflated = kept * (SERIES_DEFLATE * trusted if kind == "series" else 1.0)
        total += max(deflated, raw / 300) * 4 / 3
    return total / 1e6


def stored_bytes(ds, names: list[str]) -> dict[str, int]:
    """The bytes each variable takes in the map's file (compressed), from its metadata."""
    import h5py
    with h5py.File(ds.encoding["source"], "r") as f:
        return {name: int(f[name].id.get_storage_size()) for name in names}


def surface_payload(ds, x: str | None, y: str | None, map_path: str, steps: dict[str, int] | None = None) -> dict:
    """A surface map (surface-map's file) as the page reads a regime map: its axes (the
    geometry's, the load's and level: a slider, level 1 first), each level's regime and t*
    and X* per cell (and, with a box of tolerances, t* and the regimes at its ends), and the
    caps touched and the area fraction per time (NaN where the
    snapshot is flagged: not valid is never shown as a number); clicking a cell gives the
    `punchsweep surface` command of that point. `steps` keeps every K-th value of an axis
    (--every)."""
    steps = steps or {}
    x, y = surface_axes(ds, x, y)
    texture = surface_texture(ds)
    sel = {n: slice(None, None, k) for n, k in steps.items()}
    ds = (ds.isel(sel) if sel else ds).load()
    names = list(ds["regime"].dims)
    axes = []
    for n in names:
        values = np.asarray(ds[n].values, dtype=float)
        log = values.size > 2 and values.min() > 0 and values.max() / values.min() >= 10
        unit = pm.units(ds, n)
        per_scaled = float(ds[n].attrs.get("per_scaled", 1.0))
        axes.append({"name": n, "values": [float(v) for v in values], "scaled": [float(v) / per_scaled for v in values],
                     "unit": unit, "log": bool(log), "labels": None,
                     "label": f"{n}: {attr_text(ds[n].attrs.get('long_name', n))}" + (f" [{unit}]" if unit not in ("", "1") else "")})
    parts = {"flags": {}, "variables": {}, "series": {}}
    for kind, v, dtype in surface_arrays(ds):
        entry = {"data": packed(surface_array(ds, kind, v), dtype)}
        if kind == "flags":
            f = pm.flags(ds, v)
            entry["codes"] = {str(c): m for c, m in zip(f.codes, f.meanings)}
        else:
            entry = {"unit": pm.units(ds, v), "long_name": attr_text(ds[v].attrs.get("long_name", v)), **entry}
        parts[kind][v] = entry
    words = ", ".join(f"{k} = {v}" for k, v in texture.items() if k != "times")
    return {
        "source": Path(map_path).name,
        "title": f"surface map: {words}",
        "material": attr_text(ds.attrs.get("material", "")), "material_path": "",
        "localization": "", "creep_law": "", "C": 0.5, "R": "",
        "time_unit": attr_text(ds.attrs.get("time_unit", "T_eps")),
        "axes": axes, "x": x, "y": y, "shape": [len(a["values"]) for a in axes],
        "variables": parts["variables"], "flags": parts["flags"], "series": parts["series"],
        "time": [float(t) for t in ds["t"].values] if parts["series"] else [],
        "colours": pm.REGIME_COLOURS, "coarsened": {n: k for n, k in steps.items() if k > 1},
        "initial": {"level": 1 if ds.sizes["level"] > 1 else 0},
        "surface": {"texture": {k: v for k, v in texture.items() if k != "times"},
                    "scatter": attr_text(ds.attrs.get("scatter_kind", ""))},
    }


PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>__TITLE__</title>
<style>
body { font-family: sans-serif; margin: 12px; color: #222; }
#controls { display: flex; flex-wrap: wrap; gap: 10px 24px; align-items: center; margin: 6px 0; }
#controls label { font-size: 13px; }
#controls input[type=range] { width: 180px; vertical-align: middle; }
#plot { width: 980px; height: 640px; }
#readout, #command { font-family: monospace; font-size: 12px; white-space: pre-wrap; background: #f6f6f6;
  padding: 6px; margin: 4px 0; min-height: 1.2em; }
h1 { font-size: 18px; margin: 4px 0; }
.note { font-size: 12px; color: #555; }
</style>
<script id="plotly-packed" type="text/plain">__PLOTLY__</script>
</head><body>
<h1 id="title"></h1>
<div class="note" id="subtitle"></div>
<div id="controls"></div>
<div id="plot"></div>
<div class="note">Hover a cell to read it; click it for the <code>punchsweep</code> command that reproduces it.</div>
<div id="readout"></div>
<div id="command"></div>
<script id="map-data" type="application/json">__DATA__</script>
<script>
"use strict";
const MAP = JSON.parse(document.getElementById("map-data").textContent);

async function inflate(b64) {
  const bytes = Uint8Array.from(atob(b64), c => c.charCodeAt(0));
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}
async function unpack(b64, Type) { return new Type((await inflate(b64)).buffer); }
// plotly.js, embedded compressed: inflated and run before the first plot.
async function loadPlotly() {
  const code = new TextDecoder().decode(await inflate(document.getElementById("plotly-packed").textContent));
  const script = document.createElement("script");
  script.text = code;
  document.head.appendChild(script);
}

const state = { x: MAP.axes.findIndex(a => a.name === MAP.x), y: MAP.axes.findIndex(a => a.name === MAP.y),
                fixed: MAP.axes.map(a => (MAP.initial || {})[a.name] ?? 0), colour: "regime", time: 0 };
const data = { variables: {}, flags: {}, series: {} };
const strides = MAP.shape.map((_, k) => MAP.shape.slice(k + 1).reduce((a, b) => a * b, 1));

function flatIndex(index) { return index.reduce((s, v, k) => s + v * strides[k], 0); }
function fmt(v) { return v === null || Number.isNaN(v) ? "NaN" : (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0)) ? v.toExponential(4) : Number(v.toPrecision(6)).toString(); }
// A text of the map as plotly must get it: plotly reads pseudo-HTML in titles, labels and
// hover text (<a href>, <b>, <br>, entities), so &, < and > are given as entities.
function plain(text) { return String(text).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;"); }
// A word of a shell command, quoted where the shell would read it otherwise.
function shellWord(word) {
  const w = String(word);
  return /^[A-Za-z0-9_.,:=@%+\\/-]+$/.test(w) ? w : "'" + w.replace(/'/g, "'\\''") + "'";
}
// A command line from its words, each quoted for the shell: option names too (a map's
// attributes and axis names are the file's text, and a pasted command runs what they say).
function commandLine(words) { return words.map(shellWord).join(" "); }
function unitText(u) { return u && u !== "1" ? " " + u : ""; }
function axisValueText(a, i) { return a.labels ? a.labels[i] : fmt(a.values[i]) + unitText(a.unit); }

function cellIndex(ix, iy) {
  const index = state.fixed.slice();
  index[state.x] = ix; index[state.y] = iy;
  return index;
}

function flagName(name, k) {
  const f = MAP.flags[name];
  return f.codes[String(data.flags[name][k])] || String(data.flags[name][k]);
}

function valueAt(name, k) {
  if (name in data.flags) return flagName(name, k);
  if (name in data.variables) return data.variables[name][k];
  return undefined;
}

function readout(index) {
  const k = flatIndex(index);
  const lines = [];
  MAP.axes.forEach((a, j) => lines.push(`${a.name} = ${axisValueText(a, index[j])}`));
  for (const name of Object.keys(MAP.flags)) lines.push(`${name}: ${flagName(name, k)}`);
  for (const [name, v] of Object.entries(MAP.variables)) lines.push(`${name} = ${fmt(data.variables[name][k])}${unitText(v.unit)}`);
  if (MAP.time.length) {
    const nt = MAP.time.length;
    for (const [name, v] of Object.entries(MAP.series)) {
      const value = data.series[name][k * nt + state.time];
      // A surface map leaves a flagged snapshot blank (NaN): said so, not as a number.
      const said = MAP.surface && Number.isNaN(value) ? "flagged (not valid)" : `${fmt(value)}${unitText(v.unit)}`;
      lines.push(`${name}(t = ${fmt(MAP.time[state.time])}) = ${said}`);
    }
  }
  return lines;
}

// Units the command line takes as they are (a length with --R, a pressure with a material):
// the clicked point's command is written in them, as the map shows its axes.
const PHYSICAL = new Set(["m", "mm", "um", "nm", "Pa", "kPa", "MPa", "GPa"]);
// A surface map's cell: `punchsweep surface` with the map's texture keywords and the cell's
// axes (level is the answer's, not an input).
// The point commands' option for a map's axis: its name, but --pressure for a pressure in
// its unit and --ramp for ramp_time (the load's rise time; a sweep's grid.ramp_time).
const OPTION = {ramp_time: "ramp"};
const optionOf = (a, physical) => (physical && a.name === "pbar" ? "pressure" : OPTION[a.name] || a.name);

function surfaceCommand(index) {
  const words = ["punchsweep", "surface"];
  for (const [key, value] of Object.entries(MAP.surface.texture)) words.push(`--${key}`, value);
  // An axis the map shows in a physical unit (um, kPa) is written in it, as the command takes
  // it beside the texture's --R and material; the others in their scale.
  // (To 15 digits: 20 kPa over E0* and back is 20.000000000000004 kPa, and the command reads
  // 20kPa as the map read it.)
  const value = (a, j) => (PHYSICAL.has(a.unit) ? `${Number(a.values[index[j]].toPrecision(15))}${a.unit}` : a.scaled[index[j]]);
  MAP.axes.forEach((a, j) => {
    if (a.name === "level") return;
    if (a.name === "scatter_width") words.push("--scatter", `${MAP.surface.scatter}:${value(a, j)}`);
    else words.push(`--${optionOf(a, PHYSICAL.has(a.unit))}`, value(a, j));
  });
  if (MAP.time.length) words.push("--times", MAP.time.join(","));
  return commandLine(words);
}

function pointCommand(index) {
  if (MAP.surface) return surfaceCommand(index);
  const words = ["punchsweep", "point"];
  const physical = a => PHYSICAL.has(a.unit);
  MAP.axes.forEach((a, j) => {
    if (a.name === "material") words.push("--material", `${a.labels ? a.labels[index[j]] : index[j]}.ini`);
    else if (a.name === "time") return;
    else if (physical(a)) words.push(`--${optionOf(a, true)}`, `${String(a.values[index[j]])}${a.unit}`);
    else words.push(`--${optionOf(a, false)}`, a.scaled[index[j]]);
  });
  if (MAP.R && MAP.axes.some(a => physical(a) && a.name !== "pbar")) words.push("--R", MAP.R.replace(/ /g, ""));
  const unnamed = MAP.material && !MAP.material_path && !MAP.axes.some(a => a.name === "material");
  if (MAP.material_path && !MAP.axes.some(a => a.name === "material")) words.push("--material", MAP.material_path);
  if (unnamed) words.push("--material", "MATERIAL.ini");
  if (!MAP.axes.some(a => a.name === "C")) words.push("--C", MAP.C);
  words.push("--localization", MAP.localization);
  if (MAP.time.length) words.push("--times", MAP.time.join(","));
  return commandLine(words) + (unnamed ? "\\n(MATERIAL.ini: the map's material_file attribute holds its text)" :
    MAP.material_path ? "\\n(the material file as the sweep was given it, relative to where it ran)" : "");
}

function grid() {
  const ax = MAP.axes[state.x], ay = MAP.axes[state.y];
  const nx = ax.values.length, ny = ay.values.length;
  const cat = [], logt = [], text = [], series = [];
  const delayed = Object.entries(MAP.flags.regime.codes).find(([c, m]) => m === "delayed");
  const immediate = Object.entries(MAP.flags.regime.codes).find(([c, m]) => m === "immediate");
  const never = Object.entries(MAP.flags.regime.codes).find(([c, m]) => m === "never");
  const nt = MAP.time.length;
  for (let iy = 0; iy < ny; ++iy) {
    const rc = [], rl = [], rt = [], rs = [];
    for (let ix = 0; ix < nx; ++ix) {
      const k = flatIndex(cellIndex(ix, iy));
      const code = String(data.flags.regime[k]);
      const t = data.variables.t_star ? data.variables.t_star[k] : NaN;
      rc.push(code === immediate[0] ? 0 : code === never[0] ? 1 : code === delayed[0] ? null : 2);
      rl.push(code === delayed[0] && t > 0 ? Math.log10(t) : null);
      rt.push(readout(cellIndex(ix, iy)).map(plain).join("<br>"));
      if (state.colour !== "regime") rs.push(data.series[state.colour][k * nt + state.time]);
    }
    cat.push(rc); logt.push(rl); text.push(rt); series.push(rs);
  }
  return { cat, logt, text, series };
}

// A categorical axis (material) is drawn at its indices and ticked with its labels.
function categoryTicks(a) { return a.labels ? { tickvals: a.values, ticktext: a.labels.map(plain) } : {}; }

// A heat map's cell edges: midway between the values, geometrically on a log axis (plotly's
// own arithmetic midpoints put a coarse log axis's first edge below zero and drop its first
// column), the ends as far out as the first and last gaps.
function edges(a) {
  const v = a.values, n = v.length;
  if (n < 2) return v;
  const f = a.log ? Math.log : x => x, g = a.log ? Math.exp : x => x;
  const e = [f(v[0]) - (f(v[1]) - f(v[0])) / 2];
  for (let i = 1; i < n; ++i) e.push((f(v[i - 1]) + f(v[i])) / 2);
  e.push(f(v[n - 1]) + (f(v[n - 1]) - f(v[n - 2])) / 2);
  return e.map(g);
}

function draw() {
  const ax = MAP.axes[state.x], ay = MAP.axes[state.y];
  const ex = edges(ax), ey = edges(ay);
  const g = grid();
  const c = MAP.colours;
  const traces = [];
  if (state.colour === "regime") {
    traces.push({ type: "heatmap", x: ex, y: ey, z: g.cat, text: g.text, hoverinfo: "text",
      zmin: 0, zmax: 2, showscale: false, name: "regime",
      colorscale: [[0, c.immediate], [0.33, c.immediate], [0.34, c.never], [0.66, c.never], [0.67, c.not_computed], [1, c.not_computed]] });
    traces.push({ type: "heatmap", x: ex, y: ey, z: g.logt, text: g.text, hoverinfo: "text",
      colorscale: "YlOrRd", reversescale: true, name: "log10 t*", colorbar: { title: { text: plain(`log10 t* [${MAP.time_unit}]`) } } });
  } else {
    traces.push({ type: "heatmap", x: ex, y: ey, z: g.series, text: g.text, hoverinfo: "text",
      colorscale: "Viridis", colorbar: { title: { text: plain(`${state.colour}${unitText(MAP.series[state.colour].unit)}`) } } });
  }
  if (MAP.flags.answer_source) {  // cells the BEM answered: open squares
    const bem = Object.entries(MAP.flags.answer_source.codes).find(([c, m]) => m === "bem");
    const xs = [], ys = [];
    for (let iy = 0; iy < ay.values.length; ++iy) for (let ix = 0; ix < ax.values.length; ++ix) {
      if (bem && String(data.flags.answer_source[flatIndex(cellIndex(ix, iy))]) === bem[0]) { xs.push(ax.values[ix]); ys.push(ay.values[iy]); }
    }
    traces.push({ type: "scatter", mode: "markers", x: xs, y: ys, name: "answered by the BEM", hoverinfo: "skip",
                  marker: { symbol: "square-open", color: "#000", size: 7 } });
  }
  // A design window (--design): its edges across the picture where its quantity is an axis,
  // in the axis's unit (the window's edges are in R; the axis shows R times per_scaled).
  if (MAP.design) {
    const w = MAP.design;
    for (const [a, across] of [[ay, ax], [ax, ay]]) {
      if (a.name !== w.quantity || !w.edges.length) continue;
      const per = a.scaled[0] ? a.values[0] / a.scaled[0] : 1;
      w.edges.forEach(([name, value], i) => {
        const v = value * per, ends = [across.values[0], across.values[across.values.length - 1]];
        const line = { type: "scatter", mode: "lines", name: plain(name), hoverinfo: "skip",
                       line: { color: "#009e73", width: 3, dash: i ? "dot" : "solid" } };
        traces.push(a === ay ? { ...line, x: ends, y: [v, v] } : { ...line, x: [v, v], y: ends });
      });
    }
  }
  if (ay.name === "dh" && data.variables.h_0) {
    const h0 = [], hinf = [];
    for (let ix = 0; ix < ax.values.length; ++ix) {
      const k = flatIndex(cellIndex(ix, 0));
      h0.push(data.variables.h_0[k]); hinf.push(data.variables.h_inf[k]);
    }
    traces.push({ type: "scatter", mode: "lines", x: ax.values, y: h0, name: "h_0: below, immediate", line: { color: "#000", width: 2 }, hoverinfo: "skip" });
    traces.push({ type: "scatter", mode: "lines", x: ax.values, y: hinf, name: "h_inf: above, never", line: { color: "#000", width: 2, dash: "dash" }, hoverinfo: "skip" });
  }
  const fixedText = MAP.axes.map((a, j) => j === state.x || j === state.y ? null : `${a.name} = ${axisValueText(a, state.fixed[j])}`).filter(Boolean).join(", ");
  const layout = {
    title: { text: `${plain(MAP.title)}<br><sub>${plain(fixedText + (state.colour !== "regime" ? `; t = ${fmt(MAP.time[state.time])} ${MAP.time_unit}` : ""))}</sub>` },
    xaxis: Object.assign({ title: { text: plain(ax.label) }, type: ax.log ? "log" : "linear" }, categoryTicks(ax)),
    yaxis: Object.assign({ title: { text: plain(ay.label) }, type: ay.log ? "log" : "linear", range: [Math.min(...ey), Math.max(...ey)] }, categoryTicks(ay)),
    legend: { orientation: "h", y: -0.15 }, margin: { t: 80 },
  };
  if (ay.log) layout.yaxis.range = layout.yaxis.range.map(Math.log10);
  return Plotly.react("plot", traces, layout, { displaylogo: false, responsive: false });
}

function controls() {
  const box = document.getElementById("controls");
  box.innerHTML = "";
  const select = (id, label, options, value, onchange) => {
    const l = document.createElement("label");
    l.textContent = label + " ";
    const s = document.createElement("select");
    s.id = id;
    options.forEach(([v, t]) => { const o = document.createElement("option"); o.value = v; o.textContent = t; s.appendChild(o); });
    s.value = value;
    s.addEventListener("change", () => onchange(s.value));
    l.appendChild(s); box.appendChild(l);
  };
  const axesOptions = MAP.axes.map((a, j) => [String(j), a.name]);
  select("x-axis", "across", axesOptions, String(state.x), v => { if (+v !== state.y) state.x = +v; controls(); draw(); });
  select("y-axis", "up", axesOptions, String(state.y), v => { if (+v !== state.x) state.y = +v; controls(); draw(); });
  if (MAP.time.length) {
    select("colour", "colour by", [["regime", "regime and t*"], ...Object.keys(MAP.series).map(n => [n, n])], state.colour,
           v => { state.colour = v; draw(); });
  }
  MAP.axes.forEach((a, j) => {
    if (j === state.x || j === state.y) return;
    if (a.values.length === 1) {  // one value: said, not a slider
      const l = document.createElement("label");
      l.textContent = `${a.name} = ${axisValueText(a, 0)}`;
      box.appendChild(l);
      return;
    }
    const l = document.createElement("label");
    const r = document.createElement("input");
    r.type = "range"; r.min = 0; r.max = a.values.length - 1; r.step = 1; r.value = state.fixed[j]; r.id = `slider-${a.name}`;
    const span = document.createElement("span");
    span.textContent = `${a.name} = ${axisValueText(a, state.fixed[j])}`;
    r.addEventListener("input", () => { state.fixed[j] = +r.value; span.textContent = `${a.name} = ${axisValueText(a, state.fixed[j])}`; draw(); });
    l.appendChild(r); l.appendChild(span); box.appendChild(l);
  });
  if (MAP.time.length) {
    const l = document.createElement("label");
    const r = document.createElement("input");
    r.type = "range"; r.min = 0; r.max = MAP.time.length - 1; r.step = 1; r.value = state.time; r.id = "slider-time";
    const span = document.createElement("span");
    span.textContent = `t = ${fmt(MAP.time[state.time])} ${MAP.time_unit}`;
    r.addEventListener("input", () => { state.time = +r.value; span.textContent = `t = ${fmt(MAP.time[state.time])} ${MAP.time_unit}`; draw(); });
    l.appendChild(r); l.appendChild(span); box.appendChild(l);
  }
}

const ready = (async () => {
  await loadPlotly();
  for (const [name, v] of Object.entries(MAP.variables)) if (v.data) data.variables[name] = await unpack(v.data, Float64Array);
  for (const [name, v] of Object.entries(MAP.flags)) data.flags[name] = await unpack(v.data, Int8Array);
  for (const [name, v] of Object.entries(MAP.series)) if (v.data) data.series[name] = await unpack(v.data, Float64Array);
  // The area fractions the page computes: pi (a1^2 + a2^2) / l^2 (explore.py's DERIVED).
  const li = MAP.axes.findIndex(a => a.name === "l"), nl = li >= 0 ? MAP.axes[li].values.length : 1;
  const areaFraction = (a1, a2, per) => Float64Array.from(a1, (v, i) => {
    const l = MAP.axes[li].values[Math.floor(i / per) % nl];
    return Math.PI * (v * v + a2[i] * a2[i]) / (l * l);
  });
  for (const [name, v] of Object.entries(MAP.variables)) {
    if (v.derived) data.variables[name] = areaFraction(data.variables[v.derived[0]], data.variables[v.derived[1]], strides[li]);
  }
  for (const [name, v] of Object.entries(MAP.series)) {
    if (v.derived) data.series[name] = areaFraction(data.series[v.derived[0]], data.series[v.derived[1]], strides[li] * MAP.time.length);
  }
  document.getElementById("title").textContent = `${MAP.source}: ${MAP.title}`;
  document.getElementById("subtitle").textContent = `axes: ${MAP.axes.map(a => `${a.name} (${a.values.length})`).join(", ")}` +
    (Object.keys(MAP.coarsened).length ? `; coarsened: ${JSON.stringify(MAP.coarsened)}` : "");
  controls();
  await draw();
  const plot = document.getElementById("plot");
  plot.on("plotly_hover", ev => {
    const p = ev.points[0];
    document.getElementById("readout").textContent = readout(cellIndex(p.pointNumber[1], p.pointNumber[0])).join("\\n");
  });
  plot.on("plotly_click", ev => {
    const p = ev.points[0];
    document.getElementById("command").textContent = pointCommand(cellIndex(p.pointNumber[1], p.pointNumber[0]));
  });
})();

// For scripts and the browser tests: the state, the decoded data and the page's own read-outs.
window.explorer = { ready, state, data, MAP, flatIndex, cellIndex, readout, pointCommand, valueAt, draw, controls };
</script>
</body></html>
"""


def render(data: dict, plotly_js: str) -> str:
    """The page. The data go in as JSON with every <, > and & written as a \\u escape, so no
    text of the map (a material's name such as `<!--<script>`) can end or comment out the
    script element; the page's title is HTML-escaped; the page's script passes every text
    it gives plotly through plain() (plotly reads pseudo-HTML: tags, links, entities)."""
    text = (json.dumps(data, separators=(",", ":"))
            .replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026"))
    return (PAGE.replace("__PLOTLY__", plotly_js)
            .replace("__TITLE__", html.escape(f"punchsweep explorer: {data['source']}"))
            .replace("__DATA__", text))


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    if Path(args.output).suffix.lower() not in (".html", ".htm"):
        raise pm.MapError(f"-o {args.output}: the page is HTML; name it .html")
    out = pm.check_output(args.output, suffixes=(), inputs=[args.map] + ([args.design] if args.design else []))
    if not PLOTLY_JS.is_file():
        raise pm.MapError(f"{PLOTLY_JS} not found: install Debian's python3-plotly (bash cmake/install-deps.sh)")
    design = design_window(args.design)  # a window that is no window is refused before the map is read
    if is_surface_map(args.map):
        return surface_page(args, out, design)
    ds = pm.open_map(args.map)
    if not pm.is_completed(ds):
        raise pm.MapError(f"{args.map} is not completed (resume the sweep first)")
    steps = coarsening(ds, args.every)
    # The size is estimated first: a map far too large is refused without building its page.
    refuse_if_far_too_large(ds, steps, args.max_mb, pm.axes(ds))
    data = payload(ds, args.x, args.y, steps, args.map)
    data["design"] = design
    if data["design"] and data["design"]["quantity"] not in (args.x, args.y):
        print(f"explore.py: note: the design window is of {data['design']['quantity']}, which is neither --x nor "
              f"--y; it is drawn when the page's axes show it", file=sys.stderr)
    page = render(data, plotly_packed())
    size_mb = len(page.encode("utf-8")) / 1e6
    if size_mb > args.max_mb:
        biggest = max(pm.axes(ds), key=lambda n: ds.sizes[n])
        raise pm.MapError(f"the page would be {size_mb:.1f} MB, above --max-mb {args.max_mb:g} (plotly.js is "
                          f"{plotly_mb():.1f} MB of it): coarsen the map, e.g. --every {biggest}=2, or raise --max-mb")
    pm.write_whole(out, lambda tmp: Path(tmp).write_text(page, encoding="utf-8"), inputs=[args.map])
    print(f"explore.py: wrote {out} ({size_mb:.1f} MB: plotly.js {plotly_mb():.1f} MB compressed, the map "
          f"{size_mb - plotly_mb():.1f} MB)")
    return 0


def surface_page(args: argparse.Namespace, out: Path, design: dict | None) -> int:
    """The page of a surface map: its axes, texture and --every checked and its size estimated
    from the axes' lengths (and a few blocks of each array) before any array is read whole, so
    a map far above --max-mb is refused at once, naming the --every that fits."""
    ds = open_surface_map(args.map)
    x, y = surface_axes(ds, args.x if args.x_given else None, args.y if args.y_given else None)
    surface_texture(ds)
    thinned = movable_axes(ds)
    steps = coarsening(ds, args.every, thinned)
    refuse_if_far_too_large(ds, steps, args.max_mb, thinned, surface_estimate_mb, slack=1.25)
    if y == "level" and not args.y_given:
        print(f"explore.py: note: the map has one axis besides level ({x}): drawn across, the levels up",
              file=sys.stderr)
    if design:
        print("explore.py: note: a design window (the two-level square lattice's) is not drawn on a surface "
              "map's page", file=sys.stderr)
    data = surface_payload(ds, x, y, args.map, steps)
    data["design"] = None
    page = render(data, plotly_packed())
    size_mb = len(page.encode("utf-8")) / 1e6
    if size_mb > args.max_mb:
        biggest = max(thinned, key=lambda n: ds.sizes[n])
        k = max(2, every_that_fits(ds, biggest, args.max_mb, surface_estimate_mb))
        raise pm.MapError(f"the page would be {size_mb:.1f} MB, above --max-mb {args.max_mb:g} (plotly.js is "
                          f"{plotly_mb():.1f} MB of it): coarsen the map, e.g. --every {biggest}={k}, or raise --max-mb")
    pm.write_whole(out, lambda tmp: Path(tmp).write_text(page, encoding="utf-8"), inputs=[args.map])
    print(f"explore.py: wrote {out} ({size_mb:.1f} MB, a surface map)")
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "explore.py"))
