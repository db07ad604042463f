"""The map scripts take a map's axes, units and flag codes from the file, not from copies of
today's layout: on a synthetic map (written here with xarray) whose axes are reordered, lack T
and s, and add `temperature` (in K) and a categorical `material`, and whose regime and valid
codes are renumbered and reordered, the reader, summary.py, regime_map.py, critical_dh.py,
evolution.py --map and model_error.py give what the construction says, and name the file's
axes in their errors."""
from __future__ import annotations

import csv
import json
import sys
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
POSTPROCESS = REPO / "postprocess"
sys.path.insert(0, str(POSTPROCESS))
import critical_dh  # noqa: E402
import evolution  # noqa: E402
import model_error  # noqa: E402
import punchsweep_maps as pm  # noqa: E402
from script_runner import call  # noqa: E402
import regime_map  # noqa: E402
import summary  # noqa: E402

# The axes in the map's order, with their coordinate attributes.
PBAR = 0.005 * 16.0 ** (np.arange(4) / 3)
AXES = {
    "pbar": (PBAR, {"units": "E0/(1-nu^2)", "long_name": "nominal pressure", "spacing": "log"}),
    "temperature": (np.array([280.0, 300.0, 320.0]),
                    {"units": "K", "long_name": "temperature", "spacing": "linear"}),
    "dh": (np.linspace(0.02, 0.12, 6),
           {"units": "R", "long_name": "height difference of the punch levels", "spacing": "linear"}),
    "material": (np.array(["steel", "rubber"], dtype=object), {"long_name": "material"}),
    "l": (np.array([0.75]), {"units": "R", "long_name": "lattice pitch", "spacing": "linear"}),
}
NAMES = tuple(AXES)
# Codes unlike the engine's, in another order: the scripts must read them from the file.
REGIME_FLAGS = {"never": 7, "immediate": 3, "delayed": 5, "not_computed": 9}
VALID_FLAGS = {"no_solution": 13, "valid": 10, "same_level_overlap": 11, "cross_level_overlap": 12,
               "not_computed": 14}
TIMES = np.array([0.0, 1.0, 5.0])


def construction():
    """Meanings per cell (regime and validity names) and the float variables, on NAMES."""
    shape = tuple(len(v) for v, _ in AXES.values())
    p, T, dh, m, _ = np.meshgrid(*(np.arange(n) for n in shape), indexing="ij")
    h_0 = 0.03 + 0.01 * p + 0.0 * dh  # independent of dh and temperature
    h_inf = h_0 + 0.02 + 0.01 * T + 0.01 * m
    dh_value = AXES["dh"][0][dh]
    regime = np.where(dh_value <= h_0, "immediate", np.where(dh_value >= h_inf, "never", "delayed"))
    valid = np.where((m == 1) & (p == 0), "same_level_overlap", "valid").astype(object)
    valid[(m == 0) & (p == 3) & (dh == 5)] = "no_solution"
    missing = (m == 1) & (T == 2) & (dh >= 4)  # an interrupted corner
    regime = np.where(missing, "not_computed", regime)
    valid[missing] = "not_computed"
    t_star = np.where(regime == "immediate", 0.0,
                      np.where(regime == "delayed", 0.1 + dh_value + T, np.nan))
    return regime, valid.astype(str), {"t_star": t_star, "h_0": np.where(missing, np.nan, h_0),
                                       "h_inf": np.where(missing, np.nan, h_inf)}


def flag_variable(meanings: np.ndarray, codes: dict[str, int], long_name: str):
    import xarray as xr

    data = np.vectorize(codes.get)(meanings).astype(np.int8)
    return xr.Variable(NAMES, data, {"long_name": long_name,
                                     "flag_values": np.array(list(codes.values()), dtype=np.int8),
                                     "flag_meanings": " ".join(codes)})


def write_map(path: Path, drop: str | None = None) -> Path:
    """The synthetic map (with the time series and a BEM reference equal to the model, t* 1.1
    times as long); `drop` leaves out one axis (its first value taken)."""
    import xarray as xr

    regime, valid, floats = construction()
    shape = regime.shape
    variables = {"regime": flag_variable(regime, REGIME_FLAGS, "contact regime"),
                 "valid": flag_variable(valid, VALID_FLAGS, "validity"),
                 "bem_regime": flag_variable(regime, REGIME_FLAGS, "BEM regime")}
    for name, data in floats.items():
        variables[name] = xr.Variable(NAMES, data, {"units": "T_eps" if name == "t_star" else "R"})
    variables["bem_t_star"] = xr.Variable(NAMES, 1.1 * floats["t_star"], {"units": "T_eps"})
    for name in ("a1_inf", "a2_inf", "area_fraction_inf"):
        variables[name] = xr.Variable(NAMES, np.full(shape, 0.25))
    for k, name in enumerate(pm.SERIES):
        variables[name] = xr.Variable((*NAMES, "time"), np.broadcast_to(
            (k + 1) * TIMES / 10, (*shape, len(TIMES))).copy())
    coords = {name: xr.Variable(name, values, attrs) for name, (values, attrs) in AXES.items()}
    coords["time"] = xr.Variable("time", TIMES, {"units": "T_eps"})
    ds = xr.Dataset(variables, coords, attrs={"completed": np.int8(1)})
    if drop:
        ds = ds.isel({drop: 0}, drop=True)
    ds.to_netcdf(path, engine="h5netcdf")
    return path


@pytest.fixture(scope="module")
def synthetic(tmp_path_factory):
    folder = tmp_path_factory.mktemp("axes")
    return {"map": write_map(folder / "synthetic.h5"),
            "no_dh": write_map(folder / "no_dh.h5", drop="dh"), "folder": folder}




def test_reader_takes_axes_units_and_codes_from_the_file(synthetic):
    with pm.open_map(synthetic["map"]) as ds:
        assert pm.axes(ds) == NAMES
        assert [pm.units(ds, a) for a in NAMES] == ["E0/(1-nu^2)", "K", "R", "1", "R"]  # "1": dimensionless, as the module says it
        assert pm.labels(ds, "material") == ["steel", "rubber"] and pm.labels(ds, "dh") is None
        assert pm.is_log(ds, "pbar") and not pm.is_log(ds, "temperature")
        assert pm.axis_label(ds, "temperature") == "temperature [K]"
        codes = pm.flags(ds, "regime")
        assert {m: codes.code(m) for m in codes.meanings} == REGIME_FLAGS
        assert pm.flags(ds, "valid").meaning(11) == "same_level_overlap"
        at = pm.parse_at(["temperature=305", "material=rubber"], ds)
        fixed = pm.resolve_at(ds, at, free=["pbar", "dh"])
        assert [(n, f.index, f.value) for n, f in fixed.items()] == [
            ("temperature", 1, 300.0), ("material", 1, "rubber"), ("l", 0, 0.75)]
        assert fixed["temperature"].message == ("--at temperature=305 -> nearest grid value "
                                                "temperature = 300 K")
        with pytest.raises(pm.MapError, match="unknown axis 'T' for --at; valid axes: pbar, "
                                              "temperature, dh, material, l"):
            pm.parse_at(["T=2.5"], ds)
        with pytest.raises(pm.MapError, match="--at material=wood is not on the axis; material "
                                              "has the labels steel, rubber"):
            pm.resolve_at(ds, {"material": "wood"}, free=["pbar", "dh", "temperature"])


def test_colours_follow_the_meanings_of_the_file_codes(synthetic):
    regime, valid, _ = construction()
    with pm.open_map(synthetic["map"]) as ds:
        grid = pm.regime_colour_grid(ds, ds.regime.values, ds.valid.values)
    for meaning in pm.DRAWN_REGIMES:
        ok = valid == "valid"
        plain, pale = (regime == meaning) & ok, (regime == meaning) & ~ok
        assert plain.any() and np.all(grid[plain] == pm.rgba(pm.REGIME_COLOURS[meaning]))
        assert pale.any() and np.all(grid[pale] == pm.invalid_colour(meaning))
    assert np.all(grid[regime == "not_computed"] == pm.rgba(pm.REGIME_COLOURS["not_computed"]))


def test_summary_counts_per_file_meaning_over_the_file_axes(synthetic):
    rc, out, err = call(summary, synthetic["map"], "--csv")
    assert rc == 0, err
    rows = list(csv.DictReader(line for line in out.splitlines() if not line.startswith("#")))
    assert list(rows[0]) == ["axis", "value", "units", "points", "never", "immediate", "delayed",
                             "not_computed", "fraction_never", "fraction_immediate",
                             "fraction_delayed", "fraction_not_computed", "no_solution", "valid",
                             "same_level_overlap", "cross_level_overlap", "t_star_min",
                             "t_star_median", "t_star_max"]
    regime, valid, floats = construction()
    assert [r["axis"] for r in rows] == ["all"] + [a for a in NAMES for _ in AXES[a][0]]
    for row in rows:
        if row["axis"] == "all":
            take = np.ones(regime.shape, dtype=bool)
        else:
            values = list(AXES[row["axis"]][0])
            i = values.index(row["value"] if row["axis"] == "material" else float(row["value"]))
            take = np.zeros(regime.shape, dtype=bool)
            take[(slice(None),) * NAMES.index(row["axis"]) + (i,)] = True
            # An axis without units is dimensionless: "1", as the module's open_map says it.
            assert row["units"] == AXES[row["axis"]][1].get("units", "1")
        for m in REGIME_FLAGS:
            assert int(row[m]) == np.count_nonzero(take & (regime == m)), (m, row)
        for m in ("no_solution", "valid", "same_level_overlap", "cross_level_overlap"):
            assert int(row[m]) == np.count_nonzero(take & (valid == m)), (m, row)
        delayed = floats["t_star"][take & (regime == "delayed")]
        assert row["t_star_max"] == (repr(delayed.max()) if delayed.size else "")
    assert int(rows[0]["not_computed"]) == 2 * 4 > 0 and int(rows[0]["no_solution"]) == 3
    rc, out, err = call(summary, synthetic["map"], "--by", "temperature", "material")
    assert rc == 0, err
    assert "  temperature    3 values  280 .. 320 K  (linear)" in out
    assert "by temperature [K]: points per regime" in out and "by material: points" in out
    assert "\n       steel" in out and "\n      rubber" in out
    rc, _, err = call(summary, synthetic["map"], "--by", "T")
    assert rc == 2
    assert "unknown axis 'T' for --by; valid axes: pbar, temperature, dh, material, l" in err


def test_regime_map_at_accepts_any_axis_of_the_file(synthetic, tmp_path):
    png = tmp_path / "map.png"
    rc, out, err = call(regime_map, synthetic["map"], "--x", "pbar", "--y", "dh", "--at",
                        "temperature=305", "material=rubber", "-o", png)
    assert rc == 0, err
    assert out.splitlines() == ["--at temperature=305 -> nearest grid value temperature = 300 K",
                                "--at material=rubber -> nearest grid value material = rubber",
                                "l not given -> its only grid value l = 0.75 R",
                                f"regime_map.py: wrote {png}"]
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    regime, valid, floats = construction()
    with pm.open_map(synthetic["map"]) as ds:
        fixed = pm.resolve_at(ds, {"temperature": 300.0}, free=[], reserved={
            "pbar": "x", "dh": "y", "material": "facet"})
        fig, panels = regime_map.render(ds, "pbar", "dh", fixed, facet="material")
        assert [p.title for p in panels] == ["material = steel", "material = rubber"]
        assert panels[0].ax.get_xscale() == "log"
        assert panels[0].ax.get_xlabel() == "nominal pressure $\\bar p_0$ [$E_0/(1-\\nu^2)$]"
        for k, panel in enumerate(panels):
            cut = (slice(None), 1, slice(None), k, 0)
            # The synthetic map's bem_regime is its regime at every computed point, so an
            # invalid cell shows the BEM's (same) regime in full colour (regime_map.py), and
            # a delayed one the colour bar's colour of the BEM's t* (1.1 times the model's).
            t_star = np.where(valid[cut] == "valid", 1.0, 1.1) * floats["t_star"][cut]
            want = np.array([[panel.scale.to_rgba(np.log10(t)) if r == "delayed" else pm.rgba(pm.REGIME_COLOURS[r])
                              for r, t in zip(rr, tt)]
                             for rr, tt in zip(regime[cut].T, t_star.T)])  # (dh, pbar)
            np.testing.assert_allclose(panel.colours, want, atol=1e-12)


@pytest.mark.parametrize("args, message", [
    (["--x", "pbar", "--y", "dh", "--at", "T=2.5"],
     "unknown axis 'T' for --at; valid axes: pbar, temperature, dh, material, l"),
    (["--x", "pbar", "--y", "dh"], "still to fix temperature, material (temperature in {280, 300, "
                                   "320}; material in {steel, rubber})"),
    (["--x", "material", "--y", "dh"], "--x material: material is a categorical axis (steel, "
                                       "rubber); --x needs a numeric axis"),
    (["--x", "s", "--y", "dh"], "unknown axis 's' for --x; valid axes: pbar, temperature, dh"),
], ids=["at-axis-not-in-file", "axes-to-fix", "categorical-x", "x-not-in-file"])
def test_regime_map_errors_name_the_file_axes(synthetic, tmp_path, args, message):
    out = tmp_path / "x.png"
    rc, stdout, err = call(regime_map, synthetic["map"], *args, "-o", out)
    assert rc == 2 and message in err and len(err.strip().splitlines()) == 1, err
    assert not out.exists() and stdout == ""


def test_critical_dh_without_T_and_s_axes_draws_one_panel_and_curve(synthetic, tmp_path):
    png = tmp_path / "chart.png"
    rc, out, err = call(critical_dh, synthetic["map"], "--at", "temperature=320",
                        "material=steel", "-o", png)
    assert rc == 0, err
    assert "--at temperature=320 -> nearest grid value temperature = 320 K" in out
    _, _, floats = construction()
    with pm.open_map(synthetic["map"]) as ds:
        fixed = pm.resolve_at(ds, {"temperature": 320.0, "material": "steel"}, free=[],
                              reserved={"pbar": "x", "dh": "y"})
        x, T, s, h0, hinf = critical_dh.critical_curves(ds, "pbar", fixed)
        np.testing.assert_array_equal(x, PBAR)
        assert np.isnan(T).all() and np.isnan(s).all() and hinf.shape == (1, 1, 4)
        np.testing.assert_array_equal(h0[0], floats["h_0"][:, 2, 0, 0, 0])
        np.testing.assert_array_equal(hinf[0, 0], floats["h_inf"][:, 2, 0, 0, 0])
        fig = critical_dh.render(ds, "pbar", fixed)
        assert fig.axes[0].get_title() == "" and fig.axes[0].get_xscale() == "log"
        legend = [t.get_text() for t in fig.axes[-1].get_legend().get_texts()]
        assert "$h_\\infty$" in legend
    rc, _, err = call(critical_dh, synthetic["map"], "--against", "l", "--at", "temperature=300",
                      "material=steel", "pbar=0.01", "-o", tmp_path / "c.png")
    assert rc == 0, err
    rc, _, err = call(critical_dh, synthetic["no_dh"], "-o", tmp_path / "e.png")
    assert rc == 2 and not (tmp_path / "e.png").exists()
    assert ("critical_dh.py --against pbar needs the axis dh; this map has the axes pbar, "
            "temperature, material, l") in err


def test_evolution_map_mode_reads_meanings_from_the_file(synthetic, tmp_path):
    js = tmp_path / "e.json"
    regime, valid, floats = construction()
    for dh, m, want_regime, want_valid in ((0, 1, "immediate", "same_level_overlap"),
                                           (1, 0, "delayed", "valid")):
        rc, out, err = call(evolution, "--map", synthetic["map"], "--at", "pbar=0.005",
                            "temperature=280", f"dh={AXES['dh'][0][dh]}",
                            f"material={AXES['material'][0][m]}", "-o", tmp_path / "e.png",
                            "--json", js)
        assert rc == 0, err
        assert (regime[0, 0, dh, m, 0], valid[0, 0, dh, m, 0]) == (want_regime, want_valid)
        result = json.loads(js.read_text())
        assert result["regime"] == want_regime and result["valid"] == (want_valid == "valid")
        assert result["reason"] == ("" if want_valid == "valid" else want_valid)
        assert result["series"]["t"] == list(TIMES) and result["series"]["a2"] == list(TIMES / 5)
    rc, _, err = call(evolution, "--map", synthetic["map"], "--at", "pbar=0.005",
                      "temperature=320", "dh=0.12", "material=rubber", "-o", tmp_path / "n.png")
    assert rc == 2 and "was not computed" in err and "material = rubber" in err


def test_model_error_compares_by_meaning_over_the_file_axes(synthetic, tmp_path):
    regime, _, _ = construction()
    with pm.open_map(synthetic["map"]) as ds:
        r = model_error.compare(ds)
    counts = [np.count_nonzero(regime == m) for m in pm.DRAWN_REGIMES]
    np.testing.assert_array_equal(r["confusion"], np.diag(counts))
    assert r["agreement"] == 1.0 and r["sampled"] == sum(counts)
    assert list(r["t_star_by_axis"]) == list(NAMES)
    assert [v for v, _ in r["t_star_by_axis"]["material"]] == ["steel", "rubber"]
    assert r["t_star"]["median"] == pytest.approx(0.1 / 1.1, rel=1e-12)
    errors, cut = tmp_path / "errors.png", tmp_path / "slice.png"
    rc, out, err = call(model_error, synthetic["map"], "--errors-plot", errors, "--slice-plot", cut,
                        "--at", "temperature=300", "material=steel")
    assert rc == 0, err
    assert "material: steel:" in out and "temperature K:" in out
    assert errors.read_bytes()[:4] == cut.read_bytes()[:4] == b"\x89PNG"


def test_a_map_without_flag_meanings_is_refused_with_exit_2(synthetic):
    import h5py

    path = synthetic["folder"] / "no_meanings.h5"
    path.write_bytes(synthetic["map"].read_bytes())
    with h5py.File(path, "r+") as f:
        del f["valid"].attrs["flag_meanings"]
    rc, out, err = call(summary, path)
    assert rc == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert ("is not a punchsweep regime map ('valid' has no flag_values/flag_meanings "
            "attributes, so its codes cannot be read)") in err
