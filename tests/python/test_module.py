"""The Python module punchsweep (issue 14) against the command line it wraps: point and
reference equal their --format json bit for bit, classify equals point, inputs broadcast,
bad input raises the command's message, open_map decodes a real map, the examples run."""
from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))


def cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, *args], capture_output=True, text=True)


def cli_json(command: str, options: list[str]) -> dict:
    done = cli(command, *options, "--format", "json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def same_bits(a, b) -> bool:
    """Equal to the bit: the same values, NaN where the other has NaN, the same signs."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=True) and np.array_equal(np.signbit(a), np.signbit(b))


def from_json_array(values) -> np.ndarray:
    return np.array([np.nan if v is None else v for v in values], dtype=float)


MATERIAL = str(REPO / "materials" / "nbr_linder2011.ini")
POINTS = [
    dict(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2),                                    # delayed
    dict(l=0.75, dh=0.05, T=2.5, pbar=0.06, s=2, localization="paper"),               # immediate, the paper's model
    dict(l=1.25, dh=0.12, T=2.0, pbar=0.005, s=1, C=0.4),                             # never, a cone
    dict(l=0.5, dh=0.01, T=5.0, pbar=0.08, s=3, times=[0.0, 0.25, 1.0, 10.0]),        # flagged invalid
    dict(l=0.75, dh=0.02, pbar=0.005, s=2, material=MATERIAL, times=[0, 100, 10000], ramp=20.0),
]


def options_of(kw: dict) -> list[str]:
    args = []
    for k, v in kw.items():
        text = ",".join(repr(float(t)) for t in v) if isinstance(v, list) else (v if isinstance(v, str) else repr(v))
        args += ["--" + k.replace("_", "-"), text]
    return args


@pytest.mark.parametrize("kw", POINTS, ids=lambda kw: ",".join(f"{k}={v}" for k, v in kw.items() if k != "material"))
def test_point_equals_the_cli_json_bit_for_bit(kw):
    expected = cli_json("point", options_of(kw))
    got = punchsweep.point(**kw)
    for key, value in expected.items():
        if key == "series":
            assert set(value) == set(got.series)
            for name, column in value.items():
                assert same_bits(got.series[name], from_json_array(column)), name
        elif key == "localization":
            assert got.localization == value
        elif key == "physical":  # the physical fields, where a scale is known
            assert set(value) == set(got.physical)
            for name, v in value.items():
                if name == "series":
                    assert set(v) == set(got.physical["series"])
                    for column, values in v.items():
                        assert same_bits(got.physical["series"][column], from_json_array(values)), column
                else:
                    assert same_bits(got.physical[name], v), name
        elif isinstance(value, float) or value is None:
            # The sensitivity keys (dt_star_dNAME, dlog_t_star_dlog_NAME) are in .sensitivity,
            # t_star_low/high in .t_star_range.
            sensitive = key.startswith(("dt_star_d", "dlog_t_star_dlog_"))
            g = got.sensitivity[key] if sensitive else getattr(got, key)
            assert (g is None and value is None) or (g is not None and same_bits(g, value)), key
        else:
            assert getattr(got, key) == value, key
    assert got.localization == expected.get("localization", "paper")
    assert set(got.sensitivity) == {k for k in expected if k.startswith(("dt_star_d", "dlog_t_star_dlog_"))}


def test_reference_equals_the_cli_json_bit_for_bit():
    kw = dict(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2, bem_grid=32)
    expected = cli_json("reference", options_of(kw))
    got = punchsweep.reference(**kw)
    for key, value in expected.items():
        if key == "seconds":
            continue
        if key == "series":
            for name, column in value.items():
                assert same_bits(got.series[name], from_json_array(column)), name
        elif isinstance(value, float) or value is None:
            g = getattr(got, key)
            assert (g is None and value is None) or same_bits(g, value), key
        else:
            assert getattr(got, key) == value, key


def random_points(count: int, seed: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    return dict(l=rng.uniform(0.5, 1.25, count), dh=rng.uniform(0.005, 0.12, count), T=rng.uniform(1.5, 10, count),
                pbar=np.exp(rng.uniform(np.log(0.005), np.log(0.08), count)), s=rng.integers(1, 4, count).astype(float))


@pytest.mark.parametrize("localization", ["refined", "paper", "periodic"])
def test_classify_equals_point_on_random_points(localization):
    count = 10_000 if localization == "refined" else 2_000
    p = random_points(count, seed=14)
    c = punchsweep.classify(p["l"], p["dh"], p["T"], p["pbar"], p["s"], localization=localization)
    assert all(c[k].shape == (count,) for k in ("regime", "t_star", "h_0", "h_inf", "valid"))
    assert c["regime"].dtype == np.int8 and c["valid"].dtype == np.bool_
    names = c.regime_names()
    mismatches = []
    for i in range(count):
        r = punchsweep.point(l=p["l"][i], dh=p["dh"][i], T=p["T"][i], pbar=p["pbar"][i], s=int(p["s"][i]),
                             times=[0.0], localization=localization)
        row = (names[i], c["t_star"][i], c["h_0"][i], c["h_inf"][i], c["a1_inf"][i], c["a2_inf"][i],
               c["area_fraction_inf"][i], bool(c["valid"][i]), c["valid_code"][i] == 0)
        want = (r.regime, np.nan if r.t_star is None else r.t_star, r.h_0, r.h_inf, r.a1_inf, r.a2_inf,
                r.area_fraction_inf, r.valid, r.valid)
        if not (row[0] == want[0] and all(same_bits(a, b) for a, b in zip(row[1:7], want[1:7])) and row[7:] == want[7:]):
            mismatches.append((i, row, want))
    assert not mismatches, mismatches[:5]
    # The sample covers every regime and, for the localization models, both validity flags;
    # the periodic model holds at all of them (merged spots are part of its solution).
    assert set(names) == {"immediate", "delayed", "never"}
    if localization == "periodic":
        assert c["valid"].all()
    else:
        assert c["valid"].any() and not c["valid"].all()


@pytest.mark.parametrize("localization", ["periodic", "refined"])
def test_classify_takes_a_material_and_its_temperature(localization):
    """classify(material=..., temperature=...) (issue 23): a Prony series with a WLF shift at
    scattered temperatures, and one without a shift (no temperature), equal point() with
    --material at every point, t* in the file's time unit."""
    pla = str(REPO / "materials" / "pla_prusament_chapuis2025.ini")
    rng = np.random.default_rng(23)
    n = 300
    l, dh = rng.uniform(0.5, 1.25, n), rng.uniform(0.005, 0.12, n)
    pbar, s = np.exp(rng.uniform(np.log(0.005), np.log(0.08), n)), rng.integers(1, 4, n).astype(float)
    temperature = rng.uniform(66, 85, n)
    for material, temps in ((pla, temperature), (MATERIAL, None)):
        c = punchsweep.classify(l, dh, pbar=pbar, s=s, localization=localization, material=material,
                                temperature=temps)
        assert c.time_unit == "s"
        names = c.regime_names()
        for i in range(0, n, 3):
            extra = {} if temps is None else {"temperature": float(temps[i])}
            r = punchsweep.point(l=l[i], dh=dh[i], pbar=pbar[i], s=int(s[i]), times=[0.0], material=material,
                                 localization=localization, **extra)
            assert names[i] == r.regime, (i, names[i], r.regime)
            assert same_bits(c["t_star"][i], np.nan if r.t_star is None else r.t_star)
            assert same_bits(c["h_inf"][i], r.h_inf) and bool(c["valid"][i]) == r.valid
        assert len(set(names)) >= 2
    with pytest.raises(ValueError, match="T is the standard linear solid"):
        punchsweep.classify(0.75, 0.05, 2.5, 0.06, 2, material=pla, temperature=75)
    with pytest.raises(ValueError, match="temperature"):
        punchsweep.classify(0.75, 0.05, pbar=0.06, s=2, material=pla, temperature=200)


def test_classify_returns_every_per_point_variable_of_a_regime_map(tmp_path):
    """classify's arrays are the model's per-point quantities as a sweep's regime map stores
    them (one declaration, map::kQuantities): the same names, and at the map's own points the
    same values (a flag's codes; the validity flag as a bool with its codes as valid_code)."""
    path = tmp_path / "map.h5"
    done = cli("sweep", "--grid.l", "0.5,0.75,1.0", "--grid.dh", "0.01,0.05,0.1", "--grid.T", "2.5", "--grid.pbar",
               "0.02,0.06", "--grid.s", "1,2", "--quantities", "regime", "--model.localization", "refined", "--quiet",
               "--output", str(path))
    assert done.returncode == 0, done.stderr
    with h5py.File(path) as f:
        shape = f["regime"].shape
        per_point = {name: f[name][...] for name in f if isinstance(f[name], h5py.Dataset)
                     and f[name].shape == shape and not name.startswith(("bem_", "answer_"))}
        grid = {name: f[name][...] for name in ("l", "dh", "T", "pbar", "s")}
    assert {"regime", "t_star", "valid", "a2_inf"} <= set(per_point), sorted(per_point)
    L, DH, T, P, S = np.meshgrid(*(grid[k] for k in ("l", "dh", "T", "pbar", "s")), indexing="ij")
    c = punchsweep.classify(L, DH, T, P, S, localization="refined")
    assert set(c) == set(per_point) | {"valid_code"}, (sorted(c), sorted(per_point))
    for name, stored in per_point.items():
        got = c["valid_code"] if name == "valid" else c[name]
        assert got.dtype == stored.dtype and same_bits(got, stored), name
    assert np.array_equal(c["valid"], per_point["valid"] == 0) and not c["valid"].all()


def test_classify_returns_the_quantities_named_and_refuses_others():
    p = random_points(500, seed=7)
    args = (p["l"], p["dh"], p["T"], p["pbar"], p["s"])
    every = punchsweep.classify(*args)
    some = punchsweep.classify(*args, quantities=["t_star", "valid"])
    assert set(some) == {"t_star", "valid", "valid_code"}
    assert all(same_bits(some[k], every[k]) for k in some)
    assert set(punchsweep.classify(*args, quantities="a2_inf")) == {"a2_inf"}
    with pytest.raises(ValueError, match="quantities: 't_str' is not one of: regime, t_star, h_0"):
        punchsweep.classify(*args, quantities=["t_str"])


def test_classify_broadcasts_like_numpy():
    l = np.array([0.5, 0.75, 1.0])[:, None, None]
    dh = np.linspace(0.01, 0.1, 4)[None, :, None]
    pbar = np.array([0.01, 0.02, 0.04, 0.06, 0.08])[None, None, :]
    c = punchsweep.classify(l, dh, 2.5, pbar, 2)
    for key in ("regime", "t_star", "h_0", "h_inf", "valid"):
        assert c[key].shape == (3, 4, 5)
    flat = punchsweep.classify(np.broadcast_to(l, (3, 4, 5)).ravel(), np.broadcast_to(dh, (3, 4, 5)).ravel(),
                               np.full(60, 2.5), np.broadcast_to(pbar, (3, 4, 5)).ravel(), np.full(60, 2.0))
    for key in ("regime", "t_star", "h_0", "h_inf", "valid"):
        assert same_bits(c[key].ravel(), flat[key])
    scalar = punchsweep.classify(0.75, 0.075, 2.5, 0.06, 2)
    assert scalar["regime"].shape == () and punchsweep.REGIMES[int(scalar["regime"])] == "delayed"
    # h_0 and h_inf do not depend on dh: the same along that axis.
    assert same_bits(c["h_0"][:, 0, :], c["h_0"][:, 3, :])


def cli_message(options: list[str]) -> str:
    done = cli("point", *options)
    assert done.returncode == 2
    line = done.stderr.strip().splitlines()[0]
    return line.split(": ", 1)[1] if line.startswith("punchsweep") else line


@pytest.mark.parametrize("bad, options", [
    (dict(l=-0.5), ["--l", "-0.5"]),
    (dict(s=0), ["--s", "0"]),
    (dict(T=0.5), ["--T", "0.5"]),
    (dict(pbar=0.0), ["--pbar", "0.0"]),
    (dict(localization="shells:x"), ["--localization", "shells:x"]),
])
def test_bad_input_raises_the_command_lines_message(bad, options):
    base = dict(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2)
    expected = cli_message(options_of({**base, **{k: v for k, v in bad.items()}}))
    with pytest.raises(ValueError) as point_error:
        punchsweep.point(**{**base, **bad})
    assert str(point_error.value) == expected
    # classify says the same for the same value (the arrays' other values admissible).
    if "localization" in bad:
        with pytest.raises(ValueError) as error:
            punchsweep.classify(0.75, 0.075, 2.5, 0.06, 2, localization=bad["localization"])
    else:
        arrays = {k: np.array([v, bad.get(k, v)]) for k, v in base.items()}
        with pytest.raises(ValueError) as error:
            punchsweep.classify(arrays["l"], arrays["dh"], arrays["T"], arrays["pbar"], arrays["s"])
    assert str(error.value) == expected


def test_point_rejects_a_missing_option_and_a_bad_material_as_the_cli_does():
    with pytest.raises(ValueError) as error:
        punchsweep.point(l=0.75, dh=0.075, T=2.5, s=2)
    assert str(error.value) == cli_message(["--l", "0.75", "--dh", "0.075", "--T", "2.5", "--s", "2"])
    with pytest.raises(ValueError, match="no_such.ini"):
        punchsweep.point(l=0.75, dh=0.02, pbar=0.005, s=2, material="no_such.ini")


def test_open_map_decodes_a_real_map(tmp_path):
    path = tmp_path / "map.h5"
    # The refined model, whose map has flagged points to decode.
    done = cli("sweep", "--grid.l", "0.5,0.75", "--grid.dh", "0.01,0.05,0.1", "--grid.T", "2.5", "--grid.pbar",
               "0.02,0.06", "--grid.s", "2", "--quantities", "full", "--model.localization", "refined", "--quiet",
               "--output", str(path))
    assert done.returncode == 0, done.stderr
    ds = punchsweep.open_map(path)
    import h5py
    with h5py.File(path) as f:
        codes = f["regime"][...]
        valid = f["valid"][...]
        t_star = f["t_star"][...]
    assert ds["regime"].shape == codes.shape
    assert np.array_equal(ds["regime_code"].values, codes)
    lookup = punchsweep.REGIMES
    assert all(ds["regime"].values.ravel()[i] == lookup[int(c)] for i, c in enumerate(codes.ravel()))
    with h5py.File(path) as f:
        meanings = f["valid"].attrs["flag_meanings"]
        meanings = (meanings.decode() if isinstance(meanings, bytes) else str(meanings)).split()
        values = [int(v) for v in f["valid"].attrs["flag_values"]]
    decoded = dict(zip(values, meanings))
    assert all(ds["valid"].values.ravel()[i] == decoded[int(c)] for i, c in enumerate(valid.ravel()))
    assert "valid" in set(ds["valid"].values.ravel()) and len(set(ds["valid"].values.ravel())) > 1
    assert np.array_equal(ds["valid_code"].values, valid)
    assert same_bits(ds["t_star"].values, t_star)
    assert all("units" in ds[name].attrs for name in ds.variables)
    assert ds["t_star"].attrs["units"] == "T_eps" and ds["l"].attrs["units"] == "R"
    assert ds["a1"].attrs["units"] == "R" and ds["P1"].attrs["units"] == "R^2 E0/(1-nu^2)"
    # Decoded values equal classify's at the map's own points.
    L, DH, P = np.meshgrid(ds["l"].values, ds["dh"].values, ds["pbar"].values, indexing="ij")
    c = punchsweep.classify(L, DH, 2.5, P, 2, localization="refined")
    assert np.array_equal(c["regime"], codes[:, :, 0, :, 0])


def test_reference_is_interrupted_by_ctrl_c():
    """Ctrl-C (SIGINT) stops a long reference() between its BEM time steps with
    KeyboardInterrupt: a point at N = 1024 (each solve about 0.4 s, the whole point 12 s
    here) is signalled 2 s in and must be back within 3 s."""
    took = seconds_to_interrupt(
        "punchsweep.reference(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2, times=[0, 5, 50], bem_grid=1024)", after=2.0)
    assert took < 3.0, f"reference took {took:.2f} s to stop after SIGINT"


def test_open_map_decodes_lazily_and_slices_equal_the_whole(tmp_path):
    """Issue 22: open_map decoded every flag at once (about 260 bytes a point: 13 GB for the
    production map); now a flag is decoded where it is read, so opening a map
    takes far less than decoding it (100,000 points here), and any slice equals the same
    slice of the whole."""
    import tracemalloc
    path = tmp_path / "big.h5"
    done = cli("sweep", "--grid.l", "linspace(0.5,1.5,25)", "--grid.dh", "linspace(0.01,0.12,40)", "--grid.T", "2,5",
               "--grid.pbar", "logspace(0.005,0.08,25)", "--grid.s", "1,2", "--quantities", "regime", "--quiet",
               "--output", str(path))
    assert done.returncode == 0, done.stderr
    tracemalloc.start()
    ds = punchsweep.open_map(path)
    opened = tracemalloc.get_traced_memory()[1]
    whole = ds["regime"].values
    decoded = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert whole.size == 100_000
    assert opened < 0.1 * decoded, (opened, decoded)
    part = ds["regime"].isel(l=slice(3, 9), T=1, s=0).values
    assert np.array_equal(part, whole[3:9, :, 1, :, 0])
    assert np.array_equal(ds["valid"][2, 5].values, ds["valid"].values[2, 5])
    assert set(np.unique(whole)) <= set(punchsweep.REGIMES.values()) | {"not_computed"}


def test_open_map_says_what_is_not_a_map(tmp_path):
    for path, why in [(tmp_path / "none.h5", "no such file"),
                      (tmp_path / "text.h5", "is not an HDF5 file, so not a punchsweep regime map"),
                      (tmp_path / "plain.h5", "is not a punchsweep regime map \\(no regime, valid")]:
        if path.name == "text.h5":
            path.write_text("not HDF5 at all\n")
        if path.name == "plain.h5":
            import h5py
            with h5py.File(path, "w") as f:
                f["x"] = np.arange(3.0)
        with pytest.raises(punchsweep.NotAMapError, match=why):
            punchsweep.open_map(path)
    damaged = tmp_path / "damaged.h5"
    done = cli("sweep", "--grid.l", "0.75", "--grid.dh", "0.05", "--grid.T", "2.5", "--grid.pbar", "0.06",
               "--grid.s", "2", "--quiet", "--output", str(damaged))
    assert done.returncode == 0, done.stderr
    damaged.write_bytes(damaged.read_bytes()[:2000])
    with pytest.raises(ValueError, match="is not a readable punchsweep regime map"):
        punchsweep.open_map(damaged)


def test_options_are_read_whole_and_whole_numbers_are_integers():
    """Issue 22: a NUL inside an option cut it silently ('0.75\\x00junk' evaluated 0.75);
    s=2.0 (a map's s is float64) was refused though classify took it."""
    with pytest.raises(ValueError, match="NUL character"):
        punchsweep.point(l="0.75\x00junk", dh=0.075, T=2.5, pbar=0.06, s=2)
    a = punchsweep.point(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2.0, times=[0, 1])
    b = punchsweep.point(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2, times=[0, 1])
    assert a.t_star == b.t_star and same_bits(a.series["a1"], b.series["a1"])
    with pytest.raises(ValueError, match="--s = 2.5"):
        punchsweep.point(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2.5)


@pytest.mark.parametrize("script", sorted(p.name for p in (REPO / "examples").glob("*.py")))
def test_examples_run(script, tmp_path):
    picture = tmp_path / "picture.png"
    env = {**os.environ, "MPLBACKEND": "Agg"}
    done = subprocess.run([sys.executable, str(REPO / "examples" / script), "--output", str(picture)],
                          capture_output=True, text=True, env=env, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    # What each prints, checked by another route (issue 35 item 11: a PNG alone proves little).
    if script == "dh_for_touch_time.py":
        found = re.search(r"h\(0\) = ([\d.]+) R, h\(inf\) = ([\d.]+) R\n"
                          r"dh = ([\d.]+) R makes level 2 touch at t\* = ([\d.]+) T_eps \(target 2.0\)", done.stdout)
        assert found, done.stdout
        h_0, h_inf, dh = (float(found[k]) for k in (1, 2, 3))
        assert h_0 < dh < h_inf
        # The point command's route: t* = 2 lies within the printed dh's rounding (6 decimals).
        below, above = (punchsweep.point(l=0.75, dh=dh + d, T=2.5, pbar=0.06, s=2).t_star for d in (-5e-7, 5e-7))
        assert below <= 2.0 <= above and above - below < 1e-3
    else:
        lines = re.findall(r"^(.*): h\(0\) = ([\d.]+) R, h\(inf\) = ([\d.]+) R; at dh = ([\d.]+) R t\* = (\S+) s; "
                           r"0 of 40 points flagged invalid$", done.stdout, flags=re.M)
        assert len(lines) == 3, done.stdout
        # At t = 0 every material has its modulus E0*: h(0) is the elastic one of the lattice,
        # the same as a standard linear solid's at any T.
        elastic = float(punchsweep.classify(0.75, 0.0, 2.0, 0.01, 2)["h_0"])
        for label, h_0, h_inf, dh, t in lines:
            assert float(h_0) == pytest.approx(elastic, abs=1e-5) and float(h_inf) > float(h_0), label
            assert 0 < float(t) < math.inf and float(h_0) < float(dh), label
    import matplotlib.image
    pixels = matplotlib.image.imread(picture)
    assert pixels.shape[0] > 400 and float(pixels[..., :3].std()) > 0.05  # drawn, not blank


def seconds_to_interrupt(call: str, after: float) -> float:
    """Runs `call` (after `import numpy as np, punchsweep`) in a fresh interpreter, sends it
    SIGINT `after` seconds in, and returns how long it took to raise KeyboardInterrupt
    (failing if it finished or raised anything else)."""
    import signal
    import time
    script = ("import numpy as np, punchsweep, sys\n"
              "print('started', flush=True)\n"
              "try:\n"
              f"    {call}\n"
              "except KeyboardInterrupt:\n"
              "    print('interrupted', flush=True)\n"
              "    sys.exit(0)\n"
              "print('finished', flush=True)\n")
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, env=dict(os.environ))
    assert proc.stdout.readline().strip() == "started"
    time.sleep(after)
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=120)
    assert out.strip() == "interrupted", out
    return time.monotonic() - sent


def test_classify_is_interrupted_by_ctrl_c():
    """Ctrl-C (SIGINT) stops a long classify within about a second with KeyboardInterrupt
    (issue 22: it was ignored while the loop ran without the GIL). 400,000 scattered
    points under the refined model, each with a curve of its own, take minutes; the signal
    comes after 1.5 s."""
    took = seconds_to_interrupt(
        "rng = np.random.default_rng(1); n = 400_000; punchsweep.classify(rng.uniform(0.5, 1.5, n), "
        "rng.uniform(0.005, 0.15, n), rng.uniform(1.5, 8, n), rng.uniform(0.002, 0.1, n), 2, "
        "localization='refined')", after=1.5)
    assert took < 2.0, f"classify took {took:.2f} s to stop after SIGINT"


@pytest.mark.parametrize("localization", ["periodic", "paper"])
def test_classify_takes_a_ramp_and_a_material_at_its_reference_temperature(localization):
    """classify(..., ramp_time=...) (issue 23: one batch evaluator for the sweep and classify,
    so the load that a sweep's ramp_time axis takes works here too) equals point() with
    --ramp at scattered points, for the standard linear solid and for a material with a
    shift, whose temperature left out is its reference temperature, as point()'s."""
    pla = str(REPO / "materials" / "pla_prusament_chapuis2025.ini")
    rng = np.random.default_rng(7)
    n = 120
    l, dh = rng.uniform(0.5, 1.25, n), rng.uniform(0.005, 0.12, n)
    pbar, s = np.exp(rng.uniform(np.log(0.005), np.log(0.08), n)), rng.integers(1, 4, n).astype(float)
    ramp = rng.choice([0.0, 0.4, 3.0, 50.0], n)
    T = rng.uniform(1.5, 8.0, n)
    for material in (None, pla):
        if material is None:
            c = punchsweep.classify(l, dh, T, pbar, s, localization=localization, ramp_time=ramp)
        else:
            c = punchsweep.classify(l, dh, pbar=pbar, s=s, localization=localization, material=material,
                                    ramp_time=ramp)
        names = c.regime_names()
        for i in range(0, n, 2):
            law = {"T": float(T[i])} if material is None else {"material": material}
            r = punchsweep.point(l=l[i], dh=dh[i], pbar=pbar[i], s=int(s[i]), times=[0.0], ramp=float(ramp[i]),
                                 localization=localization, **law)
            assert names[i] == r.regime, (material, i, names[i], r.regime)
            assert same_bits(c["t_star"][i], np.nan if r.t_star is None else r.t_star), (material, i)
            assert same_bits(c["h_0"][i], r.h_0) and same_bits(c["h_inf"][i], r.h_inf)
            assert bool(c["valid"][i]) == r.valid
        assert len(set(names)) >= 2
    # A ramp only delays: every t* under a ramp is at least the step's.
    step = punchsweep.classify(l, dh, T, pbar, s, localization=localization)
    ramped = punchsweep.classify(l, dh, T, pbar, s, localization=localization, ramp_time=ramp)
    both = np.isfinite(step["t_star"]) & np.isfinite(ramped["t_star"])
    assert both.sum() > 10 and np.all(ramped["t_star"][both] >= step["t_star"][both])
    with pytest.raises(ValueError, match="ramp"):
        punchsweep.classify(0.75, 0.05, 2.5, 0.06, 2, ramp_time=-1.0)
    with pytest.raises(ValueError, match="no temperature shift"):
        punchsweep.classify(0.75, 0.05, pbar=0.06, s=2, material=MATERIAL, temperature=30.0)


def _prony_constants(path):
    """E_inf, E_i, tau_i in Pa and the file's time unit, and its [shift], read here with
    configparser (independently of the engine)."""
    import configparser
    cp = configparser.ConfigParser(inline_comment_prefixes=("#",))
    cp.read(path)
    scale = {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "GPa": 1e9}[cp["material"]["modulus_unit"]]
    numbers = lambda key: np.array([float(x) for x in cp["material"][key].split(",")])  # noqa: E731
    shift = {k: float(v) for k, v in cp["shift"].items() if k != "kind"} if cp.has_section("shift") else None
    return float(cp["material"]["E_inf"]) * scale, numbers("E_i") * scale, numbers("tau_i"), shift


def test_material_gives_its_moduli_compliance_and_shift():
    """punchsweep.Material (issue 24's materials in Python, begun with issue 23's classify):
    E(t) equals the file's Prony series; J(t) is its interconverse (checked in the Laplace
    domain, s^2 J^(s) E^(s) = 1, by quadrature here); a_T is the file's WLF; a temperature
    rescales time by a_T; and the object goes wherever a material file goes."""
    path = REPO / "materials" / "pla_prusament_chapuis2025.ini"
    m = punchsweep.Material(path)
    E_inf, E_i, tau_i, shift = _prony_constants(path)
    assert m.time_unit == "s" and m.poisson == 0.35 and m.reference_temperature == shift["t_ref"]
    assert m.E0_Pa == pytest.approx(E_inf + E_i.sum(), rel=1e-12)
    assert m.plane_strain_modulus_Pa == pytest.approx(m.E0_Pa / (1 - 0.35 ** 2), rel=1e-12)
    t = np.geomspace(1e-15, 1e4, 60)
    expected = E_inf + (E_i[None, :] * np.exp(-t[:, None] / tau_i[None, :])).sum(axis=1)
    assert np.allclose(m.E(t), expected, rtol=1e-10, atol=0)
    assert m.J(0.0) == pytest.approx(1 / m.E0_Pa, rel=1e-12)
    assert m.J(1e12) == pytest.approx(1 / E_inf, rel=1e-9)
    u = np.linspace(np.log(1e-18), np.log(1e9), 400_001)
    for s in (1e-3, 1.0, 1e3):
        x = np.exp(u)
        keep = s * x < 60
        J_hat = np.trapz((m.J(x[keep]) * np.exp(-s * x[keep]) * x[keep]), u[keep])
        E_hat = E_inf / s + (E_i * tau_i / (1 + s * tau_i)).sum()
        assert s * s * J_hat * E_hat == pytest.approx(1.0, rel=1e-4), s
    C1, C2, T_ref = shift["c1"], shift["c2"], shift["t_ref"]
    for T in (70.0, 85.0):
        a = 10 ** (-C1 * (T - T_ref) / (C2 + T - T_ref))
        assert m.a_T(T) == pytest.approx(a, rel=1e-12)
        assert np.allclose(m.J(t, temperature=T), m.J(t / a), rtol=1e-12, atol=0)
    assert m.a_T([65.0, 75.0]).shape == (2,)
    with pytest.raises(ValueError, match="outside the shift's range"):
        m.a_T(200)
    # Wherever a material file goes: point(), classify().
    c = punchsweep.classify(0.75, [0.005, 0.02], pbar=5.187e-4, s=2, material=m, temperature=75,
                            localization="periodic")
    for i, dh in enumerate((0.005, 0.02)):
        r = punchsweep.point(l=0.75, dh=dh, pbar=5.187e-4, s=2, material=m, temperature=75, times=[0.0],
                             localization="periodic")
        assert c.regime_names()[i] == r.regime
        assert same_bits(c["t_star"][i], np.nan if r.t_star is None else r.t_star)
    nbr = punchsweep.Material(MATERIAL)
    assert nbr.reference_temperature is None and nbr.shift is None
    with pytest.raises(ValueError, match="no temperature shift"):
        nbr.J(1.0, temperature=30)
    with pytest.raises(ValueError):
        punchsweep.Material(REPO / "README.md")


def test_material_from_arrays_equals_its_file(tmp_path):
    """Material.prony(...) from the PLA file's own constants (read here with configparser)
    is the file's material: the same J, E and a_T bit for bit and the same classify answers;
    its temporary file goes with it; the engine's checks apply to arrays too."""
    import gc
    import configparser
    path = REPO / "materials" / "pla_prusament_chapuis2025.ini"
    _, _, tau_i, shift = _prony_constants(path)
    cp = configparser.ConfigParser(inline_comment_prefixes=("#",))
    cp.read(path)
    E_inf = float(cp["material"]["E_inf"])  # in the file's unit, MPa: the same numbers as the file
    E_i = [float(x) for x in cp["material"]["E_i"].split(",")]
    wlf = dict(kind="wlf", C1=shift["c1"], C2=shift["c2"], T_ref=shift["t_ref"], E_a_below=shift["e_a_below"],
               T_min=shift["t_min"], T_max=shift["t_max"])
    from_file = punchsweep.Material(path)
    made = punchsweep.Material.prony(E_inf, E_i, tau_i, 0.35, modulus_unit="MPa", shift=wlf)
    t = np.geomspace(1e-15, 1e4, 40)
    for T in (None, 70.0):
        assert same_bits(made.J(t, temperature=T), from_file.J(t, temperature=T))
        assert same_bits(made.E(t, temperature=T), from_file.E(t, temperature=T))
    assert made.a_T(80.0) == from_file.a_T(80.0)
    rng = np.random.default_rng(3)
    dh, T = rng.uniform(0.002, 0.07, 50), rng.uniform(25, 85, 50)
    a = punchsweep.classify(0.75, dh, pbar=5.187e-4, s=2, material=made, temperature=T, localization="periodic")
    b = punchsweep.classify(0.75, dh, pbar=5.187e-4, s=2, material=path, temperature=T, localization="periodic")
    assert same_bits(a["t_star"], b["t_star"]) and (a["regime"] == b["regime"]).all()
    folder = os.path.dirname(made.path)
    assert os.path.isfile(made.path) and (os.stat(folder).st_mode & 0o777) == 0o700
    del made
    gc.collect()
    assert not os.path.exists(folder)
    kept = punchsweep.Material.prony(2e6, [1e6, 5e5], [0.1, 10.0], 0.45, path=tmp_path / "mine.ini")
    assert punchsweep.Material(tmp_path / "mine.ini").E0_Pa == 3.5e6 and kept.shift is None
    with pytest.raises(ValueError, match="tau_i"):
        punchsweep.Material.prony(2e6, [1e6, 5e5], [0.1], 0.45)


def test_point_takes_lengths_and_pressures_with_units():
    """point(R="50um", l="150um", dh="2um") is the point at l = 3, dh = 0.04 (150/50 and
    2/50 worked out here), and with a material pbar="20kPa" is pressure="20kPa"'s point."""
    physical = punchsweep.point(R="50um", l="150um", dh="2um", T=2.5, pbar=0.06, s=2)
    scaled = punchsweep.point(l=3.0, dh=2.0 / 50.0, T=2.5, pbar=0.06, s=2)
    assert (physical.regime, physical.t_star) == (scaled.regime, scaled.t_star)
    assert all(np.array_equal(physical.series[q], scaled.series[q]) for q in scaled.series)
    nbr = REPO / "materials" / "nbr_linder2011.ini"
    a = punchsweep.point(material=nbr, l=0.75, dh=0.02, s=2, pbar="20kPa")
    b = punchsweep.point(material=nbr, l=0.75, dh=0.02, s=2, pressure="20kPa")
    assert a.t_star == b.t_star and np.array_equal(a.series["a1"], b.series["a1"])
    with pytest.raises(ValueError, match="needs R, the punch"):
        punchsweep.point(l="150um", dh=0.02, T=2.5, pbar=0.06, s=2)


def test_a_package_without_its_compiled_part_says_what_to_build(tmp_path):
    """The package's Python files alone (what the main job left before it built the module
    too, issue 35 item 10b): the import says which target builds `_core`, not a circular
    import."""
    package = tmp_path / "punchsweep"
    package.mkdir()
    for source in Path(punchsweep.__file__).parent.glob("*.py"):  # every Python file, no _core
        package.joinpath(source.name).write_text(source.read_text())
    r = subprocess.run([sys.executable, "-c", "import punchsweep"], capture_output=True, text=True,
                       env={**os.environ, "PYTHONPATH": str(tmp_path)})
    assert r.returncode != 0
    assert "cmake --build build --target punchsweep_python" in r.stderr, r.stderr
    assert "circular" not in r.stderr


@pytest.mark.parametrize("kwargs, message", [
    ({"C": np.array([0.5, 0.6])}, "C = array"),
    ({"dh": 0.05 + 0j}, "dh = (0.05+0j): a complex number"),
    ({"s": True}, "s = True: a bool is not a number"),
    ({"dh": None}, "dh is required (None given)"),
])
def test_classify_names_what_it_cannot_take(kwargs, message):
    """Issue 35's low items: an array C and complex input raised TypeError, s=True was taken as
    s = 1 and dh=None was reported as '--dh = nan'."""
    args = dict(l=0.75, dh=0.05, T=2.5, pbar=0.06, s=2)
    args.update(kwargs)
    with pytest.raises(ValueError, match=re.escape(message)):
        punchsweep.classify(**args)


def test_material_times_with_units_and_open_map_of_a_folder(tmp_path):
    """Material.J('1s') is J at one second (it was a bare conversion error); a folder given to
    open_map is named as one (it said 'no such file')."""
    m = punchsweep.Material(REPO / "materials" / "silicone_elite_double32.ini")
    assert m.time_unit == "s"
    assert m.J("1s") == m.J(1.0) and m.J("1min") == m.J(60.0)
    assert np.array_equal(m.E(["1s", "1min"]), m.E([1.0, 60.0]))
    with pytest.raises(ValueError, match="t = '1kPa' is not a time"):
        m.J("1kPa")
    with pytest.raises(punchsweep.NotAMapError, match="is a folder, not a map file"):
        punchsweep.open_map(tmp_path)


def test_a_material_maps_default_times_span_its_creep(tmp_path):
    """Issue 37 item 8: a material map's snapshot times, left at their default, are 0 and
    log-spaced times from 1% to 99% of the material's creep (J(0) -> J(inf)) at the grid's
    coldest and warmest temperature, held to 1 ms .. a year, to 2 digits (not 0 .. 5 of its
    time unit). The span here from the material's own J by bisection, not the engine's."""
    from scipy.optimize import brentq

    def span(material, temperature=None):
        J = lambda t: float(material.J(t, temperature=temperature))  # noqa: E731
        J0, Jinf = J(0.0), J(1e30)
        return tuple(np.exp(brentq(lambda u: J(np.exp(u)) - (J0 + q * (Jinf - J0)), -80, 80, xtol=1e-13))
                     for q in (0.01, 0.99))

    def times(*args):
        subprocess.run([BINARY, "sweep", *args, "--grid.l", "0.75", "--grid.dh", "0.01", "--grid.pbar", "5e-4",
                        "--grid.s", "2", "--output", tmp_path / "m.h5", "--overwrite", "--quiet"], check=True)
        with h5py.File(tmp_path / "m.h5") as f:
            return f["time"][:]

    silicone = REPO / "materials" / "silicone_elite_double32.ini"
    lo, hi = span(punchsweep.Material(silicone))
    t = times("--model.material", silicone)
    lo = max(lo, 1e-3)
    n = min(max(int(np.ceil(np.log10(hi / lo))) + 1, 2), 8)
    want = [0.0] + [float(f"{v:.2g}") for v in np.geomspace(lo, hi, n)]
    assert t.tolist() == want and t[-1] < 1.0  # its creep is over within a second
    # The PLA creeps for 1e16 s at 25 C: held to 1 ms .. a year (3.15576e7 s).
    pla = REPO / "materials" / "pla_prusament_chapuis2025.ini"
    t = times("--model.material", pla, "--grid.temperature", "25,85")
    assert t[0] == 0 and t[1] == 1e-3 and t[-1] == float(f"{3.15576e7:.2g}") and len(t) == 9
    # Given times stay as given.
    assert times("--model.material", silicone, "--time.times", "0,1s,2s").tolist() == [0, 1, 2]
