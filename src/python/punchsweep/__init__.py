"""punchsweep from Python: the engine in-process, for notebooks and design loops.

    >>> import punchsweep
    >>> r = punchsweep.point(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2)
    >>> r.regime, r.t_star
    ('delayed', 0.87...)
    >>> c = punchsweep.classify(0.75, [0.05, 0.075, 0.1], 2.5, 0.06, 2)
    >>> c["regime"], c["t_star"]

Units as everywhere in punchsweep: lengths in R (the punch's size), pressures in
E0* = E0/(1-nu^2), loads in R^2 E0*, time in T_eps (or a material file's time_unit).

- point(...) and reference(...) take the options of `punchsweep point` and `punchsweep
  reference` as keywords (l=, dh=, T=, pbar=, s=, C=, times=, material=, temperature=,
  pressure=, ramp=, load_table=, localization=, bem_grid=) and run the commands' own code:
  the numbers equal `--format json`'s bit for bit, and bad input raises ValueError with the
  command's message (the option, its value and its valid range).
- classify(l, dh, T, pbar, s, C=0.5) broadcasts its inputs like numpy and returns the
  regime codes, t*, h(0), h(inf), long-term radii, area fraction and validity of every point,
  without the Python interpreter lock held.
- open_map(path) opens a regime map as an xarray.Dataset with its flags decoded.
"""
from __future__ import annotations

import json
import os
import shutil
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .map_attributes import open_map as read_map
from .texture_results import (DesignRequirement, DesignResult, SurfaceLevel, SurfaceResult, TextureClassification,
                              _record, gathered_sensitivity)

try:
    from . import _core
except ImportError as error:  # the package's Python files without its compiled part
    if "_core" not in str(error):
        raise
    raise ImportError(f"punchsweep's compiled part (_core) is not built in {Path(__file__).resolve().parent}: build "
                      "it with `cmake --build build --target punchsweep_python` (bash jobs/local.sh and "
                      "bash tests/run-all.sh do)") from None

__all__ = ["point", "reference", "design", "surface", "surface_classify", "surface_map", "classify", "open_map", "fit_material", "Material", "PointResult",
           "ReferenceResult", "FitResult", "Classification", "SurfaceResult", "SurfaceLevel", "DesignResult",
           "DesignRequirement", "TextureClassification", "REGIMES"]

#: The map's regime codes (classify's `regime`, a map's `regime`) and their names.
REGIMES: dict[int, str] = {int(k): v for k, v in _core.regime_codes().items()}


def _option_text(value: Any, name: str = "an option") -> str:
    """A keyword's value as the command line reads it: floats in their shortest exact form
    (repr), sequences comma-separated, text as given. `name` (the keyword) is named where
    the value cannot be an option's: a bool (an option that is a switch takes _flag), or a
    list of lists or an array of more than one dimension (an option's list is 1-D; it was
    flattened, its shape lost)."""
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} = {value!r}: a punchsweep option takes a number or text, not a bool")
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, (complex, np.complexfloating)):
        raise ValueError(f"{name} = {value!r}: a complex number; valid: real numbers (or text with a unit)")
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return _option_text(value.item(), name)
    if isinstance(value, Iterable):
        values = list(value)
        if (isinstance(value, np.ndarray) and value.ndim > 1) or any(
                isinstance(v, Iterable) and not isinstance(v, (str, bytes)) for v in values):
            try:
                shape = f"of shape {np.shape(value)}"
            except ValueError:  # a ragged nesting
                shape = "of lists"
            raise ValueError(f"{name} = {_one_line(value)}: an array {shape}; valid: one value or a 1-D list "
                             f"of values")
        return ",".join(_option_text(v, name) for v in values)
    return str(value)


def _flag(value: Any, name: str) -> bool:
    """A switch keyword's value: True or False (numpy's bools too), else TypeError naming it
    (a string such as 'false' or 'no' is truthy, and would turn the switch on)."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise TypeError(f"{name} = {value!r}: valid: True or False (a bool)")


def _keywords(options: dict[str, Any]) -> list[tuple[str, str]]:
    """Keywords as the engine's (option name, value) pairs: underscores as dashes
    (load_table is the option load-table), values as _option_text; None is left out (the
    command's default). The engine stores each as its option, through the same declarations
    and checks as the command line; no command line is built."""
    return [(name.replace("_", "-"), _option_text(value, name)) for name, value in options.items() if value is not None]


def _result(cls, raw: dict, consumed=()):
    """A point's or reference's result dataclass from the engine's dict (_record's, the one
    builder of every result): the series as float arrays, and in `other` every key of the
    engine's that is neither a field nor `consumed` (gathered into one: sensitivity,
    t_star_range), so no output the engine gains is dropped unseen."""
    series = {k: np.asarray(v, dtype=float) for k, v in raw["series"].items()}
    return _record(cls, raw, series=series, consumed=consumed)


@dataclass(frozen=True)
class PointResult:
    """One point as `punchsweep point` evaluates it (docs/model.md).

    regime: 'immediate', 'delayed' or 'never'; t_star: the time level 2 touches (None for
    never); h_0, h_inf: the gap of the level-2 tips at t = 0 and as t -> infinity, in R;
    valid and reason: whether the localization model holds there and why not; a1_inf,
    a2_inf, area_fraction_inf: the long-term radii (R) and contact area fraction; series:
    numpy arrays t, a1, a2, P1, P2, area_fraction at the requested times (NaN where not
    computed). Numbers the engine could not compute are None, as the JSON's null.
    physical and units: where R (R="50um") or a material gives the scales, the JSON's
    "physical" fields (R, l, dh, E0_star, pressure, t_star, h_0, ..., and the series in
    physical["series"]) and each one's UDUNITS-2 unit string; empty otherwise.
    sensitivity: d t*/dx along each real-valued input as the JSON names them (dt_star_ddh,
    dt_star_dpbar, dt_star_dl, dt_star_dC, dt_star_dT or dt_star_dtemperature, in the time
    unit per the input's scale; physical[...] has them per um, Pa, K) and the elasticities
    dlog_t_star_dlog_NAME; None where t* is not delayed or not smooth there. t_star_range:
    (least, greatest) t* over point(tolerance="dh=0.05um, pressure=5%"), else None (None
    inside it: never at some corner, or, with corner_regimes["not_computed"] > 0, not
    computed); corner_regimes: how many of the box's corners are immediate, delayed,
    never and not_computed. notes: what reading the inputs changed (a tolerance box clipped
    at dh = 0), as the command prints them.
    advisories: the physical advisories raised, "beyond_paraboloid, beyond_cap,
    large_strain" or a part ("" for none; cap_radius="30um" or cap_height=... enables
    beyond_cap), advisory_reason their sentence, strain Tabor's 0.2 f'(a) at the largest
    contact radius (docs/model.md, section 16). other: any key of the command's JSON this
    class does not name (empty today; an output the engine gains lands here, not nowhere)."""
    regime: str
    t_star: float | None
    h_0: float | None
    h_inf: float | None
    valid: bool
    reason: str
    a1_inf: float | None
    a2_inf: float | None
    area_fraction_inf: float | None
    series: dict[str, np.ndarray]
    localization: str
    time_unit: str
    physical: dict = field(default_factory=dict)
    units: dict = field(default_factory=dict)
    sensitivity: dict = field(default_factory=dict)
    t_star_range: tuple | None = None
    corner_regimes: dict | None = None
    notes: tuple = ()
    advisories: str = ""
    advisory_reason: str = ""
    strain: float | None = None
    other: dict = field(default_factory=dict)


@dataclass(frozen=True)
class ReferenceResult:
    """One point as `punchsweep reference` solves it (the periodic BEM: docs/model.md,
    section 13): regime, t_star (None for never or beyond the last time) in its bracket
    [t_star_lower, t_star_upper], the solver's report (converged, cg_iterations,
    max_residual), the grid (bem_grid nodes a side, spacing in R), steps, solves, seconds,
    and the series t, a1, a2, P1, P2, area_fraction, h; other: any key of the command's
    JSON this class does not name (empty today)."""
    regime: str
    t_star: float | None
    t_star_lower: float | None
    t_star_upper: float | None
    converged: bool
    cg_iterations: int
    max_residual: float | None
    bem_grid: int
    spacing: float | None
    steps: int
    solves: int
    seconds: float
    series: dict[str, np.ndarray]
    time_unit: str
    other: dict = field(default_factory=dict)



def point(l: float | None = None, dh: float | None = None, T: float | None = None,
          pbar: float | None = None, s: int | None = None, C: float | None = None,
          times: Iterable[float] | str | None = None, *, material: str | None = None,
          temperature: float | str | None = None, pressure: str | None = None,
          ramp: float | None = None, load_table: str | None = None,
          localization: str | None = None, **options: Any) -> PointResult:
    """`punchsweep point` in-process. Keywords are its options (None: the command's default:
    C = 0.5, times 0, 0.5, 1, 2, 5, the periodic model); a material file's own
    parameters go in **options. ValueError with the command's message for bad input."""
    material = None if material is None else os.fspath(material)  # a path or a Material
    if isinstance(options.get("tolerance"), Mapping):  # {"dh": "0.05um", "pressure": "5%"}
        options["tolerance"] = ", ".join(f"{k}={_option_text(v, f'tolerance[{k!r}]')}" for k, v in options["tolerance"].items())
    keywords = _keywords(dict(l=l, dh=dh, T=T, pbar=pbar, s=s, C=C, times=times, material=material,
                              temperature=temperature, pressure=pressure, ramp=ramp,
                              load_table=load_table, localization=localization, **options))
    raw = _core.point(keywords)
    sensitivity, bounds, corners, taken = gathered_sensitivity(raw)
    return _result(PointResult, {**raw, "sensitivity": sensitivity, "t_star_range": bounds,
                                 "corner_regimes": corners}, taken)


def reference(l: float | None = None, dh: float | None = None, T: float | None = None,
              pbar: float | None = None, s: int | None = None, C: float | None = None,
              times: Iterable[float] | str | None = None, *, bem_grid: int | None = None,
              material: str | None = None, temperature: float | str | None = None,
              pressure: str | None = None, ramp: float | None = None,
              load_table: str | None = None, **options: Any) -> ReferenceResult:
    """`punchsweep reference` in-process (the periodic BEM on a bem_grid x bem_grid grid of
    the cell, default 128), without the interpreter lock held while it solves."""
    material = None if material is None else os.fspath(material)  # a path or a Material
    keywords = _keywords(dict(l=l, dh=dh, T=T, pbar=pbar, s=s, C=C, times=times, bem_grid=bem_grid,
                              material=material, temperature=temperature, pressure=pressure,
                              ramp=ramp, load_table=load_table, **options))
    return _result(ReferenceResult, _core.reference(keywords))


def design(require: str | Iterable[str], *, material: str | None = None, R: str | None = None,
           l: float | str | None = None, s: int | None = None, C: float | None = None,
           temperature: float | str | None = None, tolerance: str | Mapping | None = None,
           **options: Any) -> DesignResult:
    """`punchsweep design` in-process: the window of dh that meets every requirement
    ("touch within 1s at 30kPa", "never at 5kPa") at every temperature of `temperature`
    ("20..40C") and every corner of `tolerance` ("dh=0.5um, pressure=10%" or {"dh": "0.5um",
    "pressure": "10%"}). Or, with find="l" or find="pressure" and dh="8um", the window of the
    pitch (l="150um..400um", the range searched) or of the nominal pressure
    (pressure="1kPa..200kPa"; the requirements then name no pressure). For a texture,
    lattice="hexagonal" (or "square"), dh2="5um" (a third level; find="dh2" gives its window),
    level=2 (with find="l" or "pressure": the level the requirements are on) and grid=N or
    "auto" (the cell's nodes a pitch); the result's "texture" says which. A scattered supercell
    (supercell=3, scatter="normal:0.3um", seed=2) takes find="dh", "dh2" or "l" with requirements
    on the level's first cap, and shares of caps ("90% of level 1 within 1min") with
    find="pressure"; a cell file (cell=FILE) find="dh" (level=L) or "pressure"; a height map
    (height_map=FILE) find="pressure". Returns a DesignResult (the command's JSON, typed;
    docs/design.md): lower, upper, empty, centre, margin (in R, or E0* for the pressure),
    physical (the same in the physical unit), requirements (a DesignRequirement each, with
    its edge, binds_at and every bound), miss (where empty), texture, notes; it reads like
    the JSON's dict too (r["upper"]). ValueError with the command's message for bad input."""
    material = None if material is None else os.fspath(material)
    if isinstance(tolerance, Mapping):
        tolerance = ", ".join(f"{k}={_option_text(v, f'tolerance[{k!r}]')}" for k, v in tolerance.items())
    requirements = [require] if isinstance(require, str) else list(require)
    keywords = [("require", text) for text in requirements] + _keywords(
        dict(material=material, R=R, l=l, s=s, C=C, temperature=temperature, tolerance=tolerance, **options))
    return DesignResult.from_json(json.loads(_core.design(keywords)))


def surface(l: float | str | None = None, dh: float | str | None = None, *, lattice: str | None = None,
            dh2: float | str | None = None, T: float | None = None, pbar: float | None = None,
            s: int | None = None, C: float | None = None, times: Iterable[float] | str | None = None,
            grid: int | str | None = None, cell: str | None = None, height_map: str | None = None,
            pixel: float | str | None = None, supercell: int | None = None,
            scatter: str | None = None,
            seed: int | None = None, check: bool = False, full_curve: bool = False, material: str | None = None,
            temperature: float | str | None = None, pressure: str | None = None, ramp: float | str | None = None,
            load_table: str | None = None, **options: Any) -> SurfaceResult:
    """`punchsweep surface` in-process: a square or hexagonal lattice (lattice="hexagonal") of
    two levels, or three with dh2, or any cell (cell="FILE", docs/cli.md), or a measured
    period (height_map="FILE" of CSV, .npy or SurfaceTopography NetCDF, pixel=, height_unit=, summit_radius=,
    prominence=, level_gap=), or a supercell of a lattice or cell whose caps' heights scatter
    (supercell=8, scatter="normal:0.5um", curvature_scatter="normal:0.05", seed=1; seeds=8 for an ensemble of eight
    draws), under a material and a load, from its
    cell's elastic load curve on grid nodes per pitch (docs/model.md, section 17). Returns a
    SurfaceResult (the command's JSON, typed): levels (a SurfaceLevel each: regime, t_star,
    X_star, resolved, drop, sites, share, contact_radius, advisories), series (t, X,
    area_fraction, sites_touched, area_0 ..., load_0 ... as numpy arrays; valid and reason
    per time), physical (with R and a material: X in Pa, areas, loads in N, drops, their
    units), check (with check=True: the time stepping's levels and series on the same cell),
    curve, cell, grid, units; it reads like the JSON's dict too (r["levels"][1]["t_star"]).
    The curve stops at its first sample past X(inf), the most the load reaches (a level
    untouched by then never touches: X_star None); full_curve=True builds it to full contact.
    ValueError with the command's message for bad input."""
    material = None if material is None else os.fspath(material)
    keywords = _keywords(dict(l=l, dh=dh, lattice=lattice, dh2=dh2, T=T, pbar=pbar, s=s, C=C, times=times,
                              grid=grid, cell=None if cell is None else os.fspath(cell),
                              height_map=None if height_map is None else os.fspath(height_map), pixel=pixel,
                              supercell=supercell,
                              scatter=scatter, seed=seed, check="true" if _flag(check, "check") else None,
                              full_curve="true" if _flag(full_curve, "full_curve") else None, material=material,
                              temperature=temperature, pressure=pressure, ramp=ramp, load_table=load_table,
                              **options))
    return SurfaceResult.from_json(json.loads(_core.surface(keywords)))


# The texture's geometry that surface_classify (and classify with a texture) takes as arrays:
# each distinct combination is one load curve.
_GEOMETRY_COLUMNS = ("l", "dh", "dh2", "s")


def surface_classify(pbar=None, T=None, *, pressure=None, temperature=None, ramp_time=None,
                     material: str | None = None, R: str | None = None, **texture: Any) -> TextureClassification:
    """Each level's regime and t* of a texture (surface()'s keywords: lattice=, l=, dh=,
    dh2=, s=, C=, cell=, height_map=, supercell=, scatter=, grid=, ...) at many loads,
    broadcasting pbar (or pressure= with a material), the law's parameter (T, or temperature=
    with a material file) and ramp_time like numpy, and the geometry's l, dh, dh2 and s where
    given as arrays (or lists): each distinct geometry is one load curve. Each curve is built
    once (as far as the largest X(inf) of its points, or to full contact for none, on the grid
    its least pressure asks under grid="auto", and kept in the table cache); every point is
    then read off it (about 1e7 points a second): a material x temperature x pressure sweep at
    the cost of one curve a geometry. Returns a TextureClassification (it reads like a dict):
    t_star and regime (the map's codes, REGIMES; regime_names() as text) shaped as the
    broadcast inputs plus a last axis of levels; X_star (+inf for a level no point reaches)
    and resolved per level, and grid (nodes x, y), for one geometry, or each with the
    broadcast shape first (grid: a last axis of 2) where the geometry is given as arrays;
    time_unit and caps. Empty inputs give empty arrays of their shape (the curve is read all
    the same, for the levels, at a nominal load; not where the geometry is arrays: then
    there is no texture to read). ValueError with the command line's message for bad input,
    and naming the argument for a complex number, a bool or a list that mixes values with and
    without a unit. classify() with a texture keyword (lattice=, cell=, ...) is this call."""
    if pressure is not None:
        if pbar is not None:
            raise ValueError("surface_classify: pbar and pressure both given; valid: one of them")
        pbar = pressure
    if pbar is None:
        raise ValueError("surface_classify: pbar (or pressure) is required")
    # As classify's: every array checked (a complex one lost its imaginary part to a numpy
    # warning, a bool was taken as 1), a list that mixes values with and without a unit refused.
    load = "pressure" if pressure is not None else "pbar"
    for value, name in ((pbar, load), (T, "T"), (temperature, "temperature"), (ramp_time, "ramp_time")):
        if value is not None:
            _real(value, f"surface_classify: {name}")
    pbar = _in_scale(pbar, "pbar", material, R, f"surface_classify: {load}")
    if ramp_time is not None:
        ramp_time = _in_scale(ramp_time, "ramp_time", material, R, "surface_classify: ramp_time")
    law = _law_arrays("surface_classify", T, temperature, material)
    # The geometry given as arrays: columns of points, in the scales (lengths in R, as the
    # engine reads a bare number beside R=).
    geometry = {}
    for name in _GEOMETRY_COLUMNS:
        value = texture.get(name)
        if value is not None and np.ndim(np.asarray(value, dtype=object)) > 0:
            _real(value, f"surface_classify: {name}")
            geometry[name] = value if name == "s" else _in_scale(value, "dh" if name == "dh2" else name, material, R,
                                                                 f"surface_classify: {name}")
            del texture[name]
    shape, columns = _point_columns(dict(pbar=pbar, **law, ramp_time=ramp_time, **geometry))
    keywords = _keywords(dict(material=None if material is None else os.fspath(material), R=R, **{
        k: (os.fspath(v) if k in ("cell", "height_map") and v is not None else v) for k, v in texture.items()}))
    raw = _core.surface_classify(keywords, columns)
    levels = np.asarray(raw["t_star"]).shape[-1]
    per_point = bool(geometry)
    return TextureClassification(
        t_star=np.asarray(raw["t_star"]).reshape(*shape, levels),
        regime=np.asarray(raw["regime"]).reshape(*shape, levels),
        X_star=np.asarray(raw["X_star"]).reshape(*shape, levels) if per_point else np.asarray(raw["X_star"]),
        resolved=(np.asarray(raw["resolved"], dtype=bool).reshape(*shape, levels) if per_point
                  else np.asarray(raw["resolved"], dtype=bool)),
        time_unit=raw["time_unit"],
        grid=np.asarray(raw["grid"]).reshape(*shape, 2) if per_point else tuple(raw["grid"]), caps=raw["caps"])



def surface_map(*, pbar=None, pressure=None, T=None, temperature=None, material: str | None = None,
                R: str | None = None, output: str | os.PathLike | None = None, overwrite: bool = False,
                **texture: Any) -> "xarray.Dataset":  # noqa: F821
    """`punchsweep surface-map` in this process: each level's regime and t* of a texture over
    a grid, and at each time the share of caps in contact and the area fraction, as an
    xarray.Dataset. The geometry's l, dh and dh2 (and scatter="normal:..." widths) may be
    lists: each value is one load curve (cached); the load's pbar (or pressure= with a
    material) the law's parameters (T, or temperature=) and ramp (ramp times, '30s' with a
    material) may be lists: they are read off each curve. The Dataset's dimensions are the
    geometry keywords given as lists, then pbar, the law's and ramp_time given as lists, then
    level (t_star, regime) or t (touched, area_fraction, valid); a keyword given as one value
    is no dimension. tolerance="pressure=10%, T=0.2" adds t_star_low, t_star_high,
    regime_low and regime_high: each level's t* and regimes at the ends of that box about
    every point. quantities="regime" stores each level's touch and advisories alone (no caps, areas or
    loads over time: read in a fraction of the time); chunk=N sets the tiles (load points x
    times). The file (netCDF-4, the command's)
    is written to `output` where given (overwrite=True replaces one), else to a temporary
    file read back. Units on every variable (units, scaled_by)."""
    import tempfile
    import xarray
    given = dict(texture, pbar=pbar, pressure=pressure, T=T, temperature=temperature)
    axes = [k for k, v in given.items() if v is not None and not isinstance(v, str) and np.ndim(v) == 1]
    if isinstance(texture.get("scatter"), str) and "," in texture["scatter"]:
        axes.append("scatter_width")
    axes = [{"pressure": "pbar", "ramp": "ramp_time"}.get(k, k) for k in axes]
    keywords = _keywords(dict(texture, pbar=pbar, pressure=pressure, T=T, temperature=temperature,
                              material=None if material is None else os.fspath(material), R=R,
                              overwrite="true" if _flag(overwrite, "overwrite") else None))
    with tempfile.TemporaryDirectory() as folder:
        path = os.fspath(output) if output is not None else os.path.join(folder, "surface_map.nc")
        _core.surface_map(keywords + [("output", path)])
        with xarray.open_dataset(path, engine="h5netcdf") as ds:
            ds = ds.load()
    single = [d for d in ds.dims if d not in axes and d not in ("level", "t") and ds.sizes[d] == 1]
    return ds.squeeze(dim=single) if single else ds


@dataclass(frozen=True)
class FitResult:
    """What `fit_material` fitted (docs/fitting.md), in SI: moduli in Pa, times in s,
    temperatures in degC, angular frequencies in rad/s.

    material: the Material written (None without `output`); material_text: its text;
    report: what `punchsweep fit` prints; kind: "dma" or "relaxation"; readings: arrays per
    reading (temperature (its isotherm's), x (rad/s or s, as measured), x_reduced (omega a_T
    or t / a_T), storage/loss or modulus, their *_fit, used (within the time window));
    shift: temperatures, measured_log10_aT (on the law's zero), law_log10_aT, and the law
    (law, T_ref, C1, C2, E_a, rms_log10); prony: E_inf, E_i, tau_i, rms_relative, bic,
    candidates, chosen, fitted (the readings the series was fitted to: every one, or over 300
    the bins of them);
    problems: the fit's verdict, each check it fails with its numbers (empty for a good fit;
    a poor fit is returned only with accept_poor_fit=True, else ValueError names them)."""
    material: "Material | None"
    material_text: str
    report: str
    kind: str
    readings: dict
    shift: dict
    prony: dict
    problems: tuple = ()


def fit_material(dma=None, *, relaxation=None, reference_temperature=None, poisson=None,
                 output=None, **options: Any) -> FitResult:
    """`punchsweep fit` in-process: a material from DMA isotherms (`dma`: a CSV path, or a
    list of them, each "FILE" or "FILE@40C") or a relaxation test (`relaxation`). Other
    keywords are the command's options (shift="arrhenius", C1=..., C2=...,
    terms_per_decade=[1, 2], smoothing=0.01, time_window="1e-9s,1e9s", name=...,
    refine=False, accept_poor_fit=True). With `output` the material file and its .fit.json are written, as
    the command does. ValueError with the command's message for bad input."""
    def files(v):
        return [] if v is None else [os.fspath(v)] if isinstance(v, (str, os.PathLike)) else [os.fspath(p) for p in v]
    keywords = [("dma", f) for f in files(dma)] + [("relaxation", f) for f in files(relaxation)]
    if _flag(options.pop("accept_poor_fit", False), "accept_poor_fit"):
        keywords.append(("accept-poor-fit", "true"))
    keywords += [("refine", "yes" if _flag(options.pop("refine", True), "refine") else "no")] + _keywords(dict(reference_temperature=reference_temperature, poisson=poisson,
                                       output=None if output is None else os.fspath(output), **options))
    raw = _core.fit(keywords)
    details = json.loads(raw["details"])
    readings = {k: np.asarray(v, dtype=float) for k, v in details["readings"].items()}
    return FitResult(material=Material(raw["output"]) if raw["output"] else None,
                     material_text=raw["material_text"], report=raw["report"], kind=details["kind"],
                     readings=readings, shift=details["shift"], prony=details["prony"],
                     problems=tuple(details["verdict"]["problems"]))


@dataclass(frozen=True)
class Classification(Mapping):
    """classify's arrays, all of the broadcast shape: every per-point quantity a regime map
    stores, by its name: regime (int8, the map's codes: see REGIMES), t_star (float64 in
    time_unit, NaN for never), h_0, h_inf, a1_inf, a2_inf (float64, in R),
    area_fraction_inf, valid (bool) and valid_code (the map's validity codes). Reads like a
    dict; regime_names() gives the regimes as text."""
    arrays: dict[str, np.ndarray] = field(repr=False)
    time_unit: str = "T_eps"  #: the unit of t_star: T_eps, or the material file's

    def __getitem__(self, key: str) -> np.ndarray:
        return self.arrays[key]

    def __iter__(self):
        return iter(self.arrays)

    def __len__(self) -> int:
        return len(self.arrays)

    def regime_names(self) -> np.ndarray:
        """The regimes as text ('immediate', 'delayed', 'never'), of the same shape."""
        names = np.array([REGIMES[k] for k in sorted(REGIMES)])
        return names[self.arrays["regime"]]


class Material:
    """A material file (materials/*.ini; docs/materials) as the engine reads it, with its
    creep compliance, relaxation modulus and temperature shift. Pass it wherever a material
    file goes (`point(material=...)`, `classify(material=...)`; it is os.PathLike).

    Attributes: path, name, law ("prony", "kelvin", "power_law"), time_unit (of every t),
    E0_Pa (the instantaneous modulus E_0), poisson (nu), plane_strain_modulus_Pa
    (E0* = E_0/(1 - nu^2), the unit of the engine's pressures), description, shift (its
    description, or None), reference_temperature (degC, or None without a shift).
    ValueError with the engine's message for a file it refuses."""

    def __init__(self, path):
        self.path = os.fspath(path)
        self._file = _core.material(self.path)
        for key, value in self._file.info().items():
            setattr(self, key, value)

    def __fspath__(self) -> str:
        return self.path

    @classmethod
    def prony(cls, E_inf: float, E_i, tau_i, poisson: float, *, time_unit: str = "s", modulus_unit: str = "Pa",
              name: str = "a Prony series given in Python", shift: Mapping[str, Any] | None = None,
              path=None) -> "Material":
        """A material from arrays: E(t) = E_inf + sum_i E_i exp(-t / tau_i) (moduli in
        modulus_unit: Pa, kPa, MPa or GPa; times in time_unit: s, ms, min or h), Poisson's ratio,
        and optionally a temperature shift as the file's [shift] keys (e.g. dict(kind="wlf",
        C1=17.4, C2=51.6, T_ref=65)). It is written as a material file, to `path` when given
        (to keep or share it), else to a private temporary file removed with the object, and
        read back by the engine, whose checks and messages apply (ValueError)."""
        numbers = lambda values: ", ".join(repr(float(v)) for v in np.atleast_1d(values))  # noqa: E731
        lines = ["[material]", f"name = {name}", "law = prony", f"modulus_unit = {modulus_unit}",
                 f"time_unit = {time_unit}", f"poisson = {float(poisson)!r}", f"E_inf = {float(E_inf)!r}",
                 f"E_i = {numbers(E_i)}", f"tau_i = {numbers(tau_i)}"]
        if shift:
            lines.append("[shift]")
            lines += [f"{key} = {value if isinstance(value, str) else repr(float(value))}" for key, value in shift.items()]
        text = "\n".join(lines) + "\n"
        if "\n" in name or "\x00" in text:
            raise ValueError("Material.prony: the name must be one line")
        if path is not None:
            Path(path).write_text(text)
            return cls(path)
        import tempfile
        import weakref
        folder = tempfile.mkdtemp(prefix="punchsweep-material-")  # 0700, this user's
        file = os.path.join(folder, "material.ini")
        Path(file).write_text(text)
        try:
            made = cls(file)
        except BaseException:
            shutil.rmtree(folder, ignore_errors=True)
            raise
        weakref.finalize(made, shutil.rmtree, folder, True)
        return made

    def __repr__(self) -> str:
        return f"Material({self.path!r}: {self.description})"

    def _at(self, t, temperature, relaxation: bool) -> np.ndarray:
        # Times with a unit ('1s', '2min') in the file's time unit, as the command line reads them.
        try:
            times = np.asarray(_in_scale(_real(t, "t"), "ramp_time", self.path, None), dtype=float)
        except ValueError:  # (the engine reads the times as it reads a ramp's, and names that)
            raise ValueError(f"t = {t!r} is not a time; valid: numbers >= 0 in {self.time_unit}, or text with a "
                             f"time unit ('1s', '2min', '1h')") from None
        flat = np.ascontiguousarray(times).reshape(-1)
        T = float("nan") if temperature is None else float(_real(temperature, "temperature"))
        return self._file.evaluate(flat, T, relaxation).reshape(times.shape)

    def J(self, t, temperature=None) -> np.ndarray:
        """The uniaxial creep compliance J(t) in 1/Pa at times t (in time_unit, >= 0) and the
        temperature in degC (the reference temperature when left out; only a file with a
        shift takes one): J(t/a_T) of the file's law, J(0) = 1/E0_Pa."""
        return self._at(t, temperature, False) / self.E0_Pa

    def E(self, t, temperature=None) -> np.ndarray:
        """The uniaxial relaxation modulus E(t) in Pa, as J (the engine's interconversion:
        int_0^t E(t - s) dJ(s) = 1); E(0) = E0_Pa."""
        return self._at(t, temperature, True) * self.E0_Pa

    def a_T(self, temperature):
        """The shift factor a_T at `temperature` (degC; numbers or an array): times at the
        temperature are times at the reference one times a_T. ValueError outside the
        shift's range, or for a file without a shift."""
        T = np.asarray(_real(temperature, "temperature"), dtype=float)
        values = np.array([10.0 ** self._file.log10_shift(float(x)) for x in T.reshape(-1)]).reshape(T.shape)
        return float(values) if values.shape == () else values


def _real(values, name: str):
    """values as classify and point take them, or ValueError naming `name`: not None, not a
    bool (True would be taken as 1), not complex. Text (a value with its unit) passes."""
    if values is None:
        raise ValueError(f"{name} is required (None given)")
    if isinstance(values, np.ndarray) and values.dtype.kind in "fiu":
        return values  # numbers already: nothing to look at element by element
    array = np.asarray(values, dtype=object) if not isinstance(values, np.ndarray) else values
    kind = array.dtype.kind
    flat = array.reshape(-1) if kind == "O" else ()
    if kind == "b" or any(isinstance(v, (bool, np.bool_)) for v in flat):
        raise ValueError(f"{name} = {values!r}: a bool is not a number; valid: numbers (or text with a unit)")
    if kind == "c" or any(isinstance(v, (complex, np.complexfloating)) for v in flat):
        raise ValueError(f"{name} = {values!r}: a complex number; valid: real numbers (or text with a unit)")
    return values


def _one_line(value) -> str:
    """A value as a message shows it: its repr on one line (an array's rows joined)."""
    return " ".join(repr(value).split())


def _refuse_mixed_units(flat, values, who: str) -> None:
    """ValueError naming `who` where the values `flat` (of the argument `values`) mix numbers
    with a unit and bare ones: the engine's rule for a list (docs/cli.md, "Units"): every
    value with a unit, or every one bare (in the scale); 0 is 0 in every unit. A bare number
    beside '2kPa' would be read in E0*, a scale a thousand times or more from the value meant."""
    def text(v):
        return v.decode(errors="replace") if isinstance(v, bytes) else v

    def bare_nonzero(v) -> bool:
        v = text(v)
        if isinstance(v, str):
            if _core.has_unit(v):
                return False
            try:
                return float(v) != 0.0
            except ValueError:
                return False  # not a number: the engine's reading names it
        return v != 0

    if any(isinstance(text(v), str) and _core.has_unit(text(v)) for v in flat) and any(map(bare_nonzero, flat)):
        raise ValueError(f"{who} = {_one_line(values)}: it mixes values with and without a unit (a bare number is "
                         f"in the model's scale, one with a unit physical: docs/cli.md, Units); valid: every value "
                         f"with a unit, or every value a bare number")


def _in_scale(values, name: str, material, R, who: str = ""):
    """values (numbers, or text with units: '150um', ['1kPa', '2kPa']) in the scale of
    parameter `name`, by the engine's rule (docs/cli.md, "Units"); ValueError naming `who`
    (the argument as the caller calls it; `name` where not given) for a list that mixes
    values with and without a unit."""
    if isinstance(values, np.ndarray) and values.dtype.kind in "biuf":
        return values  # numbers: already in the scale (no per-element look)
    array = np.asarray(values, dtype=object)
    flat = array.reshape(-1)
    if not any(isinstance(v, (str, bytes)) for v in flat):
        return values
    _refuse_mixed_units(flat, values, who or name)
    path = "" if material is None else os.fspath(material)
    R = "" if R is None else str(R)
    return np.vectorize(lambda v: _core.scaled(str(v), name, path, R), otypes=[float])(array)


def _law_arrays(who: str, T, temperature, material) -> dict:
    """The law's parameters of a vectorized call by name: {"T": T} for the standard linear
    solid, or with a material {"temperature": temperature} ({} for its reference temperature,
    or one without a shift). ValueError for T beside a material or neither."""
    if material is None:
        if T is None or temperature is not None:
            raise ValueError(f"{who}: give T (the standard linear solid), or material= (and temperature= "
                             "where the material has a shift)")
        return {"T": T}
    if T is not None:
        raise ValueError(f"{who}: T is the standard linear solid's; a material's law has its own "
                         "(temperature= where the file has a shift)")
    return {} if temperature is None else {"temperature": temperature}


def _point_columns(coordinates: dict) -> tuple[tuple, dict]:
    """The points' coordinates (name: number or array) broadcast like numpy: their shape and
    each as a flat float64 array under its name, as _core's vectorized calls take them (the
    engine puts each name in its place among the point's coordinates)."""
    given = {k: v for k, v in coordinates.items() if v is not None}
    arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in given.values()))
    return arrays[0].shape, {k: np.ascontiguousarray(a).reshape(-1) for k, a in zip(given, arrays)}


def classify(l=None, dh=None, T=None, pbar=None, s=None, C: float | None = None, localization: str | None = None, *,
             material: str | None = None, temperature=None, ramp_time=None, pressure=None,
             R: str | None = None, quantities: Iterable[str] | None = None,
             **texture: Any) -> Classification | TextureClassification:
    """The regime, t*, h(0), h(inf) and validity of every point, broadcasting l, dh, pbar, s and
    the law's parameter (numbers or arrays) like numpy: T of the standard linear solid, or with
    material=FILE (a material file, as point()'s --material) its temperature in degC where the
    file has a shift (its reference temperature when left out; none without a shift). With
    ramp_time the load rises linearly to pbar over that time (T_eps, or the material's time
    unit), as point()'s --ramp; a step without. The same numbers as point() at each
    point; t* in T_eps, or in the material's time unit ("time_unit" says which). localization:
    as point()'s (None: the engine's default, periodic). Points that share (l, s, dh) share
    the model's per-pitch work (a grid is fast: over 2e6 points/s under periodic; scattered
    pitches and dh cost a table row each under periodic, a curve each under refined).
    ValueError with the command line's message for a value out of range.
    Physical units as on the command line: pressure= ('2kPa', or a list of such) instead of
    pbar with a material; l and dh as text with a length unit ('150um') with R= ('50um', the
    punch's radius of curvature); ramp_time with a time unit ('30s') with a material. Bare
    numbers stay in the scales (R, E0*, T_eps or the material's time unit).
    quantities: the names to return (of Classification's; None: all of them). Each array
    costs a large grid about 8% of its time: ("regime", "t_star") runs a third faster.
    Any texture (surface()'s keywords: lattice="hexagonal", dh2=, cell=, height_map=,
    supercell=, scatter=, seed=, grid=, curve=, ...): each level's regime and t* at every
    point, l, dh, s (and dh2) broadcast with the load's arrays, one load curve per distinct
    geometry: surface_classify()'s answer, a TextureClassification (the model's h(0), h(inf)
    and validity, quantities= and localization= are the paper's lattice's)."""
    if texture:
        if quantities is not None or localization is not None:
            raise ValueError("classify: quantities= and localization= are the paper's lattice's (its model's "
                             f"outputs); a texture ({', '.join(f'{k}=' for k in texture)}) gives each level's t* and "
                             "regime (surface_classify's)")
        return surface_classify(pbar=pbar, T=T, pressure=pressure, temperature=temperature, ramp_time=ramp_time,
                                material=material, R=R, l=l, dh=dh, s=s, C=C, **texture)
    C = 0.5 if C is None else C
    if pressure is not None:
        if pbar is not None:
            raise ValueError("classify: pbar and pressure both given; valid: one of them")
        _refuse_mixed_units(np.asarray(pressure, dtype=object).reshape(-1), pressure, "classify: pressure")
        if not all(isinstance(v, str) and _core.has_unit(v)
                   for v in np.asarray(pressure, dtype=object).reshape(-1)):
            raise ValueError(f"pressure = {pressure!r}: no unit; valid: text with a pressure unit ('2kPa', "
                             f"Pa, kPa, MPa or GPa), or pbar= in E0*")
        pbar = pressure
    if pbar is None or s is None:
        raise ValueError("classify: pbar (or pressure) and s are required")
    for value, name in ((l, "l"), (dh, "dh"), (pbar, "pbar"), (s, "s"), (T if material is None else 0.0, "T")):
        _real(value, f"classify: {name}")
    for value, name in ((temperature, "temperature"), (ramp_time, "ramp_time")):
        if value is not None:
            _real(value, f"classify: {name}")
    if np.ndim(C) != 0 or isinstance(C, (bool, np.bool_, complex, np.complexfloating, str)):
        raise ValueError(f"classify: C = {C!r}; valid: one number > 0, the shape constant of every point "
                         f"(points of several C: one call each)")
    l, dh, pbar = (_in_scale(v, n, material, R, f"classify: {n}") for v, n in ((l, "l"), (dh, "dh"), (pbar, "pbar")))
    if ramp_time is not None:
        ramp_time = _in_scale(ramp_time, "ramp_time", material, R, "classify: ramp_time")
    law = _law_arrays("classify", T, temperature, material)
    shape, columns = _point_columns(dict(l=l, dh=dh, pbar=pbar, s=s, **law, ramp_time=ramp_time))
    raw = _core.classify(columns, float(C), _core.default_localization if localization is None else str(localization),
                         "" if material is None else os.fspath(material),
                         [] if quantities is None else [quantities] if isinstance(quantities, str) else list(quantities))
    unit = raw.pop("time_unit")
    return Classification({k: np.asarray(v).reshape(shape) for k, v in raw.items()}, unit)


class NotAMapError(ValueError):
    """open_map's error for a file that is not a (readable) punchsweep map."""


def open_map(path, units: str = "physical") -> "xarray.Dataset":  # noqa: F821
    """A map (a regime map from `punchsweep sweep`, or a texture's from `surface-map`, its
    t_star, regime and X_star over a `level` dimension) as an xarray.Dataset: every flag variable
    (regime, valid, bem_regime, answer_regime, ...) decoded to its meanings as text
    ('immediate', 'delayed', ..., 'not_computed'), its codes kept as NAME_code; every
    variable and coordinate with a `units` attribute (the scale it is measured in: R,
    T_eps, E0/(1-nu^2), R^2 E0/(1-nu^2), or 1). With units="physical" (the default), the
    values whose scale the map knows are in physical units, `units` a UDUNITS-2 string:
    lengths in the unit of the sweep's model.R (um for R = 50um), pressures in Pa and loads
    in N for a material map; such a variable keeps its scale in `scaled_by` and the factor
    in `per_scaled` (scaled value = value / per_scaled). units="scaled": as the file stores
    them. Nothing is read until it is used (the
    production map's flags would take 13 GB as text). NotAMapError (a ValueError) for a
    file that is missing, damaged or no punchsweep map."""
    if units not in ("physical", "scaled"):
        raise ValueError(f"open_map: units={units!r}; valid: 'physical' or 'scaled'")
    # The one reader the scripts use too (map_attributes.open_map: its checks, its conversion).
    return read_map(path, units, "Pa", decode_flags=True, error=NotAMapError)
