#!/usr/bin/env python3
"""One elastic contact solve of the same periodic cell in punchsweep and in ContactMechanics
(github ContactEngineering/ContactMechanics: an independent periodic FFT boundary-element
code, Polonsky & Keer's constrained conjugate gradient), timed side by side in one run, and
their answers compared. A benchmark only: never a test, never a dependency of the engine.
Skipped (one line, exit 0) where ContactMechanics does not import (docs/performance.md says
how to set it up) or the punchsweep binary is missing.

  PYTHONPATH=/tmp/cm/ContactMechanics:/tmp/cm/NuMPI:benchmarks/contactmechanics_stubs \\
      /usr/bin/python3 benchmarks/contactmechanics_compare.py [--grids 64,128,256] [--X 0.04]

Units: lengths in R, pressures in E* (punchsweep's E0* = E0/(1-nu^2); ContactMechanics'
`young` argument with its default poisson = 0 is the same contact modulus, and its kernel
2/(E* |k|) is punchsweep's), loads X = mean pressure over the cell in E*, seconds wall time.

A  The hexagonal two-level cell, model::lattice_cell(hexagonal, l = 1.2, Shape{2, 0.5},
   {dh = 0.06}), on reference::lattice_grid's nx x ny grid (n nodes a pitch, ny the multiple
   of 6 nearest n sqrt(3)), the profile of reference::make_cell (the lowest of C r^2 + drop
   over the sites' nearest periodic images, node (i, j) at (i hx, j hy)) rebuilt in numpy.
   punchsweep: `punchsweep surface --lattice hexagonal ... --T 1 --pbar X --times 0
   --curve cell --grid n --check --format json`. Its "check" is the time-stepping boundary
   elements on the same cell and grid; at T = 1 and times {0} it is one contact solve from
   the uniform pressure (plus, if a site is still untouched, one warm solve at the same load
   for the long-term state; the script says so), and check.seconds times it with its set-up
   (the influence operator's kernel, FFTW estimate plans in a fresh process): an upper bound
   of one cold solve, the minimum over --repeats processes. No benchmark binary times one
   solve of a hexagonal cell (surface_benchmark's BM_LoadCurve times whole load curves of
   warm-started solves), so this is the honest per-solve figure for it. The command also
   builds the cell's load curve to full contact (once a grid: later repeats read it from a
   private cache in a temporary folder, removed at the end); its area at X, read off the
   curve, is printed beside the direct solve's.
B  The square two-level cell of reference_benchmark's BM_ElasticSolve_TwoLevel (l = 0.75,
   dh = 0.05, X = 0.06, n x n): its per-solve time (Google Benchmark, one cold solve from the
   uniform pressure, repeated; variant 1 the quarter cell preconditioned, as punchsweep
   solves; variant 0 the whole cell with the plain iteration, ContactMechanics' algorithm),
   and the answer of `punchsweep reference --T 1 --times 0 --bem-grid n` (one solve).

ContactMechanics solves the whole grid, from its own cold start, with tolerances tightened
until its complementarity residual in punchsweep's measure (max |gap| on the contact, max
penetration off it, over the displacement range) is about 1e-10, punchsweep's tolerance; its
time at its own default tolerances is printed too. Agreement: the contact area fraction by
punchsweep's own rule (reference/contact_areas.cpp: each pressed node's square, its sides
moved to where p^2 extrapolates to zero) applied to ContactMechanics' pressure, the level
loads (hexagonal: each node's load to the level lowest at it, exact while no pressed node's
square straddles the levels' crossing line, which the script checks), and (square) the tips'
displacement difference h = u(O) - u(M).
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
C_SHAPE = 0.5  # Shape{2, 0.5}: f(r) = C r^2 (R = 1)


def skip(reason: str) -> None:
    print(f"contactmechanics_compare: skipped: {reason}")
    sys.exit(0)


# --- the cells, as reference::make_cell builds them -------------------------------------

def periodic_offset(d, L):
    return d - L * np.rint(d / L)


def hexagonal_sites(l: float, dh: float):
    """model::lattice_cell(hexagonal, l, shape, {dh}): (x, y, drop, level)."""
    H = l * np.sqrt(3.0)
    return (l, H), [(0.0, 0.0, 0.0, 0), (0.5 * l, 0.5 * H, 0.0, 0),
                    (0.5 * l, H / 6.0, dh, 1), (0.0, 4.0 * H / 6.0, dh, 1),
                    (0.0, 2.0 * H / 6.0, dh, 1), (0.5 * l, 5.0 * H / 6.0, dh, 1)]


def square_sites(l: float, dh: float):
    """model::two_level_square: level 0 at the corner, level 1 (lower by dh) at the centre."""
    return (l, l), [(0.0, 0.0, 0.0, 0), (0.5 * l, 0.5 * l, dh, 1)]


def hexagonal_ny(n: int, Lx: float, Ly: float) -> int:
    """reference::lattice_grid's ny for the hexagonal cell: a multiple of 6 (tips on nodes)."""
    return 6 * max(1, int(np.floor(n * Ly / Lx / 6.0 + 0.5)))


def surfaces(cell, sites, nx, ny, at=None):
    """Each level's lowest surface C r^2 + drop at the nodes (or at the points `at`)."""
    Lx, Ly = cell
    if at is None:
        x, y = np.meshgrid(np.arange(nx) * (Lx / nx), np.arange(ny) * (Ly / ny), indexing="ij")
    else:
        x, y = at
    levels = 1 + max(s[3] for s in sites)
    low = [np.full(np.shape(x), np.inf) for _ in range(levels)]
    for cx, cy, drop, level in sites:
        r2 = periodic_offset(x - cx, Lx) ** 2 + periodic_offset(y - cy, Ly) ** 2
        low[level] = np.minimum(low[level], C_SHAPE * r2 + drop)
    return low


def tip_nodes(cell, sites, nx, ny):
    Lx, Ly = cell
    return [(int(round(cx / (Lx / nx))) % nx, int(round(cy / (Ly / ny))) % ny) for cx, cy, _, _ in sites]


# --- ContactMechanics ----------------------------------------------------------------------

def cm_solve(profile, cell, tight: bool):
    """One cold load-controlled solve; returns (seconds, pressure, displacement, offset, result)."""
    from ContactMechanics import PeriodicFFTElasticHalfSpace
    from ContactMechanics.Optimization import constrained_conjugate_gradients
    nx, ny = profile.shape
    substrate = PeriodicFFTElasticHalfSpace((nx, ny), 1.0, cell)  # young = E* (poisson 0)
    force = cm_solve.X * cell[0] * cell[1]
    options = {}
    if tight:  # residual ~1e-10 of the displacement range, as punchsweep's default tolerance
        scale = cm_solve.u_range or 0.1
        options = dict(pentol=1e-10 * scale, forcetol=1e-10 * force / (nx * ny), thermotol=1e-10)
    start = time.perf_counter()
    r = constrained_conjugate_gradients(substrate, -profile, external_force=force, **options)
    seconds = time.perf_counter() - start
    if not r.success:
        raise RuntimeError(f"ContactMechanics did not converge on {nx} x {ny}: {r.message}")
    p = r.jac / substrate.area_per_pt  # nodal forces (compressive > 0) over the node's area
    return seconds, p, r.x, r.offset, r


cm_solve.X = 0.0
cm_solve.u_range = None


def residual(profile, p, u, offset):
    """punchsweep's ContactStatus::residual of a solution (gap = profile + u - offset)."""
    gap = profile + u - offset
    c = p > 0
    worst = max(np.abs(gap[c]).max(initial=0.0), max(0.0, -gap[~c].min(initial=0.0)))
    return worst / (u.max() - u.min())


def area_fraction(p):
    """reference::level_contact_areas summed over levels, over the cell (rims = p: elastic)."""
    pressed = p > 0
    nodes = pressed.astype(float)
    for axis in (0, 1):
        for step in (-1, 1):
            nb_free = ~np.roll(pressed, -step, axis=axis)      # neighbour at i + step is free
            behind = np.roll(p, step, axis=axis)                # node at i - step
            inner2 = behind ** 2
            edge2 = p ** 2
            with np.errstate(divide="ignore", invalid="ignore"):
                off = np.where(behind > p, np.clip(edge2 / (inner2 - edge2), 0.0, 1.0), 0.5)
            nodes += np.where(pressed & nb_free, 0.5 * (off - 0.5), 0.0)
    return nodes.sum() / p.size


def level_loads(p, cell, sites, nx, ny):
    """Each level's load (R^2 E*): each node's p times its square to the level lowest at it;
    also whether every pressed node's square lies on one side of the levels' crossing."""
    hx, hy = cell[0] / nx, cell[1] / ny
    low = surfaces(cell, sites, nx, ny)
    owner1 = low[1] < low[0]
    clean = True
    pressed = np.argwhere(p > 0)
    xs, ys = pressed[:, 0] * hx, pressed[:, 1] * hy
    for a in (-0.5, 0.0, 0.5):
        for b in (-0.5, 0.0, 0.5):
            l0, l1 = surfaces(cell, sites, nx, ny, at=(xs + a * hx, ys + b * hy))
            clean = clean and bool(np.all((l1 < l0) == owner1[pressed[:, 0], pressed[:, 1]]))
    area = hx * hy
    return [float(p[~owner1].sum() * area), float(p[owner1].sum() * area)], clean


# --- punchsweep ----------------------------------------------------------------------------

def run_json(cmd, env):
    out = subprocess.run(cmd, capture_output=True, text=True, env=env, check=True)
    return json.loads(out.stdout)


def rel(a, b):
    return abs(a - b) / abs(b) if b != 0 else float("nan")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--grids", default="64,128,256", help="hexagonal cell: nodes a pitch (even)")
    ap.add_argument("--X", type=float, default=0.04, help="hexagonal cell: mean pressure, E*")
    ap.add_argument("--square-grids", default="128,256",
                    help="square cell (reference_benchmark's sizes: 128, 256, 512, 1024); '' for none")
    ap.add_argument("--repeats", type=int, default=3, help="timed solves a grid, the minimum kept")
    args = ap.parse_args()

    try:
        import ContactMechanics  # noqa: F401
        from ContactMechanics import PeriodicFFTElasticHalfSpace  # noqa: F401
        from ContactMechanics.Optimization import constrained_conjugate_gradients  # noqa: F401
    except Exception as e:  # ImportError, or a half set-up tree
        skip(f"ContactMechanics does not import ({type(e).__name__}: {e}); see docs/performance.md")
    exe = Path(os.environ.get("PUNCHSWEEP", ROOT / "build/src/app/punchsweep"))
    if not os.access(exe, os.X_OK):
        skip(f"no punchsweep binary at {exe} (set PUNCHSWEEP)")
    bench = ROOT / "build/benchmarks/reference_benchmark"

    cache = tempfile.mkdtemp(prefix="punchsweep-cm-compare-")
    env = dict(os.environ, PUNCHSWEEP_CACHE=cache)
    try:
        print(f"ContactMechanics {ContactMechanics.__file__}, numpy {np.__version__}; punchsweep {exe}")
        print("Times: wall seconds of one elastic contact solve, one core; ratio = ContactMechanics / punchsweep.\n")
        hexagonal(args, exe, env)
        if args.square_grids.strip():
            square(args, exe, env, bench)
    finally:
        shutil.rmtree(cache, ignore_errors=True)


def cm_timed(profile, cell, X, repeats):
    """ContactMechanics on `profile` at X: once at its default tolerances (its time, and the
    displacement range the tight tolerances scale by), then `repeats` times tightened to
    punchsweep's; the default's time, the tight times, and the last tight answer."""
    cm_solve.X, cm_solve.u_range = X, None
    t_default, p, u, offset, _ = cm_solve(profile, cell, tight=False)
    cm_solve.u_range = u.max() - u.min()
    t_cm = []
    for _ in range(max(1, repeats)):
        t, p, u, offset, r = cm_solve(profile, cell, tight=True)
        t_cm.append(t)
    return t_default, t_cm, p, u, offset, r


def hexagonal(args, exe, env) -> None:
    l, dh, X = 1.2, 0.06, args.X
    cell, sites = hexagonal_sites(l, dh)
    print(f"A. Hexagonal two-level cell: l = {l} R, dh = {dh} R, s = 2, C = 0.5, X = {X} E* (mean pressure)")
    print("   punchsweep: `surface --check` at T = 1, times 0 (one cold solve with set-up, quarter cell, "
          "preconditioned; min over repeats)")
    head = (f"   {'grid':>11} | {'CM s/solve':>10} {'iters':>5} {'(CM default tol)':>16} {'CM resid':>8} | {'ps s/solve':>10} "
            f"{'ratio':>6} | {'area CM':>9} {'area ps':>9} {'rel diff':>8} | {'load_1 CM':>10} {'rel diff':>8} "
            f"| {'ps curve: area at X':>19} {'curve s':>7}")
    print(head)
    for n in (int(v) for v in args.grids.split(",") if v.strip()):
        nx, ny = n, hexagonal_ny(n, *cell)
        low = surfaces(cell, sites, nx, ny)
        profile = np.minimum(low[0], low[1])
        t_default, t_cm, p, u, offset, r = cm_timed(profile, cell, X, args.repeats)
        res = residual(profile, p, u, offset)
        loads, clean = level_loads(p, cell, sites, nx, ny)
        a_cm = area_fraction(p)
        touched = np.mean([p[i, j] > 0 for i, j in tip_nodes(cell, sites, nx, ny)])

        cmd = [str(exe), "surface", "--lattice", "hexagonal", "--l", str(l), "--dh", str(dh), "--T", "1",
               "--pbar", repr(X), "--s", "2", "--times", "0", "--curve", "cell", "--grid", str(n), "--check",
               "--format", "json"]
        runs = [run_json(cmd, env) for _ in range(max(1, args.repeats))]
        first = runs[0]
        if first["grid"] != [nx, ny]:
            raise RuntimeError(f"punchsweep's grid {first['grid']} is not the script's {[nx, ny]}")
        check = first["check"]["series"]
        t_ps = min(rn["check"]["seconds"] for rn in runs)
        a_ps, load1_ps = check["area_fraction"][0], check["load_1"][0]
        print(f"   {f'{nx} x {ny}':>11} | {min(t_cm):>10.4f} {r.nit:>5d} {t_default:>16.4f} {res:>8.1e} | {t_ps:>10.5f} "
              f"{min(t_cm) / t_ps:>6.0f} | {a_cm:>9.6f} {a_ps:>9.6f} {rel(a_cm, a_ps):>8.1e} | "
              f"{loads[1]:>10.6f} {rel(loads[1], load1_ps):>8.1e} | "
              f"{first['series']['area_fraction'][0]:>19.6f} {first['curve']['seconds']:>7.2f}")
        notes = []
        if not clean:
            notes.append("a pressed node straddles the levels' crossing: load_1 by node is approximate")
        if check["sites_touched"][0] < 1.0 or touched < 1.0:
            notes.append(f"sites touched: CM {touched:.3f}, punchsweep {check['sites_touched'][0]:.3f} "
                         "(an untouched site adds a warm long-term solve to check.seconds)")
        if abs(sum(loads) - X * cell[0] * cell[1]) > 1e-9 * X * cell[0] * cell[1]:
            notes.append(f"CM's load {sum(loads)} is not X Lx Ly")
        for note in notes:
            print(f"   {'':>11}   note: {note}")
    print("   Columns: seconds a solve (CM at residual ~1e-10 as punchsweep's tolerance; at CM's own default "
          "tolerances in brackets), iters = CM's iterations; CM resid = its residual in punchsweep's measure; area = contact area "
          "fraction (punchsweep's rim rule); load_1 = level 1's load in R^2 E*; rel diff = |CM - ps| / ps; "
          "ps curve = the load curve's area fraction at X (interpolated) and the curve's build seconds.\n")


def square(args, exe, env, bench) -> None:
    l, dh, X = 0.75, 0.05, 0.06
    cell, sites = square_sites(l, dh)
    grids = [int(v) for v in args.square_grids.split(",") if v.strip()]
    print(f"B. Square two-level cell of reference_benchmark's BM_ElasticSolve_TwoLevel: l = {l} R, dh = {dh} R, "
          f"X = {X} E*")
    bm = {}
    if os.access(bench, os.X_OK):
        pattern = "BM_ElasticSolve_TwoLevel/(" + "|".join(str(n) for n in grids) + ")/"
        out = run_json([str(bench), f"--benchmark_filter={pattern}", "--benchmark_format=json"], env)
        for b in out["benchmarks"]:
            _, n, variant = b["name"].split("/")[:3]
            scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
            bm[(int(n), int(variant))] = (b["real_time"] * scale, int(b["cg_iterations"]), b["residual"])
    else:
        print(f"   (no {bench}: Google Benchmark figures left out)")
    print(f"   {'grid':>11} | {'CM s/solve':>10} {'iters':>5} | {'BM quarter+PCG':>14} {'iters':>5} {'ratio':>6} | "
          f"{'BM whole plain':>14} {'iters':>5} {'ratio':>6} | {'area CM':>9} {'rel diff':>8} | "
          f"{'h CM (R)':>12} {'rel diff':>8} | {'P2 CM':>10} {'rel diff':>8}")
    for n in grids:
        low = surfaces(cell, sites, n, n)
        _, t_cm, p, u, offset, r = cm_timed(np.minimum(low[0], low[1]), cell, X, args.repeats)
        loads, _ = level_loads(p, cell, sites, n, n)
        h_cm = u[0, 0] - u[n // 2, n // 2]
        ref = run_json([str(exe), "reference", "--l", str(l), "--dh", str(dh), "--T", "1", "--pbar", repr(X),
                        "--s", "2", "--times", "0", "--bem-grid", str(n), "--format", "json"], env)
        s = ref["series"]
        cells = []
        for variant in (1, 0):
            if (n, variant) in bm:
                t, it, _ = bm[(n, variant)]
                cells.append(f"{t:>14.5f} {it:>5d} {min(t_cm) / t:>6.0f}")
            else:
                cells.append(f"{'-':>14} {'-':>5} {'-':>6}")
        print(f"   {f'{n} x {n}':>11} | {min(t_cm):>10.4f} {r.nit:>5d} | {cells[0]} | {cells[1]} | "
              f"{area_fraction(p):>9.6f} {rel(area_fraction(p), s['area_fraction'][0]):>8.1e} | "
              f"{h_cm:>12.9f} {rel(h_cm, s['h'][0]):>8.1e} | {loads[1]:>10.7f} {rel(loads[1], s['P2'][0]):>8.1e}")
    print("   BM = build/benchmarks/reference_benchmark (Google Benchmark, one cold solve a iteration, plans made "
          "before timing), seconds a solve and CG iterations; ratio = CM / BM; the answers (area fraction, h = u(O) - u(M), "
          "level 2's load P2 in R^2 E*) against `punchsweep reference --T 1 --times 0` (one solve).")


if __name__ == "__main__":
    main()
