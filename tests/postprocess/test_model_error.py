"""model_error.py: the comparison figures are right for a reference whose differences from
the model are known by construction (bem_* variables written here with h5py), and the CLI
keeps the error conventions."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "postprocess"))
import model_error  # noqa: E402
import punchsweep_maps as pm  # noqa: E402
from punchsweep_point import find_binary  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
SCRIPT = REPO / "postprocess" / "model_error.py"


def add_reference(path: Path, flip: list[tuple], scale: float, sample_every: int) -> None:
    """bem_* = the model's values on every `sample_every`-th point (others not computed),
    t* scaled by `scale`, radii scaled by 1.05, and the regimes of the cells in `flip` set to
    never."""
    with h5py.File(path, "r+") as f:
        regime = f["regime"][...]
        sampled = (np.arange(regime.size).reshape(regime.shape) % sample_every) == 0
        bem = np.where(sampled, regime, -1).astype(np.int8)
        for cell in flip:
            bem[cell] = 2
        t = np.where(sampled, f["t_star"][...] * scale, np.nan)
        variables = {"bem_regime": bem, "bem_t_star": t}
        for name in ("a1", "a2"):
            variables["bem_" + name] = np.where(sampled[..., None], f[name][...] * 1.05, np.nan)
        for name, data in variables.items():
            d = f.create_dataset(name, data=data)
            for i, axis in enumerate(["l", "dh", "T", "pbar", "s", "time"][: data.ndim]):
                d.dims[i].attach_scale(f[axis])
        for key in ("flag_values", "flag_meanings"):  # as the engine writes them
            f["bem_regime"].attrs[key] = f["regime"].attrs[key]
        f.attrs["bem_grid"] = np.int32(64)
        f.attrs["bem_sample"] = np.int64(sampled.sum())


@pytest.fixture(scope="module")
def maps(tmp_path_factory):
    d = tmp_path_factory.mktemp("err")
    plain = d / "plain.h5"
    subprocess.run([BINARY, "sweep", "--grid.l", "0.5,0.75,1", "--grid.dh", "linspace(0.02,0.12,6)", "--grid.T",
                    "2,5", "--grid.pbar", "logspace(0.005,0.08,5)", "--grid.s", "1,2", "--time.times", "0,1,5",
                    "--quiet", "--output", str(plain)], check=True)
    with_ref = d / "ref.h5"
    shutil.copy(plain, with_ref)
    regime = h5py.File(plain, "r")["regime"][...]
    # Two sampled cells (index % 3 == 0) that the model calls immediate, flipped to never.
    flat = [i for i in range(0, regime.size, 3) if regime.flat[i] == 0][:2]
    flip = [np.unravel_index(i, regime.shape) for i in flat]
    add_reference(with_ref, flip, scale=1.1, sample_every=3)
    return plain, with_ref, regime, flip


def test_confusion_agreement_and_errors_match_the_construction(maps):
    _, with_ref, regime, flip = maps
    ds = pm.open_map(with_ref)
    r = model_error.compare(ds)
    sampled = regime.flat[::3]
    assert r["sampled"] == sampled.size
    expected = np.zeros((3, 3), dtype=int)
    for code in range(3):
        expected[code, code] = int(np.sum(sampled == code))
    expected[0, 0] -= 2
    expected[0, 2] += 2
    np.testing.assert_array_equal(r["confusion"], expected)
    assert r["agreement"] == pytest.approx((sampled.size - 2) / sampled.size, rel=1e-15)
    # t* scaled by 1.1: |t - 1.1 t| / (1.1 t) = 1/11 at every delayed pair.
    assert r["t_star"]["count"] == int(np.sum(sampled == 1))
    assert r["t_star"]["median"] == pytest.approx(1 / 11, rel=1e-12)
    assert r["t_star"]["worst"] == pytest.approx(1 / 11, rel=1e-12)
    assert r["radii"]["a1"]["median"] == pytest.approx(0.05 / 1.05, rel=1e-12)
    # Per axis: each value's median is 1/11 wherever it has delayed pairs.
    for rows in r["t_star_by_axis"].values():
        for _, s in rows:
            assert s["count"] == 0 or s["median"] == pytest.approx(1 / 11, rel=1e-12)


def test_cli_prints_the_report_and_draws_both_pictures(maps, tmp_path):
    _, with_ref, _, _ = maps
    errors, slice_png = tmp_path / "errors.png", tmp_path / "slice.png"
    done = subprocess.run([sys.executable, str(SCRIPT), str(with_ref), "--errors-plot", str(errors), "--slice-plot",
                           str(slice_png), "--x", "pbar", "--y", "dh", "--at", "l=0.75", "T=5", "s=2"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "agreement:" in done.stdout and "t* relative error" in done.stdout
    assert "--at l=0.75 -> nearest grid value l = 0.75" in done.stdout
    for png in (errors, slice_png):
        assert png.read_bytes()[:4] == b"\x89PNG"


def test_map_without_reference_is_refused_with_exit_2(maps, tmp_path):
    plain, _, _, _ = maps
    done = subprocess.run([sys.executable, str(SCRIPT), str(plain), "--errors-plot", str(tmp_path / "e.png")],
                          capture_output=True, text=True)
    assert done.returncode == 2
    assert "--reference bem" in done.stderr and len(done.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "e.png").exists()
