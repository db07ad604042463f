"""docs/design.md's walk-through, DMA file -> fit -> design window -> picture, run as written
(each command of its sh block, `punchsweep` the engine under test, `> FILE` as the shell
would) in a scratch folder, and its Python block; the printed window checked against the
one the page shows, the picture's curves against the JSON's bounds."""
from __future__ import annotations

import json
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
ENGINE = os.environ.get("PUNCHSWEEP", str(REPO / "build/src/app/punchsweep"))
DOC = REPO / "docs" / "design.md"
sys.path.insert(0, str(REPO / "postprocess"))
import design_picture  # noqa: E402
from script_runner import call  # noqa: E402


def block(kind: str, containing: str) -> str:
    blocks = [b for b in re.findall(rf"```{kind}\n(.*?)```", DOC.read_text(), flags=re.S) if containing in b]
    assert len(blocks) == 1, f"expected one {kind} block with {containing!r} in docs/design.md"
    return blocks[0]


def window_numbers(text: str) -> list[float]:
    line = next(x for x in text.splitlines() if x.startswith("window:"))
    return [float(v) for v in re.findall(r"(\d+\.?\d*) um", line)]


@pytest.fixture(scope="module")
def recipe(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("design")
    for name in ("examples", "postprocess"):
        (tmp / name).symlink_to(REPO / name)
    printed = []
    for command in block("sh", "punchsweep fit").replace("\\\n", " ").splitlines():
        if not command.strip():
            continue
        argv = shlex.split(command)
        target = None
        if ">" in argv:
            argv, target = argv[:argv.index(">")], argv[argv.index(">") + 1]
        if argv[0] == "punchsweep":
            argv = [ENGINE, *argv[1:]]
        elif argv[0].endswith(".py"):
            argv = [sys.executable, *argv]
        r = subprocess.run(argv, cwd=tmp, capture_output=True, text=True)
        assert r.returncode == 0, (command, r.stderr)
        if target:
            (tmp / target).write_text(r.stdout)
        printed.append(r.stdout)
    return tmp, printed


def test_the_walk_through_prints_the_window_the_page_shows(recipe):
    tmp, printed = recipe
    assert (tmp / "tpe_a.ini").is_file() and (tmp / "window.png").stat().st_size > 10_000
    shown = window_numbers(block("text", "punchsweep design: the height difference"))
    got = window_numbers(printed[1])
    # lower, upper, centre, margin: as the page shows them, to their last printed digit.
    assert np.allclose(got, shown, atol=0.002), (got, shown)
    d = json.loads((tmp / "window.json").read_text())
    assert [d["physical"][k] for k in ("lower", "upper", "centre")] == pytest.approx(got[:3], abs=0.0006)


def test_the_pictures_curves_are_the_designs_bounds(recipe):
    """What design_picture.py draws, by another route than the image: each curve's tightest
    point is its requirement's edge, at the temperature the JSON says it binds."""
    tmp, _ = recipe
    d = json.loads((tmp / "window.json").read_text())
    for r, Ts, edge in design_picture.bound_curves(d):
        k = int(np.argmin(edge)) if r["side"] == "upper" else int(np.argmax(edge))
        assert edge[k] == pytest.approx(r["edge_physical"], rel=1e-12)
        if not r["binds_at"]["every_temperature"]:
            assert Ts[k] == r["binds_at"]["temperature"]
    assert list(Ts) == d["temperatures"]


def test_the_picture_refuses_what_is_no_design(tmp_path):
    (tmp_path / "x.json").write_text('{"kind": "dma"}')
    rc, _, err = call(design_picture, tmp_path / "x.json", "-o", tmp_path / "x.png")
    assert rc == 2 and "not the JSON of `punchsweep design --format json`" in err
    assert not (tmp_path / "x.png").exists()


def test_the_python_block_runs_and_says_what_its_comment_says(monkeypatch, capsys):
    pytest.importorskip("punchsweep")
    monkeypatch.chdir(REPO)
    text = block("python", "punchsweep.design(")
    exec(text, {})  # noqa: S102 - the page's own text
    first = capsys.readouterr().out.splitlines()[0].split()
    comment = re.search(r"# ([\d.]+) ([\d.]+) um", text)
    assert [round(float(first[0]), 3), round(float(first[1]), 3), first[2]] == \
        [float(comment[1]), float(comment[2]), "um"]


def test_the_readme_design_example_prints_what_it_shows():
    readme = (REPO / "README.md").read_text()
    example = next(b for b in re.findall(r"```sh\n(.*?)```", readme, flags=re.S) if "punchsweep design" in b)
    lines = example.splitlines()
    n = next(k for k, x in enumerate(lines) if not x.endswith("\\")) + 1  # the command and its continuations
    argv = shlex.split(" ".join(x.rstrip("\\") for x in lines[:n]).removeprefix("$ "))
    shown = "\n".join(lines[n:])
    r = subprocess.run([ENGINE, *argv[1:]], cwd=REPO, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    for line in shown.splitlines():
        assert line.strip() in r.stdout, (line, r.stdout)


def test_the_pitch_window_the_page_shows(recipe):
    """docs/design.md's --find l example (the question at dh = 8 um, l's own tolerance 5 um,
    on the true material) prints the window the page shows."""
    tmp, _ = recipe
    r = subprocess.run([ENGINE, "design", "--find", "l", "--dh", "8um", "--l", "150um..400um", "--material",
                        "examples/dma_exports/tpe_a_truth.ini", "--R", "80um", "--s", "2", "--temperature", "20..40C", "--require",
                        "touch within 1s at 30kPa", "--require", "never at 5kPa", "--tolerance",
                        "dh=0.5um, pressure=10%, l=5um"], cwd=tmp, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    shown = window_numbers(block("text", "l >= "))
    assert np.allclose(window_numbers(r.stdout), shown, rtol=2e-3), (r.stdout, shown)


def test_the_pressure_window_the_page_shows():
    """docs/design.md's --find pressure example, run as written, prints the lines the page shows."""
    argv = shlex.split(block("sh", "--find pressure --dh 8um").replace("\\\n", " "))
    assert argv[:2] == ["punchsweep", "design"]
    r = subprocess.run([ENGINE, *argv[1:]], cwd=REPO, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    for line in block("text", "touch within 1min: pressure >= ").strip().splitlines():
        assert line.strip() in r.stdout, (line, r.stdout)


@pytest.mark.parametrize("command, printed", [
    ("--dh2 5um --temperature 20..40C", "hexagonal lattice of 3 levels; the requirements on level 1"),
    ("--dh 2um --dh2 5um --supercell 3", "90% of level 1 within 1min: pressure >="),
    ("--temperature 20 --require \"touch within 1s at 30kPa\"", "touch within 1s at 30kPa: dh <= 7.13 um"),
    ("--require \"90% of level 1 within 1min at 20kPa\"", "90% of level 1 within 1min at 20kPa: dh <= 6.877 um"),
])
def test_the_texture_windows_the_page_shows(command, printed):
    """docs/design.md's texture examples (a hexagonal three-level mould's dh window; a scattered
    one's pressure window from shares of caps, its dh window from the level's first cap and
    from shares of the level's caps),
    run as written, print the lines the page shows."""
    argv = shlex.split(block("sh", command).replace("\\\n", " "))
    assert argv[:2] == ["punchsweep", "design"]
    r = subprocess.run([ENGINE, *argv[1:]], cwd=REPO, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    for line in block("text", printed).strip().splitlines():
        assert line.strip() in r.stdout, (line, r.stdout)
