"""From a DMA test to a material (issue 25, docs/fitting.md): `punchsweep fit` and
`punchsweep.fit_material` recover a known material from noisy isotherms written as an
instrument exports them, fit a published data set with its quality reported, and refuse
what they cannot read with exit 2 and nothing written.

Expected values come from the known material (its moduli computed here with numpy, its
t* from the engine reading a material file written here from the known constants), from the
data set's published shift factors, and from pyvisco run on the same data."""
from __future__ import annotations

import json
import math
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
PUBLISHED = REPO / "materials" / "dma" / "nrel_pyvisco_ems_ca.csv"

# The known material: a Prony series (Pa, s) and WLF at 23 degC.
E_INF = 1.0e6
E_I = np.array([4e6, 3e6, 2e6, 1.5e6, 1e6])
TAU = np.array([1e-5, 1e-3, 1e-1, 3.0, 100.0])
C1, C2, T_REF = 9.0, 120.0, 23.0
TEMPERATURES = [0, 10, 23, 35, 50, 65, 80]
NOISE = 0.01


def log10_aT(T):
    return -C1 * (np.asarray(T) - T_REF) / (C2 + np.asarray(T) - T_REF)


def moduli(omega):
    wt = np.asarray(omega)[:, None] * TAU
    return E_INF + (E_I * wt**2 / (1 + wt**2)).sum(1), (E_I * wt / (1 + wt**2)).sum(1)


def cli(*args) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True)


def write_dma(path: Path, header="temperature [C],frequency [Hz],storage [MPa],loss [MPa]", seed=25,
              temperatures=TEMPERATURES, with_temperature=True):
    """Isotherms 0.1-100 Hz (10 per isotherm), each reading's logged temperature wandering by
    0.1 K, E' and E'' with 1% noise, rows shuffled; returns the rows (T, f, E', E'' in MPa)."""
    rng = np.random.default_rng(seed)
    rows = []
    for T in temperatures:
        f = np.logspace(-1, 2, 10)
        s, l = moduli(2 * np.pi * f * 10 ** log10_aT(T))
        for k in range(len(f)):
            rows.append((T + rng.normal(0, 0.1), f[k], s[k] * (1 + NOISE * rng.normal()) / 1e6,
                         l[k] * (1 + NOISE * rng.normal()) / 1e6))
    rng.shuffle(rows)
    lines = [header] + [",".join(repr(float(v)) for v in (r if with_temperature else r[1:])) for r in rows]
    path.write_text("\n".join(lines) + "\n")
    return rows


def write_truth(path: Path):
    path.write_text("[material]\nname = the known material\nlaw = prony\nmodulus_unit = Pa\ntime_unit = s\n"
                    f"poisson = 0.5\nE_inf = {E_INF!r}\nE_i = {', '.join(repr(float(v)) for v in E_I)}\n"
                    f"tau_i = {', '.join(repr(float(v)) for v in TAU)}\n"
                    f"[shift]\nkind = wlf\nC1 = {C1!r}\nC2 = {C2!r}\nT_ref = {T_REF!r}\n")


def t_star(material: Path, dh: str, temperature: float) -> float:
    r = cli("point", "--material", material, "--R", "50um", "--l", "150um", "--dh", dh, "--pressure", "100kPa",
            "--s", "2", "--temperature", temperature, "--format", "json")
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    assert d["regime"] == "delayed", d["regime"]
    return d["t_star"]


@pytest.fixture(scope="module")
def fitted(tmp_path_factory):
    """The issue's spelling on the known material's isotherms."""
    tmp = tmp_path_factory.mktemp("fit")
    write_dma(tmp / "data.csv")
    r = cli("fit", "--dma", tmp / "data.csv", "--reference-temperature", "23", "--poisson", "0.5",
            "-o", tmp / "material.ini")
    assert r.returncode == 0, r.stderr
    write_truth(tmp / "truth.ini")
    return tmp, r.stdout


def test_the_issue_spelling_writes_a_material_the_engine_reads(fitted):
    tmp, report = fitted
    text = (tmp / "material.ini").read_text()
    assert "law = prony" in text and "[shift]" in text and "kind = wlf" in text
    m = punchsweep.Material(tmp / "material.ini")
    assert m.law == "prony" and m.poisson == 0.5 and m.reference_temperature == 23
    assert "RMS relative error over all 70 readings: E'" in report and "wrote" in report
    assert (tmp / "material.fit.json").is_file()


def test_the_moduli_are_recovered_within_the_noise(fitted):
    tmp, _ = fitted
    d = json.loads((tmp / "material.fit.json").read_text())
    r = {k: np.asarray(v) for k, v in d["readings"].items()}
    # The fit against the true moduli at each reading's true reduced frequency.
    true_s, true_l = moduli(r["x"] * 10 ** log10_aT(r["temperature"]))
    err = np.concatenate([r["storage_fit"] / true_s - 1, r["loss_fit"] / true_l - 1])
    assert np.sqrt(np.mean(err**2)) < 2 * NOISE
    assert np.sqrt(np.mean((r["storage_fit"] / true_s - 1) ** 2)) < NOISE
    # The series: a Prony fit's terms are not unique under noise (a term at the data's edge
    # may split in two), the relaxation modulus they sum to is: within 2% of the truth's over
    # the times the readings cover (1/(2 pi 100 Hz a_T(0 C)) to 1/(2 pi 0.1 Hz a_T(80 C))).
    prony = d["prony"]
    t = np.logspace(np.log10(1 / (2 * np.pi * 100 * 10 ** log10_aT(0))),
                    np.log10(1 / (2 * np.pi * 0.1 * 10 ** log10_aT(80))), 300)
    E_t = prony["E_inf"] + (np.asarray(prony["E_i"]) * np.exp(-t[:, None] / np.asarray(prony["tau_i"]))).sum(1)
    assert np.max(np.abs(E_t / (E_INF + (E_I * np.exp(-t[:, None] / TAU)).sum(1)) - 1)) < 0.02
    assert abs(prony["E_inf"] / E_INF - 1) < 0.02
    # The law: polished with the series (every reading weighs in, not only the overlap of E',
    # which says little where E' flattens near the glassy plateau): within 0.03 decades of
    # the truth at every isotherm (the law of the overlap shifts alone missed by 0.039 at 0 C).
    shift = d["shift"]
    assert shift["joint"] and shift["polished"]
    assert np.max(np.abs(np.asarray(shift["law_log10_aT"]) - log10_aT(shift["temperatures"]))) < 0.03
    assert abs(shift["C1"] - C1) < 0.05 * C1 and abs(shift["C2"] - C2) < 0.05 * C2


def test_a_design_points_t_star_is_recovered(fitted):
    """t* of caps of R = 50 um on a 150 um pitch under 100 kPa, from the fitted file against
    the known one: within 2% at T_ref (the Prony fit's error), within 8% at 50 degC (where
    the fitted shift law's 0.02 decades add 4%)."""
    tmp, _ = fitted
    for dh, T, tol in (("10um", 23, 0.02), ("20um", 23, 0.02), ("10um", 50, 0.08), ("20um", 50, 0.08)):
        truth, fit = t_star(tmp / "truth.ini", dh, T), t_star(tmp / "material.ini", dh, T)
        assert abs(fit / truth - 1) < tol, (dh, T, fit, truth)


def test_python_fits_what_the_command_fits(fitted, tmp_path):
    tmp, _ = fitted
    r = punchsweep.fit_material(tmp / "data.csv", reference_temperature=23, poisson=0.5, output=tmp_path / "m.ini")
    assert r.material_text.split("[material]")[1] == (tmp / "material.ini").read_text().split("[material]")[1]
    assert r.material.name == punchsweep.Material(tmp / "material.ini").name
    assert r.kind == "dma" and len(r.readings["storage"]) == 70 and r.readings["used"].all()
    assert r.prony["E_inf"] == pytest.approx(E_INF, rel=0.02)
    without = punchsweep.fit_material(str(tmp / "data.csv"), reference_temperature="296.15K", poisson=0.5)
    assert without.material is None and without.prony["E_i"] == r.prony["E_i"]


def test_one_file_per_temperature_and_tan_delta_give_the_same_fit(fitted, tmp_path):
    tmp, _ = fitted
    rows = write_dma(tmp_path / "all.csv")
    specs = []
    for T in TEMPERATURES:
        mine = [r for r in rows if abs(r[0] - T) < 1]
        path = tmp_path / f"iso{T}.csv"
        # tan delta instead of E'', and no temperature column: the temperature rides on the name.
        path.write_text("frequency [Hz];storage [GPa];tan_delta\n" +
                        "".join(f"{r[1]!r};{r[2] / 1e3!r};{r[3] / r[2]!r}\n" for r in mine))
        specs.append(f"{path}@{sum(r[0] for r in mine) / len(mine)!r}C")
    a = punchsweep.fit_material(tmp_path / "all.csv", reference_temperature=23, poisson=0.5)
    b = punchsweep.fit_material(specs, reference_temperature=23, poisson=0.5)
    # The same readings up to rounding (GPa, E' tan delta): the same fit, to the refinement's
    # convergence (REFINED, below).
    assert b.shift["C1"] == pytest.approx(a.shift["C1"], rel=1e-6)
    assert_same_fit(a, b)


# The refinement of the times stops where a step gains less than 1e-10 of the cost (the
# sum of squared relative residuals, rss ~ n noise^2): a fit is then determined to about
# sqrt(1e-10 rss / n) ~ 1e-7 of each modulus (1% noise). Ten times that, with margin: 1e-5.
# (Before issue 35 it merged times that met and stopped there, in the valley the merged pair
# had left: rounding of the inputs moved the fit by 1e-3, on one machine and not another.)
REFINED = 1e-5


def assert_same_fit(a, b, x_rtol=1e-8, moduli_rtol=REFINED):
    ia, ib = (np.lexsort((r.readings["x"], r.readings["temperature"])) for r in (a, b))
    for key, rtol in (("x_reduced", x_rtol), ("storage_fit", moduli_rtol), ("loss_fit", moduli_rtol)):
        assert np.allclose(b.readings[key][ib], a.readings[key][ia], rtol=rtol, atol=0), key


# Where the law is fitted together with the series (joint), the joint residual has
# neighbouring minima a rounding may choose between: on one machine (its libm) readings moved
# by 1e-15 gave C2 = 118.573 or 118.715 K, a_T 0.26% apart and the moduli 6.4e-4 apart (the
# engine before issue 48 alike). The fits then agree to a tenth of their stated accuracy
# (docs/fitting.md: the law within 0.03 decades, 7% in a_T; E' and E'' within the 1% noise).
JOINT_X, JOINT_MODULI = 7e-3, 1e-3


def test_the_fit_does_not_depend_on_the_inputs_rounding(tmp_path):
    """Readings moved by 1e-15 (what another machine's libm or a unit conversion leaves) give
    the same fit to REFINED where the law is the overlap's: the refinement converges, it does
    not stop where rounding leaves it; where the law is fitted with the series (joint), to a
    tenth of the stated accuracy (JOINT_X, JOINT_MODULI)."""
    rows = np.array(write_dma(tmp_path / "all.csv"))
    header = "temperature [C],frequency [Hz],storage [MPa],loss [MPa]\n"
    fits = []
    for seed in range(4):
        rng = np.random.default_rng(seed)
        moved = rows * (1 + (1e-15 * rng.standard_normal(rows.shape) if seed else 0))
        path = tmp_path / f"moved{seed}.csv"
        path.write_text(header + "".join(",".join(repr(float(v)) for v in r) + "\n" for r in moved))
        fits.append(punchsweep.fit_material(path, reference_temperature=23, poisson=0.5))
    for b in fits[1:]:
        if fits[0].shift["joint"] or b.shift["joint"]:
            assert_same_fit(fits[0], b, x_rtol=JOINT_X, moduli_rtol=JOINT_MODULI)
        else:
            assert_same_fit(fits[0], b)


@pytest.mark.parametrize("header, rows, message", [
    ("temperature [C],frequency,storage [MPa],loss [MPa]", "20,1,1,0.1", "names no unit"),
    ("temperature [C],frequency [Hz],storage [psi],loss [MPa]", "20,1,1,0.1", "'psi' is not a unit it takes"),
    ("temperature [F],frequency [Hz],storage [MPa],loss [MPa]", "20,1,1,0.1", "(valid: C, degC or K)"),
    ("temperature [C],frequency [Hz],storage [MPa]", "20,1,1", "needs 'storage [unit]' and 'loss [unit]'"),
    ("temperature [C],frequency [Hz],storage [MPa],loss [MPa]", "20,1,abc,0.1", "line 2: column 3: 'abc' is not a number"),
    ("temperature [C],frequency [Hz],storage [MPa],loss [MPa]", "20,1,-1,0.1", "'-1' is not > 0"),
    ("temperature [C],frequency [Hz],storage [MPa],loss [MPa]", "20,1,1", "3 values where the header has 4"),
])
def test_bad_files_are_refused_by_line_and_column_and_nothing_is_written(tmp_path, header, rows, message):
    (tmp_path / "bad.csv").write_text(header + "\n" + rows + "\n")
    r = cli("fit", "--dma", tmp_path / "bad.csv", "--poisson", "0.5", "-o", tmp_path / "m.ini")
    assert r.returncode == 2 and message in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "m.ini").exists() and not (tmp_path / "m.fit.json").exists()


def test_bad_options_are_refused(fitted, tmp_path):
    tmp, _ = fitted
    data = tmp / "data.csv"
    for args, message in (
            ([], "missing --poisson"),
            (["--poisson", "0.7"], "--poisson = 0.7 is outside its range: -1 < NU <= 0.5"),
            (["--poisson", "0.5"], "missing --reference-temperature: the data span"),
            (["--poisson", "0.5", "--reference-temperature", "23", "--shift", "vogel"], "--shift"),
            (["--poisson", "0.5", "--reference-temperature", "23", "--C1", "9"], "--C1 and --C2 together"),
            (["--poisson", "0.5", "--reference-temperature", "23", "--time-window", "1s"], "--time-window"),
            (["--poisson", "0.5", "--reference-temperature", "-300"], "not above absolute zero"),
            # Issue 35 item 9: far outside the isotherms (0 to 80 C), in C or in K.
            (["--poisson", "0.5", "--reference-temperature", "-100"], "is far outside the data, whose readings span"),
            (["--poisson", "0.5", "--reference-temperature", "23K"], "(-250.15 degC) is far outside the data"),
            (["--poisson", "0.5", "--reference-temperature", "200"], "valid: -10.2 to 90.1 degC"),
            # Issue 35 item 8: a name the material file cannot hold whole.
            (["--poisson", "0.5", "--reference-temperature", "23", "--name", "a\n[material]"], "--name = 'a?[material]'"),
            (["--poisson", "0.5", "--reference-temperature", "23", "--name", "Sample #3; batch=7"],
             "# and ; start a comment in a material file"),
    ):
        r = cli("fit", "--dma", data, *args, "-o", tmp_path / "m.ini")
        assert r.returncode == 2 and message in r.stderr, (args, r.stderr)
        assert not (tmp_path / "m.ini").exists()
    # Too few isotherms for WLF: the reason, not a number.
    write_dma(tmp_path / "two.csv", temperatures=[10, 23])
    r = cli("fit", "--dma", tmp_path / "two.csv", "--poisson", "0.5", "--reference-temperature", "23",
            "-o", tmp_path / "m.ini")
    assert r.returncode == 2 and "too few to fit WLF" in r.stderr
    # ... which a given law or Arrhenius accepts.
    r = cli("fit", "--dma", tmp_path / "two.csv", "--poisson", "0.5", "--reference-temperature", "23",
            "--C1", C1, "--C2", C2, "-o", tmp_path / "m.ini")
    assert r.returncode == 0, r.stderr
    assert f"C1 = {C1:g}" in (tmp_path / "m.ini").read_text()


def test_the_output_may_not_destroy_what_its_path_names(fitted, tmp_path):
    """Issue 35 item 1: `-o` naming a pipe, a folder, a link or the measurements themselves
    (under any name: a hard link too) is refused with exit 2, and every path stays as it
    was; nothing is written beside them. (A device such as /dev/null is refused by the same
    rule, tested without a write in tests/io/output_file_test.cpp.)"""
    tmp, _ = fitted
    data = tmp_path / "d.csv"
    data.write_bytes((tmp / "data.csv").read_bytes())
    before = data.read_bytes()
    (tmp_path / "target.ini").write_text("the link's target")
    (tmp_path / "link.ini").symlink_to(tmp_path / "target.ini")
    (tmp_path / "folder").mkdir()
    os.mkfifo(tmp_path / "pipe")
    os.link(data, tmp_path / "hard.ini")
    listing = sorted(p.name for p in tmp_path.iterdir())
    for output, message in (("pipe", "pipe is a pipe"), ("folder", "folder is a folder"),
                             ("link.ini", "link.ini is a symbolic link"), ("d.csv", "is the input"),
                             ("hard.ini", "is the input"), ("no/m.ini", "the folder")):
        r = cli("fit", "--dma", data, "--reference-temperature", "23", "--poisson", "0.5", "-o", tmp_path / output)
        assert r.returncode == 2 and message in r.stderr, (output, r.stderr)
        assert str(tmp_path / output) in r.stderr, r.stderr
    r = cli("fit", "--dma", f"{data}@23C", "--reference-temperature", "23", "--poisson", "0.5", "--C1", C1, "--C2", C2,
            "-o", data)
    assert r.returncode == 2 and "is the input" in r.stderr, r.stderr
    assert (tmp_path / "pipe").is_fifo() and (tmp_path / "folder").is_dir() and (tmp_path / "link.ini").is_symlink()
    assert (tmp_path / "target.ini").read_text() == "the link's target"
    assert data.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == listing


def test_names_and_paths_reach_the_material_file_whole(fitted, tmp_path):
    """Issue 35 item 8: a name is stored as given; a file name with a line break, # or ;
    (written raw into the header comment and the default name before) leaves the file one
    the engine reads, with every line where it belongs."""
    tmp, _ = fitted
    r = cli("fit", "--dma", tmp / "data.csv", "--reference-temperature", "23", "--poisson", "0.5",
            "--name", "Sample 3, batch 7 (ü)", "-o", tmp_path / "m.ini")
    assert r.returncode == 0, r.stderr
    assert "\nname = Sample 3, batch 7 (ü)\n" in (tmp_path / "m.ini").read_text()
    odd = tmp_path / "a\n[material]\nname = x #;.csv"
    odd.write_bytes((tmp / "data.csv").read_bytes())
    r = cli("fit", "--dma", odd, "--reference-temperature", "23", "--poisson", "0.5", "-o", tmp_path / "o.ini")
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "o.ini").read_text()
    lines = text.splitlines()
    assert [k for k, line in enumerate(lines) if line.strip() == "[material]"] == [3]  # after the 3 comment lines
    assert len([line for line in lines if line.startswith("name")]) == 1
    assert "\nname = fitted to a_[material]_name = x __.csv\n" in text
    r = cli("point", "--material", tmp_path / "o.ini", "--R", "50um", "--l", "150um", "--dh", "1um", "--pressure",
            "100kPa", "--s", "2", "--temperature", "23", "--format", "json")
    assert r.returncode == 0, r.stderr


def write_glassy_isotherms(path: Path, swap=False):
    """Issue 35 item 2's case: 5 equal Prony terms (tau 1e-4..1e4 s), WLF C1 12, C2 80 K at
    23 C, isotherms 0-80 C every 10 K (0.1-100 Hz), 1% noise, seed 7: the 0 C isotherm sits
    on the glassy plateau (its true shift 4.85 decades). `swap` labels 30 C as 40 C and back."""
    rng = np.random.default_rng(7)
    tau, E_i = np.logspace(-4, 4, 5), np.full(5, 3e6)
    rows = ["temperature [C],frequency [Hz],storage [MPa],loss [MPa]"]
    for T in range(0, 81, 10):
        for f in np.logspace(-1, 2, 10):
            wt = 2 * np.pi * f * 10 ** (-12 * (T - 23) / (80 + T - 23)) * tau
            storage, loss = 1e6 + (E_i * wt**2 / (1 + wt**2)).sum(), (E_i * wt / (1 + wt**2)).sum()
            label = {30: 40, 40: 30}.get(T, T) if swap else T
            rows.append(f"{label},{f!r},{storage * (1 + 0.01 * rng.normal()) / 1e6!r},"
                        f"{loss * (1 + 0.01 * rng.normal()) / 1e6!r}")
    path.write_text("\n".join(rows) + "\n")
    (path.parent / "glassy_truth.ini").write_text(
        "[material]\nname = truth\nlaw = prony\nmodulus_unit = Pa\ntime_unit = s\npoisson = 0.5\nE_inf = 1e6\n"
        f"E_i = {', '.join(repr(float(v)) for v in E_i)}\ntau_i = {', '.join(repr(float(v)) for v in tau)}\n"
        "[shift]\nkind = wlf\nC1 = 12\nC2 = 80\nT_ref = 23\n")


def test_a_glassy_cold_isotherm_is_placed_by_fitting_the_law_with_the_series(tmp_path):
    """Issue 35 item 2: E' overlap places the glassy 0 C isotherm 2 decades short (its shift
    below 10 C's, E'' then fitted to 39%); the fit sees it fail its checks and fits WLF
    together with the series over E' and E'' instead: the law within 2% of the truth, E'
    and E'' within 1.5% (the noise is 1%), and t* within 5% of the truth's at 5, 23 and
    60 C (as with the true law given: 6%)."""
    data = tmp_path / "glassy.csv"
    write_glassy_isotherms(data)
    r = cli("fit", "--dma", data, "--reference-temperature", "23", "--poisson", "0.5", "-o", tmp_path / "m.ini")
    assert r.returncode == 0, r.stderr
    assert "fitted together with the series" in r.stdout
    d = json.loads((tmp_path / "m.fit.json").read_text())
    assert d["shift"]["joint"] and d["verdict"]["problems"] == []
    assert d["shift"]["C1"] == pytest.approx(12.0, rel=0.02) and d["shift"]["C2"] == pytest.approx(80.0, rel=0.02)
    rms = re.search(r"RMS relative error over all 90 readings: E' ([\d.]+)%, E'' ([\d.]+)%", r.stdout)
    assert float(rms[1]) < 1.5 and float(rms[2]) < 1.5, r.stdout
    for T in (5.0, 23.0, 60.0):
        got, want = t_star(tmp_path / "m.ini", "10um", T), t_star(tmp_path / "glassy_truth.ini", "10um", T)
        assert got == pytest.approx(want, rel=0.05), T
    r = cli("fit", "--dma", data, "--reference-temperature", "23", "--poisson", "0.5", "-o", tmp_path / "g.ini",
            "--C1", "12", "--C2", "80")
    assert r.returncode == 0 and "POOR FIT" not in r.stdout, r.stderr
    for T in (5.0, 23.0, 60.0):
        got, want = t_star(tmp_path / "g.ini", "10um", T), t_star(tmp_path / "glassy_truth.ini", "10um", T)
        assert got == pytest.approx(want, rel=0.06), T


def test_a_poor_fit_is_refused_with_its_numbers_or_written_with_its_verdict(tmp_path):
    """Issue 35 item 2: the fit judges itself. Labels of 30 and 40 C swapped: no law meets
    the readings within the limits (E' about 11%, E'' 21%), and the overlap's rising shift
    at 40 C is named: refused, exit 2, nothing written. --accept-poor-fit writes it with the
    verdict in the material file, the .fit.json and the report; Python says the same."""
    write_glassy_isotherms(tmp_path / "glassy.csv", swap=True)
    data = tmp_path / "glassy.csv"
    args = ["fit", "--dma", data, "--reference-temperature", "23", "--poisson", "0.5", "-o", tmp_path / "m.ini"]
    r = cli(*args)
    assert r.returncode == 2, r.stderr
    assert "the fit is poor; nothing written" in r.stderr and "the shifts rise with temperature: 40 degC" in r.stderr
    assert re.search(r"E'' is fitted to (\d+\.?\d*)% \(RMS over every reading\); limit 20%", r.stderr), r.stderr
    assert not (tmp_path / "m.ini").exists() and not (tmp_path / "m.fit.json").exists()
    r = cli(*args, "--accept-poor-fit")
    assert r.returncode == 0 and "POOR FIT, written with --accept-poor-fit" in r.stdout, r.stderr
    assert "# POOR FIT, written with --accept-poor-fit: " in (tmp_path / "m.ini").read_text()
    verdict = json.loads((tmp_path / "m.fit.json").read_text())["verdict"]
    assert verdict["poor"] and any("E''" in p for p in verdict["problems"])
    result = punchsweep.fit_material(data, reference_temperature=23, poisson=0.5, accept_poor_fit=True)
    assert list(result.problems) == verdict["problems"]
    with pytest.raises(ValueError, match="the fit is poor"):
        punchsweep.fit_material(data, reference_temperature=23, poisson=0.5)


def draw_material(seed: int, folder: Path):
    """A synthetic rubber drawn at random (issue 35 item 2): 4-10 Prony terms spread over 4-12
    decades, WLF (C1 8-17, C2 50-150 K) or Arrhenius (E_a 100-300 kJ/mol) at 23 C, isotherms
    -30 to 60 C every 10 K at 0.1-100 Hz (10 each), noise 0.5-3% on E' and E''. Writes the
    data (CSV) and the truth (a material file); returns (data, truth, law name, log10 a_T,
    noise)."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(4, 11))
    span, lo = rng.uniform(4, 12), rng.uniform(-6, -1)
    tau = np.logspace(lo, lo + span, n)
    E = np.exp(rng.normal(0, 0.7, n)) * 1e6 * rng.uniform(1, 5)
    E_inf = rng.uniform(0.05, 0.3) * E.sum()
    wlf = rng.random() < 0.6
    if wlf:
        C1, C2 = rng.uniform(8, 17), rng.uniform(50, 150)
        law, shift = "wlf", f"kind = wlf\nC1 = {C1!r}\nC2 = {C2!r}\nT_ref = 23\n"
    else:
        E_a = rng.uniform(1e5, 3e5)
        law, shift = "arrhenius", f"kind = arrhenius\nE_a = {E_a!r}\nT_ref = 23\n"
    noise = rng.uniform(0.005, 0.03)

    def log10_aT(T):
        if wlf:
            return -C1 * (T - 23) / (C2 + T - 23)
        return E_a / (np.log(10) * 8.314462618) * (1 / (T + 273.15) - 1 / 296.15)

    rows = ["temperature [C],frequency [Hz],storage [MPa],loss [MPa]"]
    for T in range(-30, 61, 10):
        for f in np.logspace(-1, 2, 10):
            wt = 2 * np.pi * f * 10 ** log10_aT(T) * tau
            storage, loss = E_inf + (E * wt**2 / (1 + wt**2)).sum(), (E * wt / (1 + wt**2)).sum()
            rows.append(f"{T},{f!r},{storage * (1 + noise * rng.normal()) / 1e6!r},"
                        f"{loss * (1 + noise * rng.normal()) / 1e6!r}")
    data, truth = folder / f"drawn{seed}.csv", folder / f"drawn{seed}_truth.ini"
    data.write_text("\n".join(rows) + "\n")
    truth.write_text("[material]\nname = truth\nlaw = prony\nmodulus_unit = Pa\ntime_unit = s\npoisson = 0.5\n"
                     f"E_inf = {E_inf!r}\nE_i = {', '.join(repr(float(v)) for v in E)}\n"
                     f"tau_i = {', '.join(repr(float(v)) for v in tau)}\n[shift]\n" + shift)
    return data, truth, law, log10_aT, noise


def design_t_star(material, dh_um: float, T: float):
    r = cli("point", "--material", material, "--R", "50um", "--l", "150um", "--dh", f"{dh_um!r}um", "--pressure",
            "50kPa", "--s", "2", "--temperature", T, "--format", "json")
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    return d["regime"], d["t_star"], d["h_0"], d["h_inf"]


def seen_by_the_data(truth: Path, lo: float, hi: float, dest: Path) -> Path:
    """The truth as readings covering relaxation times lo..hi (at T_ref) can see it: its
    terms slower than hi held in E_inf, those faster than lo dropped. Where this material's
    t* differs from the truth's, no fit of those readings can know which is meant."""
    text = truth.read_text()
    E, tau = (np.array([float(v) for v in re.search(rf"^{key} = (.*)$", text, re.M)[1].split(",")])
              for key in ("E_i", "tau_i"))
    E_inf = float(re.search(r"^E_inf = (.*)$", text, re.M)[1]) + E[tau > hi].sum()
    keep = (tau >= lo) & (tau <= hi)
    text = re.sub(r"^E_inf = .*$", f"E_inf = {E_inf!r}", text, flags=re.M)
    for key, values in (("E_i", E[keep]), ("tau_i", tau[keep])):
        text = re.sub(rf"^{key} = .*$", f"{key} = " + ", ".join(repr(float(v)) for v in values), text, flags=re.M)
    dest.write_text(text)
    return dest


def test_randomly_drawn_materials_are_fitted_or_refused_never_silently_wrong(tmp_path):
    """Issue 35 item 2 on twelve materials drawn at random (draw_material). Each fit is either
    refused with its reason (exit 2: no rubbery plateau within the data, isotherms that
    neither overlap nor fit one law with the series within 5%, a poor fit) or written. A
    written one is held to the truth where its data determine the answer: caps of 50 um on a
    150 um pitch under 50 kPa, dh a quarter and half of the way from the truth's h(0) to
    h(inf), at -20, 23 and 50 C, wherever the truth's t* (reduced to 23 C) lies within the
    times the isotherms cover and the truth as the readings see it (seen_by_the_data) has
    the same t* within 1%; there the fit's t* is within 5% of the truth's. Measured:
    docs/fitting.md."""
    written, judged, errors, unseen = 0, 0, [], []
    for seed in range(12):
        data, truth, law, log10_aT, noise = draw_material(seed, tmp_path)
        out = tmp_path / f"fit{seed}.ini"
        r = cli("fit", "--dma", data, "--reference-temperature", "23", "--poisson", "0.5", "--shift", law, "-o", out)
        if r.returncode != 0:
            assert r.returncode == 2 and r.stderr.startswith("punchsweep: ") and not out.exists(), (seed, r.stderr)
            continue
        written += 1
        # The times the data cover, at 23 C: 1/(2 pi 100 Hz a_T(-30 C)) .. 1/(2 pi 0.1 Hz a_T(60 C)).
        lo, hi = 1 / (2 * np.pi * 100 * 10 ** log10_aT(-30)), 1 / (2 * np.pi * 0.1 * 10 ** log10_aT(60))
        seen = seen_by_the_data(truth, lo, hi, tmp_path / f"seen{seed}.ini")
        _, _, h_0, h_inf = design_t_star(truth, 1.0, 23.0)
        for q in (0.25, 0.5):
            dh = 50 * (h_0 + q * (h_inf - h_0))
            for T in (-20.0, 23.0, 50.0):
                regime, want, _, _ = design_t_star(truth, dh, T)
                if regime != "delayed" or not lo <= want / 10 ** log10_aT(T) <= hi:
                    continue  # the data cannot say what happens there
                seen_regime, seen_t, _, _ = design_t_star(seen, dh, T)
                if seen_regime != "delayed" or abs(seen_t / want - 1) > 0.01:
                    unseen.append((seed, q, T, seen_regime, seen_t and round(seen_t / want - 1, 4)))
                    continue  # what decides t* lies beyond the readings
                judged += 1
                got_regime, got, _, _ = design_t_star(out, dh, T)
                assert got_regime == "delayed", (seed, q, T)
                errors.append((abs(got / want - 1), noise, seed, q, T))
    print(f"written {written} of 12, judged {judged} design points; t* errors (error, noise, seed, q, T): "
          f"{sorted(errors, reverse=True)}; not determined by the data (seed, q, T, regime, t*/truth - 1): {unseen}")
    for error, noise, seed, q, T in errors:
        assert error <= 0.05, (seed, q, T, error, noise)
    assert written >= 6 and judged >= 30, (written, judged)


def test_files_as_instruments_and_spreadsheets_write_them(fitted, tmp_path):
    """Issue 35's low items: CR-only line ends, a quoted cell holding the separator, '+1',
    and a file name holding '@' are read as they mean; an empty header column, a
    temperature given twice (a column and '@'), a tan_delta that contradicts loss/storage,
    and a law given twice are refused naming the line or option; Poisson's ratio with
    blanks around it, or subnormal, is a number. (Lost in 5c08a2e, restored.) Issue 37: a
    separator at the end of every line, as exports write it, is no column."""
    tmp, _ = fitted
    lines = (tmp / "data.csv").read_text().splitlines()
    base = ["--reference-temperature", "23", "--poisson", "0.5"]

    def fit(path, *more, out="m.ini"):
        return cli("fit", "--dma", path, *base, *more, "-o", tmp_path / out)

    reference = fit(tmp / "data.csv", out="ref.ini")
    assert reference.returncode == 0
    want = (tmp_path / "ref.ini").read_text().split("law = prony")[1]  # the name differs: the file's

    def same_material(name):
        return (tmp_path / name).read_text().split("law = prony")[1] == want

    (tmp_path / "cr.csv").write_bytes("\r".join(lines).encode() + b"\r")
    assert fit(tmp_path / "cr.csv", out="cr.ini").returncode == 0 and same_material("cr.ini")
    quoted = [lines[0].replace("temperature [C]", '"temperature [C], as logged"')] + [
        "+" + line for line in lines[1:]]
    (tmp_path / "quoted.csv").write_text("\n".join(quoted) + "\n")
    r = fit(tmp_path / "quoted.csv", out="quoted.ini")
    assert r.returncode == 0 and same_material("quoted.ini"), r.stderr
    at = tmp_path / "sample@lab.csv"
    at.write_text((tmp / "data.csv").read_text())
    assert fit(at, out="at.ini").returncode == 0 and same_material("at.ini")
    (tmp_path / "trailing.csv").write_text(lines[0] + ",\n" + "\n".join(line + "," for line in lines[1:]) + "\n")
    r = fit(tmp_path / "trailing.csv", out="trailing.ini")
    assert r.returncode == 0 and same_material("trailing.ini"), r.stderr
    middle = [lines[0].replace(",frequency", ",,frequency")] + [line.replace(",", ",,", 1) for line in lines[1:]]
    for text, message in (
            ("\n".join(middle), "line 1: column 2 of the header is empty"),
            (lines[0] + ",tan_delta\n" + "\n".join(line + ",0.5" for line in lines[1:]), "contradict each other"),
    ):
        (tmp_path / "bad.csv").write_text(text + "\n")
        r = fit(tmp_path / "bad.csv")
        assert r.returncode == 2 and message in r.stderr, r.stderr
    r = fit(f"{tmp / 'data.csv'}@50C")
    assert r.returncode == 2 and "a temperature was given after '@'" in r.stderr, r.stderr
    r = fit(tmp / "data.csv", "--C1", "9", "--C2", "120", "--E-a", "1e5")
    assert r.returncode == 2 and "not both" in r.stderr, r.stderr
    for poisson in ("0.3 ", "1e-320"):
        r = cli("fit", "--dma", tmp / "data.csv", "--reference-temperature", "23", "--poisson", poisson,
                "-o", tmp_path / "p.ini")
        assert r.returncode == 0, (poisson, r.stderr)
    assert not (tmp_path / "m.ini").exists()


EXPORTS = REPO / "examples" / "dma_exports"


@pytest.mark.parametrize("export", ["trios_lims.txt", "semicolon_decimal_comma.csv", "parentheses_crlf.csv"])
def test_instrument_exports_give_the_material_of_the_documented_form(export, tmp_path):
    """Issue 37 item 2: the shipped exports (examples/dma_exports/make_exports.py: a preamble
    before the header, units in parentheses or in a row of their own, the degree sign,
    'Storage Modulus', "E'", 'tan(delta)' and 'tan δ', semicolons with decimal commas, CR
    LF, trailing separators) hold the same readings, digit for digit, as documented.csv:
    each gives the same material, to the last digit."""
    base = ["--reference-temperature", "23", "--poisson", "0.5"]
    r = cli("fit", "--dma", EXPORTS / "documented.csv", *base, "-o", tmp_path / "documented.ini")
    assert r.returncode == 0, r.stderr
    r = cli("fit", "--dma", EXPORTS / export, *base, "-o", tmp_path / "export.ini")
    assert r.returncode == 0, r.stderr
    want = (tmp_path / "documented.ini").read_text().split("law = prony")[1]
    assert (tmp_path / "export.ini").read_text().split("law = prony")[1] == want
    assert r.stdout.startswith("punchsweep fit: 70 DMA readings at 7 temperature(s)"), r.stdout
    # Issue 37 item 8: the material is named after the sample the preamble names.
    assert "\nname = fitted to TPE-A\n" in (tmp_path / "export.ini").read_text()
    assert "\nname = fitted to documented.csv\n" in (tmp_path / "documented.ini").read_text()


def test_the_exports_are_what_their_generator_writes(tmp_path):
    """The shipped files are the generator's output (so the test above tests what the
    generator says they are)."""
    import shutil
    copy = tmp_path / "dma_exports"
    shutil.copytree(EXPORTS, copy)
    subprocess.run(["/usr/bin/python3", copy / "make_exports.py"], check=True)
    for name in ("documented.csv", "trios_lims.txt", "semicolon_decimal_comma.csv", "parentheses_crlf.csv"):
        assert (copy / name).read_bytes() == (EXPORTS / name).read_bytes(), name


def test_an_export_with_a_bad_unit_row_or_no_unit_is_refused_naming_the_line(tmp_path):
    """A units row is read only where it holds no number; a unit it gives that the column
    does not take is refused naming the units row's line; a column with no unit anywhere is
    refused naming the header's."""
    text = (EXPORTS / "trios_lims.txt").read_text()
    (tmp_path / "psi.txt").write_text(text.replace("Hz\tMPa\tMPa", "Hz\tpsi\tMPa"))
    r = cli("fit", "--dma", tmp_path / "psi.txt", "--reference-temperature", "23", "--poisson", "0.5",
            "-o", tmp_path / "m.ini")
    assert r.returncode == 2 and "line 13: column 'Storage modulus': 'psi' is not a unit it takes" in r.stderr, r.stderr
    lines = text.splitlines()
    (tmp_path / "nounits.txt").write_text("\n".join(lines[:12] + lines[13:]) + "\n")
    r = cli("fit", "--dma", tmp_path / "nounits.txt", "--reference-temperature", "23", "--poisson", "0.5",
            "-o", tmp_path / "m.ini")
    assert r.returncode == 2 and "line 12: column 'Frequency' names no unit" in r.stderr, r.stderr
    assert not (tmp_path / "m.ini").exists()

# Published: the shift factors shipped with the data (pyvisco,
# verification/freq_raw/freq_Eplexor_raw__shift_factors.csv, T_ref = -5 C), and pyvisco 1.0.4's
# own get_aT on the same readings (run for this test's reference values; its WLF C1 = 98.09,
# C2 = 430.03 K).
SHIPPED = {100: -19.02, 92: -18.24, 85: -17.4, 77: -16.5, 70: -15.48, 62: -14.4, 55: -13.14, 47: -11.64,
           40: -9.72, 32: -7.74, 25: -6.12, 18: -4.62, 10: -3.18, 3: -1.68, -5: 0, -12: 1.62, -20: 3.54,
           -27: 5.1, -35: 6.96, -43: 9.12, -50: 11.1}
PYVISCO = [11.356, 9.166, 7.009, 5.161, 3.603, 1.662, 0, -1.656, -3.190, -4.652, -6.115, -7.704, -9.627,
           -11.449, -12.868, -14.018, -15.015, -15.928, -16.770, -17.549, -18.289]


def test_the_published_data_set_is_fitted_and_its_quality_reported(tmp_path):
    r = punchsweep.fit_material(PUBLISHED, reference_temperature=-5, poisson=0.35, output=tmp_path / "ems.ini")
    T = np.asarray(r.shift["temperatures"])
    assert len(T) == 21
    measured = np.asarray(r.shift["measured_log10_aT"])
    relative = measured - measured[np.argmin(np.abs(T + 5))]  # zero at the -5 C isotherm, as both references
    # pyvisco drops an isotherm's first reading where the temperature had not yet settled,
    # which moves its coldest isotherm (-50 C) by 0.76 decades from ours; elsewhere within 0.25.
    assert np.max(np.abs(relative - PYVISCO)[1:]) < 0.25 and abs(relative[0] - PYVISCO[0]) < 0.8
    # The shipped factors differ from pyvisco's own by up to 0.73 decades at 100 C; ours too.
    shipped = np.array([SHIPPED[min(SHIPPED, key=lambda t: abs(t - x))] for x in T])
    assert np.max(np.abs(relative - shipped)[(T > -45) & (T <= 55)]) < 0.5
    assert np.max(np.abs(relative - shipped)) < 1.0
    assert r.shift["C1"] == pytest.approx(98.09, rel=0.05) and r.shift["C2"] == pytest.approx(430.03, rel=0.05)
    # Quality, as the report states it: over all 210 readings E' within 5.1%, E'' 11.2%
    # (pyvisco's own fit of these data, on the shipped shifts, leaves a relative residual of
    # 0.014 in E'/E_0 unweighted: not comparable); the series written, for the default
    # window of 1e-10 to 1e12 s at -5 C, over the readings within it.
    assert r.prony["rms_relative_all"]["storage"] < 0.06 and r.prony["rms_relative_all"]["loss"] < 0.12
    inside = (r.readings["x_reduced"] >= 1e-12) & (r.readings["x_reduced"] <= 1e10)
    assert (r.readings["used"] == inside).all() and 130 < inside.sum() < 150
    assert r.prony["rms_relative"]["storage"] < 0.06 and r.prony["rms_relative"]["loss"] < 0.14
    assert "RMS relative error over all 210 readings: E' " in r.report
    picture = tmp_path / "fit.png"
    done = subprocess.run(["/usr/bin/python3", REPO / "postprocess" / "fit_picture.py", tmp_path / "ems.fit.json",
                           "-o", picture], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert picture.stat().st_size > 50_000


def test_a_relaxation_test_at_three_temperatures(tmp_path):
    """E(t) = E_inf + sum E_i exp(-t a_T / tau_i) read at 3 temperatures, 1e-2 to 1e3 s,
    in minutes and kPa: the terms inside the readings' span and the law come back."""
    rows = ["temperature [K],time [min],modulus [kPa]"]
    for T in (10.0, 23.0, 40.0):
        aT = 10 ** log10_aT(T)
        for t in np.logspace(-2, 3, 21):
            E = E_INF + (E_I * np.exp(-t / aT / TAU)).sum()
            rows.append(f"{T + 273.15!r},{t / 60!r},{E / 1e3!r}")
    (tmp_path / "relax.csv").write_text("\n".join(rows) + "\n")
    r = cli("fit", "--relaxation", tmp_path / "relax.csv", "--reference-temperature", "23C", "--poisson", "0.5",
            "-o", tmp_path / "m.ini")
    assert r.returncode == 0, r.stderr
    d = json.loads((tmp_path / "m.fit.json").read_text())
    assert d["kind"] == "relaxation" and len(d["readings"]["modulus"]) == 63
    assert d["prony"]["rms_relative"]["modulus"] < 1e-3
    assert np.max(np.abs(np.asarray(d["shift"]["law_log10_aT"]) - log10_aT(d["shift"]["temperatures"]))) < 0.02
    assert abs(d["prony"]["E_inf"] / E_INF - 1) < 0.01
    # Given to --dma instead, it is refused by name.
    wrong = cli("fit", "--dma", tmp_path / "relax.csv", "--poisson", "0.5", "-o", tmp_path / "x.ini")
    assert wrong.returncode == 2 and "give them to --relaxation" in wrong.stderr


def test_smoothing_evens_the_spectrum_of_noisy_data(fitted, tmp_path):
    """On the grid (no refinement) a penalty on second differences of the E_i makes the
    spectrum smoother (sum of squared second differences of the log-grid weights) at little
    cost in the fit (RMS within twice the noise)."""
    tmp, _ = fitted
    common = dict(reference_temperature=23, poisson=0.5, refine=False, terms_per_decade=[3])
    rough = punchsweep.fit_material(tmp / "data.csv", **common)
    smooth = punchsweep.fit_material(tmp / "data.csv", smoothing=0.01, **common)

    def roughness(prony):
        # The weights on the full grid (a term NNLS dropped weighs 0).
        tau = np.asarray(prony["tau_i"])
        grid = np.logspace(np.log10(tau.min()), np.log10(tau.max()), int(round(np.log10(tau.max() / tau.min()) * 3)) + 1)
        w = np.zeros(grid.size)
        for t, e in zip(tau, prony["E_i"]):
            w[np.argmin(np.abs(np.log10(grid / t)))] += e
        return float(np.sum(np.diff(w / 1e6, 2) ** 2))

    assert len(smooth.prony["E_i"]) > len(rough.prony["E_i"])  # weight spread over more terms
    assert roughness(smooth.prony) < roughness(rough.prony)
    assert smooth.prony["rms_relative"]["storage"] < 2 * NOISE


# Issue 48 (part B): a long export, a header in capitals, the report's shifts, the picture's hint.

def write_long_export(path: Path, per_isotherm: int, seed=25):
    """The known material's isotherms as write_dma makes them (0.1 K wander, 1% noise, rows
    shuffled), per_isotherm frequencies each from 0.1 to 100 Hz, written to 6 digits as
    instruments do: 2,850 an isotherm is 19,950 readings in 0.66 MB."""
    rng = np.random.default_rng(seed)
    rows = []
    for T in TEMPERATURES:
        f = np.logspace(-1, 2, per_isotherm)
        s, l = moduli(2 * np.pi * f * 10 ** log10_aT(T))
        rows += [(T + rng.normal(0, 0.1), f[k], s[k] * (1 + NOISE * rng.normal()) / 1e6,
                  l[k] * (1 + NOISE * rng.normal()) / 1e6) for k in range(len(f))]
    rng.shuffle(rows)
    path.write_text("temperature [C],frequency [Hz],storage [MPa],loss [MPa]\n" +
                    "".join(",".join(f"{v:.6g}" for v in r) + "\n" for r in rows))


def test_a_long_export_is_fitted_to_bins_of_its_readings(fitted, tmp_path):
    """A 20,000-reading export took 143 s (docs/fitting.md promises 1 to 25 s): each of the
    fit's ~28,000 least-squares solves (the law polished with the series) is linear in the
    readings. More than 300 readings are now binned per isotherm in log10 frequency for the
    fit (each bin at its readings' geometric means, weighted by their number); the errors
    are reported over every reading. The fit is as good as the full one was (C1 9.0014,
    C2 120.013 K, E_inf 0.03% off, t* within 0.13% of the truth's; binned to 294: 9.0005,
    120.0003 K, 0.006%, 0.09%). A file of 300 readings or fewer is fitted as read (every
    test file: unchanged to the last digit)."""
    data = tmp_path / "long.csv"
    write_long_export(data, 2850)
    assert data.stat().st_size < 1 << 20
    r = cli("fit", "--dma", data, "--reference-temperature", "23", "--poisson", "0.5", "-o", tmp_path / "m.ini")
    assert r.returncode == 0, r.stderr
    assert "the 19950 readings were binned to 294 for the fit" in r.stdout, r.stdout
    rms = re.search(r"RMS relative error over all 19950 readings: E' ([\d.]+)%, E'' ([\d.]+)%", r.stdout)
    assert float(rms[1]) < 1.05 and float(rms[2]) < 1.05, r.stdout  # the noise: 1%
    d = json.loads((tmp_path / "m.fit.json").read_text())
    assert d["prony"]["fitted"] == 294 and len(d["readings"]["x"]) == 19950
    assert abs(d["shift"]["C1"] / C1 - 1) < 1e-3 and abs(d["shift"]["C2"] / C2 - 1) < 1e-3
    assert abs(d["prony"]["E_inf"] / E_INF - 1) < 1e-3
    tmp, report = fitted
    for dh, T in (("10um", 23), ("20um", 23), ("10um", 50), ("20um", 50)):
        truth, fit = t_star(tmp / "truth.ini", dh, T), t_star(tmp_path / "m.ini", dh, T)
        assert abs(fit / truth - 1) < 0.002, (dh, T, fit, truth)
    small = json.loads((tmp / "material.fit.json").read_text())
    assert small["prony"]["fitted"] == 70 and "binned" not in report


def test_a_tan_delta_in_capitals_is_read_and_a_column_not_known_is_named(fitted, tmp_path):
    """'TAN Δ' (capital delta, as some instruments write tan delta) was not recognised, and
    the refusal ('a DMA file needs ... columns') named no column. Greek capitals are matched
    as their small letters, as Latin ones are: 'TAN Δ' is tan δ, and gives the material that
    'tan_delta' gives. A header still short of a column says what it saw and the names it
    takes, on one line."""
    tmp, _ = fitted
    rows = [line.split(",") for line in (tmp / "data.csv").read_text().splitlines()[1:]]
    materials = {}
    for name, header in (("lower", "tan_delta"), ("capital", "TAN \u0394"), ("capital_parentheses", "Tan(\u0394) [-]")):
        (tmp_path / f"{name}.csv").write_text(f"temperature [C],frequency [Hz],storage [MPa],{header}\n" + "".join(
            f"{r[0]},{r[1]},{r[2]},{float(r[3]) / float(r[2])!r}\n" for r in rows))
        r = cli("fit", "--dma", tmp_path / f"{name}.csv", "--reference-temperature", "23", "--poisson", "0.5",
                "-o", tmp_path / f"{name}.ini")
        assert r.returncode == 0, (header, r.stderr)
        materials[name] = (tmp_path / f"{name}.ini").read_text().split("law = prony")[1]
    assert materials["capital"] == materials["lower"] == materials["capital_parentheses"]
    (tmp_path / "phi.csv").write_text((tmp_path / "lower.csv").read_text().replace("tan_delta", "tan phi", 1))
    r = cli("fit", "--dma", tmp_path / "phi.csv", "--reference-temperature", "23", "--poisson", "0.5",
            "-o", tmp_path / "phi.ini")
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert ("phi.csv, line 1: a DMA file needs 'storage [unit]' and 'loss [unit]' (or 'tan_delta') columns; "
            "the header's columns: \"temperature [C]\" (temperature), \"frequency [Hz]\" (frequency), "
            "\"storage [MPa]\" (storage), \"tan phi\" (not used); the names taken") in r.stderr, r.stderr
    assert "tan_delta = tandelta, tan(delta), tand, tan\u03b4, tan(\u03b4), lossfactor;" in r.stderr, r.stderr
    assert not (tmp_path / "phi.ini").exists()


def test_the_reported_measured_shifts_sit_on_the_laws_zero(fitted, tmp_path):
    """The law fitted with the series has its own zero (log10 a_T = 0 at T_ref); the overlap's
    shifts, relative to each other, kept the zero of the overlap's law, so they sat off the
    reported law by a constant: 0.21 decades on the glassy data (1.3 on a drawn rubber),
    which read as a misfit. They are now put on the law's zero by the constant that best
    matches it (their mean offset is 0), as the overlap's own law's zero is fitted, and the
    report says so; the RMS about the law is taken after (glassy 0.942 -> 0.918 decades)."""
    tmp, report = fitted
    data = tmp_path / "glassy.csv"
    write_glassy_isotherms(data)
    r = cli("fit", "--dma", data, "--reference-temperature", "23", "--poisson", "0.5", "-o", tmp_path / "g.ini")
    assert r.returncode == 0, r.stderr
    for text, details in ((r.stdout, tmp_path / "g.fit.json"), (report, tmp / "material.fit.json")):
        shift = json.loads(details.read_text())["shift"]
        assert shift["joint"]
        offset = np.asarray(shift["measured_log10_aT"]) - np.asarray(shift["law_log10_aT"])
        assert abs(offset.mean()) < 1e-12, offset
        assert shift["rms_log10"] == pytest.approx(np.sqrt(np.mean(offset**2)), rel=1e-12)
        assert "(the measured shifts are relative to each other: shown on the law's zero, log10 a_T = 0 at 23 degC, " \
               "by the constant that best matches the law)" in text, text
    assert '("measured", 0.918 decades RMS about it)' in r.stdout, r.stdout


def test_the_picture_hint_runs_from_any_folder(fitted, tmp_path):
    """The report's picture command named postprocess/fit_picture.py relative to the checkout,
    so it failed from any other folder. It now names the script by its absolute path in the
    source tree the binary was built from, and the details by theirs: run as printed, from
    another folder, it draws the picture."""
    import shlex
    tmp, _ = fitted
    work, elsewhere = tmp_path / "work", tmp_path / "elsewhere"
    work.mkdir()
    elsewhere.mkdir()
    r = subprocess.run([BINARY, "fit", "--dma", tmp / "data.csv", "--reference-temperature", "23", "--poisson", "0.5",
                        "-o", "my material.ini"], capture_output=True, text=True, cwd=work)
    assert r.returncode == 0, r.stderr
    hint = re.search(r"^picture: (.*)$", r.stdout, re.M)[1]
    words = shlex.split(hint)
    assert words[:2] == ["/usr/bin/python3", str(REPO / "postprocess" / "fit_picture.py")], hint
    assert words[2] == str(work / "my material.fit.json"), hint
    done = subprocess.run(words, capture_output=True, text=True, cwd=elsewhere)
    assert done.returncode == 0, done.stderr
    assert (elsewhere / "fit.png").stat().st_size > 20_000
