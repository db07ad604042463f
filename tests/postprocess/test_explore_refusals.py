"""postprocess/explore.py on what a probe found: a surface map's page is thinned by --every and
its size estimated from the axes' lengths before any of its arrays is read (a map far above
--max-mb refused at once, naming the --every that fits); a surface map with one axis besides
level is drawn (that axis across, the levels up); a forged texture keyword is refused, and every
word of a clicked cell's command is quoted for the shell; a --design that is no regular file,
or whose edges are text, is refused by name (exit 2, one line, nothing written)."""
from __future__ import annotations

import json
import os
import re
import shlex
import shutil
import subprocess

import h5py
import pytest

from test_explore import ENGINE, REPO, embedded, explore, in_chromium, tpe_map_and_window


def surface_map(path, *axes: str) -> None:
    """`punchsweep surface-map` of a hexagonal texture (two levels below the tallest caps),
    over the given axes (options and values)."""
    subprocess.run([ENGINE, "surface-map", "--lattice", "hexagonal", "--l", "1.2", "--dh2", "0.09", "--s", "2",
                    "--grid", "48", *axes, "--output", path], check=True, capture_output=True)


@pytest.fixture(scope="module")
def surface(tmp_path_factory):
    """A small surface map (dh x pbar x T) and a larger one, whose page is 7.5 MB."""
    tmp = tmp_path_factory.mktemp("surface")
    small, large = tmp / "small.nc", tmp / "large.nc"
    surface_map(small, "--dh", "0.04,0.05,0.06", "--pbar", "logspace(0.002,0.05,9)", "--T", "2,4",
                "--times", "0,1,5")
    surface_map(large, "--dh", "0.04,0.06", "--pbar", "logspace(0.001,0.05,400)", "--T", "linspace(1.5,8,150)",
                "--times", "0,0.5,1,2,5,10,20,50")
    return small, large


def test_every_thins_a_surface_maps_axes(surface, tmp_path):
    small, _ = surface
    page = tmp_path / "p.html"
    done = explore(small, "-o", page, "--every", "dh=2", "pbar=3")
    assert done.returncode == 0, done.stderr
    d = embedded(page)
    with h5py.File(small) as f:
        names = [dim[0].name.rsplit("/", 1)[-1] for dim in f["regime"].dims]
        want = {n: f[n][...] for n in names}
    shape = dict(zip([a["name"] for a in d["axes"]], d["shape"]))
    assert shape["dh"] == 2 and shape["pbar"] == 3 and shape["T"] == 2 and d["coarsened"] == {"dh": 2, "pbar": 3}
    for a in d["axes"]:
        step = {"dh": 2, "pbar": 3}.get(a["name"], 1)
        assert a["values"] == pytest.approx(list(want[a["name"]][::step]), rel=0)
    done = explore(small, "-o", tmp_path / "q.html", "--every", "level=2")
    assert done.returncode == 2 and "the levels are the map's answer" in done.stderr, done.stderr


def test_a_surface_map_far_above_max_mb_is_refused_before_its_arrays_are_read(surface, monkeypatch, tmp_path):
    import script_runner
    import explore as explore_module
    _, large = surface
    whole = tmp_path / "whole.html"
    assert explore(large, "-o", whole).returncode == 0
    ds = explore_module.open_surface_map(str(large))
    assert explore_module.surface_estimate_mb(ds, {}) == pytest.approx(whole.stat().st_size / 1e6, rel=0.15)

    def read(*args, **kwargs):
        raise AssertionError("a page array was read before the size was checked")

    monkeypatch.setattr(explore_module, "surface_array", read)
    monkeypatch.setattr(explore_module, "surface_payload", read)
    rc, _, err = script_runner.call(explore_module, large, "-o", tmp_path / "p.html", "--max-mb", "4")
    assert rc == 2 and "(estimated), above --max-mb 4" in err and "Traceback" not in err, err
    every = re.search(r"--every (\w+)=(\d+)", err)
    assert every and every[1] == "pbar" and not (tmp_path / "p.html").exists(), err
    monkeypatch.undo()
    done = explore(large, "-o", tmp_path / "p.html", "--max-mb", "4", "--every", f"{every[1]}={every[2]}")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "p.html").stat().st_size <= 4e6


@pytest.fixture(scope="module")
def one_axis(tmp_path_factory):
    """A cell file's texture under a material without a temperature shift, over the pressure
    alone: a surface map whose axes are pbar and level."""
    path = tmp_path_factory.mktemp("one_axis") / "cell.nc"
    subprocess.run([ENGINE, "surface-map", "--cell", REPO / "examples" / "cells" / "hexagonal_two_level.ini",
                    "--material", REPO / "materials" / "silicone_elite_double32.ini", "--R", "80um",
                    "--pressure", "1kPa,5kPa,20kPa,50kPa", "--times", "0,1s", "--grid", "48", "--output", path],
                   check=True, capture_output=True)
    with h5py.File(path) as f:
        assert [dim[0].name.rsplit("/", 1)[-1] for dim in f["regime"].dims] == ["pbar", "level"]
    return path


def test_a_surface_map_with_one_axis_besides_level_is_drawn_against_the_levels(one_axis, tmp_path):
    """(This ended in StopIteration.)"""
    page = tmp_path / "cell.html"
    done = explore(one_axis, "-o", page)
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr
    assert "one axis besides level (pbar)" in done.stderr
    d = embedded(page)
    assert (d["x"], d["y"], d["shape"]) == ("pbar", "level", [4, 2])
    done = explore(one_axis, "-o", tmp_path / "p.html", "--y", "pbar")
    assert done.returncode == 2 and "--x and --y are both pbar" in done.stderr, done.stderr


@pytest.mark.browser
def test_a_one_axis_surface_maps_page_in_chromium(one_axis, tmp_path):
    """The pressure across and the levels up: each cell reads its level's regime and t* as the
    file holds them, and its command, run, gives that level's."""
    page = tmp_path / "cell.html"
    assert explore(one_axis, "-o", page).returncode == 0
    r, _ = in_chromium(page, [[0, 0], [3, 1], [1, 1]], tmp_path)
    with h5py.File(one_axis) as f:
        codes = dict(zip(f["regime"].attrs["flag_values"], f["regime"].attrs["flag_meanings"].split()))
        for cell in r["cells"]:
            (ip, level) = cell["index"]
            assert (ip, level) == (cell["ix"], cell["iy"])
            assert cell["regime"] == codes[f["regime"][ip, level]]
            argv = shlex.split(cell["command"])
            assert argv[:2] == ["punchsweep", "surface"] and "--level" not in argv
            run = subprocess.run([ENGINE, *argv[1:], "--format", "json"], capture_output=True, text=True)
            assert run.returncode == 0, (argv, run.stderr)
            assert json.loads(run.stdout)["levels"][level]["regime"] == cell["regime"]


def test_a_forged_texture_keyword_is_refused(surface, tmp_path):
    small, _ = surface
    forged = tmp_path / "forged.nc"
    shutil.copy(small, forged)
    with h5py.File(forged, "r+") as f:
        texture = json.loads(f.attrs["texture"])
        f.attrs["texture"] = json.dumps({"lattice; touch PWNED; #": "hexagonal", **texture})
    done = subprocess.run(["/usr/bin/python3", REPO / "postprocess" / "explore.py", forged, "-o", "p.html"],
                          capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 2 and "'lattice; touch PWNED; #'" in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and not (tmp_path / "p.html").exists()
    assert not (tmp_path / "PWNED").exists()


@pytest.mark.browser
def test_every_word_of_a_clicked_cells_command_is_quoted_for_the_shell(tmp_path):
    """A regime map whose localization attribute is forged: the clicked cell's command, pasted
    into a shell, runs nothing it names (every word quoted; the engine refuses the option)."""
    path = tmp_path / "map.h5"
    subprocess.run([ENGINE, "sweep", "--grid.l", "0.75", "--grid.dh", "linspace(0.02,0.12,6)", "--grid.T", "2.5",
                    "--grid.pbar", "logspace(0.005,0.08,5)", "--grid.s", "2", "--output", path, "--quiet"], check=True)
    with h5py.File(path, "r+") as f:
        f.attrs["localization"] = "periodic; touch PWNED; #"
    page = tmp_path / "map.html"
    done = explore(path, "-o", page)
    assert done.returncode == 0, done.stderr
    r, _ = in_chromium(page, [[0, 0], [3, 4]], tmp_path)
    for cell in r["cells"]:
        command = cell["command"].split("\n")[0]
        argv = shlex.split(command)
        assert argv[argv.index("--localization") + 1] == "periodic; touch PWNED; #", command
        subprocess.run(["bash", "-c", command.replace("punchsweep", shlex.quote(ENGINE), 1)], capture_output=True,
                       cwd=tmp_path)
        assert not (tmp_path / "PWNED").exists(), command


@pytest.fixture(scope="module")
def window(tmp_path_factory):
    """A regime map over dh and the pressure, and a design window of dh
    (`punchsweep design --format json`) for it."""
    path, text = tpe_map_and_window(tmp_path_factory.mktemp("design"),
                                    ["--require", "touch within 1s at 30kPa", "--require", "never at 5kPa"],
                                    dh_values=5, pressures=4)
    return path, json.loads(text)


@pytest.mark.parametrize("tamper, field", [
    (lambda d: d.__setitem__("lower", "none"), 'lower = "none" is not a number or null'),
    (lambda d: d.__setitem__("upper", "0.1"), 'upper = "0.1" is not a number or null'),
    (lambda d: d["physical"].__setitem__("lower", "7.5"), 'physical.lower = "7.5" is not a number or null'),
    (lambda d: d["physical"].__setitem__("upper", None), "physical.upper = null is not a finite number"),
    (lambda d: d.__setitem__("physical", "um"), 'physical = "um" is not an object'),
    (lambda d: d.__setitem__("empty", "no"), 'empty = "no" is not true or false'),
], ids=["lower", "upper", "physical.lower", "physical.upper", "physical", "empty"])
def test_a_design_window_with_text_edges_is_refused_by_the_field(window, tmp_path, tamper, field):
    path, d = window
    d = json.loads(json.dumps(d))
    tamper(d)
    bad = tmp_path / "window.json"
    bad.write_text(json.dumps(d))
    done = explore(path, "-o", tmp_path / "p.html", "--design", bad)
    assert done.returncode == 2 and f"--design {bad}: {field}" in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and len(done.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "p.html").exists()


def test_a_design_window_that_is_no_regular_file_is_refused(window, tmp_path):
    path, d = window
    good = tmp_path / "window.json"
    good.write_text(json.dumps(d))
    assert explore(path, "-o", tmp_path / "good.html", "--design", good).returncode == 0
    fifo = tmp_path / "window.fifo"
    os.mkfifo(fifo)
    for design, kind in ((fifo, "a pipe"), (tmp_path, "a folder")):
        done = subprocess.run(["/usr/bin/python3", REPO / "postprocess" / "explore.py", path, "-o",
                               tmp_path / "p.html", "--design", design], capture_output=True, text=True, timeout=60)
        assert done.returncode == 2 and f"--design {design} is {kind}" in done.stderr, done.stderr
        assert not (tmp_path / "p.html").exists()
