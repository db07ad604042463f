"""postprocess/surface_picture.py: each level's t* over a map surface-map wrote (netCDF-4,
every axis a dimension, one value or more). What it draws is checked by another route than the image: the
nearest values --at picks, the panels' arrays against the map's own, and the refusals."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "postprocess"))
import surface_picture  # noqa: E402
from script_runner import call  # noqa: E402


@pytest.fixture(scope="module")
def hex_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("surface") / "hex.nc"
    punchsweep.surface_map(lattice="hexagonal", l=1.2, dh=[0.04, 0.05, 0.06], dh2=0.09, s=2, grid=32,
                           pbar=[0.002, 0.005, 0.01, 0.02, 0.05], T=[2.0, 4.0, 8.0], times=[0, 1, 5], output=path)
    return path


def test_a_slice_is_drawn_per_level(hex_map, tmp_path):
    rc, out, err = call(surface_picture, hex_map, "--at", "T=4.3", "-o", tmp_path / "hex.png")
    assert rc == 0, err
    assert (tmp_path / "hex.png").stat().st_size > 10_000
    ds, said = surface_picture.select(surface_picture.read_map(str(hex_map)), ["T=4.3"])
    assert said == ["T = 4"]  # the nearest value, said
    whole = surface_picture.read_map(str(hex_map))
    np.testing.assert_array_equal(ds.t_star.values, whole.t_star.sel(T=4.0).squeeze(["l", "dh2"]).values)
    fig = surface_picture.render(ds, said, time=1.2)
    assert len(fig.axes) >= 3  # a panel per level below the tallest (2) and the caps', with colour bars
    # The caps' panel: the map's share at its nearest time (1), blank where it is flagged.
    caps = [a for a in fig.axes if a.get_title().startswith("caps in contact at t = 1 ")]
    assert len(caps) == 1
    at = ds.sel(t=1.0)
    expected = np.where(at.valid.transpose("dh", "pbar").values == 0, at.touched.transpose("dh", "pbar").values, np.nan)
    drawn = np.ma.filled(caps[0].collections[0].get_array(), np.nan).reshape(expected.shape)
    np.testing.assert_array_equal(drawn, expected)
    rc, _, err = call(surface_picture, hex_map, "--at", "T=4", "dh=0.05", "-o", tmp_path / "line.png")
    assert rc == 0, err


def test_refusals_name_the_problem(hex_map, tmp_path):
    rc, _, err = call(surface_picture, hex_map, "-o", tmp_path / "x.png")
    assert rc == 2 and "3 axes of several values (dh, pbar, T); fix all but two with --at" in err
    rc, _, err = call(surface_picture, hex_map, "--at", "z=1", "-o", tmp_path / "x.png")
    assert rc == 2 and "no axis 'z' (the map's: l, dh, dh2, pbar, T)" in err
    (tmp_path / "not.nc").write_text("hello")
    rc, _, err = call(surface_picture, tmp_path / "not.nc", "-o", tmp_path / "x.png")
    assert rc == 2 and "is not an HDF5 file, so not a punchsweep regime map" in err  # the one reader's words
    # A regime map of `sweep` (regime without a level axis) is the other script's to draw.


def test_cells_whose_regime_the_tolerance_decides_are_hatched(tmp_path):
    """A map with a box of tolerances: the cells of each level whose regime differs between
    regime_low and regime_high (as the file holds them) are hatched, and no others."""
    path = tmp_path / "tol.nc"
    punchsweep.surface_map(l=0.75, dh=list(np.linspace(0.01, 0.05, 9)), s=2, pbar=list(np.geomspace(1e-3, 0.05, 8)),
                           T=4, tolerance="pbar=20%, T=0.5", output=path)
    ds, said = surface_picture.select(surface_picture.read_map(str(path)), [])
    band = surface_picture.tolerance_band(ds, 1, ["dh", "pbar"])
    low, high = (ds[v].sel(level=1).transpose("dh", "pbar").values for v in ("regime_low", "regime_high"))
    np.testing.assert_array_equal(band, low != high)
    assert 0 < band.sum() < band.size  # some cells decided by the box, some not
    fig = surface_picture.render(ds, said)
    panel = [a for a in fig.axes if a.get_title().startswith("level 1")][0]
    hatched = [c for c in panel.collections if c.get_hatch() == "xx"]
    assert len(hatched) == 1 and len(hatched[0].get_paths()) == band.sum()
    assert any("tolerance (pbar=20%, T=0.5)" in t.get_text() for t in panel.get_legend().get_texts())
    rc, _, err = call(surface_picture, path, "-o", tmp_path / "tol.png")
    assert rc == 0, err


def test_a_material_map_is_drawn_in_kPa_and_um(tmp_path):
    """A map made with a material and R (issue 49): the one reader gives its pressure in kPa, its
    lengths in um and t* in s, and the picture's axes and titles say so (a map of E0* and R
    showed "10µ" on its pressure axis)."""
    truth = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    path = tmp_path / "tpe.nc"
    punchsweep.surface_map(material=str(truth), R="60um", lattice="hexagonal", l="200um", dh=["2um", "3um"],
                           dh2="5um", s=2, pressure=["10kPa", "20kPa", "30kPa"], temperature=20, times="1s, 1min",
                           grid=32, output=path)
    ds, said = surface_picture.select(surface_picture.read_map(str(path)), ["temperature=20"])
    np.testing.assert_allclose(ds.pbar.values, [10, 20, 30], rtol=1e-12)
    np.testing.assert_allclose(ds.dh.values, [2, 3], rtol=1e-12)
    assert (ds.pbar.attrs["units"], ds.dh.attrs["units"], ds.t_star.attrs["units"], ds.X_star.attrs["units"]) == \
        ("kPa", "um", "s", "kPa")
    fig = surface_picture.render(ds, said)
    labels = [a.get_xlabel() for a in fig.axes] + [a.get_ylabel() for a in fig.axes]
    assert "pbar (kPa)" in labels and "dh (um)" in labels
    assert all(a.get_title().endswith("kPa") for a in fig.axes[:2] if a.get_title().startswith("level"))


def test_a_scattered_map_is_drawn_over_its_draws(tmp_path):
    """--over-seeds (issue 51): a map with a seed axis drawn as its median t* over the draws,
    the mean share of caps in contact, and hatched the cells whose draws' regimes differ;
    each against the map's own arrays reduced here by numpy."""
    path = tmp_path / "seeds.nc"
    punchsweep.surface_map(lattice="hexagonal", l=1.5, dh=[0.03, 0.06, 0.09], s=2, supercell=2, scatter="normal:0.01",
                           seed=[1, 2, 3], grid=16, pbar=[0.003, 0.006, 0.01, 0.03], T=2.5, times=[0.3, 3], output=path)
    whole = surface_picture.read_map(str(path))
    ds, said = surface_picture.select(surface_picture.over_seeds(whole), [])
    whole = whole.squeeze()  # (l, T and the scatter's width: one value each)
    t = whole.t_star.sel(level=1).transpose("seed", "dh", "pbar").values
    median = np.median(t, axis=0)
    np.testing.assert_array_equal(ds.t_star.sel(level=1).transpose("dh", "pbar").values, median)
    regimes = whole.regime.sel(level=1).transpose("seed", "dh", "pbar").values
    spread = regimes.min(axis=0) != regimes.max(axis=0)
    np.testing.assert_array_equal(ds.regime_spread.sel(level=1).transpose("dh", "pbar").values != 0, spread)
    np.testing.assert_allclose(ds.touched.transpose("t", "dh", "pbar").values,
                               whole.touched.transpose("seed", "t", "dh", "pbar").values.mean(axis=0), rtol=1e-15)
    expected_regime = np.where(median == 0, 0, np.where(np.isinf(median), 2, 1))
    np.testing.assert_array_equal(ds.regime.sel(level=1).transpose("dh", "pbar").values, expected_regime)
    fig = surface_picture.render(ds, said)
    panel = [a for a in fig.axes if a.get_title().startswith("level 1")][0]
    hatched = [c for c in panel.collections if c.get_hatch() == "xx"]
    assert spread.any() and len(hatched) == 1 and len(hatched[0].get_paths()) == spread.sum()
    assert any("between the draws (3 draws)" in t.get_text() for t in panel.get_legend().get_texts())
    assert "median over 3 draws, seeds 1, 2, 3" in fig._suptitle.get_text()
    rc, _, err = call(surface_picture, path, "--over-seeds", "-o", tmp_path / "seeds.png")
    assert rc == 0, err
    rc, _, err = call(surface_picture, path, "-o", tmp_path / "x.png")
    assert rc == 2 and "fix all but two with --at" in err  # without --over-seeds the seed is an axis like any
