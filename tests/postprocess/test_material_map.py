"""A material map (`[model] material = F.ini`) as Python users meet it: times in the file's
unit, the material's attributes, and the postprocess scripts drawing it in physical units
(pressures in kPa from E0*, t* in the file's unit)."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "postprocess"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402
import regime_map  # noqa: E402
from punchsweep_point import find_binary  # noqa: E402
from script_runner import call  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
MATERIAL = REPO / "materials" / "nbr_linder2011.ini"


@pytest.fixture(scope="module")
def material_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("map") / "nbr.h5"
    done = subprocess.run([BINARY, "sweep", "--model.material", str(MATERIAL), "--grid.l", "0.75",
                           "--grid.dh", "linspace(0.01, 0.04, 4)", "--grid.pbar", "logspace(0.002, 0.02, 5)",
                           "--grid.s", "2", "--time.times", "0, 10, 1000", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


def test_map_carries_the_material_and_its_units(material_map):
    ds = pm.open_map(material_map)
    assert ds.attrs["material_file"] == MATERIAL.read_text()
    assert ds.attrs["time_unit"] == "s"
    assert ds.t_star.attrs["units"] == "s" and ds.time.attrs["units"] == "s"
    assert list(pm.axes(ds)) == ["l", "dh", "pbar", "s"]
    # The reader gives pressures in kPa: pbar E0*, E0* = E_0/(1 - nu^2) with E_0 = E_inf + sum E_i
    # of the file (1200 + 1607.1 + 228.6 + 361.5 + 63.9 + 68.7 kPa), nu = 0.5.
    E0_star_kPa = (1200 + 1607.1 + 228.6 + 361.5 + 63.9 + 68.7) / (1 - 0.25)
    assert ds.pbar.attrs["units"] == "kPa" and "scaled_by" not in ds.pbar.attrs
    np.testing.assert_allclose(ds.pbar.values, np.geomspace(0.002, 0.02, 5) * E0_star_kPa, rtol=1e-9)


def test_regime_map_draws_it_in_kpa_and_seconds(material_map, tmp_path):
    out = tmp_path / "map.png"
    rc, _, err = call(regime_map, material_map, "--x", "pbar", "--y", "dh", "--at", "l=0.75", "s=2", "-o", out)
    assert rc == 0, err
    assert out.stat().st_size > 10_000
    ds = pm.open_map(material_map)
    assert "kPa" in pm.axis_label(ds, "pbar")
    assert pm.unit_tex(pm.units(ds, "t_star")) == "s"


def test_touch_by_interpolates_in_log_time():
    import critical_dh
    dh = np.array([0.1, 0.2, 0.3, 0.4])
    t_star = np.array([0.0, 10.0, 1000.0, np.nan])
    assert critical_dh.touch_by_curve(dh, t_star, 100.0) == pytest.approx(0.25, rel=1e-12)  # halfway in log t
    assert critical_dh.touch_by_curve(dh, t_star, 5.0) == pytest.approx(0.15, rel=1e-12)  # linear from t* = 0
    assert critical_dh.touch_by_curve(dh, t_star, 1e4) == 0.3  # the last that touches; the next never does
    assert np.isnan(critical_dh.touch_by_curve(dh, np.array([5.0, 50.0, np.nan, np.nan]), 1.0))
    # Even the largest dh touches by then: the answer is above the grid, not its top value.
    assert critical_dh.touch_by_curve(dh, np.array([0.0, 1.0, 2.0, 3.0]), 100.0) == np.inf


def test_touch_by_curves_stop_at_the_grid_edge_and_say_so(tmp_path):
    """Issue 25: above some pressure the touch-by curves were drawn flat at the grid's top dh;
    they now stop there, with a warning and a legend mark."""
    import critical_dh
    path = tmp_path / "low.h5"
    # A dh grid far too low for 60 s: at every pressure level 2 touches at its top.
    done = subprocess.run([BINARY, "sweep", "--model.material", str(MATERIAL), "--grid.l", "0.75",
                           "--grid.dh", "linspace(0.001, 0.004, 4)", "--grid.pbar", "0.01, 0.02, 0.04",
                           "--grid.s", "2", "--quantities", "regime", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    ds = pm.open_map(path)
    t_top = ds.t_star.isel(dh=-1).values.ravel()
    assert np.all(np.nan_to_num(t_top, nan=np.inf) <= 60.0)  # the premise, from the map itself
    fixed = pm.resolve_at(ds, pm.parse_at(["l=0.75", "s=2"], ds), free=["T", "s"], optional=("T", "s"),
                          reserved={"pbar": "the horizontal axis", "dh": "the vertical axis"})
    assert np.all(np.isinf(critical_dh.touch_by_curves(ds, "pbar", fixed, [60.0])))
    out = tmp_path / "chart.png"
    rc, _, err = call(critical_dh, path, "--against", "pbar", "--at", "l=0.75", "--touch-by", "60", "-o", out)
    assert rc == 0, err
    assert "touches even at the grid's largest dh" in err and "extend grid.dh" in err
    assert out.stat().st_size > 10_000


def test_critical_dh_against_temperature_of_a_wlf_map(tmp_path):
    import critical_dh
    material = tmp_path / "wlf.ini"
    material.write_text(MATERIAL.read_text() + "[shift]\nkind = wlf\nC1 = 17.44\nC2 = 51.6\nT_ref = 20\n")
    path = tmp_path / "wlf.h5"
    done = subprocess.run([BINARY, "sweep", "--model.material", str(material), "--grid.l", "0.75",
                           "--grid.dh", "linspace(0.005, 0.06, 12)", "--grid.temperature", "10, 20, 30",
                           "--grid.pbar", "0.005", "--grid.s", "2", "--quantities", "regime", "--quiet",
                           "--output", str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    ds = pm.open_map(path)
    # WLF: colder is slower, so the dh that touches within 100 s shrinks with falling temperature.
    fixed = pm.resolve_at(ds, pm.parse_at(["l=0.75", "s=2", "pbar=23.532kPa"], ds), free=["T", "s"],
                          optional=("T", "s"),
                          reserved={"temperature": "the horizontal axis", "dh": "the vertical axis"})
    curves = critical_dh.touch_by_curves(ds, "temperature", fixed, [100.0])[0, 0, 0]
    assert curves[0] <= curves[1] <= curves[2] and curves[0] < curves[2]
    out = tmp_path / "chart.png"
    rc, _, err = call(critical_dh, path, "--against", "temperature", "--at", "l=0.75", "pbar=23.532kPa",
                      "--touch-by", "1,100", "-o", out)
    assert rc == 0, err
    assert out.stat().st_size > 10_000


@pytest.fixture(scope="module")
def physical_map(tmp_path_factory):
    """The new user's map, given in um and kPa (docs/cli.md, Units)."""
    path = tmp_path_factory.mktemp("map") / "um.h5"
    done = subprocess.run([BINARY, "sweep", "--model.material", str(MATERIAL), "--model.R", "50um",
                           "--grid.l", "150um", "--grid.dh", "1um, 2um, 3um, 4um", "--grid.pressure",
                           "logspace(5kPa, 50kPa, 5)", "--grid.s", "2", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


def test_a_map_given_R_draws_lengths_in_its_unit(physical_map, tmp_path):
    ds = pm.open_map(physical_map)
    # Lengths in R's unit: l = 3 R of 50 um, radii and h likewise; a load R^2 E0* in N.
    assert ds.l.attrs["units"] == "um" and ds.l.values.tolist() == [150.0]
    np.testing.assert_allclose(ds.dh.values, [1, 2, 3, 4], rtol=1e-14)
    assert ds.a1.attrs["units"] == "um" and ds.h_inf.attrs["units"] == "um"
    assert ds.P1.attrs["units"] == "N"
    np.testing.assert_allclose(ds.pbar.values, np.geomspace(5, 50, 5), rtol=1e-12)
    assert "$\\mu$m" in pm.axis_label(ds, "dh") and "kPa" in pm.axis_label(ds, "pbar")
    out = tmp_path / "um.png"
    rc, _, err = call(regime_map, physical_map, "--x", "pbar", "--y", "dh", "--at", "l=150um", "s=2", "-o", out)
    assert rc == 0, err
    assert out.stat().st_size > 10_000


@pytest.mark.parametrize("text, expected", [("2um", 2.0), ("0.002mm", 2.0), ("0.04", 2.0), ("2000nm", 2.0)])
def test_at_takes_a_unit_or_a_bare_number_in_the_scale(physical_map, text, expected):
    ds = pm.open_map(physical_map)
    assert pm.parse_at([f"dh={text}"], ds)["dh"] == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("text, says", [("2kPa", "'kPa' is a pressure, dh a length"), ("2parsec", "not a unit"),
                                        ("um", "not a number")])
def test_at_refuses_unit_mistakes(physical_map, text, says):
    with pytest.raises(pm.MapError, match=says):
        pm.parse_at([f"dh={text}"], ds=pm.open_map(physical_map))
