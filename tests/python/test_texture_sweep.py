"""Issue 49: `punchsweep sweep` takes any texture through a [texture] section. The held-out
shape of the check: a hexagonal three-level mould (2 dh x 6 pressures x 2 temperatures,
64 nodes a pitch) in physical units, every point equal to `surface` at that point, opened by
the one reader with a level dimension and the pressure in Pa."""
from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import numpy as np

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
TRUTH = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"

CONFIG = f"""# The study's mould: hexagonal, three levels, TPE-A, in um, kPa and degC.
[texture]
lattice = hexagonal
grid = 64
[model]
material = {TRUTH}
R = 60um
s = 2
[grid]
l = 200um
dh = 2um, 3um
dh2 = 5um
pressure = logspace(5kPa, 50kPa, 6)
temperature = 20, 40
[time]
times = 1s, 1min
"""


def test_a_texture_sweep_is_surface_at_every_point_in_physical_units(tmp_path):
    config = tmp_path / "tpe.ini"
    config.write_text(CONFIG)
    out = tmp_path / "tpe.nc"
    run = subprocess.run([BINARY, "sweep", "--config", str(config), "--output", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    # Progress in the map's own length unit, one line a geometry.
    assert "geometry 2 (l = 200 um, dh = 3 um, dh2 = 5 um): curve" in run.stderr, run.stderr
    ds = punchsweep.open_map(out)
    assert ds.t_star.dims == ("l", "dh", "dh2", "pbar", "temperature", "level") and ds.sizes["level"] == 3
    assert (ds.pbar.attrs["units"], ds.dh.attrs["units"], ds.t_star.attrs["units"]) == ("Pa", "um", "s")
    pressures = np.logspace(np.log10(5e3), np.log10(5e4), 6)
    np.testing.assert_allclose(ds.pbar.values, pressures, rtol=1e-12)
    np.testing.assert_allclose(ds.dh.values, [2.0, 3.0], rtol=1e-12)
    checked, advised = 0, set()
    import h5py
    with h5py.File(out) as f:
        raw = {name: f[name][()] for name in ("level_touched", "level_area", "level_load")}
    assert ds.level_area.attrs["units"] == "um^2" and ds.level_load.attrs["units"] == "N"
    np.testing.assert_allclose(ds.level_area.values, raw["level_area"] * 60.0 ** 2, rtol=1e-12)
    for i, dh in enumerate(["2um", "3um"]):
        for j, pressure in enumerate(pressures):
            for k, temperature in enumerate([20, 40]):
                one = punchsweep.surface(material=str(TRUTH), R="60um", s=2, lattice="hexagonal", grid=64, l="200um",
                                         dh=dh, dh2="5um", pressure=f"{pressure!r}Pa", temperature=temperature,
                                         times="1s, 1min")
                at = ds.isel(l=0, dh=i, dh2=0, pbar=j, temperature=k)
                assert [lv["regime"] for lv in one["levels"]] == list(at.regime.values)
                t = [np.inf if lv["t_star"] is None else lv["t_star"] for lv in one["levels"]]
                # (to the last bits of the pressure, which the command line gets as decimal text)
                np.testing.assert_allclose(at.t_star.values, t, rtol=1e-12)
                np.testing.assert_array_equal(at.touched.values, one["series"]["sites_touched"])
                area = [np.nan if a is None else a for a in one["series"]["area_fraction"]]
                np.testing.assert_allclose(at.area_fraction.values, area, rtol=1e-12)
                # Each level's contact radius (in um: R is 60 um) and advisories by the last time.
                np.testing.assert_allclose(at.contact_radius.values, [60 * lv["contact_radius"] for lv in one["levels"]],
                                           rtol=1e-12)
                assert list(at.advised.values) == [int(lv["advisories"] != "") for lv in one["levels"]]
                advised.update(lv["advisories"] for lv in one["levels"])
                # Each level's caps touched, area and load at each time (the file's, in R and E0*).
                for level in range(3):
                    np.testing.assert_allclose(raw["level_touched"][0, i, 0, j, k, :, level],
                                               one["series"][f"touched_{level}"], rtol=1e-12)
                    np.testing.assert_allclose(raw["level_area"][0, i, 0, j, k, :, level],
                                               one["series"][f"area_{level}"], rtol=1e-12, atol=1e-15)
                    np.testing.assert_allclose(raw["level_load"][0, i, 0, j, k, :, level],
                                               one["series"][f"load_{level}"], rtol=1e-9, atol=1e-15)
                checked += 1
    assert checked == 24 and advised >= {"", "beyond_paraboloid"}  # both cases met


def test_a_texture_sweep_refuses_what_it_cannot_take(tmp_path):
    """Bad keys name the key and what is valid, exit 2, nothing written."""
    config = tmp_path / "tpe.ini"
    config.write_text(CONFIG + "[quantities]\nfull = 1\n")
    out = tmp_path / "bad.nc"
    run = subprocess.run([BINARY, "sweep", "--config", str(config), "--output", str(out)], capture_output=True, text=True)
    assert run.returncode == 2 and "line 17: unknown section [quantities]" in run.stderr, run.stderr
    config.write_text(CONFIG)
    for args, message in [(["--texture.latice", "square"], "unknown key texture.latice"),
                          (["--texture.supercell", "40"], "--supercell = 40 is outside its range: an integer in [1, 32]"),
                          (["--grid.pressure", "5"], "--pressure"),
                          (["--run.quiet", "maybe"], "run.quiet = maybe: valid: true or false")]:
        run = subprocess.run([BINARY, "sweep", "--config", str(config), "--output", str(out), *args],
                             capture_output=True, text=True)
        assert run.returncode == 2 and message in run.stderr, (args, run.stderr)
    assert not list(tmp_path.glob("bad.nc*"))


def test_the_seed_is_an_axis_of_a_scattered_texture(tmp_path):
    """seed = 1, 2, 3 under [texture] with a scatter: one supercell drawn per seed (a curve
    each), and each seed's caps in contact at every time equal `surface --seed` alone."""
    config = tmp_path / "seeds.ini"
    config.write_text("[texture]\nsupercell = 3\nscatter = normal:0.005\nseed = 1, 2, 3\ngrid = 16\n"
                      "[model]\ns = 2\n[grid]\nl = 0.75\ndh = 0.03\npbar = 0.004, 0.01\nT = 4\n[time]\ntimes = 0, 1, 5\n")
    out = tmp_path / "seeds.nc"
    run = subprocess.run([BINARY, "sweep", "--config", str(config), "--output", str(out), "--quiet"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    ds = punchsweep.open_map(out)
    assert ds.touched.dims == ("l", "dh", "scatter_width", "seed", "pbar", "T", "t")
    np.testing.assert_array_equal(ds.seed.values, [1, 2, 3])
    differ = set()
    for k, seed in enumerate([1, 2, 3]):
        for i, pbar in enumerate([0.004, 0.01]):
            one = punchsweep.surface(supercell=3, scatter="normal:0.005", seed=seed, grid=16, s=2, l=0.75, dh=0.03,
                                     pbar=pbar, T=4, times=[0, 1, 5])
            touched = ds.touched.values[0, 0, 0, k, i, 0]
            np.testing.assert_array_equal(touched, one["series"]["sites_touched"])
            differ.add(tuple(touched))
    assert len(differ) > 2  # the seeds draw different caps
    bad = subprocess.run([BINARY, "sweep", "--config", str(config), "--output", str(tmp_path / "bad.nc"),
                          "--texture.seed", "1, 2.5"], capture_output=True, text=True)
    assert bad.returncode == 2 and "--seed = '1, 2.5': 2.5 is not an integer" in bad.stderr, bad.stderr


def test_a_sample_of_load_points_is_stepped_in_time_as_surface_check(tmp_path):
    """[reference] sample = 4: four load points of the map (drawn with the seed, the same on
    any rank) are stepped in time on the curve's own cell, as `surface --check` steps them:
    check_regime, check_t_star and check_area_fraction there equal its numbers, NaN and
    not_computed elsewhere; and the curve's answer agrees with the stepping within its
    resolution (half its interval, plus 1e-3 of t*) at every sampled point."""
    config = tmp_path / "check.ini"
    config.write_text("[texture]\nlattice = hexagonal\ngrid = 64\n[model]\ns = 2\n[grid]\nl = 1.2\ndh = 0.02, 0.04\n"
                      "dh2 = 0.08\npbar = logspace(0.002, 0.05, 6)\nT = 2, 4\n[time]\ntimes = 0, 1, 5\n"
                      "[reference]\nsample = 4\nseed = 3\n")
    out = tmp_path / "check.nc"
    run = subprocess.run([BINARY, "sweep", "--config", str(config), "--output", str(out), "--quiet"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    import h5py
    with h5py.File(out) as f:
        assert int(f.attrs["check_sample"]) == 4 and int(f.attrs["check_seed"]) == 3
        code = f["check_regime"][()]
        sampled = np.argwhere(code[..., 0] >= 0)
        assert len(sampled) == 4
        assert np.all(code[code[..., 0] < 0] == -1) and np.isnan(f["check_t_star"][()][code[..., 0] < 0]).all()
        pbars, Ts = f["pbar"][()], f["T"][()]
        for at in map(tuple, sampled):
            _, dh_index, _, p_index, T_index = at
            one = punchsweep.surface(lattice="hexagonal", grid=64, s=2, l=1.2, dh=[0.02, 0.04][dh_index], dh2=0.08,
                                     pbar=float(pbars[p_index]), T=float(Ts[T_index]), times=[0, 1, 5], check=True)
            check = one["check"]
            assert [punchsweep.REGIMES[int(c)] for c in code[at]] == [lv["regime"] for lv in check["levels"]]
            t = [np.inf if lv["t_star"] is None else lv["t_star"] for lv in check["levels"]]
            np.testing.assert_array_equal(f["check_t_star"][at], t)
            np.testing.assert_array_equal(f["check_area_fraction"][at], check["series"]["area_fraction"])
            # The curve against the stepping: the same regimes, t* within the stepping's resolution.
            np.testing.assert_array_equal(f["regime"][at], code[at])
            mine, theirs = f["t_star"][at], f["check_t_star"][at]
            finite = np.isfinite(theirs)
            assert np.all(np.abs(mine[finite] - theirs[finite])
                          <= 0.5 * f["check_t_star_resolution"][at][finite] + 1e-3 * theirs[finite])


def test_python_surface_map_takes_the_seed_axis_and_a_check_sample():
    """Python's surface_map writes through the same writer: seed=[1, 2] is an axis, and
    check_sample=2 steps two of its load points in time (the same draw as the command's)."""
    ds = punchsweep.surface_map(l=0.75, dh=0.03, s=2, supercell=2, scatter="normal:0.005", seed=[1, 2], grid=16,
                                pbar=[0.004, 0.01], T=4, times=[0, 1, 5], check_sample=2)
    assert ds.t_star.dims == ("seed", "pbar", "level") and ds.level_load.dims == ("seed", "pbar", "t", "level")
    sampled = ds.check_regime.values[..., 0] >= 0
    assert sampled.sum() == 2
    np.testing.assert_array_equal(ds.check_regime.values[sampled], ds.regime.values[sampled])


def test_every_map_states_its_layout_and_a_newer_one_is_refused(tmp_path):
    """A regime map and a texture's map carry layout_version, the numbers the reader knows
    (LAYOUT_VERSIONS, the engine's map::k*LayoutVersion); a map written before the attribute
    opens; one of a newer layout is refused, naming it."""
    import h5py
    from punchsweep.map_attributes import LAYOUT_VERSIONS

    regime = tmp_path / "regime.h5"
    subprocess.run([BINARY, "sweep", "--grid.l", "0.75", "--grid.dh", "0.05,0.1", "--grid.T", "2.5", "--grid.pbar", "0.06",
                    "--grid.s", "2", "--output", str(regime), "--quiet"], check=True)
    texture = tmp_path / "texture.nc"
    subprocess.run([BINARY, "sweep", "--texture.lattice", "hexagonal", "--texture.grid", "16", "--model.s", "2",
                    "--grid.l", "1.2", "--grid.dh", "0.05", "--grid.pbar", "0.02", "--grid.T", "2", "--output", str(texture),
                    "--quiet"], check=True)
    for path, kind in ((regime, "regime"), (texture, "texture")):
        with h5py.File(path, "r") as f:
            assert int(f.attrs["layout_version"]) == LAYOUT_VERSIONS[kind], (kind, f.attrs["layout_version"])
        punchsweep.open_map(path).close()
        with h5py.File(path, "r+") as f:
            f.attrs["layout_version"] = LAYOUT_VERSIONS[kind] + 1.0
        try:
            punchsweep.open_map(path)
        except punchsweep.NotAMapError as e:
            assert f"its layout_version is {LAYOUT_VERSIONS[kind] + 1}, newer than this reader's {kind} maps" in str(e)
        else:
            raise AssertionError(f"a {kind} map of a newer layout opened")
    # A map as written before the attribute: the same map without it (HDF5 cannot delete an
    # attribute of a file that tracks their order, so the map is written again by xarray).
    import xarray as xr
    before = tmp_path / "before.h5"
    with xr.open_dataset(regime, engine="h5netcdf", decode_cf=False) as ds:
        ds.attrs.pop("layout_version")
        ds.to_netcdf(before, engine="h5netcdf")
    with h5py.File(before, "r") as f:
        assert "layout_version" not in f.attrs
    punchsweep.open_map(before).close()
