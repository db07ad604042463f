"""Shared reading of punchsweep regime maps (the HDF5 contract in docs/maps.md).

Everything the map scripts (regime_map.py, critical_dh.py, summary.py, evolution.py --map,
model_error.py) have in common lives here: opening a map with xarray (h5netcdf), its axes and
their metadata (units, long_name, log spacing), the meanings of its flag codes, the
`--at AXIS=VALUE` nearest-grid-value selection, the regime colours, output-path checks and the
one-line user-error convention (exit code 2).

A map describes itself, and nothing here keeps a copy of that description:
  - its axes are the dimensions of the `regime` variable, in their order (today l, dh, T,
    pbar, s; which axes a map has depends on how it was swept);
  - an axis's units, long_name and spacing are the attributes of its coordinate variable; a
    coordinate of text values is a categorical axis, selected by label;
  - the codes of `regime`, `valid` and `bem_regime` and what they mean are those variables'
    flag_values/flag_meanings attributes (Flags).
The scripts name an axis only where they need that one (critical_dh.py: dh and --against),
and name flag meanings (immediate, delayed, never, not_computed, valid), never codes.

It reads the file only; it never runs or parses the engine.
"""
from __future__ import annotations

import argparse
import math
import re
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

SERIES = ("a1", "a2", "P1", "P2", "area_fraction")
"""The time-series variables of a `--quantities full` map."""

# Flag meanings the scripts act on (docs/maps.md, "Validity"); their codes are read from the map.
DRAWN_REGIMES = ("immediate", "delayed", "never")
"""The regimes of computed points, in the order they are drawn and tabulated."""
NOT_COMPUTED = "not_computed"
VALID = "valid"

# Fixed categorical colours per regime meaning (Okabe-Ito, readable with colour-vision
# deficiencies).
REGIME_COLOURS = {"immediate": "#0072B2", "delayed": "#E69F00", "never": "#009E73",
                  NOT_COMPUTED: "#3A3A3A"}
INVALID_WHITE_MIX = 0.55
"""Invalid points are drawn in their regime colour mixed this much with white (and hatched)."""
T_STAR_CMAP = ("YlOrRd", 0.12, 0.78)
"""Delayed points are coloured by log10 t* from this sequential colormap (name, and the part
of it used: light yellow for the shortest t*, red for the longest), warm and so apart from
the immediate blue and the never green; a delayed point without a finite t* keeps
REGIME_COLOURS["delayed"]."""

# How the plots typeset units as they appear in the file and the usual axis symbols; a unit
# or axis not listed is written as the file has it.
_UNIT_TEX = {"R": "$R$", "um": "$\\mu$m", "1": "-", "degC": "°C", "E0/(1-nu^2)": "$E_0/(1-\\nu^2)$", "T_eps": "$T_\\varepsilon$",
             "R^2 E0/(1-nu^2)": "$R^2 E_0/(1-\\nu^2)$"}
# The punch shapes f(r) = C r^s / R^(s-1) a title names (with C = 0.5, s = 2 is the paraboloid
# of a spherical cap of radius R).
SHAPE_NAMES = {1: "cones", 2: "spherical caps"}
_SYMBOL_TEX = {"l": "$l$", "dh": "$\\Delta h$", "T": "$T$", "pbar": "$\\bar p_0$", "s": "$s$"}

AT_HELP = ("Any axis of the map may be given: a bare number in the axis's scale (l and dh in "
           "R, pbar in E0/(1-nu^2), T and s dimensionless), or with a unit (dh=2um, pbar=2kPa) where "
           "the map knows the scale (model.R, a material; `summary.py MAP.h5` lists a map's axes "
           "and units); a categorical axis takes one of its labels. The nearest grid "
           "value is used (nearest in log space for a log-spaced axis) and reported; a value more "
           "than half a grid step outside the axis is an error. An axis with a single value may "
           "be left out.")
"""The part of the --at help that every map script shares (add_at_option)."""


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


def add_at_option(parser, what: str, more: str = "") -> None:
    """The --at AXIS=VALUE option (repeatable) with the shared help text; `what` says what it
    fixes in this script, `more` adds a script's own rule."""
    parser.add_argument("--at", nargs="+", action="extend", default=[], metavar="AXIS=VALUE",
                        help=f"{what}. {AT_HELP}" + (f" {more}" if more else ""))


# ---------------------------------------------------------------------------------------------
# Opening a map


def open_map(path: str | Path):
    """The map as an xarray Dataset, pressures in kPa and flags as their codes, by the
    package's one reader (src/python/punchsweep/map_attributes.py: its checks, its
    conversion); MapError (exit 2) naming what is wrong with a file that is no regime map."""
    return _MAP_ATTRIBUTES.open_map(path, "physical", "kPa", decode_flags=False, error=MapError)


# Physical units an --at value may carry, in SI (the engine's units: docs/cli.md, "Units").
_SI = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9, "Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "GPa": 1e9,
       "N": 1.0, "s": 1.0, "ms": 1e-3, "min": 60.0, "h": 3600.0}


def physical_scales(ds) -> dict[str, tuple[float, str]]:
    """What one unit of each scale the map knows is in physical units: the module's table
    (src/python/punchsweep/map_attributes.py), with pressures in kPa (what a picture shows):
    R in its unit, E0/(1-nu^2) in kPa, loads in N, the rates of t* per R's unit and per kPa."""
    return _MAP_ATTRIBUTES.physical_scales(ds.attrs, "kPa", MapError)


def _load_map_attributes():
    """src/python/punchsweep/map_attributes.py, loaded by its path (the module's package
    needs its build; this file does not)."""
    import importlib.util

    path = Path(__file__).resolve().parents[1] / "src" / "python" / "punchsweep" / "map_attributes.py"
    spec = importlib.util.spec_from_file_location("punchsweep_map_attributes", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def scale_attributes(attrs, error=MapError):
    """The map's physical scales, checked by the one rule the module's open_map uses
    (src/python/punchsweep/map_attributes.py): (E0_star_Pa, (R number, unit), R_m)."""
    return _MAP_ATTRIBUTES.scale_attributes(attrs, error)


_MAP_ATTRIBUTES = _load_map_attributes()


def has_series(ds) -> bool:
    """Whether the map holds the time series (made with --quantities full)."""
    return "time" in ds.variables and all(name in ds.variables for name in SERIES)


def is_completed(ds) -> bool:
    """The global attribute `completed` is 1 only when the map is whole. A texture's map
    (its `texture` attribute) has no such attribute: it is written under its name only once
    every geometry is in (until then it is FILE.partial), so a texture's map is whole."""
    if "texture" in ds.attrs and "completed" not in ds.attrs:
        return True
    return int(np.asarray(ds.attrs.get("completed", 0)).item()) == 1


# ---------------------------------------------------------------------------------------------
# Flag codes and their meanings


@dataclass(frozen=True)
class Flags:
    """The codes of one flag variable and what they mean (its flag_values/flag_meanings)."""
    variable: str
    codes: tuple[int, ...]
    meanings: tuple[str, ...]

    def code(self, meaning: str) -> int:
        """The code of `meaning`; MapError if the variable's flags do not list it."""
        if meaning not in self.meanings:
            raise MapError(f"the flags of '{self.variable}' have no meaning '{meaning}' "
                           f"(flag_meanings: {' '.join(self.meanings)})")
        return self.codes[self.meanings.index(meaning)]

    def meaning(self, code: int) -> str:
        """What `code` means; MapError for a code the flags do not list."""
        if int(code) not in self.codes:
            raise MapError(f"'{self.variable}' holds the code {int(code)}, which its flag_values "
                           f"({' '.join(map(str, self.codes))}) do not list")
        return self.meanings[self.codes.index(int(code))]


def flags(ds, variable: str = "regime") -> Flags:
    """The codes and meanings of a flag variable (regime, valid, bem_regime) as the map
    records them; MapError if its flag_values/flag_meanings are missing or do not pair up."""
    codes, words = _MAP_ATTRIBUTES.flag_table(ds[variable].attrs, variable, MapError)
    return Flags(variable, codes, words)


# ---------------------------------------------------------------------------------------------
# Axes and their metadata


def axes(ds) -> tuple[str, ...]:
    """The map's axes: the dimensions of `regime`, in their order."""
    return tuple(ds["regime"].dims)


def require_axes(ds, names, what: str) -> None:
    """MapError unless the map has every axis in `names` (which `what` needs)."""
    missing = [n for n in names if n not in axes(ds)]
    if missing:
        raise MapError(f"{what} needs the ax{'is' if len(missing) == 1 else 'es'} "
                       f"{', '.join(missing)}; this map has the axes {', '.join(axes(ds))}")


def parse_axis(ds, name: str, option: str) -> str:
    """`name` if it is an axis of the map, else MapError naming the map's axes."""
    if name not in axes(ds):
        raise MapError(f"unknown axis '{name}' for {option}; valid axes: {', '.join(axes(ds))} "
                       f"(the axes of this map)")
    return name


def labels(ds, name: str) -> list[str] | None:
    """The labels of a categorical axis (a coordinate of text values); None for a numeric one."""
    values = ds[name].values
    if values.dtype.kind not in "OSU":
        return None
    return [v.decode() if isinstance(v, bytes) else str(v) for v in values]


def is_categorical(ds, name: str) -> bool:
    return labels(ds, name) is not None


def require_numeric(ds, name: str, option: str) -> None:
    """MapError if `name` is a categorical axis, where `option` needs a numeric one."""
    names = labels(ds, name)
    if names is not None:
        raise MapError(f"{option} {name}: {name} is a categorical axis ({', '.join(names)}); "
                       f"{option} needs a numeric axis")


def grid_values(ds, name: str) -> list:
    """An axis's grid values: floats, or the labels of a categorical axis."""
    names = labels(ds, name)
    return names if names is not None else [float(v) for v in ds[name].values]


def value_text(value) -> str:
    """A grid value for tables and messages: 6 significant digits, or the label."""
    return value if isinstance(value, str) else f"{value:.6g}"


def units(ds, name: str) -> str:
    """The unit a variable is shown in, as open_map leaves it in `units`: physical where the
    map knows the scale (um, kPa, s, N), else the scale ("R", "E0/(1-nu^2)", "T_eps", "1")."""
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


def symbol_tex(name: str) -> str:
    """An axis's symbol typeset for matplotlib ('$\\bar p_0$' for pbar), else its name."""
    return _SYMBOL_TEX.get(name, name)


def format_value(ds, name: str, value, tex: bool = False) -> str:
    """'l = 0.75 R', 'T = 2.5' (dimensionless: no unit), for titles and messages; a categorical
    axis's value is its label."""
    u = units(ds, name)
    number = value_text(value)
    if tex:
        sym = _SYMBOL_TEX.get(name, name)
        unit = "" if u in ("", "1") else " " + unit_tex(u)
        if name == "s" and value in SHAPE_NAMES:  # for a reader who does not know f(r) = C r^s / R^(s-1)
            return f"{SHAPE_NAMES[value]} ({sym} = {number})"
        return f"{sym} = {number}{unit}"
    return f"{name} = {number}{unit_suffix(ds, name)}"


def unit_suffix(ds, name: str) -> str:
    """' R' for a dimensional axis, '' for a dimensionless one (units '1')."""
    u = units(ds, name)
    return "" if u in ("", "1") else f" {u}"


# ---------------------------------------------------------------------------------------------
# --at AXIS=VALUE: nearest grid values


def parse_at(items: list[str] | None, ds, lists: bool = False) -> dict[str, float | str | list]:
    """['l=0.75', 'T=2.5'] -> {'l': 0.75, 'T': 2.5} for the axes of the map `ds` (a categorical
    axis keeps the label: 'material=steel' -> 'steel'); MapError for bad syntax, axis or number.
    With `lists`, 'temperature=20,30,40' gives a list (the panels of a facet axis); without,
    a list is refused."""
    at: dict[str, float | str | list] = {}
    for item in items or []:
        name, eq, text = item.partition("=")
        name, text = name.strip(), text.strip()
        if not eq or not name:
            raise MapError(f"--at '{item}' is not AXIS=VALUE (axes of this map: "
                           f"{', '.join(axes(ds))})")
        parse_axis(ds, name, "--at")
        parts = [p.strip() for p in text.split(",")] if "," in text else [text]
        if len(parts) > 1 and not lists:
            raise MapError(f"--at {name}={text}: one value per axis here (a list of values picks the "
                           f"panels of a faceted axis, in regime_map.py)")
        values = [p if is_categorical(ds, name) else at_number(ds, name, p) for p in parts]
        value: float | str | list = values if len(parts) > 1 else values[0]
        if name in at:
            raise MapError(f"--at gives {name} twice")
        at[name] = value
    return at


def at_number(ds, name: str, text: str) -> float:
    """An --at value on the axis's coordinate as the map shows it. One rule, as on every
    command line: a number with a unit (2kPa, 50um, 1min) is physical and converted to the
    axis's unit; a bare number is in the axis's scale (R, E0/(1-nu^2), T_eps), converted where
    the map shows the axis in physical units."""
    match = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z]*)\s*", text)
    if match is None:
        raise MapError(f"--at {name}='{text}' is not a number, or a number and a unit")
    value, unit = float(match.group(1)), match.group(2)
    if not math.isfinite(value):
        raise MapError(f"--at {name}={text} is not a finite number")
    attrs = ds[name].attrs
    shown = str(attrs.get("units", ""))
    if not unit:
        return value * float(attrs.get("per_scaled", 1.0))
    if unit not in _SI:
        raise MapError(f"--at {name}={text}: '{unit}' is not a unit; valid: {', '.join(_SI)}")
    if shown not in _SI:
        raise MapError(f"--at {name}={text}: {name} is in {units(ds, name) or 'no unit'} on this map, "
                       f"which has no physical scale for it; give {name} in {units(ds, name) or 'numbers'}")
    if _dimension(unit) != _dimension(shown):
        raise MapError(f"--at {name}={text}: '{unit}' is a {_dimension(unit)}, {name} a {_dimension(shown)} "
                       f"(in {shown})")
    return value * _SI[unit] / _SI[shown]


def _dimension(unit: str) -> str:
    return {"m": "length", "mm": "length", "um": "length", "nm": "length", "N": "force",
            "s": "time", "ms": "time", "min": "time", "h": "time"}.get(unit, "pressure")


def _given(value) -> str:
    return value if isinstance(value, str) else f"{value:g}"


def nearest_index(ds, name: str, value) -> int:
    """Index of the grid value nearest to `value` (in log space for a log-spaced axis); on a
    categorical axis, the index of the label `value`.

    A value outside the axis range by more than half the end grid step is an error. An axis
    with one value accepts only that value (to 1e-9 relative).
    """
    names = labels(ds, name)
    if names is not None:
        if _given(value) not in names:
            raise MapError(f"--at {name}={_given(value)} is not on the axis; {name} has the "
                           f"labels {', '.join(names)}")
        return names.index(_given(value))
    if isinstance(value, str):
        raise MapError(f"--at {name}='{value}' is not a number")
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
    """One fixed axis: its grid index and value (a label on a categorical axis), and how it
    was chosen."""
    index: int
    value: float | str
    message: str


def resolve_at(ds, at: dict[str, float | str], free: list[str], optional: tuple[str, ...] = (),
               reserved: dict[str, str] | None = None) -> dict[str, Fixed]:
    """Fixes every axis of the map not in `free`: from --at (nearest value) or, with one value,
    the value.

    `optional` axes may be fixed by --at but stay free otherwise; `reserved` maps axis names
    to why --at may not fix them (e.g. 'the x axis'). `free`, `optional` and `reserved` may
    name axes the map does not have. Returns only the fixed axes, in the map's axis order.
    """
    reserved = reserved or {}
    for name in at:
        parse_axis(ds, name, "--at")
        if name in reserved:
            raise MapError(f"--at {name}: {name} is {reserved[name]} and cannot be fixed")
    fixed: dict[str, Fixed] = {}
    unfixed = []
    for name in axes(ds):
        if name in reserved or (name in free and name not in at):
            continue
        grid = grid_values(ds, name)
        if name in at:
            i = nearest_index(ds, name, at[name])
            msg = (f"--at {name}={_given(at[name])} -> nearest grid value "
                   f"{format_value(ds, name, grid[i])}")
            fixed[name] = Fixed(i, grid[i], msg)
        elif name in optional:
            continue
        elif len(grid) == 1:
            fixed[name] = Fixed(0, grid[0], f"{name} not given -> its only grid value "
                                            f"{format_value(ds, name, grid[0])}")
        else:
            unfixed.append(name)
    if unfixed:
        choices = "; ".join(f"{n} in {grid_summary(ds, n)}" for n in unfixed)
        raise MapError(f"fix every remaining axis with --at AXIS=VALUE: still to fix "
                       f"{', '.join(unfixed)} ({choices})")
    return fixed


def grid_summary(ds, name: str, limit: int = 6) -> str:
    grid = grid_values(ds, name)
    if len(grid) <= limit or is_categorical(ds, name):
        return "{" + ", ".join(value_text(v) for v in grid) + "}"
    return f"[{grid[0]:.6g} .. {grid[-1]:.6g}] ({len(grid)} values)"


# ---------------------------------------------------------------------------------------------
# Output files and colours


def material_names(ds) -> dict[str, str]:
    """The material's name (up to its first comma) by label: {'': name} for a one-material
    map (global attribute material, the file's [material] name), {label: name} for a map
    with a categorical material axis (its material attribute holds 'label: name' lines); {}
    for a map without a material."""
    text = str(ds.attrs.get("material", "")).strip()
    if not text:
        return {}
    if "material" in ds.dims:
        names = {}
        for line in text.splitlines():
            label, _, name = line.partition(":")
            names[label.strip()] = name.split(",")[0].strip() or label.strip()
        return names
    return {"": text.split(",")[0].strip()}


def map_parts(ds) -> tuple[str, str, str]:
    """(material or creep law, model, load) as map_context words them: the material's name up
    to the first comma (the labels' names joined for a map of several), else the creep law;
    the model from the attribute localization; the load ('step load', 'ramped load' with a
    ramp_time axis, 'load table' where the identity names one)."""
    attrs = ds.attrs
    material = "; ".join(material_names(ds).values())
    law = material or str(attrs.get("creep_law", "")).replace("_", " ") or "creep law not recorded"
    spelling = str(attrs.get("localization", "paper"))
    model = {"periodic": "periodic model", "paper": "the paper's model",
             "shells:200": "refined model"}.get(spelling, f"model {spelling}")
    identity = str(attrs.get("identity", ""))
    if "ramp_time" in ds.dims:
        load = "ramped load"
    elif re.search(r"^model\.load_table = \S", identity, flags=re.M):
        load = "load table"
    else:
        load = "step load"
    return law, model, load


def map_context(ds) -> str:
    """What a picture of the map must say besides its axes: the material (its name up to the
    first comma) or the creep law, the model, and the load: 'NBR rubber; the paper's model;
    step load'. Read from the map's attributes (material, creep_law, localization,
    identity) and axes (ramp_time)."""
    return "; ".join(map_parts(ds))


def parse_time(ds, text: str, option: str) -> tuple[float, str]:
    """A time given on the command line (`option`, e.g. --touch-within) in the unit of the map's
    t_star, and how to write it: '60s' or '1min' (s, min, h) where the map's times are
    physical (a material map), a bare number in the map's time unit (T_eps, or the
    material's). MapError for anything else, or for a time <= 0."""
    match = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z]*)\s*", text)
    if match is None:
        raise MapError(f"{option} '{text}' is not a time: a number, or a number and a unit (s, min, h)")
    value, unit = float(match.group(1)), match.group(2)
    shown = units(ds, "t_star")
    if not math.isfinite(value) or value <= 0:
        raise MapError(f"{option} {text}: the time must be > 0 and finite")
    if not unit:
        return value, f"{value:g} {shown}"
    if unit not in _SI or _dimension(unit) != "time":
        raise MapError(f"{option} {text}: '{unit}' is not a unit of time; valid: s, min, h")
    if shown not in _SI or _dimension(shown) != "time":
        raise MapError(f"{option} {text}: this map's times are in {shown or 'no unit'} (no material, so "
                       f"no physical time scale); give a bare number in {shown or 'its time unit'}")
    return value * _SI[unit] / _SI[shown], f"{value:g} {unit}"


def output_problem(path: str | Path, inputs=()) -> str | None:
    """The rule for every file punchsweep writes (the engine's io::output_file_problem): None
    when `path` may be written, else why not. Refused: a missing folder; a symbolic link (a
    link planted there would have the file written where it points); an existing file that
    is not a regular file (a folder, a device such as /dev/null, a pipe: a file renamed over
    it would replace it, and a pipe would block the writer); one of `inputs` (compared by
    device and inode, so another spelling or a hard link is caught)."""
    import os
    import stat

    path = Path(path)
    if not path.parent.is_dir():
        return f"'{path}': the folder '{path.parent}' does not exist"
    try:
        st = os.lstat(path)
    except FileNotFoundError:
        return None
    if stat.S_ISLNK(st.st_mode):
        return f"'{path}' is a symbolic link; punchsweep writes no file through a link: remove it or choose another name"
    if not stat.S_ISREG(st.st_mode):
        return f"'{path}' is {file_kind(st.st_mode)}, which a written file would replace; choose another name"
    for source in inputs:
        try:
            si = os.stat(source)
        except (OSError, TypeError, ValueError):
            continue
        if (si.st_dev, si.st_ino) == (st.st_dev, st.st_ino):
            return f"'{path}' is the input '{source}', which writing would destroy; choose another name"
    return None


def file_kind(mode: int) -> str:
    """What a file that is not a regular file is, by its st_mode: "a folder", "a pipe", ..."""
    import stat

    return ("a folder" if stat.S_ISDIR(mode) else "a character device" if stat.S_ISCHR(mode)
            else "a block device" if stat.S_ISBLK(mode) else "a pipe" if stat.S_ISFIFO(mode)
            else "a socket" if stat.S_ISSOCK(mode) else "not a regular file")


def read_json(path: str | Path, what: str, is_it, not_it: str) -> dict:
    """A JSON object an engine command wrote (`what`, "a fit's details"), refused with
    MapError naming the file where it cannot be read, is not a regular file (a pipe would
    block the reader until something writes to it; a device may never end) or `is_it(d)` is
    false (`not_it` says what it is not)."""
    import json
    import os
    import stat

    try:
        mode = os.stat(path).st_mode
    except OSError as e:
        raise MapError(f"{path}: cannot read {what}: {e.strerror or e}") from None
    if not stat.S_ISREG(mode):
        raise MapError(f"{path} is {file_kind(mode)}, not a file: give the file that holds {what}")
    try:
        with open(path, encoding="utf-8") as f:
            d = json.load(f)
    except (OSError, ValueError) as e:
        raise MapError(f"{path}: cannot read {what}: {e}") from None
    if not isinstance(d, dict) or not is_it(d):
        raise MapError(f"{path}: not {not_it}")
    return d


# What a design window (`punchsweep design --format json`) can be of, as the pictures name it.
DESIGN_QUANTITIES = {"dh": "height difference dh", "l": "pitch l", "pbar": "nominal pressure"}


def read_design_window(path: str | Path) -> dict:
    """A design window (`punchsweep design --format json`, or `punchsweep.design(...).to_dict()` written
    with json.dump), MapError where the file is none."""
    return read_json(path, "a design window",
                     lambda d: d.get("quantity") in DESIGN_QUANTITIES and isinstance(d.get("requirements"), list)
                     and "lower" in d and "upper" in d,
                     "the JSON of `punchsweep design --format json` (no 'quantity', 'lower', 'upper' and "
                     "'requirements')")


def design_quantity(d: dict) -> str:
    """The window's quantity as a reader says it: dh, l or pressure."""
    return "pressure" if d["quantity"] == "pbar" else d["quantity"]


def picture_args(argv: list[str], prog: str, doc: str, name: str, metavar: str, written_by: str):
    """The arguments of a script that draws one input file (a JSON an engine command wrote):
    the file as `name` and -o/--output, the picture."""
    p = Parser(prog=prog, description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument(name, metavar=metavar, help=f"written by {written_by}")
    p.add_argument("-o", "--output", required=True, help="picture to write (.png or .pdf)")
    return p.parse_args(argv)


def picture_of(source: str, output: str, read, render, dpi: int) -> None:
    """A picture of one input file: the output checked first (check_output), then
    render(read(source)) saved to it, and a line saying so."""
    out = check_output(output, inputs=[source])
    save_figure(render(read(source)), out, dpi=dpi, inputs=[source])
    print(f"wrote {output}")


def check_output(path: str | Path, suffixes=(".png", ".pdf"), inputs=()) -> Path:
    """The output path, checked before any work: a known suffix, and output_problem's rule."""
    path = Path(path)
    if suffixes and path.suffix.lower() not in suffixes:
        raise MapError(f"output '{path}' has an unsupported suffix '{path.suffix}'; "
                       f"use {' or '.join(suffixes)}")
    problem = output_problem(path, inputs)
    if problem:
        raise MapError(f"output {problem}")
    return path


def write_whole(path: str | Path, write, inputs=()) -> None:
    """Writes a file whole under output_problem's rule: `write(temporary)` fills a file
    beside `path` (created here, exclusively), which is then renamed over it; nothing is
    left on a failure."""
    import os

    path = check_output(path, suffixes=(), inputs=inputs)
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    try:
        os.close(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644))
        write(tmp)
        os.replace(tmp, path)
    except OSError as e:
        raise MapError(f"cannot write '{path}': {e.strerror or e}") from None
    finally:
        if tmp.exists():
            tmp.unlink()


def rgba(colour: str) -> np.ndarray:
    from matplotlib.colors import to_rgba
    return np.array(to_rgba(colour))


def invalid_colour(meaning: str) -> np.ndarray:
    """The paler shade an invalid point of regime `meaning` (e.g. 'delayed') is drawn in."""
    return pale(rgba(REGIME_COLOURS[meaning]))


# The drawn categories: DRAWN_REGIMES[k] is k for valid points, k + 3 for invalid ones; 6 is
# any other regime code (not computed).
CATEGORY_NOT_COMPUTED = 6


def categories(ds, regime: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """Category per cell: 0-2 valid regimes, 3-5 the same regimes invalid, 6 not computed.
    The codes are the map's (`ds`: the flags of regime and valid)."""
    regime_flags, valid_flags = flags(ds, "regime"), flags(ds, "valid")
    regime = np.asarray(regime)
    ok = np.asarray(valid) == valid_flags.code(VALID)
    cat = np.full(regime.shape, CATEGORY_NOT_COMPUTED, dtype=np.int16)
    for k, meaning in enumerate(DRAWN_REGIMES):
        this = regime == regime_flags.code(meaning)
        cat[this & ok] = k
        cat[this & ~ok] = k + len(DRAWN_REGIMES)
    return cat


def category_colours() -> np.ndarray:
    """RGBA per category (index = category)."""
    return np.array([rgba(REGIME_COLOURS[m]) for m in DRAWN_REGIMES]
                    + [invalid_colour(m) for m in DRAWN_REGIMES]
                    + [rgba(REGIME_COLOURS[NOT_COMPUTED])])


def t_star_colormap():
    """The sequential colormap of log10 t* for delayed points (T_STAR_CMAP)."""
    import matplotlib
    from matplotlib.colors import ListedColormap

    name, lo, hi = T_STAR_CMAP
    return ListedColormap(matplotlib.colormaps[name](np.linspace(lo, hi, 256)), name=f"{name}_t_star")


def t_star_norm(t_star: np.ndarray):
    """Normalize on log10 t* over whole decades around the finite positive values of
    `t_star` (one decade where they all lie within one); None if there are none."""
    from matplotlib.colors import Normalize

    t = np.asarray(t_star, dtype=float)
    t = t[np.isfinite(t) & (t > 0)]
    if t.size == 0:
        return None
    lo, hi = math.floor(math.log10(t.min())), math.ceil(math.log10(t.max()))
    return Normalize(vmin=lo, vmax=max(hi, lo + 1))


def pale(colours: np.ndarray) -> np.ndarray:
    """RGBA colours mixed with white as invalid points are drawn (INVALID_WHITE_MIX)."""
    c = np.array(colours, dtype=float)
    c[..., :3] = (1 - INVALID_WHITE_MIX) * c[..., :3] + INVALID_WHITE_MIX
    return c


def regime_colour_grid(ds, regime: np.ndarray, valid: np.ndarray, t_star: np.ndarray | None = None,
                       norm=None) -> np.ndarray:
    """The fill colour (RGBA, shape (..., 4)) each cell is drawn with, hatching aside: the
    regime's colour; with `t_star` and `norm` (t_star_norm), a delayed cell with a finite t* > 0
    takes t_star_colormap() at norm(log10 t*), paler where it is invalid."""
    cat = categories(ds, regime, valid)
    grid = category_colours()[cat]
    if t_star is None or norm is None:
        return grid
    t = np.asarray(t_star, dtype=float)
    delayed = (cat == DRAWN_REGIMES.index("delayed")) | (cat == DRAWN_REGIMES.index("delayed") + len(DRAWN_REGIMES))
    coloured = delayed & np.isfinite(t) & (t > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        shade = t_star_colormap()(np.asarray(norm(np.where(coloured, np.log10(t), np.nan)), dtype=float))
    invalid = cat >= len(DRAWN_REGIMES)
    grid[coloured & ~invalid] = shade[coloured & ~invalid]
    grid[coloured & invalid] = pale(shade[coloured & invalid])
    return grid


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


def save_figure(fig, path: Path, dpi: int = 150, inputs=()) -> None:
    """Writes the figure whole (format from the suffix; write_whole's rule) and closes it."""
    import matplotlib.pyplot as plt

    fmt = Path(path).suffix.lstrip(".").lower() or None
    try:
        write_whole(path, lambda tmp: fig.savefig(tmp, dpi=dpi, format=fmt), inputs)
    finally:
        plt.close(fig)
