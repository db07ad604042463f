"""A sparse mould whose caps' heights scatter against Greenwood and Williamson (issue 51's
physics check): caps far apart are independent Hertz caps, so cap k touches when the caps
above it, each pressed by its depth below the tallest tip less its own drop, carry the
cell's load (X* = sum_i (4/3) (drop_k - drop_i)^(3/2) / (Lx Ly), s = 2, C = 1/2, E* = 1).
The engine answers each cap from the small-spot limit (the caps in contact as punches in
each other's periodic field, docs/model.md 17.6), which holds the elastic interaction that
Greenwood and Williamson leave out: the field of a cap at distance r, P / (pi r), so the
difference falls as 1 / l with the caps' distances at the same drops and loads per cap.
Under creep the share in contact at time t is the elastic one at X(t) = pbar J(t)
(J(t) = T - (T - 1) exp(-t) for the standard linear solid)."""
from __future__ import annotations

import numpy as np
import pytest
import scipy.optimize

import punchsweep

K, SD = 8, 0.01  # an 8 x 8 supercell, heights of SD 0.01 R


def mould(tmp_path, l, seed=1, pbar=None, times=(0, 0.5, 1, 2, 5), grid=16):
    cell = tmp_path / f"one-{l}.cell"
    cell.write_text(f"[cell]\nLx = {l}\nLy = {l}\ns = 2\nC = 0.5\nsite = {l / 2}, {l / 2}, 0, 0\n")
    # (the same loads per cap at every pitch: the cell's load over its area)
    pbar = 1e-5 * (10.0 / l) ** 2 if pbar is None else pbar
    return punchsweep.surface(cell=cell, supercell=K, scatter=f"normal:{SD}", seed=seed, T=2.5, pbar=pbar, grid=grid,
                              times=list(times))


def greenwood_williamson(drops, area):
    """Each cap's touchdown load with independent Hertz caps (E* = 1, R = 1)."""
    return np.array([4.0 / 3.0 * np.sum(np.clip(d - drops, 0.0, None) ** 1.5) / area for d in drops])


def greenwood_williamson_area(caps, X, area):
    """The contact area of independent Hertz caps under the cell's load X * area: sunk to one
    depth delta below the tallest tip that carries it, each spot pi (delta - drop)."""
    drops = np.array([c["drop"] for c in caps])
    load = lambda delta: 4.0 / 3.0 * np.sum(np.clip(delta - drops, 0.0, None) ** 1.5) - X * area  # noqa: E731
    delta = scipy.optimize.brentq(load, 0.0, 1.0)
    return np.pi * np.sum(np.clip(delta - drops, 0.0, None))


def deviations(result, l):
    caps = result.cap_list
    drops = np.array([c["drop"] for c in caps])
    X = np.array([c["X_star"] for c in caps], dtype=float)
    gw = greenwood_williamson(drops, (K * l) ** 2)
    below = drops > 0
    assert np.count_nonzero(~below) == 1  # the tallest cap drawn, at X* = 0
    assert all(c["touchdown_from"] == "small_spot_limit" and c["resolved"] for c, b in zip(caps, below) if b)
    # The share in contact against load: the load at which it reaches each step.
    return X[below] / gw[below] - 1.0, np.sort(X[below]) / np.sort(gw[below]) - 1.0


def test_a_sparse_moulds_caps_touch_as_greenwood_and_williamson_say(tmp_path):
    """l = 40 R: every cap's X* (and the share curve's every step) within 1% of Greenwood and
    Williamson's; at l = 10 R the interaction is four times as large (the 1 / l of a cap's
    field, within a quarter), its median under 1% of X*."""
    far, far_share = deviations(mould(tmp_path, 40.0), 40.0)
    near, near_share = deviations(mould(tmp_path, 10.0), 10.0)
    print(f"l = 40 R: median {np.median(abs(far)):.2e}, worst {abs(far).max():.2e}; "
          f"l = 10 R: median {np.median(abs(near)):.2e}, worst {abs(near).max():.2e}")
    assert abs(far).max() <= 0.01 and abs(far_share).max() <= 0.01
    assert np.median(abs(near)) <= 0.01
    assert np.median(abs(near)) / np.median(abs(far)) == pytest.approx(4.0, rel=0.25)
    assert abs(near).max() / abs(far).max() == pytest.approx(4.0, rel=0.25)


def test_under_creep_the_share_in_contact_is_greenwood_and_williamsons_at_X_of_t(tmp_path):
    """l = 40 R, a standard linear solid (T = 2.5) under a step: X(t) = pbar J(t), and the
    share of caps in contact at each time is Greenwood and Williamson's at X(t), but for caps
    whose X* lies within 1% of X(t) (the elastic interaction's band at this pitch)."""
    times = np.array([0.0, 0.2, 0.5, 1.0, 2.0, 5.0])
    pbar = 3e-7
    result = mould(tmp_path, 40.0, pbar=pbar, times=times)
    X = pbar * (2.5 - 1.5 * np.exp(-times))
    np.testing.assert_allclose(result.series["X"], X, rtol=1e-12)
    drops = np.array([c["drop"] for c in result.cap_list])
    gw = greenwood_williamson(drops, (K * 40.0) ** 2)
    share = result.series["touched_0"]
    assert 0.2 < share[0] < share[-1] < 1.0  # the question spans the caps' touches
    for k, x in enumerate(X):
        expected = np.mean(gw <= x)
        band = np.mean(np.abs(gw / x - 1.0) <= 0.01)
        assert abs(share[k] - expected) <= band + 1e-12, f"t = {times[k]}"
    assert np.array_equal(result.series["touched_0"], result.series["sites_touched"])


def test_a_sparse_moulds_contact_area_is_greenwood_and_williamsons(tmp_path):
    """The area in contact at each time, l = 40 R on 16 nodes a pitch (a node 2.5 R across,
    the spots 0.1-0.25 R): Greenwood and Williamson's (the caps sunk to one depth delta
    under the load, each spot pi (delta - drop)) within 0.5%, every snapshot valid (the
    spots' areas the small-spot limit's, as their touchdowns are)."""
    times = np.array([0.0, 0.5, 1.0, 2.0, 5.0])
    result = mould(tmp_path, 40.0, pbar=3e-7, times=times)
    assert all(result.series["valid"])
    for X, mine in zip(result.series["X"], result.series["area_0"]):
        assert mine == pytest.approx(greenwood_williamson_area(result.cap_list, X, (K * 40.0) ** 2), rel=5e-3)


def test_grid_auto_sizes_no_grid_for_the_spots_the_limit_reads(tmp_path):
    """The sparse mould at l = 10 R under --grid auto (the default): every time's load lies
    within the small-spot limit's reach, so no grid need resolve its spots (sized for them,
    auto asked 256 and 512 nodes a pitch, 2048^2 and 4096^2 nodes, about 5200 s estimated
    here). It takes the least grid whose resolved part starts within the reach (at most 32
    nodes a pitch), every snapshot valid, each cap's X* and every series the same as on 16
    nodes a pitch (the limit's on both) and the areas Greenwood and Williamson's within the
    interaction's 0.5%."""
    times = (0.0, 0.5, 1.0, 2.0, 5.0)
    auto = mould(tmp_path, 10.0, times=times, grid="auto")
    fixed = mould(tmp_path, 10.0, times=times)
    assert auto["grid"][0] <= 32 * K and auto["curve"]["held_to_grid"] * 2 * K == auto["grid"][0]
    assert all(auto.series["valid"])
    for name in ("X", "area_fraction", "area_0", "touched_0"):
        np.testing.assert_allclose(auto.series[name], fixed.series[name], rtol=1e-12, err_msg=name)
    np.testing.assert_allclose([c["X_star"] for c in auto.cap_list], [c["X_star"] for c in fixed.cap_list], rtol=1e-12)
    for X, mine in zip(auto.series["X"], auto.series["area_0"]):
        assert mine == pytest.approx(greenwood_williamson_area(auto.cap_list, X, (K * 10.0) ** 2), rel=5e-3)
