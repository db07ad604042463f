"""A map over a box of tolerances (issue 37 item 3): `sweep --tolerance "dh=0.5um,
pressure=10%"` stores, at every point, t* at the box's ends and the regimes there, checked
against the engine's t* at each corner by another route (punchsweep.classify, the batch
evaluator, over the corners' own grid), and drawn by regime_map.py as the band where the
answer depends on where in the box a part falls."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
TPE = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"


def sweep(path: Path, *extra) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, "sweep", "--model.material", TPE, "--model.R", "80um", "--grid.l", "250um",
                           "--grid.dh", "linspace(4um, 12um, 17)", "--grid.pressure", "logspace(3kPa, 50kPa, 12)",
                           "--grid.temperature", "20,40", "--grid.s", "2", "--quantities", "regime", "--quiet",
                           "--output", path, *extra], capture_output=True, text=True)


@pytest.fixture(scope="module")
def tolerance_map(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("tol") / "m.h5"
    r = sweep(path, "--tolerance", "dh=0.5um, pressure=10%")
    assert r.returncode == 0, r.stderr
    return path


def test_every_point_holds_the_least_and_greatest_t_star_of_its_corners(tolerance_map):
    with h5py.File(tolerance_map) as f:
        assert f.attrs["tolerance"] == "dh=0.5um, pressure=10%"
        dh = f["dh"][:] * 80.0  # um (R = 80 um)
        pbar = f["pbar"][:]
        T = f["temperature"][:]
        got = {k: f[k][0, :, :, :, 0] for k in ("t_star_low", "t_star_high", "regime_low", "regime_high")}
    # The corners by classify: dh -+ 0.5 um, pbar -+ 10%, at every grid point.
    D, Tm, P = np.meshgrid(dh, T, pbar, indexing="ij")
    corners = [punchsweep.classify(250 / 80, (D + sd * 0.5) / 80, pbar=P * (1 + sp * 0.1), s=2, material=TPE,
                                   temperature=Tm) for sd in (-1, 1) for sp in (-1, 1)]
    codes = {name: code for code, name in punchsweep._core.regime_codes().items()}
    t = np.stack([np.where(c["regime"] == codes["never"], np.inf, c["t_star"]) for c in corners])
    regime = np.stack([c["regime"] for c in corners])
    assert [codes[k] for k in ("immediate", "delayed", "never")] == [0, 1, 2]  # ordered as their t*
    low, high = t.min(0), t.max(0)
    np.testing.assert_allclose(np.where(np.isfinite(low), low, np.nan), got["t_star_low"], rtol=1e-12)
    np.testing.assert_allclose(np.where(np.isfinite(high), high, np.nan), got["t_star_high"], rtol=1e-12)
    assert (regime.min(0) == got["regime_low"]).all() and (regime.max(0) == got["regime_high"]).all()
    # The map holds all three cases: robust delayed, robust never, and mixed.
    assert ((got["regime_low"] == 1) & (got["regime_high"] == 1)).any()
    assert ((got["regime_low"] == 2) & (got["regime_high"] == 2)).any()
    assert (got["regime_low"] != got["regime_high"]).any()


def test_the_reader_and_the_picture_show_the_band(tolerance_map, tmp_path):
    ds = punchsweep.open_map(tolerance_map)
    assert ds.attrs["tolerance"] == "dh=0.5um, pressure=10%"
    assert set(np.unique(ds["regime_low"].values)) <= {"immediate", "delayed", "never"}
    assert ds["t_star_low"].attrs["units"] == "s"
    sys.path.insert(0, str(REPO / "postprocess"))
    import punchsweep_maps as pm
    import regime_map
    m = pm.open_map(tolerance_map)
    fixed = pm.resolve_at(m, {"l": 3.125 * 80, "s": 2, "temperature": 20}, free=["pbar", "dh"])
    d = regime_map.slices(m, "pbar", "dh", None, fixed)[0]
    band = regime_map.tolerance_band(m, d, None)
    assert band is not None and band.any() and (band == (d.regime_low != d.regime_high)).all()
    # A touch-within view: the band is where the two ends fall in different classes (within
    # 1 s, later, never).
    within = regime_map.tolerance_band(m, d, (1.0, "1 s"))
    cls = lambda r, t: np.where((r == 0) | ((r == 1) & (t <= 1.0)), 0, np.where(r == 1, 1, 2))  # noqa: E731
    assert (within == (cls(d.regime_low, d.t_star_low) != cls(d.regime_high, d.t_star_high))).all()
    assert (within & ~band).any()  # delayed at both ends, but one within 1 s and one later
    out = tmp_path / "band.png"
    r = subprocess.run([sys.executable, REPO / "postprocess" / "regime_map.py", tolerance_map, "--x", "pbar", "--y",
                        "dh", "--at", "l=250um", "s=2", "temperature=20", "--touch-within", "1s", "-o", out],
                       capture_output=True, text=True)
    assert r.returncode == 0 and out.stat().st_size > 10_000, r.stderr


def test_a_map_without_a_box_has_none_of_it_and_bad_boxes_are_refused(tmp_path):
    r = sweep(tmp_path / "plain.h5")
    assert r.returncode == 0, r.stderr
    with h5py.File(tmp_path / "plain.h5") as f:
        assert "tolerance" not in f.attrs and not {"t_star_low", "regime_low"} & set(f)
    for box, words in (("pressure=200%", "the box reaches"), ("T=1", "T is no axis of this map"), ("s=1", "'s' is no real-valued input"),
                       ("dh=1kPa", "is a pressure, not a length"), ("l=2%, l=3%", "'l' is given twice")):
        r = sweep(tmp_path / "bad.h5", "--tolerance", box)
        assert r.returncode == 2 and words in r.stderr and "output.tolerance" in r.stderr, (box, r.stderr)
        assert not (tmp_path / "bad.h5").exists()
    # The box is part of the map's identity: a resume with another is refused.
    r = sweep(tmp_path / "plain.h5", "--resume", "--tolerance", "dh=0.5um")
    assert r.returncode == 2 and "output.tolerance" in r.stderr, r.stderr


def test_the_design_chart_draws_the_touch_by_band(tolerance_map, tmp_path):
    """critical_dh.py --touch-by on a map with a box: the dh below which level 2 touches by
    t at every corner of the box (from t_star_high) lies under the nominal curve, and that
    at some corner (t_star_low) above it."""
    sys.path.insert(0, str(REPO / "postprocess"))
    import critical_dh
    import punchsweep_maps as pm
    m = pm.open_map(tolerance_map)
    fixed = pm.resolve_at(m, {"l": 250.0, "temperature": 20}, free=["pbar", "dh", "s"])
    times = [0.1, 1.0]
    nominal, every, some = (critical_dh.touch_by_curves(m, "pbar", fixed, times, v)
                            for v in ("t_star", "t_star_high", "t_star_low"))
    both = np.isfinite(nominal) & np.isfinite(every) & np.isfinite(some)
    assert both.sum() >= 10
    assert (every[both] <= nominal[both] + 1e-12).all() and (nominal[both] <= some[both] + 1e-12).all()
    # dh -+ 0.5 um alone makes the band 1 um wide (less the grid's interpolation error).
    assert (some[both] - every[both] > 0.5).all()
    out = tmp_path / "chart.png"
    r = subprocess.run([sys.executable, REPO / "postprocess" / "critical_dh.py", tolerance_map, "--against", "pbar",
                        "--at", "l=250um", "temperature=20", "s=2", "--touch-by", "0.1,1", "-o", out],
                       capture_output=True, text=True)
    assert r.returncode == 0 and out.stat().st_size > 10_000, r.stderr
