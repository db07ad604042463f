"""Physical advisories (issue 25; docs/model.md, section 16): where a valid point stands for
less than it seems. Expected values are computed here from the point's own long-term radii
and the shape, by the documented rules (a paraboloid for a sphere to a = 0.3 R; the cap's
base radius sqrt(H (2R - H)); Tabor's strain 0.2 f'(a) against 10%)."""
from __future__ import annotations

import json
import math
import os
import subprocess
from pathlib import Path

import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
SILICONE = REPO / "materials" / "silicone_elite_double32.ini"


def expected(r, s=2, C=0.5, cap=None):
    a = max(r.a1_inf, r.a2_inf)
    strain = 0.2 * C * s * a ** (s - 1)
    raised = []
    if s == 2 and C == 0.5 and a > 0.3:
        raised.append("beyond_paraboloid")
    if cap is not None and a > cap:
        raised.append("beyond_cap")
    if strain > 0.1:
        raised.append("large_strain")
    return ", ".join(raised), strain


@pytest.mark.parametrize("kw", [
    dict(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2),       # a1 0.35 R: beyond the paraboloid
    dict(l=3.0, dh=0.04, T=2.5, pbar=0.0005, s=2),       # small spots: none
    dict(l=0.75, dh=0.02, T=2.5, pbar=0.05, s=1, C=0.3),  # a cone: its slope sets the strain
])
def test_the_advisories_follow_the_radii_by_the_documented_rules(kw):
    r = punchsweep.point(**kw)
    names, strain = expected(r, kw["s"], kw.get("C", 0.5))
    assert r.advisories == names
    assert r.strain == pytest.approx(strain, rel=1e-12)
    assert r.valid  # advisories are not validity
    assert bool(r.advisory_reason) == bool(names)


def test_the_issues_case_is_advised():
    """100 kPa on the silicone under caps of R = 50 um: a1 = 0.64 R was 'valid'."""
    r = punchsweep.point(material=SILICONE, R="50um", l="150um", dh="2um", pressure="100kPa", s=2)
    assert r.valid and r.a1_inf > 0.6
    assert r.advisories == "beyond_paraboloid, large_strain"
    assert "0.3 R" in r.advisory_reason and "10%" in r.advisory_reason


def test_a_cap_of_finite_size(tmp_path):
    base = dict(material=SILICONE, R="50um", l="150um", dh="2um", pressure="2kPa", s=2)
    r = punchsweep.point(**base)
    a_um = max(r.a1_inf, r.a2_inf) * 50
    inside = punchsweep.point(cap_radius=f"{a_um * 1.01!r}um", **base)
    outside = punchsweep.point(cap_radius=f"{a_um * 0.99!r}um", **base)
    assert "beyond_cap" not in inside.advisories and "beyond_cap" in outside.advisories
    # The height of a sphere's cap gives its base radius: B = sqrt(H (2R - H)).
    H = 50 - math.sqrt(50**2 - (a_um * 0.99) ** 2)
    by_height = punchsweep.point(cap_height=f"{H!r}um", **base)
    assert "beyond_cap" in by_height.advisories
    # JSON and the table say it too.
    done = subprocess.run([BINARY, "point", "--material", SILICONE, "--R", "50um", "--l", "150um", "--dh", "2um",
                           "--pressure", "2kPa", "--s", "2", "--cap-radius", f"{a_um * 0.99!r}um", "--format", "json"],
                          capture_output=True, text=True, check=True)
    d = json.loads(done.stdout)
    assert d["advisories"] == "beyond_cap" and "base radius" in d["advisory_reason"]


@pytest.mark.parametrize("args, message", [
    (["--cap-radius", "1um", "--cap-height", "1um"], "not both"),
    (["--cap-height", "60um"], "0 < H <= R"),
    (["--cap-radius", "2kPa"], "--cap-radius"),
    (["--cap-radius", "-1um"], "B > 0"),
])
def test_bad_cap_options_are_refused(args, message):
    done = subprocess.run([BINARY, "point", "--material", SILICONE, "--R", "50um", "--l", "150um", "--dh", "2um",
                           "--pressure", "2kPa", "--s", "2", *args], capture_output=True, text=True)
    assert done.returncode == 2 and message in done.stderr, done.stderr
