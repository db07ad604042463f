"""`punchsweep surface` (issue 38): a texture's touch times and areas from its cell's elastic
load curve. The two-level square lattice against `punchsweep point` (the periodic model's
tables, built at n = 512 with their small-spot table: another code path than the curve);
the command's outputs, units and refusals."""
from __future__ import annotations

import json
import re
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import punchsweep
from lattice_maps import lattice_heights

REPO = Path(__file__).resolve().parents[2]
TRUTH = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
TIMES = [0, 0.5, 1, 2, 5, 50]


def cli(*args) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, "surface", *map(str, args)], capture_output=True, text=True)


def test_two_level_square_surface_reads_the_periodic_tables_at_random_points():
    """The issue's check: on the two-level square lattice `surface` reads the periodic model's
    tables (--curve auto), so at random points over the whole range users reach (log-uniform
    in pbar 1e-9 to 1e-1 and l 0.1 to 10 R, s = 1, 2, 3, dh uniform in [0, 1.3 h_inf] so that
    every regime occurs) it gives `point`'s regime, t* to 1e-6 (the same touchdown load and
    the same classification), each level's load to 1e-4 of pbar l^2 and the area fraction to
    5e-4 (the curve samples the tables 96 times a decade: linear interpolation between them
    leaves, measured on 200 such points from pbar 1e-7, areas within 6.4e-5 and loads within
    5.1e-6, 24 a decade 4.4e-4 and 8.6e-5, second order; on these 40 from pbar 1e-9, t* equal
    to the last bit, areas within 1.4e-5, loads within 5.1e-6)."""
    rng = np.random.default_rng(38)
    times = [0, 0.1, 0.5, 1, 2, 5, 50, 1e3]
    regimes = set()
    worst_t, worst_area, worst_load = 0.0, 0.0, 0.0
    for _ in range(40):
        l = 10 ** rng.uniform(-1, 1)
        pbar = 10 ** rng.uniform(-9, -1)
        s = int(rng.integers(1, 4))
        gaps = punchsweep.point(l=l, dh=1e-12, T=2.5, pbar=pbar, s=s, times=[0])
        dh = gaps.h_inf * rng.uniform(0.0, 1.3)
        model = punchsweep.point(l=l, dh=dh, T=2.5, pbar=pbar, s=s, times=times)
        surface = punchsweep.surface(l=l, dh=dh, T=2.5, pbar=pbar, s=s, times=times)
        assert surface["curve"]["source"] == "tables"
        level = surface["levels"][1]
        point = (l, pbar, dh, s)
        assert level["regime"] == model.regime, point
        regimes.add(model.regime)
        assert level["resolved"] and surface["series"]["valid"].all() == model.valid, point
        if model.regime == "delayed":
            worst_t = max(worst_t, abs(level["t_star"] / model.t_star - 1))
            assert level["t_star"] == pytest.approx(model.t_star, rel=1e-6), point
        area = np.max(np.abs(surface["series"]["area_fraction"] / model.series["area_fraction"] - 1))
        worst_area = max(worst_area, area)
        assert area < 5e-4, point
        for mine, theirs in (("load_0", "P1"), ("load_1", "P2")):
            difference = np.max(np.abs(surface["series"][mine] - model.series[theirs])) / (pbar * l * l)
            worst_load = max(worst_load, difference)
            assert difference < 1e-4, (point, mine)
    assert regimes == {"immediate", "delayed", "never"}
    print(f"worst t* {worst_t:.1e}, area fraction {worst_area:.1e}, load {worst_load:.1e} of pbar l^2")


def test_two_level_square_cell_curve_is_the_periodic_model_at_random_points():
    """The cell's own boundary elements (--curve cell) against the tables: random points,
    log-uniform in pbar (1e-4 to 1e-1) and l (0.3 to 3 R), dh between the gaps h(0) and
    h(inf) so that level 1 touches late (delayed): the curve on --grid auto (the smallest
    spot after t = 0 13 node spacings across its radius) gives the regime, t* to 3e-3 and the
    area fraction at every time it resolves to 2% and each level's load to 3e-4 of pbar l^2
    (measured on these 5 points: t* within 1.3e-4, areas within 1.1%, loads within 1.2e-4;
    the model's own tables hold radii to about 1e-3). The glassy spot at t = 0 does not size
    the grid: a snapshot whose area the grid leaves uncertain is flagged below_resolution."""
    rng = np.random.default_rng(38)
    worst_t, worst_area, worst_load = 0.0, 0.0, 0.0
    for _ in range(5):
        l = 10 ** rng.uniform(np.log10(0.3), np.log10(3.0))
        pbar = 10 ** rng.uniform(-4, -1)
        gaps = punchsweep.point(l=l, dh=1e-9, T=2.5, pbar=pbar, s=2, times=[0])
        dh = gaps.h_0 + (gaps.h_inf - gaps.h_0) * rng.uniform(0.1, 0.9)
        model = punchsweep.point(l=l, dh=dh, T=2.5, pbar=pbar, s=2, times=TIMES)
        surface = punchsweep.surface(l=l, dh=dh, T=2.5, pbar=pbar, s=2, times=TIMES, curve="cell")
        assert surface["curve"]["source"] == "cell"
        level = surface["levels"][1]
        assert level["regime"] == model.regime == "delayed", (l, pbar, dh)
        assert level["resolved"]
        valid = surface["series"]["valid"]
        assert valid.sum() >= 4 and set(np.asarray(surface["series"]["reason"])[~valid]) <= {"below_resolution"}
        worst_t = max(worst_t, abs(level["t_star"] / model.t_star - 1))
        areas = surface["series"]["area_fraction"][valid]
        worst_area = max(worst_area, np.max(np.abs(areas / model.series["area_fraction"][valid] - 1)))
        assert level["t_star"] == pytest.approx(model.t_star, rel=3e-3), (l, pbar, dh)
        np.testing.assert_allclose(areas, model.series["area_fraction"][valid], rtol=2e-2)
        nominal = pbar * l * l
        for mine, theirs in (("load_0", "P1"), ("load_1", "P2")):
            difference = np.max(np.abs(surface["series"][mine][valid] - model.series[theirs][valid])) / nominal
            worst_load = max(worst_load, difference)
            assert difference < 3e-4, (l, pbar, dh, mine)
    print(f"worst t* {worst_t:.1e}, area fraction {worst_area:.1e}, load {worst_load:.1e} of pbar l^2")


def test_levels_touch_in_order_and_the_sites_count():
    """Three levels on the hexagonal lattice: level 1 (the upward triangles' centres) before
    level 2 (the downward ones, deeper); the share of sites touched steps at each t* (2 of 6
    sites are the tallest, 2 more per level); areas never shrink; units stated."""
    out = punchsweep.surface(lattice="hexagonal", l=1.2, dh=0.05, dh2=0.08, T=2.5, pbar=0.02, s=2,
                             times=np.linspace(0, 20, 41), grid=48)
    first, second = out["levels"][1], out["levels"][2]
    assert first["regime"] == "immediate" and second["regime"] == "delayed"
    assert first["X_star"] < second["X_star"]
    assert [lv["sites"] for lv in out["levels"]] == [2, 2, 2]
    series = out["series"]
    expected = np.where(series["t"] >= second["t_star"], 1.0, 4 / 6)
    np.testing.assert_array_equal(series["sites_touched"], expected)
    assert np.all(np.diff(series["area_fraction"]) >= 0)
    assert np.all(series["area_2"][series["t"] < second["t_star"]] == 0)
    assert out["units"]["t"] == "T_eps" and out["units"]["area"] == "R^2"


def test_the_command_prints_what_python_returns_and_refuses_bad_input():
    args = ["--l", "0.75", "--dh", "0.03", "--T", "2.5", "--pbar", "0.01", "--s", "2", "--grid", "64"]
    run = cli(*args, "--format", "json")
    assert run.returncode == 0, run.stderr
    printed = json.loads(run.stdout)
    returned = punchsweep.surface(l=0.75, dh=0.03, T=2.5, pbar=0.01, s=2, grid=64)
    # Typed (a SurfaceLevel each), and each equal to the JSON's level by its keys.
    assert all(isinstance(level, punchsweep.SurfaceLevel) for level in returned.levels)
    assert printed["levels"] == returned["levels"]
    # The same code, and FFTW's plans its estimate's: the same bits.
    np.testing.assert_array_equal(printed["series"]["area_fraction"], returned["series"]["area_fraction"])
    table = cli(*args)
    assert table.returncode == 0 and "level 1: delayed at t* = " in table.stdout
    for bad, message in [(["--grid", "5"], "--grid = 5 is outside its range"),
                         (["--lattice", "tri"], "--lattice"),
                         (["--dh2", "-1"], "--dh2 = -1 is outside its range"),
                         (["--curve", "bem"], "--curve"),
                         (["--curve", "tables", "--grid", "64"], "--grid beside --curve tables"),
                         (["--curve", "tables", "--lattice", "hexagonal"], "--curve tables: the periodic model's tables")]:
        run = cli(*args[:-2], *bad)
        assert run.returncode == 2 and message in run.stderr and run.stdout == "", (bad, run.stderr)
    with pytest.raises(ValueError, match="--grid"):
        punchsweep.surface(l=0.75, dh=0.03, T=2.5, pbar=0.01, s=2, grid=7)
    # Past the tables' top (0.99 of where level 1 hides, C (l/sqrt 2)^s = 0.140625 R here).
    run = cli("--l", "0.75", "--dh", "0.14", "--T", "2.5", "--pbar", "0.01", "--s", "2", "--curve", "tables")
    assert run.returncode == 2 and "dh <= 0.139219 R (their top), or dh >= 0.140625 R" in run.stderr, run.stderr


def test_a_scattered_supercell_counts_its_caps_and_repeats_with_its_seed():
    """--supercell 3 --scatter normal:0.01 (R): 18 caps; the share in contact moves in steps
    of 1/18 and never falls; the same seed gives the same caps, another seed others; the
    curve's per-cap touchdowns are checked against time stepping in the C++ tests
    (tests/tables/cell_stepping_surface_test.cpp)."""
    common = dict(l=0.75, dh=0.03, T=4, pbar=0.004, s=2, supercell=3, grid=16, times=[0, 0.5, 1, 2, 5, 20])
    first = punchsweep.surface(scatter="normal:0.01", seed=3, **common)
    assert first["caps"] == 18 and first["supercell"] == 3 and first["grid"] == [48, 48]
    touched = first["series"]["sites_touched"] * 18
    np.testing.assert_allclose(touched, np.round(touched), atol=1e-9)
    assert np.all(np.diff(touched) >= 0) and touched[0] < touched[-1]
    again = punchsweep.surface(scatter="normal:0.01", seed=3, **common)
    np.testing.assert_array_equal(again["series"]["sites_touched"], first["series"]["sites_touched"])
    other = punchsweep.surface(scatter="normal:0.01", seed=4, **common)
    assert [lv["drop_max"] for lv in other["levels"]] != [lv["drop_max"] for lv in first["levels"]]
    base = ["--l", "0.75", "--dh", "0.03", "--T", "4", "--pbar", "0.004", "--s", "2", "--grid", "16"]
    for bad, message in [(["--scatter", "normal:0.01"], "--scatter needs --supercell"),
                         (["--supercell", "2", "--scatter", "gauss:0.01"], "is not one of: normal:SD"),
                         (["--supercell", "2", "--scatter", "normal:-0.01"], "is outside its range"),
                         (["--supercell", "2", "--scatter", "list:0.1,0.2"], "it needs one per cap, 8 for 2 x 2"),
                         (["--supercell", "2", "--scatter", "normal:1um"], "needs R"),
                         (["--supercell", "40"], "--supercell = 40 is outside its range")]:
        run = cli(*base, *bad)
        assert run.returncode == 2 and message in run.stderr and run.stdout == "", (bad, run.stderr)


def write_cell(tmp_path, lines: list[str]) -> Path:
    path = tmp_path / "cell.ini"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_cell_file_is_the_lattice_it_writes_out(tmp_path):
    """The hexagonal three-level lattice written as a cell file (its six sites by hand, from
    the geometry: the triangles' centres at l/sqrt(3) from three tallest sites) gives what
    --lattice hexagonal --dh2 gives on the same grid; lengths with units and --R read as R."""
    l = 1.2
    H = l * 3 ** 0.5
    R_um = 50.0
    um = lambda x: f"{x * R_um:.12g}um"  # noqa: E731
    cell = write_cell(tmp_path, [
        "[cell]", f"Lx = {um(l)}", f"Ly = {um(H)}", "s = 2", "C = 0.5",
        "site = 0, 0, 0, 0", f"site = {um(l / 2)}, {um(H / 2)}, 0, 0",
        f"site = {um(l / 2)}, {um(H / 6)}, {um(0.06)}, 1", f"site = 0, {um(4 * H / 6)}, {um(0.06)}, 1",
        f"site = 0, {um(2 * H / 6)}, {um(0.09)}, 2", f"site = {um(l / 2)}, {um(5 * H / 6)}, {um(0.09)}, 2"])
    common = dict(T=3, pbar=0.015, grid=48, times=[0, 1, 2, 5, 20])
    from_file = punchsweep.surface(cell=str(cell), R=f"{R_um}um", **common)
    lattice = punchsweep.surface(lattice="hexagonal", l=l, dh=0.06, dh2=0.09, s=2, **common)
    assert from_file["lattice"] == "cell" and from_file["grid"] == lattice["grid"] == [48, 84]
    assert from_file["notes"] == []  # every tip on a node: nothing moved
    for a, b in zip(from_file["levels"], lattice["levels"]):
        assert a["regime"] == b["regime"] and a["t_star"] == pytest.approx(b["t_star"], rel=1e-9)
    for key in ("area_fraction", "area_1", "area_2", "load_2", "sites_touched"):
        np.testing.assert_allclose(from_file["series"][key], lattice["series"][key], rtol=1e-9, atol=1e-15)


def test_a_bad_cell_file_is_refused_by_line_and_key(tmp_path):
    base = ["--T", "3", "--pbar", "0.01", "--grid", "16"]
    good = ["[cell]", "Lx = 1", "Ly = 1", "site = 0, 0, 0, 0", "site = 0.5, 0.5, 0.02, 1"]
    cases = [
        (good[:3] + ["site = 0, 0, 0"] + good[4:], ":4: site = 0, 0, 0: give x, y, drop, level"),
        (good + ["height = 2"], ":6: unknown key 'height'; valid: Lx, Ly, s, C, site"),
        (["[cell]", "Ly = 1", "site = 0, 0, 0, 0"], "missing key Lx"),
        (good[:4] + ["site = 1.5, 0.5, 0.02, 1"], "site 1: (1.5, 0.5) R is outside the cell"),
        (good[:3] + ["site = 0, 0, 0.01, 0", "site = 0.5, 0.5, 0.02, 1"], "the least drop is 0.01"),
        (good[:3] + ["site = 0, 0, 0, 0", "site = 0.5um, 0.5, 0.02, 1"], "needs R"),
        (["Lx = 1"] + good, ":1: 'Lx = 1' comes before [cell]"),
    ]
    for lines, message in cases:
        path = write_cell(tmp_path, lines)
        run = cli("--cell", path, *base)
        assert run.returncode == 2 and message in run.stderr and run.stdout == "", (lines, run.stderr)
    run = cli("--cell", write_cell(tmp_path, good), "--l", "1", *base)
    assert run.returncode == 2 and "--l beside --cell" in run.stderr
    run = cli("--cell", write_cell(tmp_path, good), *base)
    assert run.returncode == 0, run.stderr


def test_the_curve_is_kept_in_the_table_cache_and_a_damaged_one_is_built_again(tmp_path):
    """One curve per geometry and grid, to full contact: a second run with another material
    and pressure reads it (the same bits as building it), and a file edited in the cache is
    not believed (its signature fails) but built again."""
    env = {**os.environ, "PUNCHSWEEP_CACHE": str(tmp_path / "cache")}
    geometry = ["--lattice", "hexagonal", "--l", "1.2", "--dh", "0.05", "--s", "2", "--grid", "32", "--format", "json"]

    def run(*load):
        done = subprocess.run([BINARY, "surface", *geometry, *load], capture_output=True, text=True, env=env)
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout)

    first = run("--T", "2.5", "--pbar", "0.02")
    assert first["curve"]["cached"] is False
    files = list((tmp_path / "cache").glob("load-curve-*.tables"))
    assert len(files) == 1
    other_load = run("--T", "6", "--pbar", "0.005", "--times", "0,3,30")
    assert other_load["curve"]["cached"] is True
    again = run("--T", "2.5", "--pbar", "0.02")
    assert again["curve"]["cached"] is True
    assert again["levels"] == first["levels"] and again["series"] == first["series"]
    data = bytearray(files[0].read_bytes())
    data[200] ^= 1
    files[0].write_bytes(bytes(data))
    rebuilt = run("--T", "2.5", "--pbar", "0.02")
    assert rebuilt["curve"]["cached"] is False
    assert rebuilt["levels"] == first["levels"] and rebuilt["series"] == first["series"]


def test_the_curve_stops_past_the_most_the_load_reaches(tmp_path):
    """The curve is read no further than X(inf), the most the load reaches (pbar T for the
    standard linear solid in E0*, the model's J(inf) = T J(0)): it stops at its first sample
    past it and answers as the whole curve (--full-curve) does, every t*, regime and
    snapshot equal to the last bit, level 1's X* equal, while level 2, untouched by then,
    never touches with X* null (the whole curve's lies past X(inf)). A whole curve in the
    cache serves the shorter question, cut to it (the same answer as building it), and a
    question that reaches further than a saved curve continues it from where it stopped (the
    same answer as building it for that question at once; its dry run says so)."""
    env = {**os.environ, "PUNCHSWEEP_CACHE": str(tmp_path / "cache")}
    geometry = ["--lattice", "hexagonal", "--l", "1.2", "--dh", "0.03", "--dh2", "0.08", "--s", "2", "--grid", "48",
                "--times", "0,1,5", "--format", "json"]

    def run(*more, cache="off"):
        done = subprocess.run([BINARY, "surface", *geometry, *map(str, more)], capture_output=True, text=True,
                              env={**env, "PUNCHSWEEP_CACHE": cache} if cache == "off" else env)
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout)

    pbar, T = 0.005, 2.5
    short, whole = run("--pbar", pbar, "--T", T), run("--pbar", pbar, "--T", T, "--full-curve")
    assert short["curve"]["X_reach"] == pytest.approx(pbar * T, rel=1e-12)
    assert whole["curve"]["X_reach"] is None and whole["curve"]["X_full"] is not None
    assert short["curve"]["X_full"] is None
    assert pbar * T <= short["curve"]["X_last"] < pbar * T * 10 ** 0.25
    assert short["curve"]["samples"] < 0.6 * whole["curve"]["samples"]
    assert short["series"] == whole["series"]
    for mine, full in zip(short["levels"], whole["levels"]):
        assert (mine["regime"], mine["t_star"]) == (full["regime"], full["t_star"])
    assert short["levels"][1]["regime"] == "delayed" and short["levels"][1]["X_star"] == whole["levels"][1]["X_star"]
    assert short["levels"][2]["regime"] == "never" and short["levels"][2]["X_star"] is None
    assert whole["levels"][2]["X_star"] > pbar * T
    table = subprocess.run([BINARY, "surface", *geometry[:-2], "--pbar", str(pbar), "--T", str(T)], capture_output=True,
                           text=True, env={**env, "PUNCHSWEEP_CACHE": "off"})
    assert "level 2: never (untouched up to X = " in table.stdout and "the most the load reaches" in table.stdout

    # The cache: the whole curve saved, then the short question reads it cut.
    assert run("--pbar", pbar, "--T", T, "--full-curve", cache="mine")["curve"]["cached"] is False
    cut = run("--pbar", pbar, "--T", T, cache="mine")
    assert cut["curve"]["cached"] is True
    assert cut["curve"]["samples"] == short["curve"]["samples"] and cut["curve"]["X_last"] == short["curve"]["X_last"]
    assert cut["levels"] == short["levels"] and cut["series"] == short["series"]
    # A fresh cache: the short curve saved, then a question reaching further continues it
    # from where it stopped: the answer of a curve built for it at once, to the bit.
    env["PUNCHSWEEP_CACHE"] = str(tmp_path / "other")
    saved = run("--pbar", pbar, "--T", T, cache="mine")
    assert saved["curve"]["cached"] is False
    # The dry run says so: the further question's curve is in the cache to where the short
    # one stopped, and continued from there; the short question's is read.
    dry = [subprocess.run([BINARY, "surface", *geometry[:-2], "--pbar", str(p), "--T", str(T), "--dry-run"],
                          capture_output=True, text=True, env=env) for p in (4 * pbar, pbar)]
    assert all(done.returncode == 0 for done in dry), [done.stderr for done in dry]
    X_saved = re.search(r"in the cache to X = (\S+) E0\*, continued from there, at most about \S+ s on one core",
                        dry[0].stdout)
    assert X_saved, dry[0].stdout
    assert float(X_saved.group(1)) == pytest.approx(saved["curve"]["X_last"], rel=1e-2)  # (printed to 3 digits)
    assert "in the cache (read, not built)" in dry[1].stdout
    further = run("--pbar", 4 * pbar, "--T", T, cache="mine")
    assert further["curve"]["cached"] is False and further["curve"]["X_reach"] == pytest.approx(4 * pbar * T, rel=1e-12)
    at_once = run("--pbar", 4 * pbar, "--T", T)
    assert further["levels"] == at_once["levels"] and further["series"] == at_once["series"]
    assert further["curve"]["samples"] == at_once["curve"]["samples"]
    assert run("--pbar", pbar, "--T", T, cache="mine")["curve"]["cached"] is True


def test_physical_units_where_R_and_a_material_give_them():
    """--R and a material: the JSON's "physical" gives X in Pa, areas in R's unit squared,
    loads in N and drops in R's unit, each the scaled value times its scale (E0* from the
    material, 20 kPa / pbar); the loads add up to the pressure times the cell's area."""
    truth = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    out = punchsweep.surface(material=str(truth), R="80um", l="250um", dh="3um", s=2, pressure="20kPa",
                             temperature=23, times="0, 1s, 1min", grid=32)
    physical = out["physical"]
    assert physical["units"] == {"X": "Pa", "area": "um^2", "load": "N", "drop": "um", "cell": "um", "contact_radius": "um"}
    assert physical["cell"] == pytest.approx([250.0, 250.0], rel=1e-12)
    assert physical["levels"][1]["drop"] == pytest.approx(3.0, rel=1e-12)
    E0_star = 20e3 / out["series"]["X"][0]  # X(0+) = pbar for a step, pbar = 20 kPa / E0*
    np.testing.assert_allclose(physical["series"]["X"], out["series"]["X"] * E0_star, rtol=1e-12)
    np.testing.assert_allclose(physical["series"]["area_1"], out["series"]["area_1"] * 80.0 ** 2, rtol=1e-12)
    total = physical["series"]["load_0"] + physical["series"]["load_1"]
    np.testing.assert_allclose(total, 20e3 * (250e-6) ** 2, rtol=1e-9)
    assert "physical" not in punchsweep.surface(l=0.75, dh=0.03, T=2.5, pbar=0.01, s=2, grid=16)


def test_check_steps_the_same_cell_in_time():
    """--check: the time stepping of the same cell and grid beside the curve's answers; they
    agree to the stepping's t* resolution (1e-3 of the law's shortest time) and areas to 1%
    (tests/tables/cell_stepping_surface_test.cpp holds the finer comparison)."""
    out = punchsweep.surface(lattice="hexagonal", l=1.2, dh=0.06, dh2=0.09, T=4, pbar=0.015, s=2,
                             times=[0, 1, 2, 5, 8], grid=48, check=True)
    check = out["check"]
    assert check["converged"]
    # Its touches are the middles of halved steps 1e-3 T_eps wide (the standard linear
    # solid's shortest time is T_eps): within 5e-4 of its own converged t*.
    assert check["t_star_resolution"] == pytest.approx(1e-3, rel=1e-12)
    for mine, stepped in zip(out["levels"], check["levels"]):
        assert mine["regime"] == stepped["regime"]
        assert mine["t_star"] == pytest.approx(stepped["t_star"], abs=0.5 * check["t_star_resolution"] + 2e-4 * stepped["t_star"])
    np.testing.assert_allclose(out["series"]["area_fraction"], check["series"]["area_fraction"], rtol=1e-2)
    np.testing.assert_array_equal(out["series"]["sites_touched"], check["series"]["sites_touched"])
    assert "check" not in punchsweep.surface(l=0.75, dh=0.03, T=2.5, pbar=0.01, s=2, grid=16)



def test_a_measured_map_of_the_lattice_is_the_lattice(tmp_path):
    """A height map of the paper's lattice (64 x 64 pixels, as .npy in R and as CSV in um with
    --R) finds its two summits, and with --level-gap between their depths gives the lattice's
    answers on the same grid: t* and the areas at every time to 1e-9."""
    l, n, dh = 0.75, 64, 0.03
    z = lattice_heights(l, n, dh)
    np.save(tmp_path / "map.npy", z)
    np.savetxt(tmp_path / "map.csv", z * 80.0, delimiter=",")
    common = dict(T=2.5, pbar=0.01, times=[0, 1, 2, 5, 20])
    lattice = punchsweep.surface(l=l, dh=dh, s=2, grid=n, **common)
    from_npy = punchsweep.surface(height_map=str(tmp_path / "map.npy"), pixel=l / n, level_gap=dh / 2, **common)
    from_csv = punchsweep.surface(height_map=str(tmp_path / "map.csv"), R="80um", height_unit="um",
                                  pixel=f"{l / n * 80}um", level_gap="1.2um", **common)
    for measured in (from_npy, from_csv):
        assert measured["lattice"] == "height map" and measured["caps"] == 2 and measured["grid"] == [n, n]
        assert [lv["drop"] for lv in measured["levels"]] == pytest.approx([0.0, dh], abs=1e-12)
        assert measured["levels"][1]["regime"] == lattice["levels"][1]["regime"] == "delayed"
        assert measured["levels"][1]["t_star"] == pytest.approx(lattice["levels"][1]["t_star"], rel=1e-9)
        for key in ("area_fraction", "area_0", "area_1", "sites_touched"):
            np.testing.assert_allclose(measured["series"][key], lattice["series"][key], rtol=1e-9, atol=1e-15)
    one_level = punchsweep.surface(height_map=str(tmp_path / "map.npy"), pixel=l / n, **common)
    assert len(one_level["levels"]) == 1 and one_level["caps"] == 2  # no --level-gap: one level of caps


def write_surface_topography_nc(path, heights_xy, lengths=None, unit=None, periodic=1, version=2):
    """A map as SurfaceTopography's Topography.to_netcdf writes it (its NC.py: scipy's
    netcdf_file, NetCDF-3 64-bit offset by default; heights(x, y), the first index along x;
    x and y with length, periodic and length_unit), by Debian's scipy."""
    from scipy.io import netcdf_file
    nx, ny = heights_xy.shape
    with netcdf_file(path, "w", version=version) as nc:
        nc.createDimension("x", nx)
        nc.createDimension("y", ny)
        if lengths is not None:
            for name, count, length in (("x", nx, lengths[0]), ("y", ny, lengths[1])):
                v = nc.createVariable(name, "f8", (name,))
                v.length = length
                v.periodic = periodic
                if unit is not None:
                    v.length_unit = unit
                v[...] = (np.arange(count) + 0.5) * length / count
        nc.createVariable("heights", "f8", ("x", "y"))[...] = heights_xy


def test_a_surface_topography_netcdf_map_is_read_as_its_npy(tmp_path):
    """SurfaceTopography's NetCDF container (what Topography.to_netcdf writes): two cells of
    the paper's lattice along x (128 x 64 pixels, so that x and y cannot be swapped), in um
    with its lengths stated, gives the .npy map's answers on the same grid to 1e-12 with no
    --pixel or --height-unit (the file's), as NetCDF-3 (64-bit offset) and NetCDF-4; a
    classic NetCDF-3 file without lengths needs --pixel; a map marked non-periodic is read
    with a note."""
    l, n, dh = 0.75, 64, 0.03
    z = np.tile(lattice_heights(l, n, dh), (1, 2))  # rows along y: 64 x 128
    np.save(tmp_path / "map.npy", z)
    write_surface_topography_nc(tmp_path / "map.nc", z.T * 80.0, lengths=(2 * l * 80.0, l * 80.0), unit="um")
    write_surface_topography_nc(tmp_path / "bare.nc", z.T, version=1)
    write_surface_topography_nc(tmp_path / "open.nc", z.T, lengths=(2 * l, l), periodic=0)
    common = dict(T=2.5, pbar=0.01, times=[0, 1, 2, 5, 20], level_gap=dh / 2)
    from_npy = punchsweep.surface(height_map=str(tmp_path / "map.npy"), pixel=l / n, **common)
    from_nc = punchsweep.surface(height_map=str(tmp_path / "map.nc"), R="80um", **dict(common, level_gap="1.2um"))
    bare = punchsweep.surface(height_map=str(tmp_path / "bare.nc"), pixel=l / n, **common)
    open_map = punchsweep.surface(height_map=str(tmp_path / "open.nc"), **common)
    assert from_npy["caps"] == 4 and from_npy["cell"] == pytest.approx([2 * l, l], rel=1e-12)
    for measured in (from_nc, bare, open_map):
        assert measured["caps"] == 4 and measured["grid"] == [2 * n, n]
        assert measured["cell"] == pytest.approx([2 * l, l], rel=1e-12)
        assert measured["levels"][1]["t_star"] == pytest.approx(from_npy["levels"][1]["t_star"], rel=1e-12)
        for key in ("area_fraction", "area_0", "area_1", "sites_touched"):
            np.testing.assert_allclose(measured["series"][key], from_npy["series"][key], rtol=1e-12, atol=1e-15)
    assert any("not periodic" in note for note in open_map["notes"])
    assert not any("not periodic" in note for note in from_nc["notes"])
    with pytest.raises(ValueError, match="needs --pixel"):
        punchsweep.surface(height_map=str(tmp_path / "bare.nc"), **common)
    with pytest.raises(ValueError, match="lengths and heights are in um: give --R"):
        punchsweep.surface(height_map=str(tmp_path / "map.nc"), **common)
    write_surface_topography_nc(tmp_path / "oblong.nc", z.T, lengths=(2 * l, 1.1 * l))
    with pytest.raises(ValueError, match="the boundary elements need square pixels"):
        punchsweep.surface(height_map=str(tmp_path / "oblong.nc"), **common)
    # NetCDF-4 (what SurfaceTopography's parallel writer makes), by h5netcdf: the same map.
    import xarray
    axes = {name: (name, np.arange(count) * 1.0, {"length": length * 80.0, "periodic": 1, "length_unit": "um"})
            for name, count, length in (("x", 2 * n, 2 * l), ("y", n, l))}
    xarray.Dataset({"heights": (("x", "y"), z.T * 80.0)}, coords=axes).to_netcdf(tmp_path / "four.nc", engine="h5netcdf")
    four = punchsweep.surface(height_map=str(tmp_path / "four.nc"), R="80um", **dict(common, level_gap="1.2um"))
    assert four["caps"] == 4 and four["grid"] == [2 * n, n]
    assert four["levels"][1]["t_star"] == pytest.approx(from_npy["levels"][1]["t_star"], rel=1e-12)
    np.testing.assert_allclose(four["series"]["area_fraction"], from_npy["series"]["area_fraction"], rtol=1e-12)
    xarray.Dataset({"z": (("x", "y"), z.T)}).to_netcdf(tmp_path / "other4.nc", engine="h5netcdf")
    with pytest.raises(ValueError, match="no variable 'heights'"):
        punchsweep.surface(height_map=str(tmp_path / "other4.nc"), pixel=l / n, **common)
    from scipy.io import netcdf_file
    with netcdf_file(tmp_path / "other.nc", "w") as nc:
        nc.createDimension("x", 4)
        nc.createVariable("z", "f8", ("x",))[...] = np.zeros(4)
    with pytest.raises(ValueError, match="no variable 'heights'"):
        punchsweep.surface(height_map=str(tmp_path / "other.nc"), pixel=l / n, **common)


def test_a_bad_height_map_is_refused(tmp_path):
    z = lattice_heights(0.75, 16, 0.03)
    np.savetxt(tmp_path / "odd.csv", z[:, :15], delimiter=",")
    (tmp_path / "ragged.csv").write_text("1,2,3,4\n1,2,3\n1,2,3,4\n1,2,3,4\n")
    np.save(tmp_path / "big.npy", z.astype(">f8"))
    np.save(tmp_path / "good.npy", z)
    base = ["--T", "2.5", "--pbar", "0.01", "--pixel", "0.05"]
    for args, message in [(["--height-map", tmp_path / "odd.csv"], "15 x 16 pixels; the boundary elements need an even count"),
                          (["--height-map", tmp_path / "ragged.csv"], ":2: 3 values; the first row has 4"),
                          (["--height-map", tmp_path / "big.npy"], "valid: little-endian float64 or float32"),
                          (["--height-map", tmp_path / "good.npy", "--grid", "32"], "--grid beside --height-map"),
                          (["--height-map", tmp_path / "good.npy", "--l", "1"], "--l beside --height-map"),
                          (["--height-map", tmp_path / "missing.npy"], "no regular file")]:
        run = cli(*args, *base)
        assert run.returncode == 2 and message in run.stderr and run.stdout == "", (args, run.stderr)
    run = cli("--height-map", tmp_path / "good.npy", "--T", "2.5", "--pbar", "0.01")
    assert run.returncode == 2 and "--height-map needs --pixel" in run.stderr


def test_surface_classify_reads_many_loads_off_one_curve():
    """A creep ratio x pressure grid of 2,500 points off one hexagonal three-level curve: at
    random points of it, each level's regime and t* equal surface()'s for that point alone
    (the same curve, the same classification: the same bits); every regime appears; the
    arrays keep the broadcast shape with a last axis of levels."""
    texture = dict(lattice="hexagonal", l=1.2, dh=0.06, dh2=0.09, s=2, grid=48)
    T = np.linspace(1.5, 10, 50)[:, None]
    pbar = np.geomspace(1e-3, 0.05, 50)[None, :]
    out = punchsweep.surface_classify(pbar=pbar, T=T, **texture)
    assert out["t_star"].shape == out["regime"].shape == (50, 50, 3)
    names = {punchsweep.REGIMES[int(code)] for code in np.unique(out["regime"][..., 1:])}
    assert names == {"immediate", "delayed", "never"}
    rng = np.random.default_rng(5)
    for i, j in rng.integers(0, 50, size=(6, 2)):
        alone = punchsweep.surface(T=float(T[i, 0]), pbar=float(pbar[0, j]), times=[0], **texture)
        for level, expected in enumerate(alone["levels"]):
            assert punchsweep.REGIMES[int(out["regime"][i, j, level])] == expected["regime"]
            t = out["t_star"][i, j, level]
            assert (expected["t_star"] is None and np.isinf(t)) or t == expected["t_star"]
    with pytest.raises(ValueError, match="pbar = -1"):
        punchsweep.surface_classify(pbar=[0.01, -1.0], T=2.5, **texture)


def test_classify_of_a_texture_reads_a_curve_per_geometry():
    """classify with a texture keyword is one batch call over geometries and loads: l (3
    pitches) x dh (2 drops) x pbar (4) broadcast, six curves; at every point each level's
    t*, regime, X_star, resolved and grid equal surface_classify's for that geometry alone
    (the same curve, the same reading: the same bits). In physical units (pitches and drops
    with a unit beside R=, pressures in kPa under a material) likewise. The model's own
    arguments (quantities=, localization=) are refused beside a texture, naming it."""
    texture = dict(lattice="hexagonal", dh2=0.09, s=2, grid=32)
    l = np.array([1.0, 1.2, 1.5])[:, None, None]
    dh = np.array([0.03, 0.05])[None, :, None]
    pbar = np.geomspace(2e-3, 0.04, 4)[None, None, :]
    out = punchsweep.classify(l, dh, T=2.5, pbar=pbar, **texture)
    assert isinstance(out, punchsweep.TextureClassification)
    assert out.t_star.shape == out.regime.shape == out.X_star.shape == (3, 2, 4, 3) and out.grid.shape == (3, 2, 4, 2)
    assert out.levels == 3 and out.caps == 6
    for i in range(3):
        for j in range(2):
            alone = punchsweep.surface_classify(pbar=pbar[0, 0], T=2.5, l=float(l[i, 0, 0]), dh=float(dh[0, j, 0]),
                                                **texture)
            np.testing.assert_array_equal(out.t_star[i, j], alone.t_star)
            np.testing.assert_array_equal(out.regime[i, j], alone.regime)
            for k in range(4):
                np.testing.assert_array_equal(out.X_star[i, j, k], alone.X_star)
                np.testing.assert_array_equal(out.resolved[i, j, k], alone.resolved)
                assert tuple(out.grid[i, j, k]) == alone.grid
    names = {punchsweep.REGIMES[int(code)] for code in np.unique(out.regime[..., 1:])}
    assert len(names) >= 2
    physical = dict(material=str(TRUTH), R="60um", temperature=20, lattice="hexagonal", dh2="5um", s=2, grid=32)
    pressure = ["5kPa", "20kPa"]
    out = punchsweep.classify([["200um"], ["250um"]], "2um", pressure=pressure, **physical)
    assert out.t_star.shape == (2, 2, 3) and out.X_star.shape == (2, 2, 3)
    for i, pitch in enumerate(["200um", "250um"]):
        alone = punchsweep.surface_classify(pressure=pressure, l=pitch, dh="2um", **physical)
        np.testing.assert_array_equal(out.t_star[i], alone.t_star)
        np.testing.assert_array_equal(out.X_star[i, 0], alone.X_star)
    with pytest.raises(ValueError, match="quantities= and localization= are the paper's lattice's.*lattice="):
        punchsweep.classify(1.2, 0.03, T=2.5, pbar=0.01, quantities=["t_star"], **texture)


def test_surface_classify_and_maps_read_the_curve_as_far_as_their_loads_reach(tmp_path):
    """surface_classify's curve reaches the largest X(inf) of its points (pbar T for the
    standard linear solid): a level that none of them reaches reads X_star +inf and never at
    every point, one they reach the whole curve's X* (surface --full-curve's, to the bit);
    with no points the whole curve (every X_star finite). A texture map over the same
    points reads the same X_star, so its t_star and regime equal surface_classify's."""
    texture = dict(lattice="hexagonal", l=1.2, dh=0.03, dh2=0.08, s=2, grid=48)
    whole = punchsweep.surface(pbar=0.005, T=2.5, times=[0], full_curve=True, **texture)
    X_whole = [level["X_star"] for level in whole["levels"]]
    assert all(np.isfinite(X_whole))
    pbar = np.array([0.002, 0.005])
    T = np.array([2.0, 2.5])
    assert (pbar[:, None] * T[None, :]).max() < X_whole[2]  # level 2 is out of every point's reach
    out = punchsweep.surface_classify(pbar=pbar[:, None], T=T[None, :], **texture)
    assert list(out["X_star"][:2]) == X_whole[:2] and np.isinf(out["X_star"][2])
    assert {punchsweep.REGIMES[int(code)] for code in out["regime"][..., 2].ravel()} == {"never"}
    assert np.all(np.isinf(out["t_star"][..., 2]))
    empty = punchsweep.surface_classify(pbar=np.array([]), T=2.5, **texture)
    assert list(empty["X_star"]) == X_whole
    ds = punchsweep.surface_map(pbar=pbar, T=T, times=[0, 1], output=tmp_path / "m.nc", **texture)
    np.testing.assert_array_equal(ds.X_star.values.reshape(-1), out["X_star"])
    np.testing.assert_array_equal(ds.t_star.values.reshape(out["t_star"].shape), out["t_star"])
    np.testing.assert_array_equal(ds.regime.values.reshape(out["regime"].shape), out["regime"])


def test_each_levels_t_star_moves_with_the_load_as_the_closed_form_says():
    """The standard linear solid, J(t) = T - (T - 1) exp(-t): a level touching at X* has
    J(t*) = X* / pbar, so d t*/d pbar = -X* / (pbar^2 (T - 1) exp(-t*)) and d t*/dT =
    -(1 - exp(-t*)) / ((T - 1) exp(-t*)). The engine's central differences (Richardson) give
    them to 1e-6; the range over --tolerance "pressure=5%, T=0.2" is t* at the corners (the
    greatest pressure and T touch first)."""
    texture = dict(lattice="hexagonal", l=1.2, dh=0.06, dh2=0.09, s=2, grid=48)
    T, pbar = 4.0, 0.015
    out = punchsweep.surface(T=T, pbar=pbar, times=[0], tolerance="pressure=5%, T=0.2", **texture)
    for level in out["levels"][1:]:
        t, X = level["t_star"], level["X_star"]
        decay = (T - 1) * np.exp(-t)
        assert level["dt_star_dpbar"] == pytest.approx(-X / (pbar ** 2 * decay), rel=1e-6)
        assert level["dt_star_dT"] == pytest.approx(-(1 - np.exp(-t)) / decay, rel=1e-6)
        assert level["dlog_t_star_dlog_pbar"] == pytest.approx(pbar / t * level["dt_star_dpbar"], rel=1e-12)
    corners = {(p, tt): punchsweep.surface(T=tt, pbar=p, times=[0], **texture)["levels"]
               for p in (0.95 * pbar, 1.05 * pbar) for tt in (T - 0.2, T + 0.2)}
    for index, level in enumerate(out["levels"][1:], start=1):
        ts = [np.inf if c[index]["t_star"] is None else c[index]["t_star"] for c in corners.values()]
        assert level["t_star_low"] == min(ts)
        assert (level["t_star_high"] is None and np.isinf(max(ts))) or level["t_star_high"] == max(ts)
    run = cli("--l", "0.75", "--dh", "0.03", "--T", "2.5", "--pbar", "0.01", "--s", "2", "--grid", "16",
              "--tolerance", "dh=0.01")
    assert run.returncode == 2 and "needs a load curve per corner" in run.stderr


def test_the_documented_cell_example_runs():
    """docs/cli.md's example: examples/cells/hexagonal_two_level.ini with --R 80um: 4 caps,
    the shorter ones 3 um (0.0375 R) lower, every tip on a node of the grid."""
    run = cli("--cell", REPO / "examples" / "cells" / "hexagonal_two_level.ini", "--R", "80um", "--T", "3",
              "--pbar", "0.01", "--grid", "32", "--format", "json")
    assert run.returncode == 0, run.stderr
    out = json.loads(run.stdout)
    # (Level 1's touchdown, whose spots are small beside the pitch, is the small-spot limit's;
    # nothing else is noted.)
    assert out["caps"] == 4 and out["lattice"] == "cell"
    assert [note.split(" from ")[0] for note in out["notes"]] == ["level 1: X* = 0.0012825 E0*"]
    assert [lv["drop"] for lv in out["levels"]] == pytest.approx([0.0, 3.0 / 80.0], rel=1e-9)



def test_surface_with_a_ramp_reads_no_load_at_t_0():
    """A ramp starts from no load (X(0) = 0): the JSON's series hold each level's caps
    touched there too (0, none pressed), as the text does, and every series has one value a
    time (a reading without load once left the per-level shares empty and crashed JSON)."""
    out = punchsweep.surface(l=0.75, dh=0.03, s=2, T=2.5, pbar=0.01, ramp=2, times=[0, 1, 5])
    series = out["series"]
    assert series["X"][0] == 0 and series["sites_touched"][0] == 0
    assert series["touched_0"][0] == 0 and series["touched_1"][0] == 0
    assert all(len(v) == 3 for v in series.values())
    assert series["touched_0"][1] == 1 and series["touched_1"][2] == 1  # the tall at once, the short by t = 5

def test_surface_map_has_a_curve_per_geometry_and_reads_the_loads_off_it(tmp_path):
    """dh as a list is a geometry axis (one curve each), pbar and T as lists load axes read
    off each curve: every level's t* and regime equal surface_classify's for that dh alone,
    and at every point and time the share of caps touched and the area fraction equal
    surface()'s for that point alone; units and flag codes on every variable; the file
    (`output`) is the command's netCDF-4 and reads back unchanged."""
    texture = dict(lattice="hexagonal", l=1.2, dh2=0.09, s=2, grid=32)
    pbar = np.geomspace(2e-3, 0.05, 5)
    T = [2.0, 4.0, 8.0]
    times = [0, 1, 5]
    path = tmp_path / "surface_map.nc"
    ds = punchsweep.surface_map(dh=[0.04, 0.06], pbar=pbar, T=T, times=times, output=path, **texture)
    assert ds.t_star.dims == ("dh", "pbar", "T", "level") and ds.t_star.shape == (2, 5, 3, 3)
    assert ds.touched.dims == ("dh", "pbar", "T", "t") and list(ds.t.values) == times
    assert ds.t_star.attrs["units"] == "1" and ds.t_star.attrs["scaled_by"] == "T_eps"
    assert ds.pbar.attrs["scaled_by"] == "E0/(1-nu^2)" and ds.dh.attrs["scaled_by"] == "R"
    assert ds.regime.attrs["flag_meanings"] == "immediate delayed never"
    assert ds.valid.attrs["flag_meanings"] == "valid below_resolution above_top unloading"
    pbar = ds.pbar.values  # as the axis holds them (15 significant digits)
    for k, dh in enumerate([0.04, 0.06]):
        alone = punchsweep.surface_classify(pbar=pbar[:, None], T=np.asarray(T)[None, :], dh=dh, **texture)
        np.testing.assert_array_equal(ds.t_star.values[k], alone["t_star"])
        np.testing.assert_array_equal(ds.regime.values[k], alone["regime"])
        np.testing.assert_array_equal(ds.X_star.values[k], alone["X_star"])
        for i in (0, 2, 4):
            for j in (0, 2):
                one = punchsweep.surface(dh=dh, pbar=float(pbar[i]), T=T[j], times=times, **texture)
                np.testing.assert_array_equal(ds.touched.values[k, i, j], one["series"]["sites_touched"])
                np.testing.assert_array_equal(ds.area_fraction.values[k, i, j], one["series"]["area_fraction"])
                np.testing.assert_array_equal(ds.valid.values[k, i, j] == 0, one["series"]["valid"])
    import xarray
    with xarray.open_dataset(path, engine="h5netcdf") as back:  # every axis, one value or more
        assert back.t_star.dims == ("l", "dh", "dh2", "pbar", "T", "level")
        np.testing.assert_array_equal(back.t_star.squeeze(["l", "dh2"]).values, ds.t_star.values)
        np.testing.assert_array_equal(back.regime.squeeze(["l", "dh2"]).values, ds.regime.values)
    one = punchsweep.surface_map(dh=0.05, pbar=0.01, T=T, **texture)
    assert one.t_star.dims == ("T", "level")
    with pytest.raises(ValueError, match="exists: give --overwrite"):
        punchsweep.surface_map(dh=0.05, pbar=0.01, T=T, output=path, **texture)


def test_surface_map_in_physical_units_from_a_material(tmp_path):
    """pressure= in kPa and temperature= in degC with a material: pbar is the pressure over
    the material's E0* (the map's pressure variable gives it back in Pa), t* in the
    material's time unit, and each point equals surface() at that pressure and temperature."""
    truth = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    ds = punchsweep.surface_map(material=str(truth), R="80um", l="250um", dh=["2um", "3um"], s=2,
                                pressure=["5kPa", "20kPa"], temperature=[20, 40], times="0, 1s")
    assert ds.t_star.dims == ("dh", "pbar", "temperature", "level")
    assert ds.t_star.attrs["units"] == "s" and ds.pressure.attrs["units"] == "Pa"
    np.testing.assert_allclose(ds.pressure.values, [5e3, 2e4], rtol=1e-12)
    np.testing.assert_allclose(ds.dh.values, [2 / 80, 3 / 80], rtol=1e-12)
    one = punchsweep.surface(material=str(truth), R="80um", l="250um", dh="3um", s=2, pressure="20kPa",
                             temperature=40, times="0, 1s")
    assert [x["regime"] for x in one["levels"]] == [punchsweep.REGIMES[int(c)] for c in ds.regime.values[1, 1, 1]]
    t = [np.inf if x["t_star"] is None else x["t_star"] for x in one["levels"]]
    np.testing.assert_allclose(ds.t_star.values[1, 1, 1], t, rtol=1e-12)


def test_surface_map_takes_the_scatter_width_as_an_axis():
    """scatter="normal:0.005, 0.01" on a 3 x 3 supercell: the scatter's width is a geometry
    axis (one curve each, the same seed), and each width's caps in contact at every time
    equal surface()'s with that width alone."""
    common = dict(l=0.75, dh=0.03, s=2, supercell=3, grid=16, T=4, times=[0, 1, 5])
    ds = punchsweep.surface_map(scatter="normal:0.005, 0.01", pbar=[0.004, 0.01], **common)
    assert ds.t_star.dims == ("scatter_width", "pbar", "level") and ds.scatter_width.attrs["scaled_by"] == "R"
    for k, width in enumerate([0.005, 0.01]):
        for i, pbar in enumerate([0.004, 0.01]):
            one = punchsweep.surface(scatter=f"normal:{width}", pbar=pbar, **common)
            np.testing.assert_array_equal(ds.touched.values[k, i], one["series"]["sites_touched"])
            assert [lv["regime"] for lv in one["levels"]] == [punchsweep.REGIMES[int(c)] for c in ds.regime.values[k, i]]


def test_surface_map_takes_the_ramp_time_as_an_axis():
    """ramp=['0s', '2s', '30s'] with a material: the load's rise time is a load axis
    (ramp_time, in the material's time unit, read off the one curve), and each ramp's levels
    (regime, t*) and caps touched at every time equal surface() with that --ramp alone (the
    point command's reading of the ramp, not the map's)."""
    truth = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    common = dict(material=str(truth), R="80um", l="250um", dh="3um", s=2, temperature=30, times="0, 1s, 10s, 100s")
    ramps = ["0s", "2s", "30s"]
    ds = punchsweep.surface_map(pressure=["5kPa", "20kPa"], ramp=ramps, **common)
    assert ds.t_star.dims == ("pbar", "ramp_time", "level") and ds.ramp_time.attrs["units"] == "s"
    np.testing.assert_array_equal(ds.ramp_time.values, [0.0, 2.0, 30.0])
    moved = False
    for i, pressure in enumerate(["5kPa", "20kPa"]):
        for k, ramp in enumerate(ramps):
            one = punchsweep.surface(pressure=pressure, ramp=ramp, **common)  # JSON with a ramp: X(0) = 0
            if ramp != "0s":
                assert one["series"]["X"][0] == 0 and one["series"]["touched_1"][0] == 0
            assert [lv["regime"] for lv in one["levels"]] == [punchsweep.REGIMES[int(c)] for c in ds.regime.values[i, k]]
            t = [np.inf if lv["t_star"] is None else lv["t_star"] for lv in one["levels"]]
            np.testing.assert_allclose(ds.t_star.values[i, k], t, rtol=1e-12)
            np.testing.assert_array_equal(ds.touched.values[i, k], one["series"]["sites_touched"])
            moved = moved or not np.array_equal(ds.t_star.values[i, k], ds.t_star.values[i, 0])
    assert moved, "no ramp moved a touch time: the axis would not be tested"
    with pytest.raises(ValueError, match="--ramp and --load-table both given"):
        punchsweep.surface_map(pressure="5kPa", ramp=ramps, load_table="0 0; 1s 1", **common)


def test_surface_map_reads_a_box_of_tolerances_about_every_point():
    """tolerance="pbar=10%, T=0.2" on the paper's lattice: at every point each level's
    t_star_low and t_star_high are the least and greatest t* of surface_classify at the box's
    four corners (each corner read as an ordinary point, not through the map's range), t*
    lies between them, and regime_low/high are the corners' least and greatest regimes; a
    corner outside T's range (T - 0.2 < 1) leaves the point NaN and not_computed; a tolerance
    on the geometry is refused."""
    texture = dict(l=0.75, dh=0.03, s=2)
    T = [2.5, 4.0, 8.0]
    ds = punchsweep.surface_map(pbar=np.geomspace(1e-3, 0.05, 6), T=T, tolerance="pbar=10%, T=0.2", times=[0, 1],
                                **texture)
    assert ds.t_star_low.dims == ("pbar", "T", "level") and ds.attrs["tolerance"] == "pbar=10%, T=0.2"
    assert ds.t_star_low.attrs["scaled_by"] == "T_eps"
    assert ds.regime_low.attrs["flag_meanings"] == "not_computed immediate delayed never"
    wide = 0
    for i, p in enumerate(ds.pbar.values):
        for j, t in enumerate(T):
            corners = punchsweep.surface_classify(pbar=np.array([p - 0.1 * p, p + 0.1 * p])[:, None],
                                                  T=np.array([t - 0.2, t + 0.2])[None, :], **texture)
            t_star = corners["t_star"].reshape(4, -1)
            regime = corners["regime"].reshape(4, -1)
            np.testing.assert_allclose(ds.t_star_low.values[i, j], t_star.min(axis=0), rtol=1e-12)
            np.testing.assert_allclose(ds.t_star_high.values[i, j], t_star.max(axis=0), rtol=1e-12)
            np.testing.assert_array_equal(ds.regime_low.values[i, j], regime.min(axis=0))
            np.testing.assert_array_equal(ds.regime_high.values[i, j], regime.max(axis=0))
            assert np.all(ds.t_star_low.values[i, j] <= ds.t_star.values[i, j])
            assert np.all(ds.t_star.values[i, j] <= ds.t_star_high.values[i, j])
            wide += int(np.any(ds.t_star_low.values[i, j] < ds.t_star_high.values[i, j]))
    assert wide >= 3, "the box moved t* at too few points for the test to mean anything"
    edge = punchsweep.surface_map(pbar=0.01, T=[1.1, 2.5], tolerance="T=0.2", **texture)
    assert np.isnan(edge.t_star_low.values[0]).all() and (edge.regime_low.values[0] == -1).all()
    assert not np.isnan(edge.t_star_low.values[1]).any()
    with pytest.raises(ValueError, match="'dh' is no load input of a surface map"):
        punchsweep.surface_map(pbar=0.01, T=2.5, tolerance="dh=0.001", **texture)


def test_open_map_reads_a_texture_map_in_physical_units(tmp_path):
    """Issue 49: the one reader opens a texture's map as it opens a regime map: t_star and
    regime over a `level` dimension, the pressure in Pa, lengths in um, X* in Pa, t* in s,
    flags as their meanings (codes kept as NAME_code); values equal to the file's scaled ones
    times the stated scales. A map written before the scales were stated (R as "60um", no
    R_m nor E0_star_Pa) still opens, its lengths in R."""
    import h5py
    truth = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    path = tmp_path / "tpe.nc"
    scaled = punchsweep.surface_map(material=str(truth), R="60um", lattice="hexagonal", l="200um",
                                    dh=["2um", "3um"], dh2="5um", s=2, pressure=["10kPa", "20kPa", "30kPa"],
                                    temperature=[20, 40], times="1s, 1min", grid=32, output=path)
    ds = punchsweep.open_map(path)
    assert ds.t_star.dims == ("l", "dh", "dh2", "pbar", "temperature", "level") and ds.sizes["level"] == 3
    assert (ds.pbar.attrs["units"], ds.dh.attrs["units"], ds.l.attrs["units"], ds.X_star.attrs["units"],
            ds.t_star.attrs["units"]) == ("Pa", "um", "um", "Pa", "s")
    np.testing.assert_allclose(ds.pbar.values, [1e4, 2e4, 3e4], rtol=1e-12)
    np.testing.assert_allclose(ds.dh.values, [2.0, 3.0], rtol=1e-12)
    np.testing.assert_allclose(ds.l.values, [200.0], rtol=1e-12)
    E0_star = float(h5py.File(path)["pressure"][0]) / float(scaled.pbar.values[0])
    np.testing.assert_allclose(ds.X_star.values.squeeze(), scaled.X_star.values * E0_star, rtol=1e-12)
    np.testing.assert_array_equal(ds.t_star.values.squeeze(), scaled.t_star.values)
    assert set(np.unique(ds.regime.values)) <= {"immediate", "delayed", "never"}
    np.testing.assert_array_equal(ds.regime_code.values.squeeze(), scaled.regime.values)
    old = tmp_path / "old.nc"
    old.write_bytes(path.read_bytes())
    with h5py.File(old, "r+") as f:
        f.attrs["R"] = "60um"
        del f.attrs["R_m"], f.attrs["E0_star_Pa"]
    ds = punchsweep.open_map(old)
    assert ds.dh.attrs["units"] == "R" and ds.pbar.attrs["units"] == "E0/(1-nu^2)"
    np.testing.assert_allclose(ds.dh.values, [2 / 60, 3 / 60], rtol=1e-12)


@pytest.mark.parametrize("texture", [
    ["--lattice", "hexagonal", "--l", "1.2", "--dh", "0.01", "--dh2", "0.08", "--supercell", "16", "--grid", "1024"],
    ["--l", "0.75", "--dh", "0.03", "--supercell", "4", "--grid", "2048"],
])
def test_a_grid_beyond_the_budget_names_the_largest_that_fits(texture):
    """A grid beyond what one curve may take (its nodes, nodes x caps, or 80% of this machine's
    memory) is refused before any work (exit 2) with the largest --grid that fits: that one
    passes --dry-run, and the next even one up is refused. (Which budget binds, and so the
    number, depends on the machine's memory: the test holds the claim, not a number.)"""
    common = ["--T", "2.5", "--pbar", "0.02", "--s", "2", "--dry-run"]
    run = cli(*texture, *common)
    assert run.returncode == 2 and run.stdout == "", run.stderr
    found = re.search(r"the largest that fits: --grid (\d+) \((\d+) x (\d+) nodes", run.stderr)
    assert found, run.stderr
    fits = int(found.group(1))
    at = list(texture)
    at[at.index("--grid") + 1] = str(fits)
    assert cli(*at, *common).returncode == 0
    at[at.index("--grid") + 1] = str(fits + 2)
    above = cli(*at, *common)
    assert above.returncode == 2 and "is beyond" in above.stderr and "the largest that fits: --grid " + str(fits) in above.stderr


def test_the_studys_first_run_reads_its_touchdowns_in_the_small_spot_limit():
    """The study's first run (hexagonal, 60 um caps on a 200 um pitch, levels 2 and 5 um down,
    TPE-A at 10 kPa and 20 C, times 0, 1 s, 1 min, 1 h): both levels touch while the tallest
    spots are under a tenth of the pitch, so their touchdowns are the small-spot limit's
    (docs/model.md 17.6), the same on any grid (here 48 nodes a pitch and --grid auto), and
    resolved; the glassy spot at t = 0 does not size the grid (it asked 280 nodes a pitch):
    --grid auto takes at most 176, and that snapshot's area is the limit's too (the tallest
    caps alone in contact: the isolated Hertz caps' within 1e-3, the lattice's field the
    rest). (Measured against the curve on 512 x 882 nodes of the build before: t* within
    6.7e-4 and 8.8e-5, docs/performance.md.)"""
    material = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    args = ["--material", material, "--R", "60um", "--s", "2", "--lattice", "hexagonal", "--l", "200um", "--dh", "2um",
            "--dh2", "5um", "--pressure", "10kPa", "--temperature", "20", "--times", "0, 1s, 1min, 1h", "--format", "json"]
    runs = {}
    for grid in ("auto", "48"):
        run = cli(*args, "--grid", grid)
        assert run.returncode == 0, run.stderr
        runs[grid] = json.loads(run.stdout)
    auto = runs["auto"]
    assert auto["grid"][0] <= 176
    for level in (1, 2):
        mine, coarse = auto["levels"][level], runs["48"]["levels"][level]
        assert mine["touchdown_from"] == coarse["touchdown_from"] == "small_spot_limit"
        assert mine["resolved"] and mine["regime"] == "delayed"
        assert mine["t_star"] == pytest.approx(coarse["t_star"], rel=1e-12) and mine["X_star"] == pytest.approx(coarse["X_star"], rel=1e-12)
        assert any(note.startswith(f"level {level}: X* = ") and "small-spot limit" in note for note in auto["notes"])
    assert auto["series"]["reason"] == ["valid"] * 4
    assert any(note.startswith("areas and loads below X = ") and "from the small-spot limit" in note for note in auto["notes"])
    Lx, Ly = auto["cell"]
    P = auto["series"]["X"][0] * Lx * Ly / 2  # (two tallest caps a cell)
    hertz = 2 * np.pi * (3 * P / 4) ** (2 / 3) / (Lx * Ly)
    assert auto["series"]["area_fraction"][0] == pytest.approx(hertz, rel=1e-3)


def test_a_forked_process_builds_curves_after_the_parent_ran_threads(tmp_path):
    """A large curve's transforms run on OpenMP threads, whose pool does not survive a fork:
    a process forked after them (Python's multiprocessing, fork being Linux's default) must
    still build its curves (on one thread), not wait for the parent's threads for ever. The
    parent builds a 208-node curve on two threads, then a forked pool's worker builds another
    and gives the answer (its area fractions) the parent gives for it."""
    script = tmp_path / "fork.py"
    script.write_text(
        "import json, multiprocessing as mp, punchsweep\n"
        "kw = dict(lattice='hexagonal', l=1.2, s=2, pbar=0.0001, T=1.5, grid=208, times=[0, 1])\n"
        "punchsweep.surface(dh=0.01, **kw)\n"
        "def child(dh):\n"
        "    return [float(v) for v in punchsweep.surface(dh=dh, **kw)['series']['area_fraction']]\n"
        "with mp.get_context('fork').Pool(1) as pool:\n"
        "    forked = pool.map(child, [0.011])[0]\n"
        "print(json.dumps([forked, child(0.011)]))\n")
    env = {**os.environ, "OMP_NUM_THREADS": "2", "PUNCHSWEEP_CACHE": "off"}
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, env=env, timeout=240)
    assert done.returncode == 0, done.stderr
    forked, here = json.loads(done.stdout)
    assert forked == here and len(forked) == 2 and 0 < forked[0] < forked[1]
