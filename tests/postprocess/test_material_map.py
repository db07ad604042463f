"""A material map (`[model] material = F.ini`) as Python users meet it: times in the file's
unit, the material's attributes, and the postprocess scripts drawing it in physical units
(pressures in kPa from E0*, t* in the file's unit)."""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

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
MATERIAL = REPO / "materials" / "nbr_linder2011.ini"


@pytest.fixture(scope="module")
def material_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("map") / "nbr.h5"
    done = subprocess.run([BINARY, "sweep", "--model.material", str(MATERIAL), "--grid.l", "0.75",
                           "--grid.dh", "linspace(0.01, 0.04, 4)", "--grid.pbar", "logspace(0.002, 0.02, 5)",
                           "--grid.s", "2", "--time.times", "0, 10, 1000", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


def test_map_carries_the_material_and_its_units(material_map):
    ds = pm.open_map(material_map)
    assert ds.attrs["material_file"] == MATERIAL.read_text()
    assert ds.attrs["time_unit"] == "s"
    assert ds.t_star.attrs["units"] == "s" and ds.time.attrs["units"] == "s"
    assert list(pm.axes(ds)) == ["l", "dh", "pbar", "s"]
    # The reader gives pressures in kPa: pbar E0*, E0* = E_0/(1 - nu^2) with E_0 = E_inf + sum E_i
    # of the file (1200 + 1607.1 + 228.6 + 361.5 + 63.9 + 68.7 kPa), nu = 0.5.
    E0_star_kPa = (1200 + 1607.1 + 228.6 + 361.5 + 63.9 + 68.7) / (1 - 0.25)
    # The module's convention (one conversion for both readers): the unit shown, the scale
    # it came from, and the factor.
    assert ds.pbar.attrs["units"] == "kPa" and ds.pbar.attrs["scaled_by"] == "E0/(1-nu^2)"
    assert ds.pbar.attrs["per_scaled"] == pytest.approx(E0_star_kPa, rel=1e-9)
    np.testing.assert_allclose(ds.pbar.values, np.geomspace(0.002, 0.02, 5) * E0_star_kPa, rtol=1e-9)


def test_regime_map_draws_it_in_kpa_and_seconds(material_map, tmp_path):
    out = tmp_path / "map.png"
    rc, _, err = call(regime_map, material_map, "--x", "pbar", "--y", "dh", "--at", "l=0.75", "s=2", "-o", out)
    assert rc == 0, err
    assert out.stat().st_size > 10_000
    ds = pm.open_map(material_map)
    assert "kPa" in pm.axis_label(ds, "pbar")
    assert pm.unit_tex(pm.units(ds, "t_star")) == "s"


def test_touch_by_interpolates_in_log_time():
    import critical_dh
    dh = np.array([0.1, 0.2, 0.3, 0.4])
    t_star = np.array([0.0, 10.0, 1000.0, np.nan])
    assert critical_dh.touch_by_curve(dh, t_star, 100.0) == pytest.approx(0.25, rel=1e-12)  # halfway in log t
    assert critical_dh.touch_by_curve(dh, t_star, 5.0) == pytest.approx(0.15, rel=1e-12)  # linear from t* = 0
    assert critical_dh.touch_by_curve(dh, t_star, 1e4) == 0.3  # the last that touches; the next never does
    assert np.isnan(critical_dh.touch_by_curve(dh, np.array([5.0, 50.0, np.nan, np.nan]), 1.0))
    # Even the largest dh touches by then: the answer is above the grid, not its top value.
    assert critical_dh.touch_by_curve(dh, np.array([0.0, 1.0, 2.0, 3.0]), 100.0) == np.inf


def test_touch_by_starts_from_h_0_where_t_star_leaves_0():
    """Between the last immediate grid dh and the first delayed one, t* leaves 0 at h_0: the
    curve interpolates from there, so it never dips below h_0 (the PLA's 1 s curve lay under
    h_0 at 25 C, at the grid dh below it)."""
    import critical_dh
    dh = np.array([0.1, 0.2, 0.3, 0.4])
    t_star = np.array([0.0, 0.0, 1e6, np.nan])
    assert critical_dh.touch_by_curve(dh, t_star, 1.0, h0=0.25) == pytest.approx(0.25 + 1e-6 * 0.05, rel=1e-12)
    assert critical_dh.touch_by_curve(dh, t_star, 1.0) == pytest.approx(0.2 + 1e-6 * 0.1, rel=1e-12)
    # An h_0 outside the bracket (or NaN) leaves the grid point as it is.
    assert critical_dh.touch_by_curve(dh, t_star, 1.0, h0=0.15) == pytest.approx(0.2 + 1e-6 * 0.1, rel=1e-12)


def test_touch_by_curves_stop_at_the_grid_edge_and_say_so(tmp_path):
    """Issue 25: above some pressure the touch-by curves were drawn flat at the grid's top dh;
    they now stop there, with a warning and a legend mark."""
    import critical_dh
    path = tmp_path / "low.h5"
    # A dh grid far too low for 60 s: at every pressure level 2 touches at its top.
    done = subprocess.run([BINARY, "sweep", "--model.material", str(MATERIAL), "--grid.l", "0.75",
                           "--grid.dh", "linspace(0.001, 0.004, 4)", "--grid.pbar", "0.01, 0.02, 0.04",
                           "--grid.s", "2", "--quantities", "regime", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    ds = pm.open_map(path)
    t_top = ds.t_star.isel(dh=-1).values.ravel()
    assert np.all(np.nan_to_num(t_top, nan=np.inf) <= 60.0)  # the premise, from the map itself
    fixed = pm.resolve_at(ds, pm.parse_at(["l=0.75", "s=2"], ds), free=["T", "s"], optional=("T", "s"),
                          reserved={"pbar": "the horizontal axis", "dh": "the vertical axis"})
    assert np.all(np.isinf(critical_dh.touch_by_curves(ds, "pbar", fixed, [60.0])))
    out = tmp_path / "chart.png"
    rc, _, err = call(critical_dh, path, "--against", "pbar", "--at", "l=0.75", "--touch-by", "60", "-o", out)
    assert rc == 0, err
    assert "touches even at the grid's largest dh" in err and "extend grid.dh" in err
    assert out.stat().st_size > 10_000


def test_critical_dh_against_temperature_of_a_wlf_map(tmp_path):
    import critical_dh
    material = tmp_path / "wlf.ini"
    material.write_text(MATERIAL.read_text() + "[shift]\nkind = wlf\nC1 = 17.44\nC2 = 51.6\nT_ref = 20\n")
    path = tmp_path / "wlf.h5"
    done = subprocess.run([BINARY, "sweep", "--model.material", str(material), "--grid.l", "0.75",
                           "--grid.dh", "linspace(0.005, 0.06, 12)", "--grid.temperature", "10, 20, 30",
                           "--grid.pbar", "0.005", "--grid.s", "2", "--quantities", "regime", "--quiet",
                           "--output", str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    ds = pm.open_map(path)
    # WLF: colder is slower, so the dh that touches within 100 s shrinks with falling temperature.
    fixed = pm.resolve_at(ds, pm.parse_at(["l=0.75", "s=2", "pbar=23.532kPa"], ds), free=["T", "s"],
                          optional=("T", "s"),
                          reserved={"temperature": "the horizontal axis", "dh": "the vertical axis"})
    curves = critical_dh.touch_by_curves(ds, "temperature", fixed, [100.0])[0, 0, 0]
    assert curves[0] <= curves[1] <= curves[2] and curves[0] < curves[2]
    out = tmp_path / "chart.png"
    rc, _, err = call(critical_dh, path, "--against", "temperature", "--at", "l=0.75", "pbar=23.532kPa",
                      "--touch-by", "1,100", "-o", out)
    assert rc == 0, err
    assert out.stat().st_size > 10_000


@pytest.fixture(scope="module")
def physical_map(tmp_path_factory):
    """The new user's map, given in um and kPa (docs/cli.md, Units)."""
    path = tmp_path_factory.mktemp("map") / "um.h5"
    done = subprocess.run([BINARY, "sweep", "--model.material", str(MATERIAL), "--model.R", "50um",
                           "--grid.l", "150um", "--grid.dh", "1um, 2um, 3um, 4um", "--grid.pressure",
                           "logspace(5kPa, 50kPa, 5)", "--grid.s", "2", "--quiet", "--output", str(path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


def test_a_map_given_R_draws_lengths_in_its_unit(physical_map, tmp_path):
    ds = pm.open_map(physical_map)
    # Lengths in R's unit: l = 3 R of 50 um, radii and h likewise; a load R^2 E0* in N.
    assert ds.l.attrs["units"] == "um" and ds.l.values.tolist() == [150.0]
    np.testing.assert_allclose(ds.dh.values, [1, 2, 3, 4], rtol=1e-14)
    assert ds.a1.attrs["units"] == "um" and ds.h_inf.attrs["units"] == "um"
    assert ds.P1.attrs["units"] == "N"
    np.testing.assert_allclose(ds.pbar.values, np.geomspace(5, 50, 5), rtol=1e-12)
    assert "$\\mu$m" in pm.axis_label(ds, "dh") and "kPa" in pm.axis_label(ds, "pbar")
    out = tmp_path / "um.png"
    rc, _, err = call(regime_map, physical_map, "--x", "pbar", "--y", "dh", "--at", "l=150um", "s=2", "-o", out)
    assert rc == 0, err
    assert out.stat().st_size > 10_000


@pytest.mark.parametrize("text, expected", [("2um", 2.0), ("0.002mm", 2.0), ("0.04", 2.0), ("2000nm", 2.0)])
def test_at_takes_a_unit_or_a_bare_number_in_the_scale(physical_map, text, expected):
    ds = pm.open_map(physical_map)
    assert pm.parse_at([f"dh={text}"], ds)["dh"] == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("text, says", [("2kPa", "'kPa' is a pressure, dh a length"), ("2parsec", "not a unit"),
                                        ("um", "not a number")])
def test_at_refuses_unit_mistakes(physical_map, text, says):
    with pytest.raises(pm.MapError, match=says):
        pm.parse_at([f"dh={text}"], ds=pm.open_map(physical_map))


@pytest.fixture(scope="module")
def ems_map(tmp_path_factory):
    """The EMS of the DMA example (materials/dma), fitted at 25 C, on R = 50 um bumps at a
    150 um pitch, 5 MPa, 20 to 50 C: a material that creeps far (h_inf about 30 h_0)."""
    folder = tmp_path_factory.mktemp("ems")
    material, path = folder / "ems.ini", folder / "ems.h5"
    done = subprocess.run([BINARY, "fit", "--dma", str(REPO / "materials" / "dma" / "nrel_pyvisco_ems_ca.csv"),
                           "--reference-temperature", "25", "--poisson", "0.35", "-o", str(material)],
                          capture_output=True, text=True, cwd=folder)
    assert done.returncode == 0, done.stderr
    done = subprocess.run([BINARY, "sweep", "--model.material", str(material), "--model.R", "50um",
                           "--grid.l", "150um", "--grid.dh", "linspace(0.25um, 6um, 24)", "--grid.pressure", "5MPa",
                           "--grid.temperature", "20, 30, 40, 50", "--grid.s", "2", "--quantities", "regime",
                           "--quiet", "--output", str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return material, path


def test_critical_dh_of_a_far_creeping_material_reads(ems_map, tmp_path):
    """Issue: on the EMS, h_inf (49 um) stood so far above h_0 (1.5 um) that h_0 and the
    touch-by curves (2-6 um) were pressed against the bottom of a linear axis; the ^ legend gave
    the grid's largest dh as "(6)", without its unit; the title did not say the chart runs
    against temperature. Expected values from h5py and the material file."""
    import critical_dh
    import h5py

    material, path = ems_map
    name = re.search(r"^name = (.*)$", material.read_text(), flags=re.M).group(1).split(",")[0].strip()
    with h5py.File(path, "r") as f:  # axes l, dh, temperature, pbar, s; lengths in R, pbar in E0*
        R = f.attrs["R"]
        R_um = float((R.decode() if isinstance(R, bytes) else str(R)).split()[0])
        assert (R.decode() if isinstance(R, bytes) else str(R)).split()[1] == "um"
        dh_top_um = float(f["dh"][-1]) * R_um
        h0_um, hinf_um = f["h_0"][...] * R_um, f["h_inf"][...] * R_um
        t_top = f["t_star"][0, -1, :, 0, 0]
        pbar_kPa = float(f["pbar"][0]) * float(f.attrs["E0_star_Pa"]) / 1e3
    assert np.nanmax(hinf_um) > 20 * np.nanmin(h0_um)  # the premise: far beyond the factor 10
    assert np.any(np.nan_to_num(t_top, nan=np.inf) <= 3600)  # ... and an hour touches at the top dh

    out = tmp_path / "chart.png"
    rc, stdout, err = call(critical_dh, path, "--against", "temperature", "--at", "l=150um", "pbar=5MPa",
                           "--touch-by", "1,60,3600", "-o", out)
    assert rc == 0 and out.stat().st_size > 10_000, err
    assert "extend grid.dh" in err and f"largest dh = {dh_top_um:.6g} um" in err
    ds = pm.open_map(path)
    fixed = pm.resolve_at(ds, pm.parse_at(["l=150um", "pbar=5MPa"], ds), free=["T", "s"], optional=("T", "s"),
                          reserved={"temperature": "the horizontal axis", "dh": "the vertical axis"})
    fig = critical_dh.render(ds, "temperature", fixed, [1.0, 60.0, 3600.0])
    ax = fig.axes[0]
    assert ax.get_yscale() == "log"
    lo, hi = ax.get_ylim()
    assert 0 < lo < np.nanmin(h0_um) and hi > np.nanmax(hinf_um) and hi < 2 * np.nanmax(hinf_um)
    legend = [t.get_text() for t in fig.axes[-1].get_legend().get_texts()]
    (mark,) = [t for t in legend if "largest" in t]
    assert f"= {dh_top_um:g} $\\mu$m;" in mark  # "largest $\Delta h$ = 6 $\mu$m; ..."
    title = fig._suptitle.get_text()
    assert name and name in title.splitlines()[0] and "against temperature" in title.splitlines()[0]
    assert f"$\\bar p_0$ = {pbar_kPa:.6g} kPa" in title.splitlines()[1]
    assert "at $l$ = 150 $\\mu$m" in title.splitlines()[2]
    # --linear-dh: the old view, from 0 to just above h_inf.
    fig = critical_dh.render(ds, "temperature", fixed, [1.0, 60.0, 3600.0], scale="linear")
    assert fig.axes[0].get_yscale() == "linear" and fig.axes[0].get_ylim()[0] == 0


def test_regime_map_facets_a_subset_of_an_axis(tmp_path):
    """Issue 37 item 8: --at temperature=30,70 draws those temperatures, a panel each (with
    or without --facet temperature), and says which grid values they took; a list on an axis
    that is not the facet, or two lists, are refused by name."""
    path = tmp_path / "t.h5"
    pla = REPO / "materials" / "pla_prusament_chapuis2025.ini"
    subprocess.run([BINARY, "sweep", "--model.material", str(pla), "--grid.l", "0.75", "--grid.dh",
                    "linspace(0.005, 0.05, 4)", "--grid.pbar", "logspace(2e-4, 2e-3, 4)", "--grid.s", "2",
                    "--grid.temperature", "30,40,50,60,70", "--quantities", "regime", "--quiet", "--output", str(path)],
                   check=True)
    ds = pm.open_map(path)
    for extra in ([], ["--facet", "temperature"]):
        fixed = {k: pm.resolve_at(ds, {"l": 0.75, "s": 2}, free=[], reserved={"pbar": "", "dh": "", "temperature": ""})[k]
                 for k in ("l", "s")}
        want = [(T, regime_map.slices(ds, "pbar", "dh", "temperature", fixed)[k].regime)
                for k, T in enumerate(pm.grid_values(ds, "temperature")) if T in (30, 70)]
        _, panels = regime_map.render(ds, "pbar", "dh", fixed, "temperature", panels=[0, 4])
        assert len(panels) == 2
        got = regime_map.slices(ds, "pbar", "dh", "temperature", fixed, [0, 4])
        assert [d.value for d in got] == [T for T, _ in want]
        assert all((d.regime == r).all() for d, (_, r) in zip(got, want))
        out = tmp_path / f"f{len(extra)}.png"
        rc, stdout, err = call(regime_map, path, "--x", "pbar", "--y", "dh", "--at", "l=0.75", "s=2",
                               "temperature=30,70", *extra, "-o", out)
        assert rc == 0 and out.stat().st_size > 10_000, err
    rc, _, err = call(regime_map, path, "--x", "pbar", "--y", "temperature", "--at", "l=0.75", "s=2",
                      "dh=0.005,0.05", "--facet", "s", "-o", tmp_path / "x.png")
    assert rc == 2 and "a list of values picks the panels of the facet axis, which is s" in err, err
    rc, _, err = call(regime_map, path, "--x", "pbar", "--y", "dh", "--at", "l=0.75", "s=2,2", "temperature=30,70",
                      "-o", tmp_path / "x.png")
    assert rc == 2 and "a list of values picks the panels of the facet axis" in err, err


@pytest.fixture(scope="module")
def tpe_map(tmp_path_factory):
    """TPE-A (examples/dma_exports) at 20 C, caps of 80 um on a 250 um pitch, a step load:
    t* from 1e-8 s (immediate in practice) to hours."""
    path = tmp_path_factory.mktemp("tpe") / "tpe.h5"
    subprocess.run([BINARY, "sweep", "--model.material", str(REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"),
                    "--model.R", "80um", "--grid.l", "250um", "--grid.dh", "linspace(4um, 12um, 17)",
                    "--grid.pressure", "logspace(3kPa, 50kPa, 12)", "--grid.temperature", "20", "--grid.s", "2",
                    "--quantities", "regime", "--quiet", "--output", str(path)], check=True)
    return path


def test_pictures_in_the_users_time(tpe_map, tmp_path):
    """Issue 37 item 4: on a step-loaded material map a delay under 1 ms is drawn as
    immediate and the legend says so (--floor 0 draws it by t* again); titles say °C and
    "spherical caps"; the design chart takes --touch-by in the user's units and names them."""
    import critical_dh
    ds = pm.open_map(tpe_map)
    fixed = pm.resolve_at(ds, {"l": 250.0, "s": 2, "temperature": 20}, free=["pbar", "dh"])
    d = regime_map.slices(ds, "pbar", "dh", None, fixed)[0]
    fast = (d.regime == 1) & (d.t_star < 1e-3)
    slow = (d.regime == 1) & (d.t_star > 1e-2)
    assert fast.any() and slow.any()
    floor = regime_map.default_floor(ds)
    assert floor == (1e-3, "1 ms")
    immediate = pm.rgba(pm.REGIME_COLOURS["immediate"])
    fig, (panel,) = regime_map.render(ds, "pbar", "dh", fixed, floor=floor)
    assert np.allclose(panel.colours[fast], immediate) and not np.allclose(panel.colours[slow], immediate)
    texts = [t.get_text() for t in fig.legends[0].get_texts()] if fig.legends else \
        [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    assert any("within\n1 ms (immediate\nin practice)" in t for t in texts), texts
    assert "20 °C" in fig._suptitle.get_text() and "spherical caps ($s$ = 2)" in fig._suptitle.get_text()
    assert panel.scale.norm.vmin >= -3  # the colour bar starts at the floor's decade
    _, (bare,) = regime_map.render(ds, "pbar", "dh", fixed)
    assert not np.allclose(bare.colours[fast], immediate)
    rc, _, err = call(regime_map, tpe_map, "--x", "pbar", "--y", "dh", "--at", "l=250um", "s=2", "temperature=20",
                      "--floor", "0", "-o", tmp_path / "f.png")
    assert rc == 0, err
    # The design chart: --touch-by in units, named as given; a time whose curve lies above
    # the grid everywhere (here: a pitch 8x denser needs far more creep) is a note, not a line.
    fixed = pm.resolve_at(ds, {"l": 250.0, "temperature": 20}, free=["pbar", "dh", "s"])
    fig = critical_dh.render(ds, "pbar", fixed, [1.0, 60.0], "auto", ["1 s", "1 min"])
    legend = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    assert "touches by t = 1 s" in legend and "touches by t = 1 min" in legend, legend
    # dh 4 and 4.5 um only, at 4.9 kPa and up: by 1 min both touch at every pressure.
    ds_top = ds.isel(dh=slice(0, 2), pbar=slice(2, None))
    assert np.isinf(critical_dh.touch_by_curves(ds_top, "pbar", fixed, [60.0])).all()
    fig = critical_dh.render(ds_top, "pbar", fixed, [1e-9, 60.0], "auto", ["1 ns", "1 min"])
    legend = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    assert "touches by t = 1 min" not in legend and any(t.startswith("by t = 1 min: even") for t in legend), legend
    rc, _, err = call(critical_dh, tpe_map, "--against", "pbar", "--at", "l=250um", "temperature=20",
                      "--touch-by", "1s,1min,1h", "-o", tmp_path / "c.png")
    assert rc == 0, err
