"""The map plots (regime_map.py, critical_dh.py, evolution.py --map) against maps made by the
real engine: the colours drawn are the regimes stored, --at picks and reports the nearest
grid value, and user errors exit with code 2, one line and no file."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
POSTPROCESS = REPO / "postprocess"
sys.path.insert(0, str(POSTPROCESS))
import critical_dh  # noqa: E402
import evolution  # noqa: E402
import punchsweep_maps as pm  # noqa: E402
from script_runner import call  # noqa: E402
import regime_map  # noqa: E402
from punchsweep_point import find_binary  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))
# The paper's localization: the checks below need invalid cells of every regime on a small grid.
GRID = ["--model.localization", "paper", "--grid.l", "0.5,0.75,1", "--grid.dh", "linspace(0.02,0.12,11)", "--grid.T", "2,2.5,5",
        "--grid.pbar", "logspace(0.005,0.08,9)", "--grid.s", "1,2", "--time.times", "0,1,5"]
PBAR = 0.005 * 16.0 ** (np.arange(9) / 8)


def sweep(path: Path, *extra: str) -> Path:
    done = subprocess.run([BINARY, "sweep", *GRID, "--quiet", *extra, "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


@pytest.fixture(scope="module")
def maps(tmp_path_factory):
    """A full map, a regime-only map and an 'interrupted' copy with cells not computed."""
    folder = tmp_path_factory.mktemp("maps")
    full = sweep(folder / "full.h5")
    regime_only = sweep(folder / "regime.h5", "--quantities", "regime")
    partial = folder / "partial.h5"
    shutil.copy(full, partial)
    with h5py.File(partial, "r+") as f:  # as a sweep stopped part-way leaves it
        for name in ("regime", "valid"):
            f[name][:, 5:, 1, :, 1] = -1
        for name in ("t_star", "h_0", "h_inf", "a1_inf", "a2_inf", "area_fraction_inf"):
            f[name][:, 5:, 1, :, 1] = np.nan
        f.attrs["completed"] = 0
    return {"full": full, "regime": regime_only, "partial": partial}


def run(script: str, *args) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(POSTPROCESS / script), *map(str, args)],
                          capture_output=True, text=True)




def is_png(path: Path) -> bool:
    return path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def fixed_at(ds, **at) -> dict:
    free = [a for a in pm.axes(ds) if a not in at]
    return pm.resolve_at(ds, at, free=free, optional=tuple(free))


def cell_centre_pixels(fig, panel) -> tuple[np.ndarray, np.ndarray]:
    """Row and column in the saved PNG of the centre of every cell, shape (ny, nx)."""
    ax = panel.ax
    log_x, log_y = ax.get_xscale() == "log", ax.get_yscale() == "log"
    xe, ye = pm.cell_edges(panel.x, log_x), pm.cell_edges(panel.y, log_y)
    x_disp = ax.transData.transform(np.column_stack([xe, np.full_like(xe, panel.y[0])]))[:, 0]
    y_disp = ax.transData.transform(np.column_stack([np.full_like(ye, panel.x[0]), ye]))[:, 1]
    cx, cy = 0.5 * (x_disp[1:] + x_disp[:-1]), 0.5 * (y_disp[1:] + y_disp[:-1])
    height = fig.canvas.get_width_height()[1]
    cols, rows = np.meshgrid(np.floor(cx).astype(int), np.floor(height - cy).astype(int))
    return rows, cols


# --- regime_map.py ---------------------------------------------------------------------------


def test_regime_map_colour_grid_is_the_regime_colour_per_cell(maps):
    with pm.open_map(maps["partial"]) as ds:
        regime, valid = ds.regime.values, ds.valid.values
        grid = pm.regime_colour_grid(ds, regime, valid)
    assert grid.shape == regime.shape + (4,)
    for code, meaning in ((0, "immediate"), (1, "delayed"), (2, "never")):  # docs/maps.md's codes
        plain = grid[(regime == code) & (valid == 0)]
        assert len(plain) and np.all(plain == pm.rgba(pm.REGIME_COLOURS[meaning]))
        pale = grid[(regime == code) & (valid > 0)]
        assert len(pale) and np.all(pale == pm.invalid_colour(meaning))
    assert np.all(grid[regime == -1] == pm.rgba(pm.REGIME_COLOURS["not_computed"]))
    colours = {tuple(c) for c in pm.category_colours()}
    assert len(colours) == 7  # every category has its own colour


def test_regime_map_png_shows_the_stored_regime_at_every_valid_cell_centre(maps, tmp_path):
    import matplotlib.image as mpimg

    png = tmp_path / "map.png"
    done = run("regime_map.py", maps["full"], "--x", "pbar", "--y", "dh", "--at", "l=0.75", "T=2.5",
               "s=2", "--no-contours", "-o", png)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().splitlines()[-1] == f"regime_map.py: wrote {png}"
    assert is_png(png)
    image = mpimg.imread(png)
    with pm.open_map(maps["full"]) as ds:
        fig, (panel,) = regime_map.render(ds, "pbar", "dh", fixed_at(ds, l=0.75, T=2.5, s=2),
                                          contours=False)
        fig.canvas.draw()
        regime = ds.regime.sel(l=0.75, T=2.5, s=2).transpose("dh", "pbar").values
        valid = ds.valid.sel(l=0.75, T=2.5, s=2).transpose("dh", "pbar").values
        t_star = ds.t_star.sel(l=0.75, T=2.5, s=2).transpose("dh", "pbar").values
        want = pm.regime_colour_grid(ds, regime, valid, t_star, panel.scale.norm)
    assert image.shape[:2] == fig.canvas.get_width_height()[::-1]
    assert panel.colours.shape == (11, 9, 4)
    np.testing.assert_array_equal(panel.colours, want)
    # Delayed cells are coloured by their t* (test_regime_map_t_star.py), the others by regime.
    plain = pm.regime_colour_grid(ds, regime, valid)
    np.testing.assert_array_equal(panel.colours[regime != 1], plain[regime != 1])
    assert not np.any(np.all(panel.colours[regime == 1] == pm.rgba(pm.REGIME_COLOURS["delayed"]), axis=-1))
    rows, cols = cell_centre_pixels(fig, panel)
    drawn = image[rows, cols, :3]
    ok = valid == 0  # invalid cells are hatched: their centre may sit on a hatch line
    assert np.count_nonzero(ok) > 50 and len(np.unique(regime[ok])) == 3
    np.testing.assert_allclose(drawn[ok], panel.colours[ok][:, :3], atol=1.5 / 255)
    assert ds.pbar.attrs["spacing"] == "log" and panel.ax.get_xscale() == "log"
    assert panel.ax.get_yscale() == "linear"


def test_regime_map_draws_the_bem_regime_where_the_model_has_no_answer(tmp_path):
    # sweep --reference.sample invalid: at every cell the model flags, the BEM's regime in
    # its full colour (dotted, and named in the legend); elsewhere the model's colours. The
    # refined model, which flags cells.
    path = tmp_path / "invalid.h5"
    done = subprocess.run([BINARY, "sweep", "--grid.l", "0.75", "--grid.dh", "linspace(0.02,0.12,6)", "--grid.T", "5",
                           "--grid.pbar", "logspace(0.01,0.08,6)", "--grid.s", "2", "--model.localization", "refined",
                           "--reference", "bem",
                           "--bem-grid", "32", "--reference.sample", "invalid", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with pm.open_map(path) as ds:
        fig, (panel,) = regime_map.render(ds, "pbar", "dh", fixed_at(ds, l=0.75, T=5, s=2), contours=False)
        regime = ds.regime.sel(l=0.75, T=5, s=2).transpose("dh", "pbar").values
        valid = ds.valid.sel(l=0.75, T=5, s=2).transpose("dh", "pbar").values
        bem = ds.bem_regime.sel(l=0.75, T=5, s=2).transpose("dh", "pbar").values
        t_star = ds.t_star.sel(l=0.75, T=5, s=2).transpose("dh", "pbar").values
        bem_t_star = ds.bem_t_star.sel(l=0.75, T=5, s=2).transpose("dh", "pbar").values
    flagged = valid != 0
    assert flagged.any() and (~flagged).any()
    assert np.array_equal(bem != -1, flagged)  # the BEM ran exactly where the model has no answer
    colours = {0: "immediate", 1: "delayed", 2: "never"}  # docs/maps.md's codes

    def want(code, t):  # delayed: the colour bar's colour of its t* (the BEM's where the BEM answers)
        if code == 1 and np.isfinite(t):
            return panel.scale.to_rgba(np.log10(t))
        return pm.rgba(pm.REGIME_COLOURS[colours[int(code)]])
    assert (bem[flagged] == 1).any()
    for j, i in zip(*np.nonzero(flagged)):
        np.testing.assert_allclose(panel.colours[j, i], want(bem[j, i], bem_t_star[j, i]), atol=1e-12)
    for j, i in zip(*np.nonzero(~flagged)):
        np.testing.assert_allclose(panel.colours[j, i], want(regime[j, i], t_star[j, i]), atol=1e-12)
    labels = [t.get_text() for t in fig.axes[-1].get_legend().get_texts()]
    assert any("BEM" in text for text in labels), labels


def test_regime_map_draws_cells_not_computed_in_their_own_colour(maps, tmp_path):
    import matplotlib.image as mpimg

    with pm.open_map(maps["partial"]) as ds:
        fig, (panel,) = regime_map.render(ds, "pbar", "dh", fixed_at(ds, l=0.5, T=2.5, s=2),
                                          contours=False)
        fig.savefig(tmp_path / "p.png", dpi=regime_map.FIG_DPI)
        regime = ds.regime.sel(l=0.5, T=2.5, s=2).transpose("dh", "pbar").values
        legend = [t.get_text() for t in fig.axes[-1].get_legend().get_texts()]
        title = fig._suptitle.get_text()
    assert np.count_nonzero(regime == -1) == 6 * 9
    rows, cols = cell_centre_pixels(fig, panel)
    image = mpimg.imread(tmp_path / "p.png")
    np.testing.assert_allclose(image[rows, cols, :3][regime == -1],
                               np.tile(pm.rgba(pm.REGIME_COLOURS["not_computed"])[:3], (54, 1)),
                               atol=1.5 / 255)
    assert "not computed" in legend and "incomplete map" in title


def test_regime_map_reports_the_nearest_grid_value_it_picks(maps, tmp_path):
    rc, out, err = call(regime_map, maps["full"], "--x", "pbar", "--y", "dh", "--at", "l=0.8",
                        "T=2.4", "s=2", "-o", tmp_path / "m.png")
    assert rc == 0, err
    assert "--at T=2.4 -> nearest grid value T = 2.5" in out.splitlines()
    assert "--at l=0.8 -> nearest grid value l = 0.75 R" in out.splitlines()
    assert is_png(tmp_path / "m.png")


def test_nearest_index_picks_the_closest_value_in_the_axis_own_spacing(maps):
    with pm.open_map(maps["full"]) as ds:
        assert pm.nearest_index(ds, "T", 2.4) == 1 and pm.nearest_index(ds, "T", 3.8) == 2
        assert pm.nearest_index(ds, "dh", 0.0449) == 2 and pm.nearest_index(ds, "dh", 0.12) == 10
        # pbar is log-spaced: 0.024 is nearer 0.02 in value but nearer 0.0283 in log.
        assert pm.nearest_index(ds, "pbar", 0.024) == 5
        assert abs(ds.pbar.values[5] - PBAR[5]) < 1e-15
        # Half a grid step beyond the ends is accepted, more is not.
        assert pm.nearest_index(ds, "l", 1.12) == 2 and pm.nearest_index(ds, "l", 0.38) == 0
        for name, value in [("l", 1.13), ("l", 0.37), ("T", 7.6), ("pbar", 0.0034), ("pbar", -1.0)]:
            with pytest.raises(pm.MapError, match=f"--at {name}="):
                pm.nearest_index(ds, name, value)
        fixed = pm.resolve_at(ds, {"l": 0.8, "T": 2.4, "s": 2.0}, free=["pbar", "dh"])
        assert {n: f.index for n, f in fixed.items()} == {"l": 1, "T": 1, "s": 1}
        assert fixed["T"].value == 2.5


def test_regime_map_facets_one_panel_per_value_and_writes_pdf(maps, tmp_path):
    pdf = tmp_path / "facets.pdf"
    rc, out, err = call(regime_map, maps["full"], "--x", "pbar", "--y", "dh", "--at", "l=0.75",
                        "s=1", "--facet", "T", "-o", pdf)
    assert rc == 0, err
    assert pdf.read_bytes()[:5] == b"%PDF-" and out.strip().endswith(f"wrote {pdf}")
    with pm.open_map(maps["full"]) as ds:
        fig, panels = regime_map.render(ds, "pbar", "dh", fixed_at(ds, l=0.75, s=1), facet="T")
        assert [p.title for p in panels] == ["$T$ = 2", "$T$ = 2.5", "$T$ = 5"]
        for k, p in enumerate(panels):
            cut = ds.isel(l=1, s=0, T=k)
            want = cut.regime.transpose("dh", "pbar").values
            np.testing.assert_array_equal(
                p.colours, pm.regime_colour_grid(ds, want, cut.valid.transpose("dh", "pbar").values,
                                                 cut.t_star.transpose("dh", "pbar").values, p.scale.norm))
        assert all(p.scale is panels[0].scale for p in panels)  # one colour bar for every panel
        assert panels[0].ax.get_xlabel() == "nominal pressure $\\bar p_0$ [$E_0/(1-\\nu^2)$]"
        assert panels[0].ax.get_ylabel() == "height difference of the punch levels $\\Delta h$ [$R$]"


def test_regime_map_contours_label_t_star_in_the_delayed_region(maps):
    with pm.open_map(maps["full"]) as ds:
        fig, (panel,) = regime_map.render(ds, "pbar", "dh", fixed_at(ds, l=0.75, T=5, s=2))
        labels = [t.get_text() for t in panel.ax.texts]
        legend = [t.get_text() for t in fig.axes[-1].get_legend().get_texts()]
        delayed = ds.t_star.sel(l=0.75, T=5, s=2).where(ds.regime.sel(l=0.75, T=5, s=2) == 1).values
    values = [10.0 ** float(v[5:-2]) if v.startswith("$10^") else float(v.strip("$")) for v in labels]
    assert values and all(np.nanmin(delayed) < v < np.nanmax(delayed) for v in values)
    assert any("contours" in t for t in legend) and any(t.startswith("invalid") for t in legend)


@pytest.mark.parametrize("args, message", [
    (["--x", "foo", "--y", "dh"], "unknown axis 'foo' for --x; valid axes: l, dh, T, pbar, s"),
    (["--x", "dh", "--y", "dh"], "--x and --y are both 'dh'"),
    (["--x", "pbar", "--y", "dh", "--at", "l=2", "T=2", "s=1"], "--at l=2 is outside the axis range"),
    (["--x", "pbar", "--y", "dh", "--at", "l=x", "T=2", "s=1"], "--at l='x' is not a number"),
    (["--x", "pbar", "--y", "dh", "--at", "q=1", "T=2", "s=1"], "unknown axis 'q' for --at"),
    (["--x", "pbar", "--y", "dh", "--at", "T=2"], "still to fix l, s"),
    (["--x", "pbar", "--y", "dh", "--at", "l=1", "T=2", "s=1", "dh=0.1"], "dh is the y axis"),
    (["--x", "pbar", "--y", "dh", "--facet", "pbar"], "--facet pbar is already the x axis"),
], ids=["unknown-axis", "x-equals-y", "at-out-of-range", "at-not-a-number", "at-unknown-axis",
        "at-missing", "at-on-plot-axis", "facet-on-plot-axis"])
def test_regime_map_user_errors_exit_2_with_one_line_and_no_file(maps, tmp_path, args, message):
    out = tmp_path / "x.png"
    rc, stdout, err = call(regime_map, maps["full"], *args, "-o", out)
    assert rc == 2 and message in err and len(err.strip().splitlines()) == 1, err
    assert not out.exists() and stdout == ""


def test_regime_map_refuses_bad_files_and_suffixes_in_a_real_process(maps, tmp_path):
    text = tmp_path / "text.h5"
    text.write_text("not hdf5")
    cases = [(maps["full"], "x.jpg", "unsupported suffix '.jpg'; use .png or .pdf"),
             (tmp_path / "missing.h5", "x.png", "does not exist"),
             (text, "x.png", "not an HDF5 file, so not a punchsweep regime map")]
    for path, name, message in cases:
        done = run("regime_map.py", path, "--x", "pbar", "--y", "dh", "--at", "l=1", "T=2", "s=1",
                   "-o", tmp_path / name)
        assert done.returncode == 2 and message in done.stderr, done.stderr
        assert len(done.stderr.strip().splitlines()) == 1 and not (tmp_path / name).exists()


def test_regime_map_help_explains_every_option_with_units():
    done = run("regime_map.py", "--help")
    assert done.returncode == 0
    text = " ".join(done.stdout.split())  # argparse wraps to the terminal width
    for option in ("--x", "--y", "--at", "--facet", "--no-contours", "--output", "T_eps",
                   "E0/(1-nu^2)", ".png or .pdf"):
        assert option in text, option


# --- critical_dh.py --------------------------------------------------------------------------


def test_critical_dh_curves_are_the_map_h_values_and_bound_the_regimes(maps, tmp_path):
    png = tmp_path / "chart.png"
    rc, out, err = call(critical_dh, maps["full"], "--at", "l=0.75", "-o", png)
    assert rc == 0, err
    assert is_png(png) and "--at l=0.75 -> nearest grid value l = 0.75 R" in out
    with pm.open_map(maps["full"]) as ds:
        fixed = pm.resolve_at(ds, {"l": 0.75}, free=["T", "s"], optional=("T", "s"),
                              reserved={"pbar": "x", "dh": "y"})
        x, T, s, h0, hinf = critical_dh.critical_curves(ds, "pbar", fixed)
        cut = ds.isel(l=1)
        np.testing.assert_array_equal(x, ds.pbar.values)
        np.testing.assert_array_equal(T, [2, 2.5, 5])
        np.testing.assert_array_equal(h0, cut.h_0.isel(dh=3, T=2).transpose("s", "pbar").values)
        np.testing.assert_array_equal(hinf, cut.h_inf.isel(dh=7).transpose("T", "s", "pbar").values)
        # The chart's meaning: below h_0 immediate, above h_inf never, in between delayed.
        dh = ds.dh.values[:, None, None, None]
        regime = cut.regime.transpose("dh", "T", "s", "pbar").values
        assert np.all((regime == 0) == (dh <= h0[None, None]))
        assert np.all((regime == 2) == (dh >= hinf[None]))
        fig = critical_dh.render(ds, "pbar", fixed)
        assert [ax.get_xscale() for ax in fig.axes[:2]] == ["log", "log"]
        assert fig.axes[0].get_ylabel() == "critical height difference $\\Delta h$ [$R$]"


def test_critical_dh_against_pitch_draws_only_the_chosen_T(maps, tmp_path):
    pdf = tmp_path / "chart.pdf"
    rc, out, err = call(critical_dh, maps["full"], "--against", "l", "--at", "pbar=0.03", "T=2.5",
                        "-o", pdf)
    assert rc == 0, err
    assert pdf.read_bytes()[:5] == b"%PDF-"
    assert "--at pbar=0.03 -> nearest grid value pbar = 0.0282843 E0/(1-nu^2)" in out
    with pm.open_map(maps["full"]) as ds:
        fixed = pm.resolve_at(ds, {"pbar": 0.03, "T": 2.5}, free=["T", "s"], optional=("T", "s"),
                              reserved={"l": "x", "dh": "y"})
        x, T, s, h0, hinf = critical_dh.critical_curves(ds, "l", fixed)
        assert list(T) == [2.5] and hinf.shape == (1, 2, 3)
        fig = critical_dh.render(ds, "l", fixed)
        assert fig.axes[0].get_xscale() == "linear"
        assert fig.axes[0].get_xlabel() == "lattice pitch $l$ [$R$]"


def test_critical_dh_takes_h_at_any_dh_and_warns_if_it_varies_along_dh(maps, tmp_path, capsys):
    with pm.open_map(maps["full"]) as ds:
        fixed = fixed_at(ds, l=0.5)
        whole = critical_dh.critical_curves(ds, "pbar", fixed)
    with pm.open_map(maps["partial"]) as ds:  # NaN holes at some dh do not matter
        holes = critical_dh.critical_curves(ds, "pbar", fixed)
    for a, b in zip(whole, holes):
        np.testing.assert_array_equal(a, b)
    assert capsys.readouterr().err == ""
    bent = tmp_path / "bent.h5"
    shutil.copy(maps["full"], bent)
    with h5py.File(bent, "r+") as f:
        f["h_inf"][0, 3, 0, 0, 0] *= 1.01
    with pm.open_map(bent) as ds:
        critical_dh.critical_curves(ds, "pbar", fixed)
    assert "warning: h_inf varies along dh" in capsys.readouterr().err


def test_critical_dh_axis_is_log_only_where_a_panel_spans_more_than_a_factor_10():
    assert critical_dh.LOG_DH_SPAN == 10  # as docs/maps.md says
    assert critical_dh.dh_scale([[1.0, 9.0], [2.0, 3.0]]) == "linear"
    assert critical_dh.dh_scale([[1.0, 11.0], [2.0, 3.0]]) == "log"
    # One scale for every panel, from each panel's own span: 0.1-0.5 and 1-5 are a factor 5
    # each (log would only squeeze them), although a factor 50 together.
    assert critical_dh.dh_scale([[0.1, 0.5], [1.0, 5.0]]) == "linear"
    assert critical_dh.dh_scale([[0.0, 50.0, np.nan], [1.0, np.inf]]) == "linear"  # 0 has no log
    assert critical_dh.dh_scale([[1.0, 11.0]], "linear") == "linear"
    assert critical_dh.dh_scale([[1.0, 2.0]], "log") == "log"
    with pytest.raises(pm.MapError, match="--log-dh: the chart has critical dh values <= 0"):
        critical_dh.dh_scale([[0.0, 50.0]], "log")


def test_critical_dh_keeps_a_linear_dh_axis_from_0_for_a_narrow_span(maps, tmp_path):
    """At l = 0.75 R, T = 2 each panel's h_0 and h_inf lie within a factor 4 to 7 of each other
    (read here with h5py): the dh axis stays linear from 0; --log-dh forces a log axis."""
    with h5py.File(maps["full"], "r") as f:  # axes l, dh, T, pbar, s
        il, iT = int(np.argmin(np.abs(f["l"][:] - 0.75))), list(f["T"][:]).index(2.0)
        h0, hinf = f["h_0"][il, :, iT, :, :], f["h_inf"][il, :, iT, :, :]  # (dh, pbar, s)
    spans = [max(np.nanmax(h0[..., k]), np.nanmax(hinf[..., k])) / min(np.nanmin(h0[..., k]), np.nanmin(hinf[..., k]))
             for k in range(h0.shape[-1])]
    assert 3 < min(spans) and max(spans) < 8  # the premise, from the map itself
    with pm.open_map(maps["full"]) as ds:
        fixed = fixed_at(ds, l=0.75, T=2.0)
        fig = critical_dh.render(ds, "pbar", fixed)
        for k, ax in enumerate(fig.axes[:2]):
            assert ax.get_yscale() == "linear" and ax.get_ylim()[0] == 0
            assert ax.get_ylim()[1] == pytest.approx(1.05 * max(np.nanmax(h0[..., k]), np.nanmax(hinf[..., k])))
        fig = critical_dh.render(ds, "pbar", fixed, scale="log")
        assert [ax.get_yscale() for ax in fig.axes[:2]] == ["log", "log"]
    png = tmp_path / "log.png"
    rc, _, err = call(critical_dh, maps["full"], "--at", "l=0.75", "T=2", "--log-dh", "-o", png)
    assert rc == 0 and is_png(png), err


@pytest.mark.parametrize("args, message", [
    (["--at", "l=0.75", "--log-dh", "--linear-dh"], "not allowed with argument"),
    (["--at", "l=0.75", "dh=0.05"], "dh is the chart's vertical axis"),
    (["--against", "T"], "--against 'T' is not a valid choice; use l, pbar or temperature"),
    (["--against", "l"], "still to fix pbar"),
    (["--at", "l=3"], "--at l=3 is outside the axis range"),
], ids=["log-and-linear", "dh-fixed", "against-T", "pbar-not-fixed", "at-out-of-range"])
def test_critical_dh_user_errors_exit_2_with_one_line_and_no_file(maps, tmp_path, args, message):
    out = tmp_path / "c.png"
    rc, stdout, err = call(critical_dh, maps["full"], *args, "-o", out)
    assert rc == 2 and message in err and len(err.strip().splitlines()) == 1, err
    assert not out.exists()


# --- evolution.py --map ----------------------------------------------------------------------


def test_evolution_from_map_equals_punchsweep_point_at_the_nearest_grid_point(maps, tmp_path):
    png, js = tmp_path / "evo.png", tmp_path / "evo.json"
    done = run("evolution.py", "--map", maps["full"], "--at", "l=0.74", "dh=0.072", "T=2.5",
               "pbar=0.03", "s=2", "-o", png, "--json", js)
    assert done.returncode == 0, done.stderr
    assert is_png(png) and png.stat().st_size > 10_000
    lines = done.stdout.splitlines()
    assert "--at dh=0.072 -> nearest grid value dh = 0.07 R" in lines
    assert "--at pbar=0.03 -> nearest grid value pbar = 0.0282843 E0/(1-nu^2)" in lines
    from_map = json.loads(js.read_text())
    point = subprocess.run([BINARY, "point", "--l", "0.75", "--dh", repr(0.07), "--T", "2.5",
                            "--pbar", repr(float(PBAR[5])), "--s", "2", "--times", "0,1,5",
                            "--localization", "paper", "--format", "json"], capture_output=True, text=True, check=True)
    # Same keys, same doubles (docs/cli.md's contract), but t*'s sensitivity, which a map
    # holds only in part (dt_star_ddh, dt_star_dpbar, dt_star_dl in full mode), and the
    # advisories, which follow from its a1_inf and a2_inf.
    expected = {k: v for k, v in json.loads(point.stdout).items()
                if not k.startswith(("dt_star_d", "dlog_t_star_dlog_")) and
                k not in ("advisories", "advisory_reason", "strain")}
    assert from_map == expected


def test_evolution_refuses_a_regime_only_map_with_exit_2(maps, tmp_path):
    png = tmp_path / "evo.png"
    done = run("evolution.py", "--map", maps["regime"], "--at", "l=0.75", "dh=0.07", "T=2.5",
               "pbar=0.03", "s=2", "-o", png)
    assert done.returncode == 2 and not png.exists()
    assert len(done.stderr.strip().splitlines()) == 1
    assert "no time series" in done.stderr and "--quantities full" in done.stderr
    assert "point mode" in done.stderr


@pytest.mark.parametrize("args, message", [
    (["--at", "l=0.75", "dh=0.07", "T=2.5", "pbar=0.5", "s=2"],
     "--at pbar=0.5 is outside the axis range"),
    (["--at", "l=0.75", "dh=0.07"], "still to fix T, pbar, s"),
    (["--l", "0.75", "--at", "l=0.75"], "use --at, not --l"),
], ids=["at-out-of-range", "at-missing", "point-and-map-options"])
def test_evolution_map_mode_user_errors_exit_2(maps, tmp_path, args, message):
    out = tmp_path / "e.png"
    rc, _, err = call(evolution, "--map", maps["full"], *args, "-o", out)
    assert rc == 2 and message in err and len(err.strip().splitlines()) == 1, err
    assert not out.exists()


def test_evolution_from_map_refuses_a_point_not_computed(maps, tmp_path):
    out = tmp_path / "e.png"
    rc, _, err = call(evolution, "--map", maps["partial"], "--at", "l=1", "dh=0.1", "T=2.5",
                      "pbar=0.01", "s=2", "-o", out)
    assert rc == 2 and "was not computed" in err and not out.exists()


def test_summary_gives_t_star_in_the_maps_time_unit(tmp_path):
    """A material map's t* is in the material's time unit (issue 24: summary.py said
    "[T_eps]" for seconds): the headings name the unit the map's t_star carries."""
    path = tmp_path / "pla.h5"
    done = subprocess.run([BINARY, "sweep", "--config", str(REPO / "sweeps" / "materials" / "pla.ini"),
                           "--grid.dh", "0.005,0.02", "--grid.temperature", "70,80", "--quiet",
                           "--output", str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with h5py.File(path) as f:
        assert f["t_star"].attrs["units"] == "s"
    out = run("summary.py", path)
    assert out.returncode == 0, out.stderr
    assert "t* of the delayed points [s]" in out.stdout and "T_eps" not in out.stdout
    assert "t* of delayed [s]" in out.stdout
    out = run("summary.py", sweep(tmp_path / "sls.h5", "--quantities", "regime"))
    assert "t* of the delayed points [T_eps]" in out.stdout


def test_titles_name_the_material_or_law_the_model_and_the_load(maps, tmp_path):
    """Every picture's title says what was computed (issue 24: titles omitted the material
    and the load): the material's name (or the creep law), the model and the load."""
    with pm.open_map(maps["full"]) as ds:  # the standard linear solid, the paper's model, a step
        assert pm.map_context(ds) == "standard linear solid; the paper's model; step load"
        fig, _ = regime_map.render(ds, "pbar", "dh", fixed_at(ds, l=0.75, T=5, s=2), contours=False)
        assert fig._suptitle.get_text() == (
            "Regime map: standard linear solid\n"
            "step load, nominal pressure $\\bar p_0$ from 0.005 to 0.08 $E_0/(1-\\nu^2)$ (x axis)\n"
            "at $l$ = 0.75 $R$, $T$ = 5, spherical caps ($s$ = 2); the paper's model")
    small = ["--grid.l", "0.75", "--grid.dh", "0.05,0.1", "--grid.pbar", "0.01,0.02", "--grid.s", "2", "--quiet"]
    cases = {"NBR rubber; the paper's model; ramped load":
             ["--config", str(REPO / "sweeps" / "materials" / "nbr.ini"), "--grid.ramp_time", "1,10"],
             "standard linear solid; refined model; load table":
             ["--grid.T", "2.5", "--model.localization", "refined", "--model.load_table", "0:0.5,1:1"],
             "standard linear solid; periodic model; step load": ["--grid.T", "2.5"]}
    for k, (want, extra) in enumerate(cases.items()):
        path = tmp_path / f"case{k}.h5"
        done = subprocess.run([BINARY, "sweep", *small, *extra, "--output", str(path)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        with pm.open_map(path) as ds:
            assert pm.map_context(ds) == want
