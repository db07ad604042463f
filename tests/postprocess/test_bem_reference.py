"""A regime map with the periodic BEM reference (`sweep --reference bem`) as Python users
meet it: xarray (h5netcdf) reads the bem_* variables with their units, flags and fill
values, and the global attributes describe the reference."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "postprocess"))
from punchsweep_point import find_binary  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
GRID = ["--grid.l", "0.75,1", "--grid.dh", "linspace(0.02, 0.1, 5)", "--grid.T", "2.5, 6",
        "--grid.pbar", "logspace(0.01, 0.06, 4)", "--grid.s", "1,2", "--time.times", "0, 1, 5"]
SAMPLE = 12


@pytest.fixture(scope="module")
def bem_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("bem") / "map.h5"
    done = subprocess.run([BINARY, "sweep", *GRID, "--reference", "bem", "--bem-grid", "32", "--reference.sample",
                           str(SAMPLE), "--reference.seed", "7", "--quantities", "regime", "--quiet", "--output",
                           str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


def test_xarray_reads_the_bem_variables_with_units_and_dimensions(bem_map):
    with xr.open_dataset(bem_map, engine="h5netcdf") as ds:
        assert ds.bem_regime.dims == ("l", "dh", "T", "pbar", "s")
        assert ds.bem_t_star.dims == ("l", "dh", "T", "pbar", "s")
        for name in ["bem_a1", "bem_a2", "bem_P1", "bem_P2", "bem_area_fraction"]:
            assert ds[name].dims == ("l", "dh", "T", "pbar", "s", "time"), name
            assert ds[name].attrs["long_name"].startswith("periodic BEM reference: "), name
        np.testing.assert_array_equal(ds.time.values, [0, 1, 5])
        names = ["bem_t_star", "bem_a1", "bem_a2", "bem_P1", "bem_P2", "bem_area_fraction"]
        assert {ds[name].attrs["units"] for name in names} == {"1"}  # pure numbers, scaled:
        scales = {name: ds[name].attrs.get("scaled_by") for name in names}
        assert scales == {"bem_t_star": "T_eps", "bem_a1": "R", "bem_a2": "R", "bem_P1": "R^2 E0/(1-nu^2)",
                          "bem_P2": "R^2 E0/(1-nu^2)", "bem_area_fraction": None}
        assert "a1" not in ds  # --quantities regime: the model's series are not stored, the reference's are


def test_bem_regime_is_a_flag_variable_and_unsampled_points_are_not_computed(bem_map):
    with xr.open_dataset(bem_map, engine="h5netcdf") as ds:
        regime = ds.bem_regime
        assert regime.dtype == np.int8 and "_FillValue" not in regime.encoding
        assert list(regime.attrs["flag_values"]) == [0, 1, 2, -1]
        assert regime.attrs["flag_meanings"] == "immediate delayed never not_computed"
        r, t = regime.values, ds.bem_t_star.values
        sampled = r >= 0
        assert int(sampled.sum()) == SAMPLE == int(ds.attrs["bem_sample"])
        assert set(np.unique(r[sampled])) <= {0, 1, 2}
        assert np.all(np.isnan(t[~sampled])) and np.all(t[r == 0] == 0) and np.all(np.isnan(t[r == 2]))
        assert np.all(t[(r == 1) & ~np.isnan(t)] > 0)
        a1 = ds.bem_a1.values
        assert np.all(np.isnan(a1[~sampled])) and not np.any(np.isnan(a1[sampled]))
        # Masked as NaN by its _FillValue, like the model's floats.
        assert np.isnan(ds.bem_P1.encoding["_FillValue"])


def test_global_attributes_describe_the_reference(bem_map):
    with xr.open_dataset(bem_map, engine="h5netcdf") as ds:
        assert int(ds.attrs["bem_grid"]) == 32
        assert int(ds.attrs["bem_seed"]) == 7
        assert 0 < float(ds.attrs["bem_tolerance"]) < 1e-6
        assert "periodic BEM" in ds.attrs["bem_method"]
        assert "[reference]" in ds.attrs["config"] and "method = bem" in ds.attrs["config"]
