"""An ensemble of drawn textures (issue 51): `surface --seeds N` draws the scatter with seeds
--seed .. --seed + N - 1 and gives each level's first, median and last cap's touch time and
each time's area fraction and shares of caps in contact as mean, spread and 5-95% band over
the draws. Expected values: the N single-seed runs (seed=k, each its own call), their caps'
touch times sorted here, and numpy's mean, std (ddof=1) and percentile (linear)."""
from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))

# A hexagonal two-level mould, 2 x 2 cells, each cap's height scattered by 0.005 R: level 1's
# caps touch over about a decade of time, differently in each draw.
TEXTURE_NO_SCATTER = dict(lattice="hexagonal", l=1.5, dh=0.06, s=2, grid=32, T=2.5, pbar=0.01, times=[0, 0.1, 0.3, 1, 3])
TEXTURE = dict(TEXTURE_NO_SCATTER, supercell=2, scatter="normal:0.005")


def check_statistics(stats: dict, values: list[float]) -> None:
    v = np.asarray(values, dtype=float)
    assert stats["n"] == len(v)
    assert stats["mean"] == pytest.approx(v.mean(), rel=1e-12, abs=1e-15)
    assert stats["sd"] == pytest.approx(v.std(ddof=1), rel=1e-9, abs=1e-15)
    assert stats["se"] == pytest.approx(v.std(ddof=1) / np.sqrt(len(v)), rel=1e-9, abs=1e-15)
    for key, p in (("p5", 5), ("median", 50), ("p95", 95)):
        assert stats[key] == pytest.approx(np.percentile(v, p), rel=1e-12, abs=1e-15)


def test_eight_seeds_give_the_mean_spread_and_band_of_the_eight_draws():
    out = punchsweep.surface(seed=3, seeds=8, **TEXTURE)
    ensemble = out.ensemble
    assert ensemble["seeds"] == list(range(3, 11))
    singles = [punchsweep.surface(seed=seed, **TEXTURE) for seed in range(3, 11)]
    # The result's own levels and caps are the first draw's.
    assert [c["t_star"] for c in out.cap_list] == [c["t_star"] for c in singles[0].cap_list]
    for level in range(len(out.levels)):
        firsts, medians, lasts = [], [], []
        for single in singles:
            times = sorted(np.inf if c["t_star"] is None else c["t_star"] for c in single.cap_list if c["level"] == level)
            firsts.append(times[0])
            medians.append(float(np.median(times)))
            lasts.append(times[-1])
            assert times[0] == (np.inf if single.levels[level].t_star is None else single.levels[level].t_star)
        stats = ensemble["levels"][level]
        check_statistics(stats["first"], firsts)
        check_statistics(stats["median"], medians)
        check_statistics(stats["last"], lasts)
    # Level 1 spreads: its caps touch at different times in each draw.
    assert ensemble["levels"][1]["first"]["sd"] > 0 and ensemble["levels"][1]["last"]["p95"] > ensemble["levels"][1]["first"]["p5"]
    for name, key in (("area_fraction", "area_fraction"), ("touched", "sites_touched"), ("touched_1", "touched_1")):
        series = ensemble["series"][name]
        for t in range(len(TEXTURE["times"])):
            draws = [float(single.series[key][t]) for single in singles]
            stats = {stat: series[stat][t] for stat in ("mean", "sd", "se", "p5", "median", "p95")}
            check_statistics(dict(stats, n=8), draws)
    for member, single in zip(ensemble["members"], singles):
        np.testing.assert_array_equal(member["area_fraction"], single.series["area_fraction"])


def test_the_table_and_csv_give_the_ensemble_rows():
    args = ["--lattice", "hexagonal", "--l", "1.5", "--dh", "0.06", "--s", "2", "--supercell", "2", "--scatter", "normal:0.005",
            "--grid", "32", "--T", "2.5", "--pbar", "0.01", "--times", "0,0.1,0.3,1,3", "--seeds", "3"]
    csv = subprocess.run([BINARY, "surface", *args, "--format", "csv"], capture_output=True, text=True, timeout=600)
    assert csv.returncode == 0, csv.stderr
    rows = [line for line in csv.stdout.splitlines() if not line.startswith("#")]
    assert rows[0].split(",")[:3] == ["t", "area_fraction_mean", "area_fraction_sd"] and rows[0].endswith("valid_draws")
    assert len(rows) == 6
    js = json.loads(subprocess.run([BINARY, "surface", *args, "--format", "json"], capture_output=True, text=True,
                                   timeout=600).stdout)
    first_row = [float(x) for x in rows[1].split(",")]
    assert first_row[1] == pytest.approx(js["ensemble"]["series"]["area_fraction"]["mean"][0], rel=1e-5)
    assert "# ensemble: level 1, its first cap's t*: mean" in csv.stdout


@pytest.mark.parametrize("args, message", [
    (["--seeds", "4"], "needs --scatter normal:SD or uniform:HALFWIDTH"),
    (["--supercell", "2", "--scatter", "list:" + ",".join(["0"] * 24), "--seeds", "4"], "needs --scatter normal:SD or uniform"),
    (["--supercell", "2", "--scatter", "normal:0.005", "--seeds", "0"], "--seeds = 0 is outside its range: an integer in [1, 1000]"),
    (["--supercell", "2", "--scatter", "normal:0.005", "--seeds", "1001"], "an integer in [1, 1000]"),
    (["--supercell", "2", "--scatter", "normal:0.005", "--target-error", "0.01"], "--target-error needs --seeds N above 4"),
    (["--supercell", "2", "--scatter", "normal:0.005", "--seeds", "8", "--target-error", "0"],
     "--target-error = 0 is outside its range: a share in (0, 1)"),
    (["--part-caps", "100"], "--part-caps: the tallest of a part's caps follows from the heights' distribution"),
    (["--supercell", "2", "--scatter", "normal:0.005", "--part-caps", "0"], "--part-caps = 0 is outside its range"),
])
def test_a_bad_ensemble_is_refused_by_name(args, message):
    run = subprocess.run([BINARY, "surface", "--lattice", "hexagonal", "--l", "1.5", "--dh", "0.06", "--s", "2", "--T", "2.5",
                          "--pbar", "0.01", *args], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and message in run.stderr, run.stderr
    assert run.stdout == ""


def test_the_drops_origin_is_stated_above_the_design_height():
    """The drops are taken from the tallest tip drawn; `tallest_rise` says how far it lies
    above the tall caps' design height: -min over caps of (design drop + draw), here with
    the draws listed so that a tall cap, then a lower one, is the tallest."""
    plain = punchsweep.surface(supercell=2, scatter="list:" + ",".join(["0"] * 24), **TEXTURE_NO_SCATTER)
    levels = [cap["level"] for cap in plain.cap_list]
    tall, low = levels.index(0), levels.index(1)
    for k, draw, rise in ((tall, -0.003, 0.003), (low, -0.07, 0.07 - 0.06)):
        draws = [0.0] * 24
        draws[k] = draw
        out = punchsweep.surface(supercell=2, scatter="list:" + ",".join(map(str, draws)), **TEXTURE_NO_SCATTER)
        assert out["tallest_rise"] == pytest.approx(rise, rel=1e-12)
        assert out.cap_list[k]["drop"] == 0.0


def test_a_target_error_stops_at_the_first_draw_that_meets_it():
    """--target-error E: draws until the standard error of every mean share and area
    fraction is at most E (at least 4 draws, at most --seeds). The stopping draw is found
    here from the members of an ensemble of all ten draws, by numpy's standard errors."""
    full = punchsweep.surface(seeds=10, **TEXTURE).ensemble
    names = ["area_fraction", "touched"] + [f"touched_{level}" for level in range(2)]

    def largest_error(n: int) -> float:
        return max(np.std([m[name][t] for m in full["members"][:n]], ddof=1) / np.sqrt(n)
                   for name in names for t in range(len(TEXTURE["times"])))

    errors = {n: largest_error(n) for n in range(4, 11)}
    target = errors[7] * 1.0000001
    expected = next(n for n in range(4, 11) if errors[n] <= target)
    assert expected <= 7
    out = punchsweep.surface(seeds=10, target_error=target, **TEXTURE)
    assert len(out.ensemble["seeds"]) == expected
    assert out.ensemble["largest_error"] == pytest.approx(errors[expected], rel=1e-9)
    assert not any("--target-error" in note for note in out.notes)
    short = punchsweep.surface(seeds=5, target_error=1e-9, **TEXTURE)
    assert len(short.ensemble["seeds"]) == 5
    assert any("--target-error 1e-09: after 5 draws" in note for note in short.notes)


def test_a_dry_run_counts_every_draw():
    run = subprocess.run([BINARY, "surface", "--lattice", "hexagonal", "--l", "1.5", "--dh", "0.06", "--s", "2", "--supercell", "2",
                          "--scatter", "normal:0.005", "--seeds", "8", "--grid", "32", "--T", "2.5", "--pbar", "0.01", "--dry-run"],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    line = next(line for line in run.stdout.splitlines() if line.strip().startswith("--seeds 8"))
    each = float(line.split("about ")[1].split(" s each")[0])
    others = float(line.split("to build, ")[1].split(" s for the other 7")[0])
    assert each > 0 and others == pytest.approx(7 * each, rel=1e-2)


@pytest.mark.parametrize("scatter, width", [("normal", 0.005), ("uniform", 0.008)])
def test_a_parts_tallest_tip_is_the_extreme_of_its_caps_draws(scatter, width):
    """--part-caps N: the 5%, 50% and 95% points of how far the tallest of a part's N caps
    lies above the tall caps' design height, against numpy's draws of N caps (tall and
    lower ones as the hexagonal cell has them, 2 and 4 a cell; dh 0.004 R, within the scatter,
    so lower caps may be the tallest), 20000 parts; and the supercell's own band, which its
    drawn rise lies in for most seeds."""
    dh, part = 0.004, 600
    out = punchsweep.surface(supercell=2, scatter=f"{scatter}:{width}", part_caps=part, **dict(TEXTURE_NO_SCATTER, dh=dh))
    rng = np.random.default_rng(11)
    draw = (lambda size: rng.normal(0, width, size)) if scatter == "normal" else (lambda size: rng.uniform(-width, width, size))
    tall, low = part // 3, part - part // 3
    rises = np.maximum(draw((20000, tall)).max(axis=1), draw((20000, low)).max(axis=1) - dh)
    expected = np.percentile(rises, [5, 50, 95])
    spread = expected[2] - expected[0]
    np.testing.assert_allclose(out["part"]["tallest_rise"], expected, atol=0.03 * spread)
    assert out["part"]["caps"] == part
    band = out["part"]["supercell_tallest_rise"]
    small = np.maximum(draw((20000, 8)).max(axis=1), draw((20000, 16)).max(axis=1) - dh)
    np.testing.assert_allclose(band, np.percentile(small, [5, 50, 95]), atol=0.03 * (band[2] - band[0]))
    assert band[1] < out["part"]["tallest_rise"][1]  # more caps, a taller tallest


@pytest.mark.parametrize("option", [["--seeds", "3"], ["--part-caps", "100"]])
def test_a_map_refuses_the_ensembles_options_by_name(option, tmp_path):
    """A map keeps each drawn supercell on its seed axis: --seeds and --part-caps are
    surface's, refused by name with nothing written."""
    out = tmp_path / "m.nc"
    run = subprocess.run([BINARY, "surface-map", "--lattice", "hexagonal", "--l", "1.5", "--dh", "0.06", "--s", "2",
                          "--supercell", "2", "--scatter", "normal:0.005", *option, "--T", "2.5", "--pbar", "0.01",
                          "--output", out], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and f"{option[0]} is not a map's" in run.stderr, run.stderr
    assert not out.exists() and list(tmp_path.iterdir()) == []
