"""Shared reading of punchsweep regime maps (the HDF5 contract in README.md).

Everything the map scripts (regime_map.py, critical_dh.py, summary.py, evolution.py --map)
have in common lives here: opening a map with xarray (h5netcdf), axis metadata (units,
long_name, log spacing), the `--at AXIS=VALUE` nearest-grid-value selection, the regime
colours, output-path checks and the one-line user-error convention (exit code 2).

It reads the file only; it never runs or parses the engine.
"""
from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

AXES = ("l", "dh", "T", "pbar", "s")
"""The five grid axes, in the order of the map's dimensions."""

SERIES = ("a1", "a2", "P1", "P2", "area_fraction")
"""The time-series variables of a `--quantities full` map."""

# Flag codes are a file format contract (README, "Validity"); never renumber them.
REGIME_NAMES = {0: "immediate", 1: "delayed", 2: "never", -1: "not_computed"}
VALID_NAMES = {0: "valid", 1: "same_level_overlap", 2: "cross_level_overlap", 3: "no_solution",
               -1: "not_computed"}
NOT_COMPUTED = -1

# Fixed categorical colours (Okabe-Ito, readable with colour-vision deficiencies).
REGIME_COLOURS = {0: "#0072B2", 1: "#E69F00", 2: "#009E73", -1: "#3A3A3A"}
INVALID_WHITE_MIX = 0.55
"""Invalid points are drawn in their regime colour mixed this much with white (and hatched)."""

# Units as they appear in the file, and how the plots typeset them.
_UNIT_TEX = {"R": "$R$", "1": "-", "E0/(1-nu^2)": "$E_0/(1-\\nu^2)$", "T_eps": "$T_\\varepsilon$",
             "R^2 E0/(1-nu^2)": "$R^2 E_0/(1-\\nu^2)$"}
_SYMBOL_TEX = {"l": "$l$", "dh": "$\\Delta h$", "T": "$T$", "pbar": "$\\bar p_0$", "s": "$s$"}


class MapError(Exception):
    """A user error: a bad file, axis name, --at value or output path. Exit code 2."""


class Parser(argparse.ArgumentParser):
    """argparse with the project's error convention: one line on stderr, exit code 2."""

    def error(self, message: str):  # noqa: D102 (argparse API)
        print(f"{self.prog}: error: {message} (see --help)", file=sys.stderr)
        sys.exit(2)


def run_cli(main, prog: str, argv: list[str] | None = None) -> int:
    """Runs main(argv); a MapError becomes one line on stderr and exit code 2."""
    try:
        return main(sys.argv[1:] if argv is None else argv)
    except MapError as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        return 2


# ---------------------------------------------------------------------------------------------
# Opening a map


def open_map(path: str | Path):
    """The map as an xarray Dataset (engine h5netcdf); MapError unless it is a regime map."""
    import xarray as xr

    path = Path(path)
    if not path.exists():
        raise MapError(f"map file '{path}' does not exist")
    if not path.is_file():
        raise MapError(f"'{path}' is not a file")
    import h5py

    if not h5py.is_hdf5(path):
        raise MapError(f"'{path}' is not an HDF5 file, so not a punchsweep regime map")
    with h5py.File(path, "r") as f:
        missing = [n for n in (*AXES, "regime", "valid") if n not in f]
        shape = f["regime"].shape if "regime" in f else None
    if missing:
        raise MapError(f"'{path}' is not a punchsweep regime map (no {', '.join(missing)}; expected "
                       f"the axes {', '.join(AXES)} and the variables regime, valid)")
    try:
        ds = xr.open_dataset(path, engine="h5netcdf")
    except Exception as e:  # h5netcdf raises several types for a file that is not netCDF-4
        why = str(e).strip().splitlines()[0] if str(e).strip() else "unreadable"
        raise MapError(f"'{path}' is not a readable punchsweep regime map "
                       f"({type(e).__name__}: {why})") from None
    if ds["regime"].dims != AXES:
        ds.close()
        raise MapError(f"'{path}' is not a punchsweep regime map (regime has dimensions "
                       f"{ds['regime'].dims} of shape {shape}; expected {AXES})")
    return ds


def has_series(ds) -> bool:
    """Whether the map holds the time series (made with --quantities full)."""
    return "time" in ds.variables and all(name in ds.variables for name in SERIES)


def is_completed(ds) -> bool:
    """The global attribute `completed` is 1 only when the map is whole."""
    return int(np.asarray(ds.attrs.get("completed", 0)).item()) == 1


# ---------------------------------------------------------------------------------------------
# Axis metadata


def units(ds, name: str) -> str:
    return str(ds[name].attrs.get("units", ""))


def is_log(ds, name: str) -> bool:
    """Log spacing as the map records it (attribute `spacing`)."""
    return str(ds[name].attrs.get("spacing", "")) == "log"


def axis_label(ds, name: str) -> str:
    """'long_name symbol [units]' for a plot axis, typeset for matplotlib."""
    long_name = str(ds[name].attrs.get("long_name", name))
    symbol = _SYMBOL_TEX.get(name)
    if name == "T" and "T_eps/T_sigma" in long_name:
        long_name, symbol = long_name.replace("T_eps/T_sigma", "$T = T_\\varepsilon/T_\\sigma$"), None
    u = units(ds, name)
    unit = _UNIT_TEX.get(u, u) if u else "-"
    return f"{long_name} {symbol} [{unit}]" if symbol else f"{long_name} [{unit}]"


def unit_tex(unit: str) -> str:
    return _UNIT_TEX.get(unit, unit)


def format_value(ds, name: str, value: float, tex: bool = False) -> str:
    """'l = 0.75 R', 'T = 2.5' (dimensionless: no unit), for titles and messages."""
    u = units(ds, name)
    number = f"{value:.6g}"
    if tex:
        sym = _SYMBOL_TEX.get(name, name)
        unit = "" if u in ("", "1") else " " + unit_tex(u)
        return f"{sym} = {number}{unit}"
    return f"{name} = {number}{unit_suffix(ds, name)}"


def unit_suffix(ds, name: str) -> str:
    """' R' for a dimensional axis, '' for a dimensionless one (units '1')."""
    u = units(ds, name)
    return "" if u in ("", "1") else f" {u}"


# ---------------------------------------------------------------------------------------------
# --at AXIS=VALUE: nearest grid values


def parse_axis(name: str, option: str, axes=AXES) -> str:
    if name not in axes:
        raise MapError(f"unknown axis '{name}' for {option}; valid axes: {', '.join(axes)}")
    return name


def parse_at(items: list[str] | None) -> dict[str, float]:
    """['l=0.75', 'T=2.5'] -> {'l': 0.75, 'T': 2.5}; MapError for bad syntax, axis or number."""
    at: dict[str, float] = {}
    for item in items or []:
        name, eq, text = item.partition("=")
        name, text = name.strip(), text.strip()
        if not eq or not name:
            raise MapError(f"--at '{item}' is not AXIS=VALUE (axes: {', '.join(AXES)})")
        parse_axis(name, "--at")
        try:
            value = float(text)
        except ValueError:
            raise MapError(f"--at {name}='{text}' is not a number") from None
        if not math.isfinite(value):
            raise MapError(f"--at {name}={text} is not a finite number")
        if name in at:
            raise MapError(f"--at gives {name} twice")
        at[name] = value
    return at


def nearest_index(ds, name: str, value: float) -> int:
    """Index of the grid value nearest to `value` (in log space for a log-spaced axis).

    A value outside the axis range by more than half the end grid step is an error. An axis
    with one value accepts only that value (to 1e-9 relative).
    """
    grid = np.asarray(ds[name].values, dtype=float)
    log = is_log(ds, name) and np.all(grid > 0)
    if log and value <= 0:
        raise MapError(f"--at {name}={value:g}: {name} is log-spaced and needs a value > 0; "
                       f"grid from {grid[0]:.6g} to {grid[-1]:.6g}")
    g, v = (np.log(grid), math.log(value)) if log else (grid, value)
    if len(g) == 1:
        if abs(value - grid[0]) > 1e-9 * max(1.0, abs(grid[0])):
            raise MapError(f"--at {name}={value:g} is not on the axis; {name} has the single "
                           f"value {grid[0]:.6g}")
        return 0
    lo, hi = g[0] - 0.5 * (g[1] - g[0]), g[-1] + 0.5 * (g[-1] - g[-2])
    if not lo <= v <= hi:
        raise MapError(f"--at {name}={value:g} is outside the axis range: {name} runs from "
                       f"{grid[0]:.6g} to {grid[-1]:.6g}{unit_suffix(ds, name)} ({len(grid)} values; "
                       f"half a grid step beyond the ends is accepted)")
    return int(np.argmin(np.abs(g - v)))


@dataclass(frozen=True)
class Fixed:
    """One fixed axis: its grid index and value, and how it was chosen."""
    index: int
    value: float
    message: str


def resolve_at(ds, at: dict[str, float], free: list[str], optional: tuple[str, ...] = (),
               reserved: dict[str, str] | None = None) -> dict[str, Fixed]:
    """Fixes every axis not in `free`: from --at (nearest value) or, with one value, the value.

    `optional` axes may be fixed by --at but stay free otherwise; `reserved` maps axis names
    to why --at may not fix them (e.g. 'the x axis'). Returns only the fixed axes.
    """
    reserved = reserved or {}
    for name in at:
        if name in reserved:
            raise MapError(f"--at {name}: {name} is {reserved[name]} and cannot be fixed")
    fixed: dict[str, Fixed] = {}
    unfixed = []
    for name in AXES:
        if name in reserved or (name in free and name not in at):
            continue
        grid = ds[name].values
        if name in at:
            i = nearest_index(ds, name, at[name])
            msg = (f"--at {name}={at[name]:g} -> nearest grid value "
                   f"{format_value(ds, name, float(grid[i]))}")
            fixed[name] = Fixed(i, float(grid[i]), msg)
        elif name in optional:
            continue
        elif len(grid) == 1:
            fixed[name] = Fixed(0, float(grid[0]), f"{name} not given -> its only grid value "
                                                   f"{format_value(ds, name, float(grid[0]))}")
        else:
            unfixed.append(name)
    if unfixed:
        choices = "; ".join(f"{n} in {grid_summary(ds, n)}" for n in unfixed)
        raise MapError(f"fix every remaining axis with --at AXIS=VALUE: still to fix "
                       f"{', '.join(unfixed)} ({choices})")
    return fixed


def grid_summary(ds, name: str, limit: int = 6) -> str:
    grid = ds[name].values
    if len(grid) <= limit:
        return "{" + ", ".join(f"{v:.6g}" for v in grid) + "}"
    return f"[{grid[0]:.6g} .. {grid[-1]:.6g}] ({len(grid)} values)"


# ---------------------------------------------------------------------------------------------
# Output files and colours


def check_output(path: str | Path, suffixes=(".png", ".pdf")) -> Path:
    """The output path, checked before any work: known suffix, existing folder."""
    path = Path(path)
    if path.suffix.lower() not in suffixes:
        raise MapError(f"output '{path}' has an unsupported suffix '{path.suffix}'; "
                       f"use {' or '.join(suffixes)}")
    if not path.parent.is_dir():
        raise MapError(f"output folder '{path.parent}' does not exist")
    if path.is_dir():
        raise MapError(f"output '{path}' is a folder")
    return path


def rgba(colour: str) -> np.ndarray:
    from matplotlib.colors import to_rgba
    return np.array(to_rgba(colour))


def invalid_colour(code: int) -> np.ndarray:
    """The paler shade an invalid point of regime `code` is drawn in."""
    c = rgba(REGIME_COLOURS[code])
    c[:3] = (1 - INVALID_WHITE_MIX) * c[:3] + INVALID_WHITE_MIX
    return c


# The drawn categories: regime code for valid points, code + 3 for invalid, 6 not computed.
CATEGORY_NOT_COMPUTED = 6


def categories(regime: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """Category per cell: 0-2 valid regimes, 3-5 the same regimes invalid, 6 not computed."""
    regime = np.asarray(regime)
    cat = np.where(np.asarray(valid) == 0, regime, regime + 3).astype(np.int16)
    cat[regime == NOT_COMPUTED] = CATEGORY_NOT_COMPUTED
    return cat


def category_colours() -> np.ndarray:
    """RGBA per category (index = category)."""
    return np.array([rgba(REGIME_COLOURS[0]), rgba(REGIME_COLOURS[1]), rgba(REGIME_COLOURS[2]),
                     invalid_colour(0), invalid_colour(1), invalid_colour(2),
                     rgba(REGIME_COLOURS[NOT_COMPUTED])])


def regime_colour_grid(regime: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """The fill colour (RGBA, shape (..., 4)) each cell is drawn with, hatching aside."""
    return category_colours()[categories(regime, valid)]


def cell_edges(values: np.ndarray, log: bool) -> np.ndarray:
    """Cell boundaries around grid values: midpoints (geometric for a log axis)."""
    v = np.asarray(values, dtype=float)
    if log:
        return np.exp(cell_edges(np.log(v), False))
    if len(v) == 1:
        half = 0.5 * abs(v[0]) if v[0] != 0 else 0.5
        return np.array([v[0] - half, v[0] + half])
    mid = 0.5 * (v[1:] + v[:-1])
    return np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])


def style_log_axis(axis) -> None:
    """Log axis ticks written as plain numbers: at 1, 2, 5 x 10^k when the (already set)
    limits span at most two decades, else at powers of ten."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    lo, hi = sorted(axis.get_view_interval())
    narrow = lo > 0 and math.log10(hi / lo) <= 2
    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0) if narrow else (1.0,)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def save_figure(fig, path: Path, dpi: int = 150) -> None:
    """Writes the figure (format from the suffix) and closes it."""
    import matplotlib.pyplot as plt

    try:
        fig.savefig(path, dpi=dpi)
    except OSError as e:
        raise MapError(f"cannot write '{path}': {e.strerror or e}") from None
    finally:
        plt.close(fig)
