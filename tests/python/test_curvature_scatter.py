"""Caps whose curvature scatters (issue 51: "only the height scatters; a cap's radius does
not"): --curvature-scatter changes each cap's C of a supercell to C (1 + d). Expected values
from the lattice itself: every cap changed alike is the lattice of that C; a lower cap's
shape does not move its own touchdown (no pressure acts on it before its tip touches: the
gap at its tip is the drop less the taller caps' indentation, docs/model.md section 17)."""
from __future__ import annotations

import numpy as np
import pytest

import punchsweep

LATTICE = dict(lattice="hexagonal", l=1.5, dh=0.06, s=2, grid=32, T=2.5, pbar=0.01, times=[0, 0.3, 1, 3], curve="cell")


def test_every_cap_changed_alike_is_the_lattice_of_that_curvature():
    changed = punchsweep.surface(supercell=2, curvature_scatter="list:" + ",".join(["0.25"] * 24), **LATTICE)
    assert all(cap["C"] == pytest.approx(0.625, rel=1e-15) for cap in changed.cap_list)
    lattice = punchsweep.surface(C=0.625, **LATTICE)
    assert [lv.t_star for lv in changed.levels] == pytest.approx([lv.t_star for lv in lattice.levels], rel=1e-9)
    np.testing.assert_allclose(changed.series["area_fraction"], lattice.series["area_fraction"], rtol=1e-9)
    unchanged = punchsweep.surface(supercell=2, **LATTICE)
    assert changed.levels[1].t_star != pytest.approx(unchanged.levels[1].t_star, rel=1e-3)


def test_a_lower_caps_own_shape_does_not_move_its_touchdown():
    """Level 1's first cap (site 0 of level 1 in the supercell's order) twice as blunt: its
    own touchdown load is the unchanged supercell's; a tall cap made blunter moves it."""
    plain = punchsweep.surface(supercell=2, **LATTICE)
    level_1 = [k for k, cap in enumerate(plain.cap_list) if cap["level"] == 1]
    values = [0.0] * 24
    values[level_1[0]] = -0.5
    blunt = punchsweep.surface(supercell=2, curvature_scatter="list:" + ",".join(map(str, values)), **LATTICE)
    assert blunt.cap_list[level_1[0]]["C"] == pytest.approx(0.25, rel=1e-15)
    assert blunt.cap_list[level_1[0]]["X_star"] == pytest.approx(plain.cap_list[level_1[0]]["X_star"], rel=1e-6)
    tall = [k for k, cap in enumerate(plain.cap_list) if cap["level"] == 0]
    values = [0.0] * 24
    values[tall[0]] = -0.5
    blunt_tall = punchsweep.surface(supercell=2, curvature_scatter="list:" + ",".join(map(str, values)), **LATTICE)
    moved = [abs(b["X_star"] / p["X_star"] - 1) for b, p in zip(blunt_tall.cap_list, plain.cap_list) if p["level"] == 1]
    assert max(moved) > 1e-3


def test_curvatures_drawn_at_random_keep_the_heights_and_make_an_ensemble():
    heights = punchsweep.surface(supercell=2, scatter="normal:0.005", seed=5, **LATTICE)
    both = punchsweep.surface(supercell=2, scatter="normal:0.005", curvature_scatter="normal:0.1", seed=5, **LATTICE)
    assert [c["drop"] for c in both.cap_list] == [c["drop"] for c in heights.cap_list]
    ratios = np.array([c["C"] / 0.5 - 1 for c in both.cap_list])
    assert 0.02 < ratios.std() < 0.3 and len(set(ratios)) == 24
    ensemble = punchsweep.surface(supercell=2, curvature_scatter="normal:0.1", seeds=3, **LATTICE).ensemble
    assert ensemble["seeds"] == [1, 2, 3] and ensemble["levels"][1]["first"]["n"] == 3


@pytest.mark.parametrize("value, message", [
    ("uniform:1", "a half-width below 1"),
    ("list:0.1,0.2", "needs one per cap, 24"),
    ("list:" + ",".join(["-1"] * 24), "every change must be > -1"),
    ("normal:-0.1", "outside its range"),
])
def test_a_bad_curvature_scatter_is_refused_by_name(value, message):
    with pytest.raises(ValueError, match="--curvature-scatter") as refused:
        punchsweep.surface(supercell=2, curvature_scatter=value, **LATTICE)
    assert message in str(refused.value)


def test_an_ensemble_of_curvatures_alone_starts_at_the_seed_given():
    """--seeds with --curvature-scatter alone: the draws are --seed, --seed + 1, ... (the
    first took the height scatter's default seed, 1, while its draw was --seed's)."""
    ensemble = punchsweep.surface(supercell=2, curvature_scatter="normal:0.1", seed=5, seeds=2, **LATTICE).ensemble
    assert ensemble["seeds"] == [5, 6]
    for member in ensemble["members"]:
        single = punchsweep.surface(supercell=2, curvature_scatter="normal:0.1", seed=member["seed"], **LATTICE)
        np.testing.assert_array_equal(member["area_fraction"], single.series["area_fraction"])
