"""Typed results of a texture's answers: `surface()`, `design()` and `surface_classify()`.

Each is a frozen dataclass whose fields are the engine's JSON keys (docs/cli.md,
docs/design.md), read as attributes (`r.levels[1].t_star`), each value as the JSON has it
(lists as lists, null as None) but a series, which is numpy arrays. They still read like the dicts
these calls returned before (`r["levels"][1]["t_star"]`, `"check" in r`, `dict(r)`), item
access giving the same values, so code written against the dicts keeps working. A key the
engine gains that a class does not name lands in `other`, and item access finds it there:
no output is dropped unseen.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields

import numpy as np

__all__ = ["SurfaceLevel", "SurfaceResult", "DesignRequirement", "DesignResult", "TextureClassification"]


@dataclass(frozen=True, eq=False)
class _JsonRecord(Mapping):
    """Item access by the engine's JSON keys, for a dataclass built by `_record`: the keys
    are those the engine wrote, `_keys` (a field the JSON lacked, None here, is no key), each
    value the field's or, for a key no field names, `other`'s; a record made directly (no
    `_keys`) has its fields as keys. Equality is the Mapping's (by items, so a record equals
    the JSON's dict of the same values): the classes are made with eq=False."""
    _keys: tuple = field(default=(), repr=False, compare=False, kw_only=True)

    def _json_keys(self) -> tuple:
        return self._keys or tuple(f.name for f in fields(self) if f.name not in ("other", "_keys"))

    def __getitem__(self, key: str):
        if key not in self._json_keys():
            raise KeyError(key)
        return getattr(self, key) if key in self.__dataclass_fields__ else self.other[key]

    def __iter__(self):
        return iter(self._json_keys())

    def __len__(self) -> int:
        return len(self._json_keys())

    def to_dict(self) -> dict:
        """The command's JSON as plain values (dicts, lists, numbers, text, None for NaN), as
        `--format json` prints it: json.dump(r.to_dict(), file) writes what the scripts read
        (postprocess/design_picture.py takes a design's)."""
        return _plain(self)


def _plain(value):
    """`value` with every record, mapping, tuple and numpy array made plain JSON values."""
    if isinstance(value, Mapping):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, np.generic):
        return _plain(value.item())
    if isinstance(value, float) and np.isnan(value):
        return None
    return value


def _record(cls, raw: dict, **made):
    """`cls` (a result dataclass with a field `other`) from the engine's dict `raw`: each
    field from `made` (the converted values) or from raw, and in `other` every key of raw
    that no field names and `made` did not take (`made` may name keys it gathered into a
    field under "consumed"); a _JsonRecord also keeps raw's keys, in their order."""
    consumed = set(made.pop("consumed", ()))
    names = {f.name for f in fields(cls)} - {"other", "_keys"}
    values = {k: made[k] if k in made else raw[k] for k in names if k in made or k in raw}
    other = {k: v for k, v in raw.items() if k not in names and k not in consumed}
    keys = {"_keys": tuple(raw)} if issubclass(cls, _JsonRecord) else {}
    return cls(**values, other=other, **keys)


def _arrays(series: dict) -> dict:
    """A JSON series as numpy arrays: numbers as float, `valid` as bool, `reason` as text."""
    out = {}
    for k, v in series.items():
        out[k] = np.array(v, dtype=bool) if k == "valid" else list(v) if k == "reason" else np.array(v, dtype=float)
    return out


def gathered_sensitivity(raw: dict) -> tuple[dict, tuple | None, dict | None, set]:
    """A point's or a level's d t*/dx and elasticities (dt_star_dNAME, dlog_t_star_dlog_NAME),
    its (least, greatest) t* over a tolerance box and the box's corner regimes (corners_*),
    as PointResult and SurfaceLevel hold them; and the JSON's keys they take."""
    sensitivity = {k: v for k, v in raw.items() if k.startswith(("dt_star_d", "dlog_t_star_dlog_"))}
    corners = {k[len("corners_"):]: int(v) for k, v in raw.items() if k.startswith("corners_")}
    bounds = (raw["t_star_low"], raw["t_star_high"]) if "t_star_low" in raw else None
    taken = set(sensitivity) | {f"corners_{k}" for k in corners} | ({"t_star_low", "t_star_high"} if bounds else set())
    return sensitivity, bounds, corners or None, taken


@dataclass(frozen=True, eq=False)
class SurfaceLevel(_JsonRecord):
    """One level of a texture as `surface()` answers it (docs/cli.md, punchsweep surface).

    level: its index (0 the tallest caps); drop, drop_max: the least and greatest drop of its
    caps below the tallest (R); sites: its caps in the cell; regime: 'immediate', 'delayed' or
    'never'; t_star: when it touches (the time unit; None for never); X_star: the nominal
    pressure at its touchdown on the load curve (E0*); resolved: whether the curve resolves
    that touchdown (False: a finer grid answers); touchdown_from: what gave X* ('tallest',
    'tables', 'small_spot_limit' or 'curve', docs/model.md section 17.6); hidden: under a taller cap's contact;
    t_star_grid_change: t*'s change from the coarser grid (--grid auto; else None); share:
    its share of the cell's caps at full contact's load curve; contact_radius: its caps'
    widest contact radius by the last time (R); advisories: the physical advisories raised
    for it ("" for none). sensitivity: d t*/dx and dlog t*/dlog x as the JSON names them
    (where t* is delayed and smooth); t_star_range: (least, greatest) t* over the tolerance
    box, else None; corner_regimes: how many of the box's corners are immediate, delayed
    and never, else None."""
    level: int
    regime: str
    t_star: float | None
    X_star: float | None
    resolved: bool
    touchdown_from: str = ""
    drop: float | None = None
    drop_max: float | None = None
    sites: int | None = None
    hidden: bool = False
    t_star_grid_change: float | None = None
    share: float | None = None
    contact_radius: float | None = None
    advisories: str = ""
    sensitivity: dict = field(default_factory=dict)
    t_star_range: tuple | None = None
    corner_regimes: dict | None = None
    other: dict = field(default_factory=dict)

    def __getitem__(self, key: str):
        # The gathered keys read as the JSON wrote them (level["dt_star_dpbar"]).
        if key in self._json_keys() and key not in self.__dataclass_fields__:
            if key in self.sensitivity:
                return self.sensitivity[key]
            if key in ("t_star_low", "t_star_high") and self.t_star_range is not None:
                return self.t_star_range[0 if key == "t_star_low" else 1]
            if key.startswith("corners_") and self.corner_regimes is not None:
                return self.corner_regimes[key[len("corners_"):]]
        return super().__getitem__(key)

    @classmethod
    def from_json(cls, raw: dict) -> "SurfaceLevel":
        sensitivity, bounds, corners, taken = gathered_sensitivity(raw)
        return _record(cls, raw, sensitivity=sensitivity, t_star_range=bounds, corner_regimes=corners, consumed=taken)


@dataclass(frozen=True, eq=False)
class SurfaceResult(_JsonRecord):
    """`surface()`'s answer: a texture under a material and a load, from its cell's elastic
    load curve (docs/cli.md, punchsweep surface; docs/model.md, section 17).

    levels: a SurfaceLevel each; series: numpy arrays at each time (t, X, area_fraction,
    sites_touched, area_0 ..., touched_0 ..., load_0 ..., valid as bool) and reason (text per
    time); physical: with R and a material, the same in physical units (X in Pa, areas in
    um^2, loads in N, drops; its series as arrays; its units); check: with check=True the
    time stepping on the same cell (levels, series, steps, converged, seconds), else None;
    curve: the load curve's source, samples, first/resolved/last/full loads (E0*), seconds,
    whether cached and the grid it was held to; inputs: the inputs as the command reads them;
    lattice ('square', 'hexagonal', 'cell' or 'height map'); cell: the cell's sides (R);
    grid: its nodes (x, y); supercell; caps: caps in the cell; cap_list: a dict per cap
    (x, y, drop in R; level; s, C of its paraboloid; its own touch: regime, t_star, X_star,
    resolved; prominence in R for a measured map, None for its highest); summits: for a
    measured map what a summit had to rise (least_prominence, R), the map's height_range (R)
    and how many rose less (below_prominence), else None; ensemble: with seeds=N > 1 the
    draws' seeds, per level the touch times of its first, median and last cap and per series
    (area_fraction, touched, touched_0, ...) per time, each as n, mean, sd, se, p5, median,
    p95 (and infinite: draws that never touch), target_error and largest_error (with
    target_error=E: the largest standard error of a mean share or area fraction at the draws
    taken), and each draw's own values (members), else
    None (the rest of the result is the first draw's); tallest_rise: a supercell's tallest
    tip drawn (the drops' origin) above the tall caps' design height, R; with part_caps=N,
    other["part"] (caps; tallest_rise and supercell_tallest_rise as [p5, median, p95], R);
    advisories and
    advisory_reason: the texture's physical advisories and their sentence; notes: what
    reading the inputs changed; units: the unit of each scaled quantity."""
    inputs: str
    lattice: str
    levels: list[SurfaceLevel]
    series: dict
    units: dict
    cell: list = field(default_factory=list)
    grid: list = field(default_factory=list)
    supercell: int = 1
    caps: int = 0
    cap_list: list = field(default_factory=list)
    summits: dict | None = None
    ensemble: dict | None = None
    tallest_rise: float | None = None
    curve: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    advisories: str = ""
    advisory_reason: str = ""
    physical: dict | None = None
    check: dict | None = None
    cell_file: str | None = None
    height_map: str | None = None
    other: dict = field(default_factory=dict)

    @classmethod
    def from_json(cls, raw: dict) -> "SurfaceResult":
        made = dict(levels=[SurfaceLevel.from_json(level) for level in raw["levels"]], series=_arrays(raw["series"]))
        if "physical" in raw:
            made["physical"] = {**raw["physical"], "series": _arrays(raw["physical"]["series"])}
        if "check" in raw:
            made["check"] = {**raw["check"], "series": _arrays(raw["check"]["series"])}
        return _record(cls, raw, **made)


@dataclass(frozen=True, eq=False)
class DesignRequirement(_JsonRecord):
    """One requirement of a design (docs/design.md): text as given; kind ('touch_by',
    'never', 'share', ...); time, pbar (E0*) and share it names (None where it names none),
    share_level; side: which edge of the window it makes ('upper' or 'lower'); edge: that
    edge (R, or E0* for a pressure) and edge_physical in the physical unit; binds_at: where it
    binds (temperature, pbar, l, C, dh of the tolerance corner); bounds: its edge at every
    temperature and corner; advisories, advisory_reason, contact_radius (R) and strain:
    point()'s advisories at the edge (the binding corner, in the long term; "" where none)."""
    text: str
    kind: str
    side: str | None = None
    edge: float | None = None
    edge_physical: float | None = None
    time: float | None = None
    share: float | None = None
    share_level: int | None = None
    pbar: float | None = None
    binds_at: dict | None = None
    bounds: list = field(default_factory=list)
    advisories: str = ""
    advisory_reason: str = ""
    contact_radius: float | None = None
    strain: float | None = None
    other: dict = field(default_factory=dict)

    @classmethod
    def from_json(cls, raw: dict) -> "DesignRequirement":
        return _record(cls, raw)


@dataclass(frozen=True, eq=False)
class DesignResult(_JsonRecord):
    """`design()`'s answer (docs/design.md): the window of `quantity` ('dh', 'dh2', 'l' or
    'pressure') that meets every requirement at every temperature and tolerance corner.

    lower, upper: its edges (None where open), centre, margin, in `unit` (R, or E0* for a
    pressure); empty: no value meets them all (then miss says why); physical: the same in
    the physical unit with its scale; requirements: a DesignRequirement each, with the edge
    it makes and where it binds; texture: the texture searched (lattice, levels, the level
    required, drops, grid, supercell, scatter, seed, caps, file), None for the paper's
    lattice by its model; point: the fixed inputs as text; time_unit; tolerance: the box;
    temperatures: those checked; notes."""
    quantity: str
    unit: str
    empty: bool
    requirements: list[DesignRequirement]
    lower: float | None = None
    upper: float | None = None
    centre: float | None = None
    margin: float | None = None
    physical: dict | None = None
    texture: dict | None = None
    point: str = ""
    time_unit: str = ""
    tolerance: dict | None = None
    temperatures: list = field(default_factory=list)
    miss: str | None = None
    notes: list = field(default_factory=list)
    other: dict = field(default_factory=dict)

    @classmethod
    def from_json(cls, raw: dict) -> "DesignResult":
        return _record(cls, raw, requirements=[DesignRequirement.from_json(r) for r in raw["requirements"]])


@dataclass(frozen=True, eq=False)
class TextureClassification(_JsonRecord):
    """`surface_classify()`'s answer (and classify()'s with a texture): each level's regime and t*
    of a texture at many loads (and geometries).

    t_star (float64 in time_unit, 0 at once, +inf for never, as a texture map's) and regime (int8, the map's codes: see
    punchsweep.REGIMES) are shaped as the broadcast inputs plus a last axis of levels;
    X_star (E0*) and resolved (bool) per level, the touchdowns they were read from (shaped as
    t_star where the geometry was given as arrays); grid: the load curve's nodes (x, y), or
    the periodic tables' (512, 512) where they answered (an array of the inputs' shape and a
    last axis of 2 where the geometry was arrays); caps: caps in the cell. Reads like the
    dict it was (c["t_star"])."""
    t_star: np.ndarray = field(repr=False)
    regime: np.ndarray = field(repr=False)
    X_star: np.ndarray
    resolved: np.ndarray
    time_unit: str
    grid: tuple
    caps: int
    other: dict = field(default_factory=dict)

    @property
    def levels(self) -> int:
        """The texture's levels (the arrays' last axis)."""
        return self.t_star.shape[-1]

    def regime_names(self) -> np.ndarray:
        """The regimes as text ('immediate', 'delayed', 'never'), of regime's shape."""
        from . import REGIMES
        names = np.array([REGIMES[k] for k in sorted(REGIMES)])
        return names[self.regime]
