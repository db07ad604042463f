"""Issue 49's "typed results": `surface()`, `design()` and `surface_classify()` return
dataclasses (SurfaceResult with a SurfaceLevel per level, DesignResult with a
DesignRequirement per requirement, TextureClassification) whose attributes are the command's
JSON keys. Expected values are the command line's own `--format json` (another process, the
report's text parsed by json), key by key: every key reachable as an attribute or in
`other`, nothing dropped, and item access giving what the dict gave."""
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
MATERIAL = str(REPO / "examples" / "dma_exports" / "tpe_a_truth.ini")
HEXAGONAL = dict(lattice="hexagonal", l="200um", dh="2um", dh2="5um", R="60um", s=2, grid=32)


def command(name: str, options: dict, *repeated: tuple[str, str]) -> dict:
    argv = [BINARY, name, "--format", "json"]
    for key, value in options.items():
        argv += [f"--{key.replace('_', '-')}", str(value)]
    for key, value in repeated:
        argv += [f"--{key}", value]
    run = subprocess.run(argv, capture_output=True, text=True, cwd=REPO)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


# What differs between two runs of the same question: the clock, and whether the curve was
# read from the cache the first run filled.
RUN_TO_RUN = ("seconds", "cached")


def same(printed, returned) -> bool:
    """Equal as the JSON says: text and flags exactly, numbers (None as NaN) to 1e-12 of
    themselves (FFTW's measured plans depend on the arrays' alignment, which differs between
    two processes, in the last bits), lists elementwise; RUN_TO_RUN keys are not compared."""
    if isinstance(printed, dict):
        return set(printed) == set(returned) and all(same(printed[k], returned[k]) for k in printed if k not in RUN_TO_RUN)
    if isinstance(printed, list):
        if printed and all(isinstance(v, (int, float, type(None))) and not isinstance(v, bool) for v in printed):
            return np.allclose(np.array(printed, dtype=float), np.asarray(returned, dtype=float), rtol=1e-12, atol=0,
                               equal_nan=True)
        return len(printed) == len(returned) and all(same(a, b) for a, b in zip(printed, returned))
    if isinstance(printed, float) and not isinstance(returned, bool):
        return returned == pytest.approx(printed, rel=1e-12, abs=0)
    return printed == returned


def test_surface_is_typed_and_holds_every_key_of_the_commands_json():
    load = dict(material=MATERIAL, temperature=20, pressure="5kPa", times="0,1,10", tolerance="pressure=5%")
    printed = command("surface", {**HEXAGONAL, **load})
    r = punchsweep.surface(**HEXAGONAL, **load, check=False)
    assert isinstance(r, punchsweep.SurfaceResult) and r.other == {}
    assert list(r) == list(printed)  # the keys, in the command's order
    assert same(printed, dict(r)) and same(printed["levels"], [dict(level) for level in r["levels"]])
    # Attributes are the keys; a level's d t*/dx, t* range and corners are gathered.
    assert [level.regime for level in r.levels] == [level["regime"] for level in printed["levels"]]
    one = printed["levels"][1]
    assert r.levels[1].t_star == one["t_star"] and r.levels[1].X_star == one["X_star"]
    assert r.levels[1].t_star_range == (one["t_star_low"], one["t_star_high"])
    assert r.levels[1].sensitivity["dt_star_dpbar"] == one["dt_star_dpbar"]
    assert r.levels[1].corner_regimes == {"immediate": one["corners_immediate"], "delayed": one["corners_delayed"],
                                          "never": one["corners_never"]}
    assert isinstance(r.series["t"], np.ndarray) and r.series["valid"].dtype == bool
    assert r.check is None and "check" not in r and r.physical["units"]["X"] == "Pa"


def test_a_key_the_engine_gains_lands_in_other_not_nowhere():
    raw = command("surface", dict(l=0.75, dh=0.03, T=2.5, pbar=0.01, s=2, grid=32))
    raw["a_new_output"] = [1, 2]
    raw["levels"][0]["a_new_level_output"] = 3
    r = punchsweep.SurfaceResult.from_json(raw)
    assert r.other == {"a_new_output": [1, 2]} and r["a_new_output"] == [1, 2]
    assert r.levels[0].other == {"a_new_level_output": 3} and r["levels"][0]["a_new_level_output"] == 3
    with pytest.raises(KeyError):
        r["no_such_key"]


def test_design_is_typed_and_holds_every_key_of_the_commands_json():
    options = dict(material=MATERIAL, temperature="20C", **HEXAGONAL)
    del options["dh"]
    requirements = ["touch within 1s at 30kPa", "never at 5kPa"]
    printed = command("design", options, *(("require", text) for text in requirements))
    r = punchsweep.design(requirements, **options)
    assert isinstance(r, punchsweep.DesignResult) and r.other == {}
    assert list(r) == list(printed) and same(printed, dict(r))
    assert (r.quantity, r.empty) == (printed["quantity"], False)
    assert same([printed["lower"], printed["upper"]], [r.lower, r.upper])
    assert [q.text for q in r.requirements] == requirements
    for q, p in zip(r.requirements, printed["requirements"]):
        assert isinstance(q, punchsweep.DesignRequirement) and q.other == {}
        assert q.side == p["side"] and same(p["edge"], q.edge) and same(p["binds_at"], q.binds_at)
    assert r.texture["lattice"] == "hexagonal" and r.texture["levels"] == 3


def test_surface_classify_is_typed_and_reads_as_surface_at_each_load():
    texture = dict(HEXAGONAL, material=MATERIAL)
    pressures = ["5kPa", "30kPa"]
    c = punchsweep.surface_classify(pressure=pressures, temperature=20, **texture)
    assert isinstance(c, punchsweep.TextureClassification)
    assert c.levels == 3 and c.t_star.shape == (2, 3) and c["t_star"] is c.t_star and len(c) == 7
    for k, pressure in enumerate(pressures):
        one = command("surface", {**texture, "temperature": 20, "pressure": pressure, "times": "0"})
        names = [level["regime"] for level in one["levels"]]
        assert list(c.regime_names()[k]) == names
        for level, printed in enumerate(one["levels"]):
            expected = np.inf if printed["t_star"] is None else printed["t_star"]
            assert c.t_star[k, level] == pytest.approx(expected, rel=1e-9)


def test_to_dict_gives_the_commands_json_back_and_the_picture_reads_it(tmp_path):
    """json.dump(r.to_dict()) writes what `--format json` prints, so the scripts that read a
    design's JSON (postprocess/design_picture.py) draw a window made in Python."""
    options = dict(material=MATERIAL, temperature="20..40C", **HEXAGONAL)
    del options["dh"]
    requirements = ["touch within 1s at 30kPa", "never at 5kPa"]
    printed = command("design", options, *(("require", text) for text in requirements))
    r = punchsweep.design(requirements, **options)
    plain = r.to_dict()
    assert type(plain) is dict and type(plain["requirements"][0]) is dict and same(printed, plain)
    written = tmp_path / "window.json"
    written.write_text(json.dumps(plain))
    picture = tmp_path / "window.png"
    run = subprocess.run(["/usr/bin/python3", str(REPO / "postprocess" / "design_picture.py"), str(written),
                          "-o", str(picture)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert picture.stat().st_size > 10_000
    surface = punchsweep.surface(l=0.75, dh=0.03, T=2.5, pbar=0.01, s=2, grid=32)
    assert same(command("surface", dict(l=0.75, dh=0.03, T=2.5, pbar=0.01, s=2, grid=32)),
                json.loads(json.dumps(surface.to_dict())))
