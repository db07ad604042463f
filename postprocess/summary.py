#!/usr/bin/python3
"""Summary of a punchsweep regime map: how many points touch immediately, after a delay or
never, overall and per value of each axis; t* statistics of the delayed points; invalid
points per validity reason; points not computed; whether the map is complete.

Fractions are of all points in the group (not computed ones included). t* is in T_eps (the
creep time); the axis values are in their units (l, dh in R; pbar in E0/(1-nu^2); T, s
dimensionless).

CSV (--csv): first '# key = value' comment lines (map, completed, points, t_star_units),
then one header line and one row per group, with the columns
  axis                  'all' for the whole map, else the axis name (l, dh, T, pbar, s)
  value, units          the axis value and its units (empty for 'all')
  points                number of grid points in the group
  immediate, delayed, never, not_computed
                        points per regime code (0, 1, 2, -1)
  fraction_immediate, fraction_delayed, fraction_never, fraction_not_computed
                        the same divided by points
  valid, same_level_overlap, cross_level_overlap, no_solution
                        points per validity code (0, 1, 2, 3)
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

REGIMES = (0, 1, 2, -1)
VALIDITIES = (0, 1, 2, 3)
COLUMNS = (["axis", "value", "units", "points"]
           + [pm.REGIME_NAMES[c] for c in REGIMES]
           + [f"fraction_{pm.REGIME_NAMES[c]}" for c in REGIMES]
           + [pm.VALID_NAMES[c] for c in VALIDITIES]
           + ["t_star_min", "t_star_median", "t_star_max"])


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = pm.Parser(prog="summary.py", description=__doc__,
                  formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("map", metavar="MAP.h5", help="regime map written by `punchsweep sweep`")
    p.add_argument("--by", nargs="+", action="extend", metavar="AXIS",
                   help=f"break the counts down per value of these axes only (of "
                        f"{', '.join(pm.AXES)}; default: all five)")
    p.add_argument("--csv", action="store_true",
                   help="write machine-readable CSV on stdout (columns above) instead of tables")
    return p.parse_args(argv)


@dataclass
class Group:
    """Counts of one group of grid points: the whole map or one value of one axis."""
    axis: str
    value: float | None
    points: int
    regimes: dict[int, int]
    validities: dict[int, int]
    t_star: tuple[float, float, float] | None  # min, median, max over the delayed points

    def fraction(self, code: int) -> float:
        return self.regimes[code] / self.points if self.points else float("nan")


def group(axis: str, value, regime: np.ndarray, valid: np.ndarray, t_star: np.ndarray) -> Group:
    counts = np.bincount(regime.ravel().astype(np.int64) + 1, minlength=4)  # codes -1..2
    vcounts = np.bincount(valid.ravel().astype(np.int64) + 1, minlength=5)  # codes -1..3
    delayed = t_star[(regime == 1) & np.isfinite(t_star)]
    stats = None
    if delayed.size:
        stats = (float(delayed.min()), float(np.median(delayed)), float(delayed.max()))
    return Group(axis, value, int(regime.size), {c: int(counts[c + 1]) for c in REGIMES},
                 {c: int(vcounts[c + 1]) for c in VALIDITIES}, stats)


def summarize(ds, by: list[str]) -> list[Group]:
    """The whole map first, then one group per value of each axis in `by`."""
    regime = ds["regime"].values
    valid = ds["valid"].values
    t_star = ds["t_star"].values if "t_star" in ds else np.full(regime.shape, np.nan)
    groups = [group("all", None, regime, valid, t_star)]
    for axis in by:
        k = pm.AXES.index(axis)
        for i, value in enumerate(ds[axis].values):
            take = (slice(None),) * k + (i,)
            groups.append(group(axis, float(value), regime[take], valid[take], t_star[take]))
    return groups


def number(x: float | None) -> str:
    return "" if x is None else repr(float(x))


def write_csv(ds, path: str, groups: list[Group], out) -> None:
    out.write(f"# map = {path}\n# completed = {int(pm.is_completed(ds))}\n"
              f"# points = {groups[0].points}\n# t_star_units = {pm.units(ds, 't_star') or 'T_eps'}\n")
    w = csv.writer(out, lineterminator="\n")
    w.writerow(COLUMNS)
    for g in groups:
        t = g.t_star or (None, None, None)
        w.writerow([g.axis, number(g.value), "" if g.value is None else pm.units(ds, g.axis),
                    g.points, *(g.regimes[c] for c in REGIMES),
                    *(number(g.fraction(c)) for c in REGIMES),
                    *(g.validities[c] for c in VALIDITIES), *(number(v) for v in t)])


def write_table(ds, path: str, groups: list[Group], out) -> None:
    whole = groups[0]
    completed = "yes" if pm.is_completed(ds) else "NO (interrupted: resume the sweep with --resume)"
    out.write(f"map: {path}\ncompleted: {completed}\n")
    out.write("axes:\n")
    for a in pm.AXES:
        grid = ds[a].values
        spacing = ds[a].attrs.get("spacing", "")
        out.write(f"  {a:<5}{len(grid):>5} values  {grid[0]:.6g} .. {grid[-1]:.6g}"
                  f"{pm.unit_suffix(ds, a)}" + (f"  ({spacing})" if spacing else "") + "\n")
    out.write(f"points: {whole.points}, not computed: {whole.regimes[-1]}\n\n")
    out.write(f"{'regime':<22}{'points':>10}{'fraction':>11}\n")
    for c in REGIMES:
        out.write(f"{pm.REGIME_NAMES[c]:<22}{whole.regimes[c]:>10d}{whole.fraction(c):>10.2%}\n")
    if whole.t_star:
        lo, med, hi = whole.t_star
        out.write(f"\nt* of the delayed points [T_eps]: min {lo:.4g}, median {med:.4g}, "
                  f"max {hi:.4g} ({whole.regimes[1]} points)\n")
    else:
        out.write("\nt* of the delayed points [T_eps]: no delayed points\n")
    out.write(f"\n{'validity':<22}{'points':>10}{'fraction':>11}\n")
    computed = whole.points - whole.regimes[-1]
    for c in VALIDITIES:
        share = whole.validities[c] / computed if computed else float("nan")
        out.write(f"{pm.VALID_NAMES[c]:<22}{whole.validities[c]:>10d}{share:>10.2%}\n")
    out.write("(fractions of the computed points)\n")
    shown = [c for c in REGIMES if c != -1 or whole.regimes[-1]]  # not_computed: if any
    header = (f"  {'value':>10}{'points':>8}" + "".join(f"{pm.REGIME_NAMES[c]:>16}" for c in shown)
              + f"{'invalid':>9}{'t* min':>11}{'median':>11}{'max':>11}")
    current = None
    for g in groups[1:]:
        if g.axis != current:
            current = g.axis
            unit = pm.units(ds, g.axis)
            out.write(f"\nby {g.axis}" + (f" [{unit}]" if unit not in ("", "1") else "")
                      + ": points per regime (fraction), invalid points, t* of delayed [T_eps]\n")
            out.write(header + "\n")
        cells = "".join(f"{g.regimes[c]:>8d} ({g.fraction(c):>5.1%})" for c in shown)
        t = "".join(f"{v:>11.4g}" for v in g.t_star) if g.t_star else f"{'-':>11}" * 3
        invalid = sum(g.validities[c] for c in VALIDITIES if c != 0)
        out.write(f"  {g.value:>10.6g}{g.points:>8d}{cells}{invalid:>9d}{t}\n")


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    by = list(pm.AXES) if not args.by else [pm.parse_axis(a, "--by") for a in args.by]
    if len(set(by)) != len(by):
        raise pm.MapError(f"--by names an axis twice: {' '.join(by)}")
    with pm.open_map(args.map) as ds:
        groups = summarize(ds, by)
        (write_csv if args.csv else write_table)(ds, args.map, groups, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "summary.py"))
