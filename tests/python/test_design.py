"""`punchsweep design` (issue 37 item 1): the window of dh that meets every requirement at
every temperature and corner of the tolerance box, checked point by point with `punchsweep
point` (the engine's forward t*, another code path than the design's inverse)."""
from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
EXPORTS = REPO / "examples" / "dma_exports"
TRUTH = EXPORTS / "tpe_a_truth.ini"
# The engineer's question of issue 37: 80 um caps on a 250 um pitch, 20-40 C, touch within a
# second under a firm squeeze, never under a light touch, whatever the tolerance.
GEOMETRY = ["--R", "80um", "--l", "250um", "--s", "2"]
QUESTION = ["--temperature", "20..40C", "--require", "touch within 1s at 30kPa", "--require", "never at 5kPa",
            "--tolerance", "dh=0.5um, pressure=10%"]


def cli(*args) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True)


def design(material, *args) -> dict:
    # Each option once (design refuses one given twice): a pitch range in args (--find l)
    # takes the place of GEOMETRY's --l.
    geometry = [*GEOMETRY[:2], *GEOMETRY[4:]] if "--l" in args else GEOMETRY
    r = cli("design", "--material", material, *geometry, *args, "--format", "json")
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def point(material, dh_um: float, pressure_kPa: float, T: float) -> dict:
    r = cli("point", "--material", material, *GEOMETRY, "--dh", f"{dh_um!r}um", "--pressure", f"{pressure_kPa!r}kPa",
            "--temperature", T, "--format", "json")
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


@pytest.fixture(scope="module")
def fitted(tmp_path_factory) -> Path:
    """TPE-A fitted from its TRIOS-style export, as a user would."""
    out = tmp_path_factory.mktemp("design") / "tpe_a.ini"
    r = cli("fit", "--dma", EXPORTS / "trios_lims.txt", "--reference-temperature", "23", "--poisson", "0.5", "-o", out)
    assert r.returncode == 0, r.stderr
    return out


def test_each_edge_carries_points_advisories_at_its_binding_corner():
    """The README's question (TPE-A, 80 um caps on 250 um, 30 and 5 kPa): each edge's
    advisories are `point`'s at its binding corner with dh at the edge (the tall caps'
    long-term radius a1_inf and the strain from it, to 1e-9: the same model at the same
    point), and the table prints them under the requirement. At 1 kPa "never" binds where the
    caps stay within the paraboloid's bound: nothing raised, no line."""
    d = design(TRUTH, "--temperature", "20..40C", "--require", "touch within 1s at 30kPa", "--require", "never at 5kPa",
               "--require", "never at 1kPa")
    for r in d["requirements"]:
        at = r["binds_at"]
        pressure_kPa = float(r["text"].split(" at ")[1].removesuffix("kPa"))
        p = point(TRUTH, r["edge_physical"], pressure_kPa, at["temperature"])
        assert r["contact_radius"] == pytest.approx(p["a1_inf"], rel=1e-9), r["text"]
        assert r["advisories"] == p["advisories"], r["text"]
        assert r["strain"] == pytest.approx(p["strain"], rel=1e-9)
    touch, never, light = d["requirements"]
    assert touch["advisories"] == "beyond_paraboloid, large_strain" and never["advisories"] == "beyond_paraboloid"
    assert light["advisories"] == "" and light["advisory_reason"] == "" and light["contact_radius"] < 0.3
    assert "on the tall caps: The contact radius reaches 0.5041 R" in touch["advisory_reason"]
    r = cli("design", "--material", TRUTH, *GEOMETRY, "--temperature", "20..40C", "--require", "touch within 1s at 30kPa",
            "--require", "never at 1kPa")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith("  touch within 1s at 30kPa: dh <= "))
    assert lines[at + 1].startswith("    advisories at the edge, in the long term, on the tall caps: The contact radius")
    assert lines[at + 2].startswith("  never at 1kPa: dh > ") and not lines[at + 3].strip().startswith("advisories")


def test_the_window_holds_at_every_corner_and_its_edges_are_tight():
    """At every temperature checked and every corner of the box, the window's dh meets every
    requirement by `point`'s t*; just past each edge, at the corner it names, it fails."""
    d = design(TRUTH, *QUESTION)
    assert not d["empty"] and d["physical"]["unit"] == "um" and d["physical"]["dh_tolerance"] == 0.5
    lower, upper = d["physical"]["lower"], d["physical"]["upper"]
    assert 0 < lower < upper
    assert d["physical"]["centre"] == pytest.approx((lower + upper) / 2, rel=1e-12)
    assert d["temperatures"] == pytest.approx(np.linspace(20, 40, 9).tolist())
    assert d["notes"] == []  # t* falls with temperature and pressure here: nothing to say
    touch, never = d["requirements"]
    assert touch["side"] == "upper" and never["side"] == "lower"
    assert touch["edge_physical"] == upper and never["edge_physical"] == lower
    # The binding corners: the cold end and the low pressure for the touch (t* falls with
    # both), the high pressure for "never" (h_inf is the same at every temperature).
    assert touch["binds_at"]["temperature"] == 20
    assert touch["binds_at"]["pbar"] == pytest.approx(0.9 * touch["pbar"], rel=1e-12)
    assert never["binds_at"]["pbar"] == pytest.approx(1.1 * never["pbar"], rel=1e-12)
    # Every corner of the box about both edges of the window: dh -+ 0.5 um, p -+ 10%, 9 temperatures.
    for T in d["temperatures"]:
        for p in (27.0, 33.0):
            for dh in (upper - 0.5, upper + 0.5, lower + 0.5):
                r = point(TRUTH, dh, p, T)
                assert r["regime"] in ("immediate", "delayed") and r["t_star"] <= 1.0 * (1 + 1e-6), (T, p, dh, r)
        for p in (4.5, 5.5):
            # (The lower edge is open: at dh = h_inf itself the level touches at last.)
            for dh in (lower * (1 + 1e-9) - 0.5, lower + 0.5, upper + 0.5):
                assert point(TRUTH, dh, p, T)["regime"] == "never", (T, p, dh)
    # Tight: 0.01% past the upper edge, at 20 C and 27 kPa, t* is above 1 s; 0.01% below the
    # lower edge, at 5.5 kPa, the level touches in the end. And at the edge t* is 1 s.
    assert point(TRUTH, upper + 0.5, 27.0, 20.0)["t_star"] == pytest.approx(1.0, rel=1e-6)
    assert point(TRUTH, upper * 1.0001 + 0.5, 27.0, 20.0)["t_star"] > 1.0
    assert point(TRUTH, lower * 0.9999 - 0.5, 5.5, 40.0)["regime"] == "delayed"


def test_the_window_from_the_fitted_file_is_within_the_tolerance_of_the_truths(fitted):
    """Issue 37's check: the same question of the material fitted from the instrument's
    export gives a window within the dh tolerance (0.5 um) of the true material's."""
    true, fit = design(TRUTH, *QUESTION), design(fitted, *QUESTION)
    for edge in ("lower", "upper"):
        assert abs(fit["physical"][edge] - true["physical"][edge]) < 0.5, (edge, fit["physical"], true["physical"])
    # Measured: within 0.01 um (docs/design.md); the 0.5 um above is the bound.
    assert abs(fit["physical"]["centre"] - true["physical"]["centre"]) < 0.05


def test_no_design_meets_conflicting_requirements_and_the_nearest_miss_is_said():
    """A 'never' at a pressure above the 'touch' one: empty, the nearest miss at the middle
    of the gap between the edges, and what dh tolerance (here none) would close it."""
    d = design(TRUTH, "--temperature", "20..40C", "--require", "touch within 1s at 10kPa", "--require",
               "never at 12kPa", "--tolerance", "dh=0.5um")
    assert d["empty"] and d["lower"] > d["upper"]
    lower, upper = d["physical"]["lower"], d["physical"]["upper"]
    mid = f"{(lower + upper) / 2:.4g}"
    assert f"the nearest miss is dh = {mid} um" in d["miss"] and "not even an exact dh" in d["miss"], d["miss"]
    r = cli("design", "--material", TRUTH, *GEOMETRY, "--temperature", "20..40C", "--require",
            "touch within 1s at 10kPa", "--require", "never at 12kPa")
    assert r.returncode == 0 and "no design meets this" in r.stdout, r.stdout
    # Only a tolerance stands between: a dh tolerance that closes the gap is named.
    d = design(TRUTH, *QUESTION[:-1], "dh=1.5um, pressure=10%")
    exact = design(TRUTH, *QUESTION[:-1], "pressure=10%")
    width = exact["physical"]["upper"] - exact["physical"]["lower"]
    assert d["empty"] and f"a dh tolerance of +- {width / 2:.4g} um or less" in d["miss"], d["miss"]


def test_one_sided_requirements_and_the_forms_a_user_writes():
    d = design(TRUTH, "--temperature", "30", "--require", "touch at once at 30kPa")
    assert d["upper"] == pytest.approx(point(TRUTH, 1.0, 30.0, 30.0)["h_0"], rel=1e-12) and d["lower"] == 0
    d = design(TRUTH, "--temperature", "30", "--require", "No touch within 1 min at 5 kPa")
    edge = d["physical"]["lower"]
    assert point(TRUTH, edge, 5.0, 30.0)["t_star"] == pytest.approx(60.0, rel=1e-6)
    assert d["physical"]["upper"] is None  # no upper edge (JSON null for infinity)
    d = design(TRUTH, "--temperature", "30", "--require", "touch at 5kPa")  # at any time: dh <= h_inf
    assert d["upper"] == pytest.approx(point(TRUTH, 1.0, 5.0, 30.0)["h_inf"], rel=1e-12)


def test_bad_requests_are_refused_by_name():
    cases = [
        (["--require", "touch soon at 30kPa"], "--require 'touch soon at 30kPa': not a requirement"),
        (["--require", "touch within 1 parsec at 30kPa"], "--require 'touch within 1 parsec at 30kPa'"),
        (["--require", "touch within 1s at -3kPa"], "the pressure is not finite and > 0"),
        ([], "give at least one --require"),
        (["--require", "never at 5kPa", "--dh", "3um"], "--dh: the design finds dh"),
        (["--require", "never at 5kPa", "--pressure", "3kPa"], "each --require names its pressure"),
        (["--require", "never at 5kPa", "--tolerance", "dh=5%"], "give its tolerance as a length"),
        (["--require", "never at 5kPa", "--tolerance", "height=1um"], "'height' is no tolerance the design takes"),
        (["--require", "never at 5kPa", "--temperature", "40..20C"], "the range's end is not above its start"),
        (["--require", "never at 5kPa", "--temperature", "-150..20C"], "outside its range"),
        # A texture option of `surface` that design does not take was "unknown option" with no
        # hint (the textures it takes: test_design_texture.py).
        (["--require", "never at 5kPa", "--curve", "cell"],
         "--curve is a texture option of `punchsweep surface` that design does not take"),
        (["--require", "never at 5kPa", "--height-map", "scan.npy"],
         "--height-map: a measured map's design finds the pressure"),
    ]
    for extra, words in cases:
        r = cli("design", "--material", TRUTH, *GEOMETRY, *extra)
        assert r.returncode == 2 and r.stdout == "" and words in r.stderr, (extra, r.stderr)


def test_python_gives_the_commands_answer():
    d = punchsweep.design(["touch within 1s at 30kPa", "never at 5kPa"], material=TRUTH, R="80um", l="250um", s=2,
                          temperature="20..40C", tolerance={"dh": "0.5um", "pressure": "10%"})
    assert d == design(TRUTH, *QUESTION)
    with pytest.raises(ValueError, match="not a requirement"):
        punchsweep.design("touch soon at 3kPa", material=TRUTH, R="80um", l="250um", s=2)


def test_a_law_without_temperature_and_the_dimensionless_units():
    """The standard linear solid in the paper's units: times in T_eps, pressures in E0*."""
    r = cli("design", "--l", "0.75", "--T", "2.5", "--s", "2", "--require", "touch within 1 at 0.06",
            "--format", "json")
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    assert d["physical"]["unit"] == "R" and d["temperatures"] == []
    check = cli("point", "--l", "0.75", "--T", "2.5", "--s", "2", "--pbar", "0.06", "--dh", repr(d["upper"]),
                "--format", "json")
    assert json.loads(check.stdout)["t_star"] == pytest.approx(1.0, rel=1e-6)


def test_the_pitch_window_for_a_given_dh_holds_and_is_tight():
    """--find l: the window of the pitch for dh = 8 um (the dh window's centre at 250 um), its
    edges checked with `point` at the binding corner (l's own tolerance, 5 um, taken off) and
    just past them; it contains the pitch the dh window was found at."""
    d = design(TRUTH, "--find", "l", "--dh", "8um", "--l", "150um..400um", *QUESTION[:-1],
               "dh=0.5um, pressure=10%, l=5um")
    assert d["quantity"] == "l" and not d["empty"] and d["physical"]["unit"] == "um"
    lower, upper = d["physical"]["lower"], d["physical"]["upper"]
    assert 150 < lower < 250 < upper < 400
    touch, never = d["requirements"]
    assert touch["side"] == "lower" and never["side"] == "upper"
    assert touch["binds_at"]["dh"] * 80 == pytest.approx(8.5) and never["binds_at"]["dh"] * 80 == pytest.approx(7.5)

    def at(l_um, dh_um, p_kPa, T):
        r = cli("point", "--material", TRUTH, "--R", "80um", "--l", f"{l_um!r}um", "--s", "2", "--dh", f"{dh_um!r}um",
                "--pressure", f"{p_kPa!r}kPa", "--temperature", T, "--format", "json")
        assert r.returncode == 0, r.stderr
        return json.loads(r.stdout)
    # The touch edge: at l = lower - 5 um, dh + 0.5 um, 27 kPa and 20 C, t* is 1 s.
    assert at(lower - 5, 8.5, 27.0, 20)["t_star"] == pytest.approx(1.0, rel=1e-6)
    assert at((lower - 5) * 0.999, 8.5, 27.0, 20)["t_star"] > 1.0
    # The never edge: just below upper + 5 um at dh - 0.5 um and 5.5 kPa the level never
    # touches; just above, it does at last.
    assert at((upper + 5) * 0.999, 7.5, 5.5, 40)["regime"] == "never"
    assert at((upper + 5) * 1.001, 7.5, 5.5, 40)["regime"] == "delayed"
    # Inside, every corner meets both requirements.
    for T in (20, 40):
        for l_um in (lower - 5, upper + 5 - 1e-6):
            for p in (27.0, 33.0):
                assert at(l_um, 8.5, p, T)["t_star"] <= 1.0 * (1 + 1e-6)
            assert at(l_um, 7.5, 5.5, T)["regime"] == "never"
    r = cli("design", "--material", TRUTH, *GEOMETRY[:2], "--s", "2", "--find", "l", "--dh", "8um", "--l", "250um",
            "--require", "never at 5kPa")
    assert r.returncode == 2 and "the range of pitches to search" in r.stderr, r.stderr
    r = cli("design", "--material", TRUTH, *GEOMETRY, "--find", "l", "--require", "never at 5kPa")
    assert r.returncode == 2 and "--find l needs --dh" in r.stderr, r.stderr


def test_the_pressure_window_for_a_given_dh_holds_and_is_tight():
    """--find pressure: the window of the nominal pressure for dh = 8 um that makes the second
    level touch within a minute but not within a second at 20-40 C, whatever dh +- 0.1 um and
    the pressure +- 2%; its edges checked with `point` at the binding corner (the pressure's
    own tolerance taken off) and just past them, and every corner inside."""
    box = "dh=0.1um, pressure=2%"
    args = ["--find", "pressure", "--dh", "8um", "--pressure", "1kPa..200kPa", "--temperature", "20..40C",
            "--require", "touch within 1min", "--require", "no touch within 1s"]
    d = design(TRUTH, *args, "--tolerance", box)
    assert d["quantity"] == "pbar" and not d["empty"] and d["physical"]["unit"] == "kPa"
    lower, upper = d["physical"]["lower"], d["physical"]["upper"]
    assert 1 < lower < upper < 200
    touch, no_touch = d["requirements"]
    assert touch["side"] == "lower" and no_touch["side"] == "upper"
    # t* falls with temperature: a minute is hardest to reach cold, a second easiest to miss warm.
    assert touch["binds_at"]["temperature"] == 20 and no_touch["binds_at"]["temperature"] == 40
    assert touch["binds_at"]["dh"] * 80 == pytest.approx(8.1) and no_touch["binds_at"]["dh"] * 80 == pytest.approx(7.9)

    def at(dh_um, p_kPa, T):
        r = cli("point", "--material", TRUTH, *GEOMETRY, "--dh", f"{dh_um!r}um", "--pressure", f"{p_kPa!r}kPa",
                "--temperature", T, "--format", "json")
        assert r.returncode == 0, r.stderr
        return json.loads(r.stdout)
    # The touch edge: at 2% under it, dh + 0.1 um and 20 C, t* is a minute; a little lower, later.
    assert at(8.1, lower * 0.98, 20)["t_star"] == pytest.approx(60.0, rel=1e-6)
    assert at(8.1, lower * 0.98 * 0.999, 20)["t_star"] > 60.0
    # The no-touch edge: at 2% over it, dh - 0.1 um and 40 C, t* is a second; a little higher, sooner.
    assert at(7.9, upper * 1.02, 40)["t_star"] == pytest.approx(1.0, rel=1e-6)
    assert at(7.9, upper * 1.02 * 1.001, 40)["t_star"] < 1.0
    # Inside, every corner meets both.
    for T in (20, 30, 40):
        for p in (lower, upper * (1 - 1e-6)):
            for dh in (7.9, 8.1):
                for side in (0.98, 1.02):
                    t_star = at(dh, p * side, T)["t_star"]
                    assert 1.0 < t_star <= 60.0 * (1 + 1e-6), (T, p, dh, side, t_star)
    # Python's, the same window.
    py = punchsweep.design(["touch within 1min", "no touch within 1s"], material=TRUTH, R="80um", l="250um", s=2,
                           temperature="20..40C", tolerance=box, find="pressure", dh="8um", pressure="1kPa..200kPa")
    assert (py["lower"], py["upper"], py["quantity"]) == (d["lower"], d["upper"], "pbar")
    # The window from the other side: the dh window at the window's centre pressure contains 8 um.
    centre = d["physical"]["centre"]
    w = design(TRUTH, "--temperature", "20..40C", "--require", f"touch within 1min at {centre!r}kPa",
               "--require", f"no touch within 1s at {centre!r}kPa", "--tolerance", box)
    assert w["physical"]["lower"] < 8.0 < w["physical"]["upper"]


def test_the_pressure_window_says_what_tolerance_would_close_a_miss():
    """Where the pressure's own tolerance empties the window, the miss names the relative
    tolerance that would leave a point, and the engine agrees on either side of it."""
    args = ["--find", "pressure", "--dh", "8um", "--pressure", "1kPa..200kPa", "--temperature", "20..40C",
            "--require", "touch within 1min", "--require", "no touch within 1s"]
    d = design(TRUTH, *args, "--tolerance", "pressure=20%")
    assert d["empty"], d
    import re
    m = re.search(r"a pressure tolerance of \+- ([0-9.]+)% or less would meet every requirement", d["miss"])
    assert m, d["miss"]
    closing = float(m.group(1))
    assert 0 < closing < 20
    assert not design(TRUTH, *args, "--tolerance", f"pressure={closing * 0.999!r}%")["empty"]
    assert design(TRUTH, *args, "--tolerance", f"pressure={closing * 1.001!r}%")["empty"]
    # Touch within a second and never cannot both hold at one pressure: not even an exact one.
    e = design(TRUTH, "--find", "pressure", "--dh", "8um", "--pressure", "1kPa..200kPa", "--temperature", "20..40C",
               "--require", "touch within 1s", "--require", "never")
    assert e["empty"] and "not even an exact pressure" in e["miss"], e["miss"]


@pytest.mark.parametrize("args, message", [
    (["--find", "pressure", "--dh", "8um", "--require", "touch within 1s"], "--find pressure needs --pressure A..B"),
    (["--find", "pressure", "--dh", "8um", "--pressure", "30kPa", "--require", "touch within 1s"],
     "the range of pressures to search"),
    (["--find", "pressure", "--dh", "8um", "--pressure", "1kPa..100kPa", "--require", "touch within 1s at 30kPa"],
     "state the requirement without 'at 30kPa'"),
    (["--find", "pressure", "--pressure", "1kPa..100kPa", "--require", "touch within 1s"], "--find pressure needs --dh"),
    (["--find", "pressure", "--dh", "8um", "--pressure", "100kPa..1kPa", "--require", "touch within 1s"],
     "the range's end is not above its start"),
    (["--require", "touch within 1s"], "no pressure: say at which"),
    (["--pressure", "1kPa..100kPa", "--require", "touch within 1s at 30kPa"], "or --find pressure"),
])
def test_the_pressure_window_refuses_what_it_cannot_answer(args, message):
    r = cli("design", "--material", TRUTH, *GEOMETRY, *args)
    assert r.returncode == 2 and message in r.stderr and r.stdout == "", (r.stderr, r.stdout)
