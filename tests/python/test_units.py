"""Physical units end to end (issue 24): the new user's problem, a silicone under spherical
caps of R = 50 um on a 150 um pitch, asked in um and kPa through point, sweep, open_map and
classify, gives the answers of today's scaled runs (t* to 1e-12 relative), and every unit
mistake is refused in one line naming the key, exit 2.

Expected values are computed here, independently of the engine's unit code: a length in R
is the length over 50 um, a pressure in E0* is the pressure over E_0/(1 - nu^2) read from the
material file's own [elastic] lines."""
from __future__ import annotations

import configparser
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
MATERIAL = REPO / "materials" / "silicone_elite_double32.ini"
R_UM = 50.0


def E0_star_Pa() -> float:
    """E0* of the Prony material from its file, read here (not through the engine):
    E_0 = E_inf + sum E_i in modulus_unit, over 1 - nu^2."""
    parser = configparser.ConfigParser(inline_comment_prefixes=("#",))
    parser.read_string(MATERIAL.read_text())
    m = parser["material"]
    assert m["law"] == "prony" and m["modulus_unit"] == "MPa"
    E0 = (float(m["E_inf"]) + sum(float(v) for v in m["E_i"].split(","))) * 1e6
    return E0 / (1.0 - float(m["poisson"]) ** 2)


def cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True)


def point_json(*args: str) -> dict:
    done = cli("point", *args, "--format", "json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def relative(a, b) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    both_nan = np.isnan(a) & np.isnan(b)
    assert np.array_equal(np.isnan(a), np.isnan(b))
    scale = np.where(both_nan, 1.0, np.maximum(np.abs(b), 1e-300))
    return float(np.max(np.where(both_nan, 0.0, np.abs(a - b) / scale)))


def test_material_scale_read_here_is_the_engines():
    assert abs(punchsweep.Material(MATERIAL).plane_strain_modulus_Pa / E0_star_Pa() - 1.0) < 1e-12


def test_point_in_physical_units_equals_the_scaled_point():
    physical = point_json("--material", MATERIAL, "--R", "50um", "--l", "150um", "--dh", "2um",
                          "--pressure", "2kPa", "--s", "2")
    scaled = point_json("--material", MATERIAL, "--l", 150 / R_UM, "--dh", repr(2 / R_UM),
                        "--pbar", repr(2000.0 / E0_star_Pa()), "--s", "2")
    assert physical["regime"] == scaled["regime"] == "delayed"
    assert relative(physical["t_star"], scaled["t_star"]) < 1e-12
    # The JSON's physical fields and their UDUNITS-2 strings: lengths in R's unit (um).
    units = physical["units"]
    assert units["R"] == units["l"] == units["dh"] == units["a1_inf"] == units["h_0"] == "um"
    assert units["pressure"] == units["E0_star"] == "Pa" and units["P1"] == "N"
    assert units["t_star"] == units["t"] == "s"
    p = physical["physical"]
    assert p["R"] == 50 and p["l"] == 150 and p["dh"] == pytest.approx(2, rel=1e-15)
    assert p["pressure"] == pytest.approx(2000, rel=1e-15)
    assert p["E0_star"] == pytest.approx(E0_star_Pa(), rel=1e-12)
    assert p["a1_inf"] == pytest.approx(scaled["a1_inf"] * R_UM, rel=1e-12)
    # P1 + P2 is the cell's load pbar l^2 at every time (step load): 2 kPa x (150 um)^2 in N.
    total = np.add(p["series"]["P1"], p["series"]["P2"])
    assert np.allclose(total, 2000.0 * (150e-6) ** 2, rtol=5e-3)


@pytest.mark.parametrize("R", ["50um", "0.05mm", "50000nm", "50\u00b5m", "50\u03bcm"])  # both micro signs (issue 35)
def test_R_in_any_length_unit_gives_the_same_answer(R):
    a = point_json("--material", MATERIAL, "--R", R, "--l", "0.15mm", "--dh", "2um", "--pressure", "0.002MPa",
                   "--s", "2")
    b = point_json("--material", MATERIAL, "--R", "50um", "--l", "150um", "--dh", "2um", "--pressure", "2kPa",
                   "--s", "2")
    assert relative(a["t_star"], b["t_star"]) < 1e-12


def test_sweep_in_physical_units_reads_back_in_them(tmp_path):
    physical, scaled = tmp_path / "m.h5", tmp_path / "scaled.h5"
    done = cli("sweep", "--model.material", MATERIAL, "--model.R", "50um", "--grid.l", "150um",
               "--grid.dh", "1um,2um,3um", "--grid.pressure", "1kPa,2kPa", "--grid.s", "2", "--output", physical,
               "--quiet")
    assert done.returncode == 0, done.stderr
    pbar = [1000.0 / E0_star_Pa(), 2000.0 / E0_star_Pa()]
    done = cli("sweep", "--model.material", MATERIAL, "--grid.l", "3", "--grid.dh", "0.02, 0.04, 0.06",
               "--grid.pbar", ", ".join(repr(v) for v in pbar), "--grid.s", "2", "--output", scaled, "--quiet")
    assert done.returncode == 0, done.stderr

    ds = punchsweep.open_map(physical)
    assert ds.l.values.tolist() == [150.0] and ds.l.attrs["units"] == "um"
    assert np.allclose(ds.dh.values, [1, 2, 3], rtol=1e-15) and ds.dh.attrs["units"] == "um"
    assert np.allclose(ds.pbar.values, [1000, 2000], rtol=1e-12) and ds.pbar.attrs["units"] == "Pa"
    assert ds.attrs["R"] == "50 um"
    assert ds.a1.attrs["units"] == "um" and ds.P1.attrs["units"] == "N"
    reference = punchsweep.open_map(scaled)
    assert relative(ds.t_star.values, reference.t_star.values) < 1e-12
    assert relative(ds.a1.values, reference.a1.values * R_UM) < 1e-12
    # The scaled view is the file's.
    raw = punchsweep.open_map(physical, units="scaled")
    assert np.allclose(raw.dh.values, [0.02, 0.04, 0.06], rtol=1e-15) and raw.dh.attrs["units"] == "R"
    # Each cell equals point at that dh and pressure.
    for dh in (1, 2, 3):
        for pressure in (1, 2):
            one = point_json("--material", MATERIAL, "--R", "50um", "--l", "150um", "--dh", f"{dh}um",
                             "--pressure", f"{pressure}kPa", "--s", "2")
            cell = float(ds.t_star.sel(dh=dh, pbar=1000.0 * pressure).squeeze())
            expected = np.nan if one["t_star"] is None else one["t_star"]
            assert relative(cell, expected) < 1e-12


def test_classify_with_a_pressure_equals_point():
    c = punchsweep.classify(l=3.0, dh=[0.02, 0.04, 0.06], s=2, material=str(MATERIAL), pressure="2kPa")
    same = punchsweep.classify(l="150um", dh=["1um", "2um", "3um"], s=2, material=MATERIAL,
                               pressure=["2kPa"], R="50um")
    for k, dh in enumerate((0.02, 0.04, 0.06)):
        one = point_json("--material", MATERIAL, "--l", "3", "--dh", repr(dh), "--pressure", "2kPa", "--s", "2")
        expected = np.nan if one["t_star"] is None else one["t_star"]
        assert relative(c["t_star"][k], expected) < 1e-12
        assert relative(same["t_star"][k], expected) < 1e-12
        assert str(c.regime_names()[k]) == one["regime"]


def test_python_point_gives_the_physical_fields():
    r = punchsweep.point(l="150um", dh="2um", s=2, material=MATERIAL, pressure="2kPa", R="50um")
    assert r.units["t_star"] == "s" and r.units["dh"] == "um"
    assert r.physical["t_star"] == r.t_star
    assert r.physical["dh"] == pytest.approx(2.0, rel=1e-15)


@pytest.mark.parametrize("args, key, says", [
    (["point", "--T", "2", "--l", "150um", "--dh", "0.04", "--pbar", "0.01", "--s", "2"], "--l", "needs R"),
    (["point", "--T", "2", "--R", "50um", "--l", "3", "--dh", "2kPa", "--pbar", "0.01", "--s", "2"], "--dh",
     "'kPa' is a pressure, not a length"),
    (["point", "--T", "2", "--R", "50um", "--l", "3", "--dh", "2parsec", "--pbar", "0.01", "--s", "2"], "--dh",
     "'parsec' is not a length unit"),
    (["point", "--T", "2", "--R", "um", "--l", "3", "--dh", "0.04", "--pbar", "0.01", "--s", "2"], "--R",
     "is not a number"),
    (["point", "--T", "2", "--R", "50um", "--l", "-150um", "--dh", "0.04", "--pbar", "0.01", "--s", "2"], "--l",
     "outside its range"),
    (["point", "--T", "2", "--R", "-50um", "--l", "3", "--dh", "0.04", "--pbar", "0.01", "--s", "2"], "--R",
     "is not > 0"),
    (["point", "--material", str(MATERIAL), "--l", "3", "--dh", "0.04", "--pressure", "2um", "--s", "2"],
     "--pressure", "'um' is a length, not a pressure"),
    (["point", "--T", "2", "--l", "3", "--dh", "0.04", "--pbar", "0.01", "--s", "2", "--times", "0,1min"],
     "--times", "needs a material"),
    (["sweep", "--grid.dh", "2um", "--dry-run"], "grid.dh", "needs R"),
    (["sweep", "--model.R", "50um", "--grid.l", "150kPa", "--dry-run"], "grid.l", "is a pressure, not a length"),
    (["sweep", "--model.R", "50", "--dry-run"], "model.R", "has no unit"),
    (["sweep", "--model.R", "50um", "--grid.dh", "0.02, 2um", "--dry-run"], "grid.dh", "mixes values"),
    (["sweep", "--grid.pressure", "1kPa", "--dry-run"], "grid.pressure", "needs a material"),
    (["sweep", "--model.material", str(MATERIAL), "--grid.pressure", "1, 2", "--dry-run"], "grid.pressure",
     "has no unit"),
    (["sweep", "--model.material", str(MATERIAL), "--grid.pressure", "1kPa", "--grid.pbar", "0.01", "--dry-run"],
     "grid.pressure", "one of grid.pbar and grid.pressure"),
    (["sweep", "--model.R", "50um", "--grid.dh", "-2um", "--dry-run"], "grid.dh", "outside its range"),
])
def test_every_unit_mistake_is_one_line_naming_the_key(args, key, says, tmp_path):
    done = subprocess.run([BINARY, *args], capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 2, done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    assert key in lines[0] and says in lines[0], lines[0]
    assert not list(tmp_path.iterdir())  # nothing written


@pytest.mark.parametrize("kwargs, says", [
    (dict(pressure="2"), "no unit"),
    (dict(pressure="2um"), "'um' is a length, not a pressure"),
    (dict(pressure="2kPa", l="150um"), "needs R"),
    (dict(pressure="2kPa", dh="2um", R="50"), "has no unit"),
])
def test_python_unit_mistakes_raise_the_engines_message(kwargs, says):
    args = dict(l=3.0, dh=0.04, s=2, material=MATERIAL) | kwargs
    with pytest.raises(ValueError, match=says):
        punchsweep.classify(**args)
