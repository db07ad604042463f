"""The issue-12 study of localization models (studies/localization/localization_shells.py):
its K = 1 point-load model is the engine's single-level phase (eqs 9.5/9.10), and its
distributed K-shell models converge to the periodic BEM as docs/model.md, section 11,
states (the BEM numbers are the engine's reference solver at N = 512, cached)."""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "studies" / "localization"))
sys.path.insert(0, str(REPO / "postprocess"))
import localization_shells as study  # noqa: E402
from punchsweep_point import find_binary  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
BEM = {(r["l"], r["X"]): r for r in json.loads(study.CACHE.read_text())}


@pytest.mark.parametrize("l, X", [(0.5, 0.005), (0.75, 0.06), (1.5, 0.06), (0.75, 0.14)])
def test_one_shell_of_point_loads_is_the_engines_single_level_phase(l, X):
    out = json.loads(subprocess.run([BINARY, "single-level", "--l", str(l), "--s", "2", "--pbar", str(X), "--T", "1",
                                     "--times", "0", "--format", "json"], check=True, capture_output=True,
                                    text=True).stdout)
    a, h = study.single_level(l, X, K=1, distributed=False)
    assert a == pytest.approx(out["series"]["a1"][0], rel=1e-12)
    assert h == pytest.approx(out["series"]["h"][0], rel=1e-10)


def test_shells_are_counted_as_the_lattice_has_them():
    rk, nk = study.shells((0.0, 0.0), 1.0, 4)
    assert list(nk) == [4, 4, 4, 8] and rk == pytest.approx([1, 2 ** 0.5, 2, 5 ** 0.5])
    rm, nm = study.shells((0.5, 0.5), 1.0, 2)
    assert list(nm) == [4, 8] and rm == pytest.approx([0.5 ** 0.5, 2.5 ** 0.5])


def test_distributed_shells_converge_to_the_bem_where_spots_are_apart():
    # a1/l <= 0.38: the paper's model is 1.3-2.8% low in h; 100 shells of distributed
    # neighbours bring every case within 0.15%, monotonically from K = 1 to 30.
    for (l, X), ref in BEM.items():
        if ref["a1"] / l > 0.4:
            continue
        errors = [abs(study.single_level(l, X, K, True)[1] / ref["h"] - 1) for K in (3, 10, 30)]
        assert errors[0] > errors[1] > errors[2], (l, X, errors)
        assert abs(study.single_level(l, X, 100, True)[1] / ref["h"] - 1) < 1.5e-3, (l, X)
        assert abs(study.single_level(l, X, 1, False)[1] / ref["h"] - 1) > 1.2e-2, (l, X)


BEM_TWO = json.loads(study.CACHE_TWO.read_text())


def test_two_level_neighbours_of_the_paper_are_its_eight():
    kept = study.two_level_neighbours(1, 1.0, 2)
    assert [(round(r, 12), n, j) for r, n, j in kept] == [(round(0.5 ** 0.5, 12), 4, 2), (1.0, 4, 1)]
    kept = study.two_level_neighbours(2, 1.0, 2)
    assert [(round(r, 12), n, j) for r, n, j in kept] == [(round(0.5 ** 0.5, 12), 4, 1), (1.0, 4, 2)]


@pytest.mark.parametrize("l, dh, X", [(0.75, 0.05, 0.06), (1.25, 0.05, 0.025), (1.0, 0.02, 0.06)])
def test_two_level_paper_model_is_the_engines_elastic_two_level_state(l, dh, X):
    out = json.loads(subprocess.run([BINARY, "point", "--l", str(l), "--dh", str(dh), "--pbar", str(X), "--T", "1",
                                     "--s", "2", "--times", "0", "--localization", "paper", "--format", "json"],
                                    check=True, capture_output=True, text=True).stdout)["series"]
    a1, a2, Q1, Q2 = study.two_level(l, dh, X, D=2, distributed=False, guess=(out["a1"][0], out["a2"][0]))
    assert a1 == pytest.approx(out["a1"][0], rel=1e-9)
    assert a2 == pytest.approx(out["a2"][0], rel=1e-9)
    assert Q1 == pytest.approx(out["P1"][0], rel=1e-9)  # T = 1: P = Q


def test_distributed_neighbours_over_many_distances_converge_in_both_radii():
    # The paper's a2 is 14% and 25% small at its two smallest level-2 spots; 200 distances
    # of distributed neighbours bring a2 within 1% and a1 within 0.15% everywhere.
    for ref in BEM_TWO:
        a1, a2, _, _ = study.two_level(ref["l"], ref["dh"], ref["X"], D=200, distributed=True,
                                       guess=(ref["a1"], ref["a2"]))
        assert abs(a2 / ref["a2"] - 1) < 1e-2, ref
        assert abs(a1 / ref["a1"] - 1) < 1.5e-3, ref
    paper = [study.two_level(r["l"], r["dh"], r["X"], guess=(r["a1"], r["a2"]))[1] / r["a2"] - 1 for r in BEM_TWO[:2]]
    assert paper[0] < -0.1 and paper[1] < -0.2, paper


def single_level_cli(*args):
    done = subprocess.run([BINARY, "single-level", *args], capture_output=True, text=True)
    return done


def test_the_engines_distributed_shells_meet_the_bem_through_the_cli():
    # `punchsweep single-level --localization shells:D` (the C++ implementation; D distances
    # of either level, whose level-1 punches make about D/2 shells) against the BEM cache:
    # within 0.15% at D = 200 where spots are apart, as the study found at K = 100.
    for (l, X), ref in BEM.items():
        if ref["a1"] / l > 0.4:
            continue
        done = single_level_cli("--l", str(l), "--s", "2", "--pbar", str(X), "--T", "1", "--times", "0",
                                "--localization", "shells:200", "--a1-points", "2")
        assert done.returncode == 0, done.stderr
        series = json.loads(done.stdout)["series"]
        assert abs(series["h"][0] / ref["h"] - 1) < 1.5e-3, (l, X, series)
        assert abs(series["a1"][0] / ref["a1"] - 1) < 2.5e-3, (l, X, series)


def test_a_bad_localization_is_refused_with_the_valid_forms():
    done = single_level_cli("--l", "0.75", "--s", "2", "--localization", "shells:0")
    assert done.returncode == 2 and done.stdout == ""
    assert "valid: periodic" in done.stderr
    assert "= point-shells:2), refined (= shells:200, " in done.stderr


def test_the_engines_two_level_family_meets_the_bem_through_the_cli():
    # `punchsweep elastic --localization shells:200` (C++) against the BEM cache: a2 within
    # 1%, a1 within 0.15%, where the paper's `elastic` is 3-25% off in a2.
    for ref in BEM_TWO:
        args = ["elastic", "--l", str(ref["l"]), "--dh", str(ref["dh"]), "--pbar", str(ref["X"]), "--s", "2"]
        refined = json.loads(subprocess.run([BINARY, *args, "--localization", "shells:200"], check=True,
                                            capture_output=True, text=True).stdout)
        assert refined["converged"] == [True]
        assert abs(refined["a2"][0] / ref["a2"] - 1) < 1e-2, ref
        assert abs(refined["a1"][0] / ref["a1"] - 1) < 1.5e-3, ref


BEM_CREEP = json.loads(study.CACHE_CREEP.read_text())
J_AT = study.T_CREEP - (study.T_CREEP - 1) * math.exp(-study.T_AT)


def test_under_creep_the_papers_frozen_radii_are_the_engines_point():
    # D = 2 of point loads with the radii frozen at t = 0 is eqs 9.16-9.19 with eq 9.18:
    # the engine's `point` at t = 5 (SLS T = 2.5).
    for ref in BEM_CREEP:
        out = json.loads(subprocess.run([BINARY, "point", "--l", str(ref["l"]), "--dh", str(ref["dh"]), "--pbar",
                                         str(ref["X"]), "--T", str(study.T_CREEP), "--s", "2", "--times",
                                         f"{study.T_AT:g}", "--localization", "paper", "--format", "json"],
                                        check=True, capture_output=True, text=True).stdout)["series"]
        a1, a2 = study.two_level_creep(ref["l"], ref["dh"], ref["X"], J_AT, D=2, distributed=False,
                                       guess=(0.28, 0.06), frozen=True)
        assert a1 == pytest.approx(out["a1"][0], rel=1e-8) and a2 == pytest.approx(out["a2"][0], rel=1e-7), ref


def test_under_creep_distributed_neighbours_need_radii_that_follow_the_loads():
    # At t = 5 the paper's a2 is 3-7% small. 60 distances of distributed neighbours with
    # radii following the (creep-scaled) loads bring a2 within 0.6% and a1 within 0.2%;
    # with the radii frozen at t = 0 the same model drifts as D grows (docs section 11).
    for ref in BEM_CREEP:
        a1, a2 = study.two_level_creep(ref["l"], ref["dh"], ref["X"], J_AT, D=60, distributed=True,
                                       guess=(0.28, 0.06), frozen=False)
        assert abs(a2 / ref["a2"] - 1) < 6e-3 and abs(a1 / ref["a1"] - 1) < 2e-3, (ref, a1, a2)


def point_cli(l, dh, pbar, times, localization):
    return json.loads(subprocess.run([BINARY, "point", "--l", str(l), "--dh", str(dh), "--pbar", str(pbar), "--T",
                                      str(study.T_CREEP), "--s", "2", "--times", times, "--localization",
                                      localization, "--format", "json"], check=True, capture_output=True,
                                     text=True).stdout)


def test_the_refined_point_meets_the_bem_under_creep():
    # `punchsweep point --localization refined` (D = 200 distances of distributed neighbours,
    # nominal-pressure radii that follow the loads) at t = 5 (SLS T = 2.5) against the BEM at
    # N = 512: a2 within 0.5% and a1 within 0.3%, where the paper's model is 3-7% small in a2
    # and 1.4-3.0% large in a1 (docs/model.md, section 11; the study's free radii: 0.2%, 0.11%).
    for ref in BEM_CREEP:
        refined = point_cli(ref["l"], ref["dh"], ref["X"], f"{study.T_AT:g}", "refined")
        assert refined["localization"] == "shells:200" and refined["valid"] is True
        a1, a2 = refined["series"]["a1"][0], refined["series"]["a2"][0]
        assert abs(a2 / ref["a2"] - 1) < 5e-3 and abs(a1 / ref["a1"] - 1) < 3e-3, (ref, a1, a2)
        paper = point_cli(ref["l"], ref["dh"], ref["X"], f"{study.T_AT:g}", "paper")["series"]
        assert abs(paper["a2"][0] / ref["a2"] - 1) > 2.5e-2, ref


def test_the_refined_t_star_meets_the_bems_where_spots_are_apart():
    # The paper's delayed point l = 0.75, dh = 0.05, pbar0 = 0.025 (SLS T = 2.5): the BEM at
    # N = 512 touches at t* = 1.0360 T_eps (bracketed to 1e-3); the paper's model at 1.2726
    # (+22.8%), the refined one within 1%. At pbar0 = 0.06, dh = 0.075 level 2 touches where
    # the spots nearly touch (a1 = 0.44 l), the dense-contact error of section 11: the
    # refined model is early there by 5% (BEM 0.8736), the paper's late by 17.6%.
    refined = point_cli(0.75, 0.05, 0.025, "0", "refined")
    assert refined["regime"] == "delayed" and abs(refined["t_star"] / 1.0360 - 1) < 1e-2, refined["t_star"]
    dense = point_cli(0.75, 0.075, 0.06, "0", "refined")
    assert dense["regime"] == "delayed" and -0.06 < dense["t_star"] / 0.8736 - 1 < -0.04, dense["t_star"]


def test_the_family_converges_as_more_distances_are_kept():
    # t* and a2(5) of `point --localization shells:D` at the paper's dilute delayed point
    # approach the family's own limit (D = 1000) at an observed order of at least 0.8 from
    # D = 20 to 60 to 200 (measured 0.95 and 2.9: docs/model.md, section 11.2), and that
    # limit is the BEM's t* within 0.2%.
    runs = {D: point_cli(0.75, 0.05, 0.025, "5", f"shells:{D}") for D in (20, 60, 200, 1000)}
    for value in (lambda r: r["t_star"], lambda r: r["series"]["a2"][0]):
        gaps = [abs(value(runs[D]) - value(runs[1000])) for D in (20, 60, 200)]
        for (D0, g0), (D1, g1) in zip(zip((20, 60), gaps), zip((60, 200), gaps[1:])):
            assert math.log(g0 / g1) / math.log(D1 / D0) >= 0.8, gaps
    assert abs(runs[1000]["t_star"] / 1.0360 - 1) < 2e-3
