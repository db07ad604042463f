"""regime_map.py on a broad-spectrum material (issue: with the silicone's Prony series,
"delayed" spans t* from 1e-10 s to seconds, and the t* contours piled into one black band
with their labels on top of each other): delayed cells coloured by log10 t* on a colour bar,
immediate and never in their own colours, the --touch-within threshold view, contour labels
that do not overlap, and titles that name the material, its temperature and the load.

Every expected value is read from the map file with h5py, apart from the plotting code."""
from __future__ import annotations

import math
import os
import re
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "postprocess"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402
import regime_map  # noqa: E402
from punchsweep_point import find_binary  # noqa: E402
from script_runner import call  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
SILICONE = REPO / "materials" / "silicone_elite_double32.ini"
NBR = REPO / "materials" / "nbr_linder2011.ini"
# docs/maps.md's regime codes (a file format contract).
IMMEDIATE, DELAYED, NEVER = 0, 1, 2


@pytest.fixture(autouse=True)
def close_figures():
    yield
    import matplotlib.pyplot as plt
    plt.close("all")


def sweep(path: Path, *args: str) -> Path:
    done = subprocess.run([BINARY, "sweep", *args, "--quantities", "regime", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


@pytest.fixture(scope="module")
def silicone(tmp_path_factory):
    """The silicone of the issue on R = 50 um bumps: dh against pressure at two pitches."""
    return sweep(tmp_path_factory.mktemp("silicone") / "silicone.h5",
                 "--model.material", str(SILICONE), "--model.R", "50um", "--grid.l", "100um,150um",
                 "--grid.dh", "linspace(0.25um, 8um, 48)", "--grid.pressure", "logspace(0.2kPa, 50kPa, 48)",
                 "--grid.s", "2")


def read_slice(path: Path, l_index: int = 1):
    """(regime, valid, t*, dh, pbar) at the l_index-th pitch and s = 2, shaped (dh, pbar), as
    the file holds them (h5py: pbar in E0*, t* in s)."""
    with h5py.File(path, "r") as f:
        dims = [d.decode() if isinstance(d, bytes) else d for d in
                [f["regime"].dims[k][0].name.lstrip("/") for k in range(f["regime"].ndim)]]
        assert dims == ["l", "dh", "pbar", "s"]
        take = (l_index, slice(None), slice(None), 0)
        return (f["regime"][take], f["valid"][take], f["t_star"][take], f["dh"][:], f["pbar"][:])


def render(path: Path, *at: str, **options):
    ds = pm.open_map(path)
    fixed = pm.resolve_at(ds, pm.parse_at(list(at), ds), free=[], reserved={"pbar": "x", "dh": "y"})
    return ds, regime_map.render(ds, "pbar", "dh", fixed, **options)


def cell_pixels(fig, panel):
    """Row and column in the saved picture of every cell's centre, shape (ny, nx)."""
    ax = panel.ax
    xe = pm.cell_edges(panel.x, ax.get_xscale() == "log")
    ye = pm.cell_edges(panel.y, ax.get_yscale() == "log")
    x = ax.transData.transform(np.column_stack([xe, np.full_like(xe, panel.y[0])]))[:, 0]
    y = ax.transData.transform(np.column_stack([np.full_like(ye, panel.x[0]), ye]))[:, 1]
    height = fig.canvas.get_width_height()[1]
    cols, rows = np.meshgrid(np.floor(0.5 * (x[1:] + x[:-1])).astype(int),
                             np.floor(height - 0.5 * (y[1:] + y[:-1])).astype(int))
    return rows, cols


def colour_bar(fig):
    """The colour bar's axes, found by its label."""
    every = [*fig.axes, *(child for ax in fig.axes for child in ax.child_axes)]
    bars = [ax for ax in every if ax.get_ylabel().startswith("log10 t*")]
    assert len(bars) == 1, [ax.get_ylabel() for ax in every]
    return bars[0]


def test_delayed_cells_take_the_colour_bar_colour_of_their_t_star(silicone, tmp_path):
    import matplotlib.image as mpimg

    regime, valid, t_star, _, _ = read_slice(silicone)
    delayed = (regime == DELAYED) & (valid == 0)
    t = t_star[delayed]
    assert delayed.sum() > 30 and math.log10(t.max() / t.min()) > 8  # the broad spectrum
    ds, (fig, (panel,)) = render(silicone, "l=150um", "s=2", contours=False)
    png = tmp_path / "map.png"
    fig.savefig(png, dpi=regime_map.FIG_DPI)
    image = mpimg.imread(png)
    bar = colour_bar(fig)
    assert bar.get_ylabel() == "log10 t* [s]"
    # The bar spans the slice's t* (from the file), in whole decades.
    lo, hi = bar.get_ylim()
    assert lo == math.floor(math.log10(t.min())) and hi == math.ceil(math.log10(t.max()))
    rows, cols = cell_pixels(fig, panel)
    box = bar.get_window_extent()
    height = fig.canvas.get_width_height()[1]
    # The shortest, the median and the longest t* of the slice, and a cell in between.
    order = np.argsort(t)
    picks = [order[0], order[len(order) // 3], order[len(order) // 2], order[-1]]
    where = np.argwhere(delayed)
    seen = []
    for k in picks:
        j, i = where[k]
        value = math.log10(t_star[j, i])
        # The colour the bar shows at this cell's log10 t*, read off the picture's colour bar.
        y = bar.transData.transform((0.5, value))[1]
        bar_pixel = image[int(np.clip(height - y, height - box.y1 + 1, height - box.y0 - 2)),
                          int(0.5 * (box.x0 + box.x1)), :3]
        cell_pixel = image[rows[j, i], cols[j, i], :3]
        np.testing.assert_allclose(cell_pixel, bar_pixel, atol=4 / 255, err_msg=f"t* = {t_star[j, i]}")
        np.testing.assert_allclose(panel.colours[j, i], panel.scale.to_rgba(value), atol=1e-12)
        seen.append(cell_pixel)
    # Eight decades apart, the shortest and longest t* do not share a colour.
    assert np.abs(seen[0] - seen[-1]).max() > 0.2
    for code, meaning in ((IMMEDIATE, "immediate"), (NEVER, "never")):
        cells = (regime == code) & (valid == 0)
        assert cells.sum() > 30
        np.testing.assert_allclose(image[rows[cells], cols[cells], :3],
                                   np.tile(pm.rgba(pm.REGIME_COLOURS[meaning])[:3], (cells.sum(), 1)), atol=1.5 / 255)
    legend = fig.axes[-2].get_legend() if fig.axes[-2].get_legend() else fig.axes[-1].get_legend()
    labels = [t.get_text() for t in legend.get_texts()]
    assert labels[0] == "immediate" and labels[2] == "never" and "t^*" in labels[1]


def test_the_time_scale_of_a_map_without_a_material_is_T_eps(tmp_path):
    path = tmp_path / "sls.h5"
    done = subprocess.run([BINARY, "sweep", "--grid.l", "0.75", "--grid.dh", "linspace(0.02,0.12,8)", "--grid.T", "5",
                           "--grid.pbar", "logspace(0.005,0.08,8)", "--grid.s", "2", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with h5py.File(path, "r") as f:
        assert f["t_star"].attrs["scaled_by"] == "T_eps" and (f["regime"][:] == DELAYED).any()
    ds = pm.open_map(path)
    fig, _ = regime_map.render(ds, "pbar", "dh", pm.resolve_at(ds, {}, free=[], reserved={"pbar": "x", "dh": "y"}))
    assert colour_bar(fig).get_ylabel() == "log10 t* [$T_\\varepsilon$]"
    # No material, no physical time: a unit is refused, a bare number is in T_eps.
    rc, _, err = call(regime_map, path, "--x", "pbar", "--y", "dh", "--touch-within", "1min", "-o", tmp_path / "t.png")
    assert rc == 2 and "T_eps" in err and len(err.strip().splitlines()) == 1 and not (tmp_path / "t.png").exists()
    rc, _, err = call(regime_map, path, "--x", "pbar", "--y", "dh", "--touch-within", "0.5", "-o", tmp_path / "t.png")
    assert rc == 0, err


def test_touch_within_splits_delayed_cells_at_the_given_time(silicone, tmp_path):
    regime, valid, t_star, _, _ = read_slice(silicone)
    limit = 0.6  # s, given as "0.01min", "0.6s" and "0.6" (the map's unit) below
    within = (regime == IMMEDIATE) | ((regime == DELAYED) & (t_star <= limit))
    later = (regime == DELAYED) & (t_star > limit)
    never = regime == NEVER
    assert ((regime == DELAYED) & within).any() and later.any() and never.any()
    assert np.all(within | later | never)
    ok = valid == 0
    for given in ("0.01min", "0.6s", "0.6"):
        ds, (fig, (panel,)) = render(silicone, "l=150um", "s=2",
                                     within=pm.parse_time(pm.open_map(silicone), given, "--touch-within"))
        for cells, meaning in ((within, "immediate"), (later, "delayed"), (never, "never")):
            assert np.all(panel.colours[cells & ok] == pm.rgba(pm.REGIME_COLOURS[meaning])), (given, meaning)
            assert np.all(panel.colours[cells & ~ok] == pm.invalid_colour(meaning)), (given, meaning)
        legend = [t.get_text() for t in fig.axes[-1].get_legend().get_texts()]
        assert legend[:3] == [f"touches within\n{given.replace('min', ' min').replace('0.6s', '0.6 s')}"
                              if given != "0.6" else "touches within\n0.6 s", "touches later", "never"]
        assert not any(child.get_ylabel().startswith("log10 t*") for ax in fig.axes  # no colour bar
                       for child in [ax, *ax.child_axes])
        assert not panel.ax.texts  # no contours
    # A threshold below every t* leaves only the immediate cells within it.
    ds, (fig, (panel,)) = render(silicone, "l=150um", "s=2", within=(1e-12, "1e-12 s"))
    blue = np.all(panel.colours == pm.rgba(pm.REGIME_COLOURS["immediate"]), axis=-1)
    assert np.array_equal(blue, (regime == IMMEDIATE) & ok)
    out = tmp_path / "within.png"
    rc, _, err = call(regime_map, silicone, "--x", "pbar", "--y", "dh", "--at", "l=150um", "s=2",
                      "--touch-within", "0.01min", "-o", out)
    assert rc == 0, err
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("given, message", [("1kPa", "'kPa' is not a unit of time"), ("-1s", "must be > 0"),
                                            ("soon", "is not a time")])
def test_touch_within_refuses_what_is_not_a_time(silicone, tmp_path, given, message):
    out = tmp_path / "x.png"
    rc, stdout, err = call(regime_map, silicone, "--x", "pbar", "--y", "dh", "--at", "l=150um", "s=2",
                           f"--touch-within={given}", "-o", out)
    assert rc == 2 and message in err and len(err.strip().splitlines()) == 1, err
    assert not out.exists()


def label_value(text: str) -> float:
    """A contour label's number: '$10^{-6}$', '$1$', '0.2'."""
    match = re.fullmatch(r"\$10\^\{(-?\d+)\}\$", text)
    if match:
        return 10.0 ** int(match.group(1))
    return float(text.strip("$"))


def overlap(a, b) -> bool:
    """Whether two boxes share any area."""
    return min(a.x1, b.x1) > max(a.x0, b.x0) and min(a.y1, b.y1) > max(a.y0, b.y0)


@pytest.mark.parametrize("l", ["100um", "150um"])
def test_contour_labels_do_not_overlap_and_spread_over_the_decades(silicone, l):
    _, _, t_star, _, _ = read_slice(silicone, ["100um", "150um"].index(l))
    ds, (fig, (panel,)) = render(silicone, f"l={l}", "s=2")
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    texts = [t for t in panel.ax.texts if t.get_visible() and t.get_text()]
    assert len(texts) >= 3
    boxes = [t.get_window_extent(renderer) for t in texts]
    for a in range(len(boxes)):
        for b in range(a):
            assert not overlap(boxes[a], boxes[b]), (texts[a].get_text(), texts[b].get_text())
    frame = panel.ax.get_window_extent(renderer)
    assert all(frame.x0 <= b.x0 and b.x1 <= frame.x1 and frame.y0 <= b.y0 and b.y1 <= frame.y1 for b in boxes)
    values = sorted(label_value(t.get_text()) for t in texts)
    t = t_star[np.isfinite(t_star) & (t_star > 0)]
    # Decades between the file's shortest and longest delayed t*, spread over them: not
    # crowded at the never edge (the longest t*).
    assert all(t.min() < v < t.max() for v in values)
    assert all(abs(math.log10(v) - round(math.log10(v))) < 1e-9 for v in values)
    assert math.log10(values[-1] / values[0]) >= 0.4 * math.log10(t.max() / t.min())
    assert len(set(values)) == len(values)


def test_titles_name_the_material_and_the_load(silicone):
    with h5py.File(silicone, "r") as f:
        name = f.attrs["material"].split(",")[0].strip()
        kpa = f["pbar"][:] * f.attrs["E0_star_Pa"] / 1e3
        l_um = f["l"][:] * float(f.attrs["R"].split()[0])
    assert name.startswith("silicone rubber")
    # pressure across: its range in kPa
    _, (fig, _) = render(silicone, "l=150um", "s=2", contours=False)
    title = fig._suptitle.get_text()
    assert name in title and "step load" in title
    assert f"from {kpa.min():.3g} to {kpa.max():.3g} kPa" in title
    assert f"{l_um[1]:g} $\\mu$m" in title
    # pressure fixed: its grid value in kPa, nearest to 2 kPa in log space
    ds = pm.open_map(silicone)
    fixed = pm.resolve_at(ds, pm.parse_at(["pbar=2kPa", "s=2"], ds), free=[], reserved={"l": "x", "dh": "y"})
    fig, _ = regime_map.render(ds, "l", "dh", fixed, contours=False)
    nearest = kpa[np.argmin(np.abs(np.log(kpa / 2.0)))]
    title = fig._suptitle.get_text()
    assert name in title and f"$\\bar p_0$ = {nearest:.6g} kPa" in title and "step load" in title


def test_titles_name_the_temperature_of_a_shifted_material(tmp_path):
    material = tmp_path / "wlf.ini"
    material.write_text(NBR.read_text() + "[shift]\nkind = wlf\nC1 = 17.44\nC2 = 51.6\nT_ref = 20\n")
    path = sweep(tmp_path / "wlf.h5", "--model.material", str(material), "--grid.l", "0.75",
                 "--grid.dh", "linspace(0.005, 0.06, 6)", "--grid.temperature", "10, 30",
                 "--grid.pbar", "logspace(0.002, 0.02, 5)", "--grid.s", "2")
    with h5py.File(path, "r") as f:
        name = f.attrs["material"].split(",")[0].strip()
        temperatures = f["temperature"][:]
        unit = f["temperature"].attrs["units"]
    ds = pm.open_map(path)
    fixed = pm.resolve_at(ds, pm.parse_at(["l=0.75", "s=2", "temperature=30"], ds), free=[],
                          reserved={"pbar": "x", "dh": "y"})
    fig, _ = regime_map.render(ds, "pbar", "dh", fixed, contours=False)
    title = fig._suptitle.get_text()
    # The file's unit is UDUNITS' degC; a title writes °C (issue 37 item 4).
    assert unit == "degC"
    assert name in title and f"temperature = {temperatures[1]:g} °C" in title and "kPa" in title
    fig, _ = regime_map.render(ds, "pbar", "dh", pm.resolve_at(ds, pm.parse_at(["l=0.75", "s=2"], ds), free=[],
                               reserved={"pbar": "x", "dh": "y", "temperature": "facet"}), facet="temperature",
                               contours=False)
    assert "temperature on the panels" in fig._suptitle.get_text()
