#!/usr/bin/python3
"""Summary of a punchsweep regime map: how many points touch immediately, after a delay or
never, overall and per value of each axis; t* statistics of the delayed points; invalid
points per validity reason; points not computed; whether the map is complete. A texture's
map (regime over its axes and `level`) is summarised a level at a time ("level K of L"),
its validity counted over every snapshot (load points x times); with --csv its levels
follow one another under one header whose first column is `level`.

Fractions are of all points in the group (not computed ones included). t* is in the map's
time unit: T_eps (the creep time), or a material map's own (s, min or h); the axis values
are in their units (l, dh in R; pbar in E0/(1-nu^2); T, s dimensionless). The axes,
their units and the regime and validity codes and their names are read from the map (the
dimensions of `regime`, the coordinates' attributes, the flag variables'
flag_values/flag_meanings), whichever axes the map has.

CSV (--csv): first '# key = value' comment lines (map, completed, points, t_star_units),
then one header line and one row per group, with the columns
  axis                  'all' for the whole map, else the axis name (today l, dh, T, pbar, s)
  value, units          the axis value (a label on a categorical axis) and its units (empty
                        for 'all')
  points                number of grid points in the group
  immediate, delayed, never, not_computed
                        points per regime (the flag_meanings of `regime`, in its order)
  fraction_immediate, fraction_delayed, fraction_never, fraction_not_computed
                        the same divided by points
  valid, same_level_overlap, cross_level_overlap, no_solution, inaccurate, outside_table,
  unloading
                        points per validity (the flag_meanings of `valid` but not_computed)
  t_star_min, t_star_median, t_star_max
                        over the delayed points, in T_eps (empty when there are none)
`pandas.read_csv(F, comment="#")` reads it, and so does `numpy.genfromtxt(F, delimiter=",",
names=True, dtype=None, encoding=None, skip_header=4)` (the four comment lines).

Example:
  postprocess/summary.py map.h5
  postprocess/summary.py map.h5 --csv --by T s > summary.csv
"""
from __future__ import annotations

import argparse
import csv
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402


def regimes(ds) -> tuple[str, ...]:
    """The regimes counted: every flag meaning of `regime`, in the map's order."""
    return pm.flags(ds, "regime").meanings


def validities(ds) -> tuple[str, ...]:
    """The validities counted: the flag meanings of `valid` but not_computed (counted with
    the regimes)."""
    return tuple(m for m in pm.flags(ds, "valid").meanings if m != pm.NOT_COMPUTED)


def columns(ds) -> list[str]:
    """The CSV columns for this map (its flag meanings name the count columns)."""
    return (["axis", "value", "units", "points"]
            + list(regimes(ds)) + [f"fraction_{m}" for m in regimes(ds)] + list(validities(ds))
            + ["t_star_min", "t_star_median", "t_star_max"])


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="summary.py", description=__doc__,
                  formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.h5", help="regime map written by `punchsweep sweep`")
    p.add_argument("--by", nargs="+", action="extend", metavar="AXIS",
                   help="break the counts down per value of these axes of the map only "
                        "(default: every axis)")
    p.add_argument("--csv", action="store_true",
                   help="write machine-readable CSV on stdout (columns above) instead of tables")
    return p.parse_args(argv)


@dataclass
class Group:
    """Counts of one group of grid points: the whole map or one value (a float, or a label on
    a categorical axis) of one axis. Counts are keyed by flag meaning."""
    axis: str
    value: float | str | None
    points: int
    regimes: dict[str, int]
    validities: dict[str, int]
    t_star: tuple[float, float, float] | None  # min, median, max over the delayed points

    def fraction(self, meaning: str) -> float:
        return self.regimes[meaning] / self.points if self.points else float("nan")


def count(data: np.ndarray, flags: pm.Flags, meanings: tuple[str, ...]) -> dict[str, int]:
    """Points per flag meaning (codes the flags do not list are in no count)."""
    lo = min(flags.codes)
    shifted = data.ravel().astype(np.int64) - lo
    span = max(flags.codes) - lo
    counts = np.bincount(shifted[(shifted >= 0) & (shifted <= span)], minlength=span + 1)
    return {m: int(counts[flags.code(m) - lo]) for m in meanings}


def group(ds, axis: str, value, regime: np.ndarray, valid: np.ndarray,
          t_star: np.ndarray) -> Group:
    regime_flags = pm.flags(ds, "regime")
    delayed = t_star[(regime == regime_flags.code("delayed")) & np.isfinite(t_star)]
    stats = None
    if delayed.size:
        stats = (float(delayed.min()), float(np.median(delayed)), float(delayed.max()))
    return Group(axis, value, int(regime.size), count(regime, regime_flags, regimes(ds)),
                 count(valid, pm.flags(ds, "valid"), validities(ds)), stats)


def summarize(ds, by: list[str]) -> list[Group]:
    """The whole map first, then one group per value of each axis in `by`."""
    axes = pm.axes(ds)
    regime = ds["regime"].values
    # (A texture's map: valid per snapshot, over the axes and the times t, counted whole.)
    valid = ds["valid"].transpose(*axes, *(d for d in ds["valid"].dims if d not in axes)).values
    t_star = (ds["t_star"].transpose(*axes).values if "t_star" in ds
              else np.full(regime.shape, np.nan))
    groups = [group(ds, "all", None, regime, valid, t_star)]
    for axis in by:
        k = axes.index(axis)
        for i, value in enumerate(pm.grid_values(ds, axis)):
            take = (slice(None),) * k + (i,)
            groups.append(group(ds, axis, value, regime[take], valid[take], t_star[take]))
    return groups


def number(x: float | str | None) -> str:
    if isinstance(x, str):
        return x
    return "" if x is None else repr(float(x))


def write_csv(ds, path: str, groups: list[Group], out, level: int | None = None) -> None:
    """The CSV; a texture's map's levels one after another under one header, its first
    column `level` (the comment lines and the header with level 0 only)."""
    if not level:
        out.write(f"# map = {path}\n# completed = {int(pm.is_completed(ds))}\n"
                  f"# points = {groups[0].points}\n# t_star_units = {pm.units(ds, 't_star') or 'T_eps'}\n")
    w = csv.writer(out, lineterminator="\n")
    first = [] if level is None else [level]
    if not level:
        w.writerow((["level"] if level is not None else []) + columns(ds))
    for g in groups:
        t = g.t_star or (None, None, None)
        w.writerow(first + [g.axis, number(g.value), "" if g.value is None else pm.units(ds, g.axis),
                    g.points, *(g.regimes[m] for m in regimes(ds)),
                    *(number(g.fraction(m)) for m in regimes(ds)),
                    *(g.validities[m] for m in validities(ds)), *(number(v) for v in t)])


def write_table(ds, path: str, groups: list[Group], out) -> None:
    whole = groups[0]
    completed = "yes" if pm.is_completed(ds) else "NO (interrupted: resume the sweep with --resume)"
    out.write(f"map: {path}\ncompleted: {completed}\n")
    out.write("axes:\n")
    width = max(5, *(len(a) for a in pm.axes(ds)))
    for a in pm.axes(ds):
        grid = pm.grid_values(ds, a)
        spacing = ds[a].attrs.get("spacing", "")
        out.write(f"  {a:<{width}}{len(grid):>5} values  {pm.value_text(grid[0])} .. "
                  f"{pm.value_text(grid[-1])}{pm.unit_suffix(ds, a)}"
                  + (f"  ({spacing})" if spacing else "") + "\n")
    not_computed = whole.regimes.get(pm.NOT_COMPUTED, 0)
    out.write(f"points: {whole.points}, not computed: {not_computed}\n\n")
    out.write(f"{'regime':<22}{'points':>10}{'fraction':>11}\n")
    for m in regimes(ds):
        out.write(f"{m:<22}{whole.regimes[m]:>10d}{whole.fraction(m):>10.2%}\n")
    t_unit = pm.units(ds, "t_star") or "T_eps"  # a material map's is its time unit (s, min, h)
    if whole.t_star:
        lo, med, hi = whole.t_star
        out.write(f"\nt* of the delayed points [{t_unit}]: min {lo:.4g}, median {med:.4g}, "
                  f"max {hi:.4g} ({whole.regimes['delayed']} points)\n")
    else:
        out.write(f"\nt* of the delayed points [{t_unit}]: no delayed points\n")
    # A texture's map: validity per snapshot (points x times), not per point.
    snapshots = "t" in ds["valid"].dims and "t" not in pm.axes(ds)
    what = "snapshots" if snapshots else "points"
    out.write(f"\n{'validity':<22}{what:>10}{'fraction':>11}\n")
    computed = sum(whole.validities.values()) if snapshots else whole.points - not_computed
    for m in validities(ds):
        share = whole.validities[m] / computed if computed else float("nan")
        out.write(f"{m:<22}{whole.validities[m]:>10d}{share:>10.2%}\n")
    out.write(f"(fractions of the computed {what}" + (": load points x times)\n" if snapshots else ")\n"))
    shown = [m for m in regimes(ds) if m != pm.NOT_COMPUTED or not_computed]  # if any
    header = (f"  {'value':>10}{'points':>8}" + "".join(f"{m:>16}" for m in shown)
              + f"{'invalid':>9}{'t* min':>11}{'median':>11}{'max':>11}")
    current = None
    for g in groups[1:]:
        if g.axis != current:
            current = g.axis
            unit = pm.units(ds, g.axis)
            out.write(f"\nby {g.axis}" + (f" [{unit}]" if unit not in ("", "1") else "")
                      + f": points per regime (fraction), invalid points, t* of delayed [{t_unit}]\n")
            out.write(header + "\n")
        cells = "".join(f"{g.regimes[m]:>8d} ({g.fraction(m):>5.1%})" for m in shown)
        t = "".join(f"{v:>11.4g}" for v in g.t_star) if g.t_star else f"{'-':>11}" * 3
        invalid = sum(g.validities[m] for m in validities(ds) if m != pm.VALID)
        out.write(f"  {pm.value_text(g.value):>10}{g.points:>8d}{cells}{invalid:>9d}{t}\n")


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    with pm.open_map(args.map) as ds:
        # A texture's map (regime over its axes and `level`): the same summary a level at a
        # time, its validity counted over every snapshot (valid is per time, not per level).
        levels = list(range(ds.sizes["level"])) if "level" in ds["regime"].dims else [None]
        for level in levels:
            one = ds if level is None else ds.isel(level=level)
            by = list(pm.axes(one)) if not args.by else [pm.parse_axis(one, a, "--by") for a in args.by]
            if len(set(by)) != len(by):
                raise pm.MapError(f"--by names an axis twice: {' '.join(by)}")
            groups = summarize(one, by)
            if args.csv:
                write_csv(one, args.map, groups, sys.stdout, level)
                continue
            if level is not None:
                sys.stdout.write(("" if level == 0 else "\n") + f"level {level} of {len(levels)} (a texture's map: "
                                 "its regimes and t*; validity per snapshot time)\n")
            write_table(one, args.map, groups, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "summary.py"))
