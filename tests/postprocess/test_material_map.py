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
