"""summary.py against maps made by the real engine: its counts are np.unique counts of the
stored regime and valid flags, overall and per axis value, and its t* statistics those of
the delayed points."""
from __future__ import annotations

import csv
import io
import os
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
POSTPROCESS = REPO / "postprocess"
sys.path.insert(0, str(POSTPROCESS))
import punchsweep_maps as pm  # noqa: E402
import summary  # noqa: E402
from punchsweep_point import find_binary  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
GRID = ["--grid.l", "0.5,0.75,1", "--grid.dh", "linspace(0.02,0.12,11)", "--grid.T", "2,2.5,5",
        "--grid.pbar", "logspace(0.005,0.08,9)", "--grid.s", "1,2"]
REGIMES = {"immediate": 0, "delayed": 1, "never": 2, "not_computed": -1}
VALIDITIES = {"valid": 0, "same_level_overlap": 1, "cross_level_overlap": 2, "no_solution": 3, "inaccurate": 4,
              "outside_table": 5, "unloading": 6}


@pytest.fixture(scope="module")
def maps(tmp_path_factory):
    """A complete regime-only map and an 'interrupted' copy with cells not computed."""
    folder = tmp_path_factory.mktemp("summary")
    full = folder / "map.h5"
    done = subprocess.run([BINARY, "sweep", *GRID, "--quiet", "--quantities", "regime",
                           "--output", str(full)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    partial = folder / "partial.h5"
    shutil.copy(full, partial)
    with h5py.File(partial, "r+") as f:
        f["regime"][1:, :, 2, :, :] = -1
        f["valid"][1:, :, 2, :, :] = -1
        f["t_star"][1:, :, 2, :, :] = np.nan
        f.attrs["completed"] = 0
    return {"full": full, "partial": partial}


AXES = ("l", "dh", "T", "pbar", "s")  # the engine's axes today, in the map's order
COLUMNS = (["axis", "value", "units", "points", *REGIMES, *(f"fraction_{r}" for r in REGIMES),
            *VALIDITIES, "t_star_min", "t_star_median", "t_star_max"])


def flags(path: Path):
    with h5py.File(path, "r") as f:
        return (f["regime"][:], f["valid"][:], f["t_star"][:],
                {a: f[a][:] for a in AXES}, int(f.attrs["completed"]))


def run(*args) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(POSTPROCESS / "summary.py"), *map(str, args)],
                          capture_output=True, text=True)


def read_csv(text: str) -> tuple[dict[str, str], list[dict[str, str]]]:
    comments = dict(line[2:].split(" = ", 1) for line in text.splitlines() if line.startswith("# "))
    rows = list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))
    return comments, rows


def expected(regime, valid, t_star) -> dict[str, object]:
    codes, counts = np.unique(regime, return_counts=True)
    by_regime = dict(zip(codes.tolist(), counts.tolist()))
    codes, counts = np.unique(valid, return_counts=True)
    by_valid = dict(zip(codes.tolist(), counts.tolist()))
    want = {name: by_regime.get(code, 0) for name, code in REGIMES.items()}
    want.update({name: by_valid.get(code, 0) for name, code in VALIDITIES.items()})
    want["points"] = regime.size
    delayed = t_star[regime == 1]
    want["t_star"] = (delayed.min(), np.median(delayed), delayed.max()) if delayed.size else None
    return want


def check_row(row: dict[str, str], want: dict[str, object]) -> None:
    assert int(row["points"]) == want["points"]
    for name in (*REGIMES, *VALIDITIES):
        assert int(row[name]) == want[name], (name, row)
    for name in REGIMES:
        assert float(row[f"fraction_{name}"]) == pytest.approx(want[name] / want["points"], rel=1e-15)
    if want["t_star"] is None:
        assert row["t_star_min"] == row["t_star_median"] == row["t_star_max"] == ""
    else:
        got = tuple(float(row[k]) for k in ("t_star_min", "t_star_median", "t_star_max"))
        assert got == pytest.approx(want["t_star"], rel=1e-15)


def test_csv_counts_equal_unique_counts_overall_and_per_axis_value(maps):
    done = run(maps["full"], "--csv")
    assert done.returncode == 0, done.stderr
    comments, rows = read_csv(done.stdout)
    regime, valid, t_star, axes, completed = flags(maps["full"])
    assert comments["completed"] == "1" == str(completed)
    assert int(comments["points"]) == regime.size and comments["t_star_units"] == "T_eps"
    assert list(rows[0]) == COLUMNS
    assert rows[0]["axis"] == "all" and rows[0]["value"] == ""
    check_row(rows[0], expected(regime, valid, t_star))
    assert len(rows) == 1 + sum(len(v) for v in axes.values())
    table = np.genfromtxt(io.StringIO(done.stdout), delimiter=",", names=True, dtype=None,
                          encoding=None, skip_header=4)  # as the --help says
    assert list(table.dtype.names) == COLUMNS and table["points"][0] == regime.size
    rows_by = {(r["axis"], float(r["value"])): r for r in rows[1:]}
    for k, name in enumerate(AXES):
        for i, value in enumerate(axes[name]):
            take = (slice(None),) * k + (i,)
            row = rows_by[(name, float(value))]
            assert row["units"] == {"l": "R", "dh": "R", "T": "1", "pbar": "E0/(1-nu^2)", "s": "1"}[name]
            check_row(row, expected(regime[take], valid[take], t_star[take]))


def test_by_restricts_the_breakdown_and_counts_not_computed_points(maps):
    done = run(maps["partial"], "--csv", "--by", "T", "s")
    assert done.returncode == 0, done.stderr
    comments, rows = read_csv(done.stdout)
    regime, valid, t_star, axes, _ = flags(maps["partial"])
    assert comments["completed"] == "0"
    assert [r["axis"] for r in rows] == ["all", "T", "T", "T", "s", "s"]
    assert int(rows[0]["not_computed"]) == 2 * 11 * 9 * 2 > 0
    check_row(rows[0], expected(regime, valid, t_star))
    for i in range(3):
        check_row(rows[1 + i], expected(regime[:, :, i], valid[:, :, i], t_star[:, :, i]))
    assert int(rows[3]["not_computed"]) == 2 * 11 * 9 * 2 and int(rows[1]["not_computed"]) == 0


def test_plain_table_states_counts_t_star_and_completion(maps):
    regime, valid, t_star, _, _ = flags(maps["partial"])
    out = io.StringIO()
    with pm.open_map(maps["partial"]) as ds:
        groups = summary.summarize(ds, ["s"])
        summary.write_table(ds, "partial.h5", groups, out)
    text = out.getvalue()
    want = expected(regime, valid, t_star)
    assert "completed: NO" in text
    for name in (*REGIMES, *VALIDITIES):
        line = next(l for l in text.splitlines() if l.startswith(name + " "))
        assert int(line.split()[1]) == want[name], line
    lo, med, hi = want["t_star"]
    assert f"min {lo:.4g}, median {med:.4g}, max {hi:.4g} ({want['delayed']} points)" in text
    assert "by s: points per regime" in text and "not_computed" in text.split("by s")[1]
    done = run(maps["full"], "--by", "pbar")
    assert done.returncode == 0 and "completed: yes" in done.stdout
    assert "by pbar [E0/(1-nu^2)]" in done.stdout and "by l" not in done.stdout


@pytest.mark.parametrize("args, message", [
    (["--by", "x"], "unknown axis 'x' for --by; valid axes: l, dh, T, pbar, s"),
    (["--by", "T", "T"], "--by names an axis twice"),
], ids=["unknown-axis", "axis-twice"])
def test_summary_user_errors_exit_2_with_one_line(maps, args, message):
    done = run(maps["full"], *args)
    assert done.returncode == 2 and message in done.stderr and done.stdout == ""
    assert len(done.stderr.strip().splitlines()) == 1


def test_summary_refuses_a_missing_or_foreign_file(tmp_path, capsys):
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = [1, 2]
    for path, message in [(tmp_path / "nope.h5", "does not exist"),
                          (other, "is not a punchsweep regime map (no regime, valid")]:
        assert pm.run_cli(summary.main, "summary.py", [str(path)]) == 2
        captured = capsys.readouterr()
        assert captured.out == "" and message in captured.err
        assert captured.err.startswith("summary.py: error: ") and captured.err.count("\n") == 1
