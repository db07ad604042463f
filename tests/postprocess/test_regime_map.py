"""A regime map as Python users meet it: xarray (h5netcdf) labelled arrays, CF attributes,
and values equal to `punchsweep point` at sampled grid points."""
from __future__ import annotations

import json
import math
import os
import random
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
GRID = ["--grid.l", "0.5,0.75,1.25", "--grid.dh", "linspace(0.02, 0.12, 6)", "--grid.T", "1, 2.5, 10",
        "--grid.pbar", "logspace(0.005, 0.08, 5)", "--grid.s", "1,2,3", "--time.times", "0, 1, 5"]


@pytest.fixture(scope="module")
def full_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("map") / "map.h5"
    done = subprocess.run([BINARY, "sweep", *GRID, "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


def test_xarray_reads_labelled_dimensions_and_coordinates(full_map):
    with xr.open_dataset(full_map, engine="h5netcdf") as ds:
        assert dict(ds.sizes) == {"l": 3, "dh": 6, "T": 3, "pbar": 5, "s": 3, "time": 3}
        assert ds.regime.dims == ("l", "dh", "T", "pbar", "s")
        assert ds.a1.dims == ("l", "dh", "T", "pbar", "s", "time")
        np.testing.assert_array_equal(ds.l.values, [0.5, 0.75, 1.25])
        np.testing.assert_allclose(ds.pbar.values, 0.005 * 16.0 ** (np.arange(5) / 4), rtol=1e-14)
        np.testing.assert_array_equal(ds.time.values, [0, 1, 5])
        axes = ["l", "dh", "T", "pbar", "s", "time"]
        assert {ds[name].attrs["units"] for name in axes} == {"1"}  # pure numbers, each in its scale:
        scales = {name: ds[name].attrs.get("scaled_by") for name in axes}
        assert scales == {"l": "R", "dh": "R", "T": None, "pbar": "E0/(1-nu^2)", "s": None, "time": "T_eps"}
        for name in ["t_star", "h_0", "h_inf", "a1_inf", "a2_inf", "a1", "P1", "area_fraction"]:
            assert "units" in ds[name].attrs and "long_name" in ds[name].attrs, name
        assert ds.t_star.attrs["scaled_by"] == "T_eps" and ds.P1.attrs["scaled_by"] == "R^2 E0/(1-nu^2)"
        assert ds.attrs["Conventions"] == "CF-1.8" and ds.attrs["completed"] == 1
        assert "[grid]" in ds.attrs["config"] and ds.attrs["creep_law"] == "standard_linear_solid"
        assert ds.pbar.attrs["spacing"] == "log"


def test_flag_variables_carry_their_meanings_and_no_fill_value(full_map):
    with xr.open_dataset(full_map, engine="h5netcdf") as ds:
        regime = ds.regime
        assert regime.dtype == np.int8 and "_FillValue" not in regime.encoding
        assert list(regime.attrs["flag_values"]) == [0, 1, 2, -1]
        assert regime.attrs["flag_meanings"] == "immediate delayed never not_computed"
        assert list(ds.valid.attrs["flag_values"]) == [0, 1, 2, 3, 4, 5, 6, -1]
        assert ds.valid.attrs["flag_meanings"].split() == [
            "valid", "same_level_overlap", "cross_level_overlap", "no_solution", "inaccurate", "outside_table",
            "unloading", "not_computed"]
        codes = set(np.unique(regime.values))
        assert codes <= {0, 1, 2} and len(codes) == 3  # every point computed, all regimes present


def test_t_star_is_zero_for_immediate_and_nan_for_never(full_map):
    with xr.open_dataset(full_map, engine="h5netcdf") as ds:
        r, t = ds.regime.values, ds.t_star.values
        assert np.all(t[r == 0] == 0) and np.all(np.isnan(t[r == 2]))
        assert np.all(t[r == 1] > 0)
        assert not np.any(r[:, :, 0] == 1)  # T = 1 (elastic) is never delayed


def point_json(l, dh, T, pbar, s, times):
    args = [BINARY, "point", "--l", repr(l), "--dh", repr(dh), "--T", repr(T), "--pbar", repr(pbar),
            "--s", str(int(s)), "--times", ",".join(repr(t) for t in times), "--format", "json"]
    done = subprocess.run(args, capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def same(a, b):
    return (a is None and math.isnan(b)) or (a is not None and a == b) or (
        a is not None and math.isnan(a) and math.isnan(b))


def test_map_values_equal_punchsweep_point_at_sampled_points(full_map):
    rng = random.Random(7)
    with xr.open_dataset(full_map, engine="h5netcdf") as ds:
        times = [float(t) for t in ds.time.values]
        names = {0: "immediate", 1: "delayed", 2: "never"}
        for _ in range(25):
            at = {d: rng.randrange(ds.sizes[d]) for d in ["l", "dh", "T", "pbar", "s"]}
            cell = ds.isel(at)
            p = point_json(*(float(cell[d]) for d in ["l", "dh", "T", "pbar", "s"]), times)
            where = {d: float(cell[d]) for d in at}
            assert names[int(cell.regime)] == p["regime"], where
            assert int(cell.valid == 0) == int(p["valid"]), where
            # Both print/store the same doubles: equality is exact.
            assert same(p["t_star"], float(cell.t_star)), where
            for key in ["h_0", "h_inf", "a1_inf", "a2_inf", "area_fraction_inf"]:
                assert same(p[key], float(cell[key])), (key, where)
            for key in ["a1", "a2", "P1", "P2", "area_fraction"]:
                for k, value in enumerate(p["series"][key]):
                    assert same(value, float(cell[key][k])), (key, k, where)


def test_regime_quantities_map_has_no_time_series(tmp_path):
    path = tmp_path / "regime.h5"
    subprocess.run([BINARY, "sweep", *GRID, "--quiet", "--quantities", "regime", "--output", str(path)],
                   check=True)
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert "a1" not in ds and "regime" in ds and "a1_inf" in ds


def test_sweeps_default_ini_is_the_embedded_default():
    def dry(*extra):
        done = subprocess.run([BINARY, "sweep", "--dry-run", *extra], capture_output=True, text=True,
                              check=True)
        # Calibration, time estimate and the disk's free space vary from run to run.
        volatile = ("calibration", "estimated", "disk:")
        return [line for line in done.stdout.splitlines() if not any(v in line for v in volatile)]
    assert dry("--config", str(REPO / "sweeps" / "default.ini")) == dry()
    assert any("104328 in" in line for line in dry())


def test_every_units_attribute_means_what_udunits_reads(full_map):
    """UDUNITS (and so cf-units and pint-xarray) must read every `units` as the map means it:
    here every real is a pure number, "1"; a scale such as R (which UDUNITS would read as
    the roentgen) lives in `scaled_by`."""
    import shutil
    import subprocess

    udunits = shutil.which("udunits2")
    assert udunits, "udunits2 (Debian's udunits-bin, installed by cmake/install-deps.sh) is missing"
    with xr.open_dataset(full_map, engine="h5netcdf") as ds:
        names = [n for n in [*ds.coords, *ds.data_vars] if "units" in ds[n].attrs]
        assert len(names) > 10
        for name in names:
            unit = ds[name].attrs["units"]
            done = subprocess.run([udunits, "-H", unit, "-W", ""], capture_output=True, text=True,
                                  stdin=subprocess.DEVNULL)
            assert done.returncode == 0, f"{name}: udunits2 does not parse units {unit!r}: {done.stderr}"
            assert done.stdout.strip() == "1", f"{name}: units {unit!r} is read as {done.stdout.strip()!r}"
        for name in ["regime", "valid"]:
            assert "units" not in ds[name].attrs  # flags have no units
        assert "scaled_by" in ds.attrs["scales"]
