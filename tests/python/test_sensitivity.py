"""Sensitivity of t* (issue 25; docs/model.md, "Sensitivity"): the derivatives `point`
reports (dt_star_ddh, dt_star_dpbar, ...), a map's full mode stores and Python returns,
checked against finite differences of the engine's own t* taken here at random points with
another step, against the closed form of a time-shifted law's temperature derivative, and
the t* range over tolerances against the engine's t* at the box's corners."""
from __future__ import annotations

import json
import math
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
SILICONE = REPO / "materials" / "silicone_elite_double32.ini"

# A Prony material with WLF (T_ref 23 C), written here.
C1, C2, T_REF = 9.0, 120.0, 23.0
WLF_MATERIAL = f"""[material]
name = a known material with WLF
law = prony
modulus_unit = MPa
time_unit = s
poisson = 0.5
E_inf = 1
E_i = 4, 3, 2, 1.5, 1
tau_i = 1e-5, 1e-3, 0.1, 3, 100
[shift]
kind = wlf
C1 = {C1}
C2 = {C2}
T_ref = {T_REF}
"""


def central(f, x, rel=1e-5):
    """The central difference of f at x with step rel |x|, or None where f is not finite at
    both ends."""
    h = rel * abs(x)
    up, down = f(x + h), f(x - h)
    if up is None or down is None or not (math.isfinite(up) and math.isfinite(down)) or up <= 0 or down <= 0:
        return None
    return (up - down) / (2 * h)


def random_sls_points(n, seed):
    """Delayed points of the standard linear solid, drawn at random (periodic model)."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        p = dict(l=rng.uniform(0.6, 2.0), T=rng.uniform(1.5, 10.0), pbar=10 ** rng.uniform(-2.3, -1.0), s=2)
        r0 = punchsweep.point(dh=1e-6, **p)  # h_0 and h_inf do not depend on dh
        if not (r0.h_inf > r0.h_0 > 0):
            continue
        p["dh"] = r0.h_0 + rng.uniform(0.1, 0.9) * (r0.h_inf - r0.h_0)
        if punchsweep.point(**p).regime == "delayed":
            out.append(p)
    return out


@pytest.mark.parametrize("seed", [1, 2])
def test_derivatives_match_finite_differences_at_random_points(seed):
    for p in random_sls_points(4, seed):
        r = punchsweep.point(**p)
        for name in ("l", "dh", "pbar", "T"):
            fd = central(lambda v: punchsweep.point(**{**p, name: v}).t_star, p[name])
            assert fd is not None
            got = r.sensitivity[f"dt_star_d{name}"]
            assert got == pytest.approx(fd, rel=1e-4, abs=1e-9 * r.t_star / p[name]), (p, name, got, fd)
            assert r.sensitivity[f"dlog_t_star_dlog_{name}"] == pytest.approx(got * p[name] / r.t_star, rel=1e-12)


def test_physical_derivatives_on_a_material_with_units():
    """The silicone on R = 50 um caps: per um and per Pa, against differences in those units."""
    p = dict(material=SILICONE, R="50um", l="150um", s=2)
    r = punchsweep.point(dh="2um", pressure="2kPa", **p)
    assert r.regime == "delayed"
    assert r.units["dt_star_ddh"] == "s/um" and r.units["dt_star_dpbar"] == "s/Pa"
    fd_dh = central(lambda v: punchsweep.point(dh=f"{v!r}um", pressure="2kPa", **p).t_star, 2.0)
    fd_p = central(lambda v: punchsweep.point(dh="2um", pressure=f"{v!r}Pa", **p).t_star, 2000.0)
    assert r.physical["dt_star_ddh"] == pytest.approx(fd_dh, rel=1e-4)
    assert r.physical["dt_star_dpbar"] == pytest.approx(fd_p, rel=1e-4)
    # The knife edge the issue met: 1% of dh moves t* by about 116%.
    assert r.sensitivity["dlog_t_star_dlog_dh"] > 50


def test_temperature_derivative_is_the_shift_laws(tmp_path):
    """Under a step load a time shift scales t*: t*(T) = a_T(T) t*(T_ref), so
    d t*/dT = t* ln(10) d log10 a_T/dT = -t* ln(10) C1 C2 / (C2 + T - T_ref)^2."""
    path = tmp_path / "wlf.ini"
    path.write_text(WLF_MATERIAL)
    for T in (10.0, 23.0, 41.5):
        r = punchsweep.point(material=path, R="50um", l="150um", dh="20um", pressure="100kPa", s=2, temperature=T)
        assert r.regime == "delayed"
        expected = -r.t_star * math.log(10) * C1 * C2 / (C2 + T - T_REF) ** 2
        assert r.sensitivity["dt_star_dtemperature"] == pytest.approx(expected, rel=1e-6)
        assert "dlog_t_star_dlog_temperature" not in r.sensitivity  # a Celsius zero is arbitrary
        assert r.units["dt_star_dtemperature"] == "s/K"


def test_not_delayed_points_have_no_derivative():
    r = punchsweep.point(l=0.75, dh=0.01, T=2.5, pbar=0.06, s=2)
    assert r.regime == "immediate"
    assert all(v is None for v in r.sensitivity.values())


def test_a_full_map_stores_the_points_derivatives(tmp_path):
    out = tmp_path / "full.h5"
    subprocess.run([BINARY, "sweep", "--grid.l", "0.75,1.2", "--grid.dh", "0.05,0.075", "--grid.T", "2.5",
                    "--grid.pbar", "0.04,0.06", "--grid.s", "2", "--output.quantities", "full", "--output", out,
                    "--quiet"], check=True)
    with h5py.File(out) as f:
        axes = {k: f[k][...] for k in ("l", "dh", "T", "pbar", "s")}
        values = {k: f[k][...] for k in ("t_star", "dt_star_ddh", "dt_star_dpbar", "dt_star_dl")}
        assert f["dt_star_ddh"].attrs["scaled_by"] in (b"T_eps/R", "T_eps/R")
    checked = 0
    for index in np.ndindex(values["t_star"].shape):
        p = {k: float(axes[k][i]) for k, i in zip(("l", "dh", "T", "pbar", "s"), index)}
        r = punchsweep.point(localization="periodic", **{**p, "s": int(p["s"])})
        for name in ("dh", "pbar", "l"):
            stored = values[f"dt_star_d{name}"][index]
            if r.sensitivity[f"dt_star_d{name}"] is None:
                assert math.isnan(stored)
            else:
                assert stored == r.sensitivity[f"dt_star_d{name}"]
                checked += 1
    assert checked >= 6
    # A regime-only map has none of them.
    subprocess.run([BINARY, "sweep", "--grid.l", "0.75", "--grid.dh", "0.05", "--grid.T", "2.5", "--grid.pbar",
                    "0.04", "--grid.s", "2", "--output.quantities", "regime", "--output", tmp_path / "regime.h5",
                    "--quiet"], check=True)
    with h5py.File(tmp_path / "regime.h5") as f:
        assert "dt_star_ddh" not in f


def test_the_range_over_tolerances_is_the_corners_extremes():
    p = dict(material=SILICONE, R="50um", l="150um", s=2)
    r = punchsweep.point(dh="2um", pressure="2kPa", tolerance={"dh": "0.002um", "pressure": "0.5%"}, **p)
    corners = [punchsweep.point(dh=f"{d!r}um", pressure=f"{q!r}Pa", **p).t_star
               for d in (2.0 - 0.002, 2.0 + 0.002) for q in (2000 * 0.995, 2000 * 1.005)]
    # The engine steps in R and E0*, the corners here in um and Pa: equal to rounding.
    assert r.t_star_range == pytest.approx((min(corners), max(corners)), rel=1e-12)
    assert r.t_star_range[0] < r.t_star < r.t_star_range[1]
    # Wider: some corner never touches (the knife edge): the upper end is None (never).
    wide = punchsweep.point(dh="2um", pressure="2kPa", tolerance="dh=0.05um, pressure=5%", **p)
    assert wide.t_star_range[1] is None and wide.t_star_range[0] < r.t_star
    # Issue 37 item 8: what None means is said, by the corners' regimes (each checked alone).
    regimes = [punchsweep.point(dh=f"{d!r}um", pressure=f"{q!r}Pa", **p).regime
               for d in (2.0 - 0.05, 2.0 + 0.05) for q in (2000 * 0.95, 2000 * 1.05)]
    assert wide.corner_regimes == {k: regimes.count(k) for k in ("immediate", "delayed", "never")} | {"not_computed": 0}
    assert wide.corner_regimes["never"] > 0 and r.corner_regimes == {"immediate": 0, "delayed": 4, "never": 0,
                                                                     "not_computed": 0}
    assert punchsweep.point(dh="2um", pressure="2kPa", **p).corner_regimes is None  # no box, no corners
    # A box reaching below dh = 0 is clipped there, and the note reaches Python too.
    low = punchsweep.point(dh="0.01um", pressure="2kPa", tolerance="dh=0.05um", **p)
    assert low.notes and "below 0" in low.notes[0] and low.corner_regimes["immediate"] == 2


@pytest.mark.parametrize("tolerance, message", [
    ("s=1", "'s' is no real-valued input"),
    ("dh", "no '='"),
    ("dh=-1um", "not a number >= 0"),
    ("dh=2kPa", "is a pressure, not a length"),
    ("dh=2um,l=abc", "'abc'"),
    ("dh=2um, dh=3um", "'dh' is given twice"),  # issue 35: the last one was kept
    ("pressure=200%", "outside its range"),
])
def test_bad_tolerances_are_refused(tolerance, message):
    r = subprocess.run([BINARY, "point", "--material", SILICONE, "--R", "50um", "--l", "150um", "--dh", "2um",
                        "--pressure", "2kPa", "--s", "2", "--tolerance", tolerance], capture_output=True, text=True)
    assert r.returncode == 2 and message in r.stderr, r.stderr
    assert "--tolerance" in r.stderr and r.stdout == ""


def test_a_tolerance_below_dh_0_is_clipped_there_and_said_so_in_the_users_units():
    """Issue 37 item 8: dh = 1 um with a tolerance of 2 um reached dh = -1 um and was refused
    with the bound in R. The box's low side is now taken at dh = 0 (the two levels at one
    height: level 2 touches at once, t* = 0) and a note says so in the user's words; the high
    side is the point's own t* at dh = 3 um (delayed there, at 5 kPa)."""
    base = [BINARY, "point", "--material", SILICONE, "--R", "50um", "--l", "150um", "--pressure", "5kPa", "--s", "2",
            "--format", "json"]
    r = subprocess.run(base + ["--dh", "1um", "--tolerance", "dh=2um"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    assert d["notes"] == ["--tolerance dh=2um: dh minus 2um is below 0; the box's low dh is taken at 0"]
    high = json.loads(subprocess.run(base + ["--dh", "3um"], capture_output=True, text=True, check=True).stdout)
    assert high["regime"] == "delayed" and high["t_star"] > 0
    assert d["t_star_low"] == 0.0
    assert d["t_star_high"] == pytest.approx(high["t_star"], rel=1e-9)
    plain = json.loads(subprocess.run(base + ["--dh", "1um", "--tolerance", "dh=0.5um"], capture_output=True,
                                      text=True, check=True).stdout)
    assert "notes" not in plain  # within the range: no note, the output as before


def test_the_modules_point_in_json_form_is_the_commands_json():
    """The scripts read a point through the module where it is built (punchsweep_point's
    _json_form) or the command's JSON: the same keys and numbers, the box's corners and a
    clipped box's notes included (issue 37 items 6 and 8)."""
    sys.path.insert(0, str(REPO / "postprocess"))
    from punchsweep_point import _json_form
    args = dict(material=SILICONE, R="50um", l="150um", s=2, dh="0.01um", pressure="2kPa",
                tolerance="dh=0.05um, pressure=5%")
    r = subprocess.run([BINARY, "point", *[x for k, v in args.items() for x in (f"--{k}", str(v))], "--format", "json"],
                       capture_output=True, text=True, check=True)
    command = json.loads(r.stdout)
    module = _json_form(punchsweep.point(**args))
    assert set(module) == set(command)
    for k in ("t_star_low", "t_star_high", "corners_immediate", "corners_delayed", "corners_never", "notes",
              "regime", "t_star"):
        assert module[k] == command[k], k


def test_no_key_of_the_engines_point_is_dropped_by_python():
    """Issue 37 item 6: the Python result names every key of the command's JSON or keeps it
    in `other`; today it names all of them (a key the engine gains fails this test until
    PointResult says what it is)."""
    r = punchsweep.point(material=SILICONE, R="50um", l="150um", s=2, dh="0.01um", pressure="2kPa",
                         tolerance="dh=0.05um, pressure=5%")
    assert r.other == {}
    ref = punchsweep.reference(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2, bem_grid=16, times=[0, 1])
    assert ref.other == {}
    # And a key it does not name is kept, not dropped.
    raw = {"regime": "never", "series": {}, "a_new_output": 1.5}
    kept = punchsweep._result(punchsweep.ReferenceResult, {**raw, **{k: None for k in (
        "t_star", "t_star_lower", "t_star_upper", "converged", "cg_iterations", "max_residual", "bem_grid",
        "spacing", "steps", "solves", "seconds", "time_unit")}})
    assert kept.other == {"a_new_output": 1.5}
