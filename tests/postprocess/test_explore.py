"""postprocess/explore.py (issue 26): the explorer page of a regime map. The data the page
embeds decode to the map's arrays bit for bit; in headless Chromium (Debian's, driven by
playwright-core: tests/browser) the page loads with no network request and no console
error, hovering a cell reads the regime, t* and radii the map holds at that index (read
here with h5py), a slider moves the slice, the time slider moves the series, and a
screenshot is non-blank. The browser part skips, saying why, where Chromium, node or
playwright-core is missing (bash cmake/install-deps.sh installs them)."""
from __future__ import annotations

import base64
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import zlib
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
ENGINE = os.environ.get("PUNCHSWEEP", str(REPO / "build/src/app/punchsweep"))
EXPLORE = REPO / "postprocess" / "explore.py"
DRIVER = REPO / "tests" / "browser" / "explore_page.mjs"
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")


def explore(*args):
    return subprocess.run(["/usr/bin/python3", EXPLORE, *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def maps(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("explore")
    default = tmp / "default.h5"  # the default grid, full mode: 104,328 points
    subprocess.run([ENGINE, "sweep", "--output", default, "--quiet"], check=True)
    material = tmp / "material.h5"
    subprocess.run([ENGINE, "sweep", "--model.material", REPO / "materials" / "pla_prusament_chapuis2025.ini",
                    "--model.R", "50um", "--grid.l", "150um", "--grid.dh", "linspace(0.05um,3um,12)",
                    "--grid.pressure", "logspace(0.2MPa,20MPa,10)", "--grid.temperature", "50,60,70", "--grid.s", "2",
                    "--grid.ramp_time", "10s,30s", "--output", material, "--quiet"], check=True)
    pages = {}
    for name, path in (("default", default), ("material", material)):
        page = tmp / f"{name}.html"
        done = explore(path, "-o", page)
        assert done.returncode == 0, done.stderr
        pages[name] = (path, page)
    return pages


def embedded(page: Path) -> dict:
    text = page.read_text(encoding="utf-8")
    data = re.search(r'<script id="map-data" type="application/json">(.*?)</script>', text, flags=re.S).group(1)
    return json.loads(data.replace("<\\/", "</"))


def decode(packed: str, dtype: str) -> np.ndarray:
    return np.frombuffer(zlib.decompress(base64.b64decode(packed)), dtype=dtype)


@pytest.mark.parametrize("which", ["default", "material"])
def test_the_page_embeds_the_maps_arrays_bit_for_bit(maps, which):
    path, page = maps[which]
    d = embedded(page)
    assert page.stat().st_size < 40e6 and "cdn" not in page.read_text()[:2000].lower()
    with h5py.File(path) as f:
        names = [a["name"] for a in d["axes"]]
        assert d["shape"] == list(f["regime"].shape)
        for v in ("t_star", "a1_inf", "a2_inf", "h_0", "h_inf"):
            got = decode(d["variables"][v]["data"], "<f8").reshape(d["shape"])
            scale = d["variables"][v].get("unit")
            want = f[v][...]
            if which == "material" and v != "t_star":  # lengths shown in um: file value x 50
                want = want * 50.0
            assert np.array_equal(got, want, equal_nan=True) or np.allclose(got, want, rtol=1e-15, equal_nan=True), (v, scale)
        assert np.array_equal(decode(d["flags"]["regime"]["data"], "<i1").reshape(d["shape"]), f["regime"][...])
        series = decode(d["series"]["a2"]["data"], "<f8").reshape(d["shape"] + [len(d["time"])])
        assert series.shape == f["a2"].shape
        for a in d["axes"]:
            assert np.allclose(a["scaled"], f[a["name"]][...], rtol=1e-15)
        assert names == [dim[0].name.rsplit("/", 1)[-1] for dim in f["regime"].dims]


def test_refusals_and_the_size_limit(maps, tmp_path):
    path, _ = maps["default"]
    for args, message in ((["--x", "bogus"], "--x bogus: not an axis"), (["--max-mb", "5"], "above --max-mb 5"),
                          (["--every", "dh=0"], "whole number >= 1"), (["--every", "zz=2"], "'zz' is not an axis")):
        out = tmp_path / "p.html"
        done = explore(path, "-o", out, *args)
        assert done.returncode == 2 and message in done.stderr and not out.exists(), done.stderr
    done = explore(path, "-o", tmp_path / "coarse.html", "--every", "dh=2")
    assert done.returncode == 0
    with h5py.File(path) as f:
        n = f["dh"].shape[0]
    assert embedded(tmp_path / "coarse.html")["shape"][1] == (n + 1) // 2


def browser_missing() -> str | None:
    if not Path(CHROMIUM).exists():
        return f"no Chromium at {CHROMIUM} (bash cmake/install-deps.sh installs Debian's chromium)"
    if shutil.which("node") is None:
        return "no node (bash cmake/install-deps.sh installs nodejs)"
    if not (REPO / "tests" / "browser" / "node_modules" / "playwright-core").is_dir():
        return "no playwright-core in tests/browser/node_modules (bash cmake/install-deps.sh runs npm install there)"
    return None


def in_chromium(page: Path, cells: list, tmp_path: Path):
    """The page driven by tests/browser/explore_page.mjs (skipped, saying why, without a
    browser): what it read, after checking it made no request and logged no error; and the
    screenshot's path."""
    missing = browser_missing()
    if missing:
        pytest.skip(missing)
    (tmp_path / "cells.json").write_text(json.dumps(cells))
    out, shot = tmp_path / "out.json", tmp_path / "shot.png"
    done = subprocess.run(["node", DRIVER, page, tmp_path / "cells.json", out, shot], capture_output=True, text=True,
                          timeout=180)
    assert done.returncode == 0, done.stderr
    r = json.loads(out.read_text())
    assert r["requests"] == [] and r["errors"] == []
    return r, shot


def regime_axes_and_codes(f):
    """A map file's regime: its dimensions' names in order, and its codes by meaning."""
    names = [dim[0].name.rsplit("/", 1)[-1] for dim in f["regime"].dims]
    meanings = f["regime"].attrs["flag_meanings"]
    meanings = (meanings.decode() if isinstance(meanings, bytes) else meanings).split()
    return names, dict(zip(f["regime"].attrs["flag_values"], meanings))


@pytest.mark.browser
@pytest.mark.parametrize("which", ["default", "material"])
def test_the_page_in_chromium(maps, tmp_path, which):
    path, page = maps[which]
    r, shot = in_chromium(page, [[0, 0], [4, 6], [9, 11], [7, 3]], tmp_path)
    with h5py.File(path) as f:
        names, codes = regime_axes_and_codes(f)
        length = 50.0 if which == "material" else 1.0  # the page shows lengths in um
        for cell in r["cells"]:
            index = tuple(cell["index"])
            assert index[names.index("pbar")] == cell["ix"] and index[names.index("dh")] == cell["iy"]
            assert cell["regime"] == codes[f["regime"][index]]
            t = f["t_star"][index]
            assert (cell["t_star"] is None and np.isnan(t)) or cell["t_star"] == t
            assert cell["a1_inf"] == pytest.approx(f["a1_inf"][index] * length, rel=1e-15)
            assert cell["a2_inf"] == pytest.approx(f["a2_inf"][index] * length, rel=1e-15)
            # The area fractions the page computes from the radii (not embedded): the file's.
            assert cell["area_fraction_inf"] == pytest.approx(f["area_fraction_inf"][index], rel=1e-14)
            if "area_fraction" in f:
                assert cell["area_fraction"] == pytest.approx(list(f["area_fraction"][index]), rel=1e-14)
            # The hover read-out (what a user sees) is of that cell: its regime, and t* and a1_inf
            # to the 6 digits it prints.
            assert f"regime: {cell['regime']}" in cell["readout"]
            shown = dict(line.split(" = ", 1) for line in cell["readout"].splitlines() if " = " in line)
            for name, want in (("t_star", t), ("a1_inf", f["a1_inf"][index] * length)):
                number = shown[name].split()[0]
                assert (number == "NaN" and np.isnan(want)) or float(number) == pytest.approx(want, rel=1e-5), name
    assert r["slider"] is not None and r["slider"]["changed"]
    if which == "default":  # issue 37 item 6: the default map's page under 20 MB (27.1 MB before)
        assert page.stat().st_size < 20e6
    assert r["time_slider"] == {"changed": True}
    assert r["command"].startswith("punchsweep point --l ")
    # Each cell's command, run as the page gives it, says what the map says there; on the
    # material map it is in the map's units (um, kPa, --R) and names the material file as
    # the sweep was given it (issue 37 item 5).
    for cell in r["cells"]:
        argv = shlex.split(cell["command"].split("\n")[0])
        if which == "material":
            assert "--pressure" in argv and argv[argv.index("--l") + 1].endswith("um") and "--R" in argv, argv
            assert argv[argv.index("--material") + 1] == str(REPO / "materials" / "pla_prusament_chapuis2025.ini")
        done = subprocess.run([ENGINE, *argv[1:], "--format", "json"], capture_output=True, text=True)
        assert done.returncode == 0, (argv, done.stderr)
        point = json.loads(done.stdout)
        assert point["regime"] == cell["regime"]
        assert (point["t_star"] is None and cell["t_star"] is None) or \
            point["t_star"] == pytest.approx(cell["t_star"], rel=1e-12)
    import matplotlib.image
    pixels = matplotlib.image.imread(shot)
    assert shot.stat().st_size > 50_000 and pixels.shape[0] >= 900 and float(pixels[..., :3].std()) > 0.05


# Issue 35 item 4: the map's texts are data, never markup. A material's name that opens an
# HTML comment and a script, a link, quotes, an ampersand and unicode; material files (the
# material axis's labels) and a map file named with tags and quotes; an axis long_name
# with a tag.
HOSTILE_NAME = '<!--<script>alert(1)</script> <a href="https://example.com/x">link</a> "Q" \'s & ünï µm'
HOSTILE_FILES = ('ev<b>il "q" ü', "pl<a href=x>ain")


@pytest.fixture(scope="module")
def hostile(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("hostile")
    for stem, name, E_i in zip(HOSTILE_FILES, (HOSTILE_NAME, "plain"), (9, 4)):
        (tmp / f"{stem}.ini").write_text(f"[material]\nname = {name}\nlaw = prony\nmodulus_unit = MPa\n"
                                         f"time_unit = s\npoisson = 0.5\nE_inf = 1\nE_i = {E_i}\ntau_i = 1\n",
                                         encoding="utf-8")
    path = tmp / "map <i>\"x\" & 'y'.h5"
    subprocess.run([ENGINE, "sweep", "--model.material", ", ".join(f"{s}.ini" for s in HOSTILE_FILES),
                    "--model.R", "50um", "--grid.l", "150um", "--grid.dh", "linspace(0.1um,3um,5)",
                    "--grid.pbar", "logspace(0.001,0.05,4)", "--grid.s", "2", "--output", path, "--quiet"],
                   check=True, cwd=tmp)
    with h5py.File(path, "r+") as f:
        f["dh"].attrs["long_name"] = "height <b>difference</b> & more"
    page = tmp / "hostile.html"
    done = explore(path, "-o", page)
    assert done.returncode == 0, done.stderr
    return tmp, path, page


def test_hostile_texts_stay_inside_the_pages_data(hostile):
    _, path, page = hostile
    text = page.read_text(encoding="utf-8")
    data = re.search(r'<script id="map-data" type="application/json">(.*?)</script>', text, flags=re.S).group(1)
    assert "<" not in data and ">" not in data and "&" not in data
    d = json.loads(data)
    assert HOSTILE_NAME in d["title"] and d["source"] == path.name
    assert [a["labels"] for a in d["axes"] if a["name"] == "material"] == [list(HOSTILE_FILES)]
    title = re.search(r"<title>(.*?)</title>", text).group(1)
    assert "<i>" not in title and "&lt;i&gt;" in title


@pytest.mark.browser
def test_hostile_texts_are_shown_as_text_in_chromium(hostile, tmp_path):
    folder, path, page = hostile
    r, _ = in_chromium(page, [[0, 0], [3, 4]], tmp_path)
    assert r["heading"].startswith(f"{path.name}: {HOSTILE_NAME}; plain;")
    assert r["plot_title"].startswith(f"{HOSTILE_NAME}; plain;") and f"material = {HOSTILE_FILES[0]}" in r["plot_title"]
    assert r["plot_links"] == []
    assert all(f"material = {HOSTILE_FILES[0]}" in cell["readout"] for cell in r["cells"])
    assert any(t.startswith("dh: height <b>difference</b> & more") for t in r["axis_titles"]), r["axis_titles"]
    with h5py.File(path) as f:
        for cell in r["cells"]:
            # The command, run by a shell in the materials' folder as a user would paste it.
            command = cell["command"].split("\n")[0].replace("punchsweep", shlex.quote(ENGINE), 1)
            done = subprocess.run(["bash", "-c", command + " --format json"], capture_output=True, text=True,
                                  cwd=folder)
            assert done.returncode == 0, (command, done.stderr)
            point = json.loads(done.stdout)
            index = tuple(cell["index"])
            assert point["regime"] == cell["regime"]
            if cell["t_star"] is None:
                assert point["t_star"] is None and np.isnan(f["t_star"][index])
            else:
                assert point["t_star"] == pytest.approx(f["t_star"][index], rel=1e-12)


# Issue 35 item 5: the page's size is estimated before it is built, from a few blocks of each
# array; a map far above --max-mb is refused without building its page, naming a
# coarsening that fits.
def test_the_size_is_estimated_before_the_page_is_built(maps, monkeypatch, tmp_path):
    import script_runner
    import explore as explore_module
    for which in ("default", "material"):
        path, page = maps[which]
        with script_runner.pm.open_map(path) as ds:
            estimate = explore_module.estimate_mb(ds, {})
        assert estimate == pytest.approx(page.stat().st_size / 1e6, rel=0.1), which
    path, _ = maps["default"]

    def built(*args, **kwargs):
        raise AssertionError("the page was built before the size was checked")

    monkeypatch.setattr(explore_module, "payload", built)
    rc, _, err = script_runner.call(explore_module, path, "-o", tmp_path / "p.html", "--max-mb", "10")
    assert rc == 2 and "(estimated), above --max-mb 10" in err, err
    every = re.search(r"--every (\w+)=(\d+)", err)
    assert every and not (tmp_path / "p.html").exists()
    monkeypatch.undo()
    done = explore(path, "-o", tmp_path / "p.html", "--max-mb", "10", "--every", f"{every[1]}={every[2]}")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "p.html").stat().st_size <= 10e6


# Issue 35 item 7: tampered or foreign attributes are refused with exit 2, naming them, by
# the page and by the Python module's open_map (NotAMapError), never a traceback or a wrong
# unit on the page.
@pytest.mark.parametrize("tamper, message", [
    (lambda f: f.attrs.__setitem__("E0_star_Pa", "abc"), "E0_star_Pa = 'abc' is not a finite number > 0"),
    (lambda f: f.attrs.__setitem__("R", "50 parsecs"), "R = '50 parsecs' is not a length the engine writes"),
    (lambda f: f.attrs.__setitem__("R_m", 1.0), "disagree"),
    (lambda f: f["pbar"].__setitem__(0, np.nan), "the axis pbar holds values that are not finite numbers"),
    (lambda f: f["regime"].__setitem__((0, 0, 0, 0, 0), 9), "regime holds the codes [9]"),
])
def test_tampered_attributes_are_refused_by_name(maps, tmp_path, tamper, message):
    path, _ = maps["material"]
    bad = tmp_path / "bad.h5"
    shutil.copy(path, bad)
    with h5py.File(bad, "r+") as f:
        if "R" not in f.attrs and "R_m" not in f.attrs:
            pytest.fail("the material map has no R")
        tamper(f)
    done = explore(bad, "-o", tmp_path / "bad.html")
    assert done.returncode == 2 and message in done.stderr and "Traceback" not in done.stderr, done.stderr
    assert not (tmp_path / "bad.html").exists()
    if "regime holds" in message:
        return  # the module decodes an unknown code as such; the page refuses it
    sys.path.insert(0, str(REPO / "build" / "python"))
    punchsweep = pytest.importorskip("punchsweep")
    with pytest.raises(punchsweep.NotAMapError, match=re.escape(message.split(" = ")[0])):
        punchsweep.open_map(bad)


def test_an_area_fraction_the_radii_do_not_give_is_embedded(maps, tmp_path):
    """The page computes the area fractions from the radii only where the map's equal them
    (pi (a1^2 + a2^2) / l^2 to 1e-12); a map where they differ gets its own array embedded."""
    import shutil

    import script_runner  # noqa: F401 - puts postprocess/ on the path
    import explore as explore_module
    import punchsweep_maps as pm
    path, _ = maps["material"]
    data = explore_module.payload(pm.open_map(path), "pbar", "dh", {}, str(path))
    assert data["variables"]["area_fraction_inf"]["derived"] == ("a1_inf", "a2_inf")
    assert "data" not in data["variables"]["area_fraction_inf"]
    copy = tmp_path / "m.h5"
    shutil.copy(path, copy)
    with h5py.File(copy, "r+") as f:
        f["area_fraction_inf"][0, 0, 0, 0, 0] *= 1.001
    data = explore_module.payload(pm.open_map(copy), "pbar", "dh", {}, str(copy))
    assert "data" in data["variables"]["area_fraction_inf"] and "derived" not in data["variables"]["area_fraction_inf"]


def tpe_map_and_window(tmp_path, design_args: list[str], dh_values=9, pressures=8):
    """A TPE-A regime map over dh and the pressure at 20 C (l 250 um, R 80 um, s 2) and a
    design window for it (`punchsweep design ... --format json`): the map's path and the
    design's JSON text."""
    tpe = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    path = tmp_path / "tpe.h5"
    subprocess.run([ENGINE, "sweep", "--model.material", tpe, "--model.R", "80um", "--grid.l", "250um", "--grid.dh",
                    f"linspace(4um, 12um, {dh_values})", "--grid.pressure", f"logspace(3kPa, 50kPa, {pressures})",
                    "--grid.temperature", "20", "--grid.s", "2", "--quantities", "regime", "--quiet", "--output", path],
                   check=True)
    done = subprocess.run([ENGINE, "design", "--material", tpe, "--R", "80um", "--l", "250um", "--s", "2",
                           "--temperature", "20..40C", *design_args, "--format", "json"],
                          capture_output=True, text=True, check=True)
    return path, done.stdout


def drawn_window(tmp_path, design_args: list[str], explore_args: list[str], along: str):
    """A design window (`punchsweep design ... --format json`) drawn on the page of a TPE-A
    map over dh and the pressure at 20 C: the design's JSON, and the window's lines as
    Chromium has them, (name, their `along` coordinates), sorted by name."""
    path, text = tpe_map_and_window(tmp_path, design_args)
    window = tmp_path / "window.json"
    window.write_text(text)
    page = tmp_path / "p.html"
    r = explore(path, "-o", page, *explore_args, "--design", window)
    assert r.returncode == 0, r.stderr
    out, _ = in_chromium(page, [[0, 0]], tmp_path)
    drawn = sorted((line["name"], line[along]) for line in out["lines"] if line["name"].startswith("design window"))
    assert len(drawn) == 2, out["lines"]
    return json.loads(text), drawn


@pytest.mark.browser
def test_a_design_window_is_drawn_on_the_page(tmp_path):
    """Issue 37 item 5: `explore.py --design window.json` draws the window's edges across
    the heat map where its quantity (dh) is an axis, at the design's values in the map's
    unit (um)."""
    d, ((lower_name, lower_y), (upper_name, upper_y)) = drawn_window(
        tmp_path, ["--require", "touch within 1s at 30kPa", "--require", "never at 5kPa", "--tolerance",
                   "dh=0.5um, pressure=10%"], [], "y")
    assert "lower edge 7.513 um" in lower_name and "upper edge 8.483 um" in upper_name
    assert lower_y == pytest.approx([d["physical"]["lower"]] * 2, rel=1e-12)
    assert upper_y == pytest.approx([d["physical"]["upper"]] * 2, rel=1e-12)


@pytest.mark.browser
def test_a_pressure_window_is_drawn_across_the_pressure_axis(tmp_path):
    """`punchsweep design --find pressure`'s window on the page: its edges are vertical lines
    across the heat map at the design's pressures in the map's unit (kPa)."""
    d, ((lower_name, lower_x), (upper_name, upper_x)) = drawn_window(
        tmp_path, ["--find", "pressure", "--dh", "8um", "--pressure", "1kPa..200kPa", "--require",
                   "touch within 1min", "--require", "no touch within 1s", "--tolerance", "dh=0.1um, pressure=2%"],
        ["--x", "pbar", "--y", "dh"], "x")
    assert "pressure lower edge 12.38 kPa" in lower_name and "pressure upper edge 12.95 kPa" in upper_name
    assert lower_x == pytest.approx([d["physical"]["lower"]] * 2, rel=1e-12)
    assert upper_x == pytest.approx([d["physical"]["upper"]] * 2, rel=1e-12)


@pytest.mark.browser
def test_a_surface_map_in_chromium(tmp_path):
    """Issue 38: a map `surface-map` wrote (hexagonal three levels, dh x pbar x T, a ramp, a
    box of tolerances) on the page: level is a slider (level 1 first), each cell's regime, t*
    and caps touched are the file's (NaN where a snapshot is flagged), its read-out gives the
    box's t* and regimes at its ends as the file has them, and each cell's command, run, is
    `punchsweep surface` at that point (the ramp_time axis as --ramp) and gives the same
    regime and t* for level 1."""
    import punchsweep
    path = tmp_path / "surface.nc"
    punchsweep.surface_map(lattice="hexagonal", l=1.2, dh=[0.04, 0.05, 0.06], dh2=0.09, s=2, grid=48,
                           pbar=[0.002, 0.005, 0.01, 0.02, 0.05], T=[2.0, 4.0, 8.0], ramp=0.5, times=[0, 1, 5],
                           tolerance="pbar=10%, T=0.5", output=path)
    page = tmp_path / "surface.html"
    done = explore(path, "-o", page)
    assert done.returncode == 0, done.stderr
    r, _ = in_chromium(page, [[0, 0], [4, 2], [2, 1], [3, 0]], tmp_path)
    with h5py.File(path) as f:
        names, codes = regime_axes_and_codes(f)
        for cell in r["cells"]:
            index = tuple(cell["index"])
            assert index[names.index("pbar")] == cell["ix"] and index[names.index("dh")] == cell["iy"]
            assert index[names.index("level")] == 1
            assert cell["regime"] == codes[f["regime"][index]]
            t = f["t_star"][index]
            assert cell["t_star"] == (None if np.isinf(t) else t) or (np.isinf(t) and cell["t_star"] is None)
            at = index[:names.index("level")]
            want = np.where(f["valid"][at] == 0, f["touched"][at], np.nan)
            got = np.array([np.nan if v is None else v for v in cell["touched"]])
            np.testing.assert_array_equal(got, want)
            # The box of tolerances in the hover read-out: t* at its ends (6 digits) and the
            # regimes there, the file's.
            shown = dict(line.split(" = ", 1) for line in cell["readout"].splitlines() if " = " in line)
            for name in ("t_star_low", "t_star_high"):
                number, value = shown[name].split()[0], f[name][index]
                assert (number == "Infinity" and np.isinf(value)) or float(number) == pytest.approx(value, rel=1e-5), name
            low_codes = dict(zip(f["regime_low"].attrs["flag_values"], f["regime_low"].attrs["flag_meanings"].split()))
            for name in ("regime_low", "regime_high"):
                assert f"{name}: {low_codes[f[name][index]]}" in cell["readout"], (name, cell["readout"])
            argv = shlex.split(cell["command"])
            assert argv[:2] == ["punchsweep", "surface"] and "--level" not in argv
            run = subprocess.run([ENGINE, *argv[1:], "--format", "json"], capture_output=True, text=True)
            assert run.returncode == 0, (argv, run.stderr)
            level = json.loads(run.stdout)["levels"][1]
            assert level["regime"] == cell["regime"]
            assert (level["t_star"] is None and np.isinf(t)) or level["t_star"] == pytest.approx(t, rel=1e-12)
    assert r["slider"] is not None and r["slider"]["changed"]
    assert r["time_slider"] == {"changed": True}


@pytest.mark.browser
def test_a_surface_map_of_regime_quantities_in_chromium(tmp_path):
    """A texture map of each level's touch alone (quantities="regime": no caps or areas over
    time, read in a fraction of the time) is a surface map on the page: each cell's regime and
    t* are the file's, there is no time slider, and the page logs no error."""
    import punchsweep
    path = tmp_path / "regime.nc"
    punchsweep.surface_map(lattice="hexagonal", l=1.2, dh=[0.04, 0.06], dh2=0.09, s=2, grid=32,
                           pbar=[0.002, 0.01, 0.05], T=[2.0, 8.0], times=[0, 1, 5], quantities="regime", output=path)
    with h5py.File(path) as f:
        assert "touched" not in f and "level_load" not in f and "t_star" in f
    page = tmp_path / "regime.html"
    done = explore(path, "-o", page)
    assert done.returncode == 0, done.stderr
    r, _ = in_chromium(page, [[0, 0], [2, 1]], tmp_path)
    with h5py.File(path) as f:
        names, codes = regime_axes_and_codes(f)
        for cell in r["cells"]:
            index = tuple(cell["index"])
            assert cell["regime"] == codes[f["regime"][index]]
            t = f["t_star"][index]
            assert cell["t_star"] == (None if np.isinf(t) else t) or (np.isinf(t) and cell["t_star"] is None)
    assert r["time_slider"] is None


def test_a_material_surface_map_in_kPa_and_um_in_chromium(tmp_path):
    """Issue 49: a texture map made with a material and R shows its axes as the one reader
    gives them (pressure in kPa, dh in um: it showed E0* and R), and each cell's command is
    written in those units (--pressure 20kPa --dh 3um) and gives the file's t* for level 1."""
    import punchsweep
    truth = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    path = tmp_path / "tpe.nc"
    punchsweep.surface_map(material=str(truth), R="60um", lattice="hexagonal", l="200um", dh=["2um", "3um"],
                           dh2="5um", s=2, pressure=["10kPa", "20kPa", "30kPa"], temperature=20, times="1s, 1min",
                           grid=32, output=path)
    page = tmp_path / "tpe.html"
    done = explore(path, "-o", page)
    assert done.returncode == 0, done.stderr
    text = page.read_text()
    assert '"unit":"kPa"' in text and '"unit":"um"' in text
    r, _ = in_chromium(page, [[1, 1], [2, 0]], tmp_path)
    with h5py.File(path) as f:
        names, _ = regime_axes_and_codes(f)
        for cell in r["cells"]:
            index = tuple(cell["index"])
            argv = shlex.split(cell["command"])
            pressure, dh = argv[argv.index("--pressure") + 1], argv[argv.index("--dh") + 1]
            assert pressure == ["10kPa", "20kPa", "30kPa"][index[names.index("pbar")]]
            assert dh == ["2um", "3um"][index[names.index("dh")]]
            run = subprocess.run([ENGINE, *argv[1:], "--format", "json"], capture_output=True, text=True)
            assert run.returncode == 0, (argv, run.stderr)
            t = f["t_star"][index]
            level = json.loads(run.stdout)["levels"][1]
            assert (level["t_star"] is None and np.isinf(t)) or level["t_star"] == pytest.approx(t, rel=1e-12)
