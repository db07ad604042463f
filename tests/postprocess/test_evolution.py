"""The postprocess scripts against the real engine: JSON contract, paper regimes, errors."""
from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "postprocess"))
from punchsweep_point import find_binary, run_point  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
EVOLUTION = REPO / "postprocess" / "evolution.py"


def paper_points():
    with open(REPO / "sweeps" / "paper-points.csv") as f:
        rows = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(rows))


def test_json_contract_keys_and_types():
    keys = {"regime", "t_star", "h_0", "h_inf", "valid", "reason", "a1_inf", "a2_inf", "area_fraction_inf", "series"}
    # t*'s sensitivity along each real-valued input of the standard linear solid's point.
    keys |= {f"dt_star_d{x}" for x in ("l", "dh", "pbar", "C", "T")}
    keys |= {f"dlog_t_star_dlog_{x}" for x in ("l", "dh", "pbar", "C", "T")}
    keys |= {"advisories", "advisory_reason", "strain"}  # physical advisories (docs/model.md, 16)
    periodic = run_point(BINARY, 0.75, 0.075, 2.5, 0.06, 2)  # the default names its model
    assert set(periodic) == keys | {"localization"} and periodic["localization"] == "periodic"
    refined = run_point(BINARY, 0.75, 0.075, 2.5, 0.06, 2, localization="refined")
    assert set(refined) == keys | {"localization"} and refined["localization"] == "shells:200"
    r = run_point(BINARY, 0.75, 0.075, 2.5, 0.06, 2, localization="paper")
    assert set(r) == keys
    assert set(r["series"]) == {"t", "a1", "a2", "P1", "P2", "area_fraction"}
    assert r["regime"] == "delayed" and isinstance(r["valid"], bool)
    assert abs(r["t_star"] - 1.027595) < 1e-6  # docs/model.md, section 9
    assert r["series"]["t"] == [0, 0.5, 1, 2, 5]
    for P1, P2 in zip(r["series"]["P1"], r["series"]["P2"]):
        assert abs(P1 + P2 - 0.06 * 0.75**2) < 1e-12


@pytest.mark.parametrize("row", paper_points(), ids=lambda row: row["label"])
def test_paper_regimes(row):
    r = run_point(BINARY, float(row["l"]), float(row["dh"]), float(row["T"]), float(row["pbar"]),
                  int(row["s"]))
    assert r["regime"] == row["regime"]
    assert (r["t_star"] is None) == (row["regime"] == "never")


def test_evolution_draws_the_picture_and_keeps_the_result(tmp_path):
    png, js = tmp_path / "e.png", tmp_path / "e.json"
    done = subprocess.run([sys.executable, str(EVOLUTION), "--binary", BINARY, "--l", "0.75",
                           "--dh", "0.05", "--T", "2.5", "--pbar", "0.025", "--s", "2",
                           "--samples", "21", "-o", str(png), "--json", str(js)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert png.stat().st_size > 10_000 and png.read_bytes()[:4] == b"\x89PNG"
    result = json.loads(js.read_text())
    assert result["regime"] == "delayed" and len(result["series"]["t"]) == 21
    a2 = result["series"]["a2"]
    t = result["series"]["t"]
    assert all(a == 0 for a, ti in zip(a2, t) if ti < result["t_star"])
    assert all(a > 0 for a, ti in zip(a2, t) if ti > result["t_star"])


def test_evolution_passes_on_the_engine_refusal_with_exit_2(tmp_path):
    done = subprocess.run([sys.executable, str(EVOLUTION), "--binary", BINARY, "--l", "-1",
                           "--dh", "0.05", "--T", "2.5", "--pbar", "0.025", "--s", "2",
                           "-o", str(tmp_path / "x.png")], capture_output=True, text=True)
    assert done.returncode == 2
    assert "--l" in done.stderr and "l > 0" in done.stderr
    assert not (tmp_path / "x.png").exists()
