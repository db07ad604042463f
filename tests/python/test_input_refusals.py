"""Inputs as users and their instruments bring them (issue 48): height maps whose .npy header
lies about its shape, spreadsheets' decimal commas, a map in µm, a map that is no whole
period, a negative seed, and `punchsweep design`'s units, repeated options, temperatures and
bare pressures. Bad input exits with 2 and one line on stderr naming the input and what is
valid, never 1 (internal error) or a crash; what is read is read as meant."""
from __future__ import annotations

import json
import os
import struct
import subprocess
from pathlib import Path

import numpy as np
import pytest
from lattice_maps import lattice_heights

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))
TRUTH = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
GEOMETRY = ["--R", "80um", "--l", "250um", "--s", "2"]
LOAD = ["--T", "2.5", "--pbar", "0.01"]


def cli(*args) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True)


def refused(run: subprocess.CompletedProcess, *words: str) -> None:
    """Exit 2, nothing on stdout, one line on stderr holding every word."""
    assert run.returncode == 2, (run.returncode, run.stderr)
    assert run.stdout == "", run.stdout
    assert run.stderr.count("\n") <= 1 and "internal error" not in run.stderr, run.stderr
    for w in words:
        assert w in run.stderr, (w, run.stderr)


def surface_json(*args) -> dict:
    run = cli("surface", *args, "--format", "json")
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)



def write_npy(path: Path, dictionary: str, values) -> Path:
    """A .npy file (format 1.0) with this header dictionary, as a writer that lies may make it."""
    header = dictionary
    while (10 + len(header) + 1) % 64:
        header += " "
    header += "\n"
    path.write_bytes(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode()
                     + np.asarray(values, "<f8").tobytes())
    return path


@pytest.mark.parametrize("shape, descr, values, words", [
    # 4 (2^62 + 4) is 16 modulo 2^64: read as 4 x 4 before.
    ("(4, 4611686018427387908)", "<f8", 16, ["'shape' (4, 4611686018427387908) does not match the data",
                                              "holds 16 values of 8 bytes"]),
    # 2^32 x 2^32 is 0 modulo 2^64: a crash before.
    ("(4294967296, 4294967296)", "<f8", 0, ["'shape' (4294967296, 4294967296) does not match the data"]),
    # Too long for any integer: 'internal error: stoull' before.
    ("(123456789012345678901234567890, 4)", "<f8", 16, ["'123456789012345678901234567890' is no count of pixels"]),
    # An item size too long for an int: 'internal error: stoi' before.
    ("(4, 4)", "<f99999999999", 16, ["'descr' (dtype) '<f99999999999'", "valid: little-endian float64 or float32"]),
    ("(4, 4)", "<i8", 16, ["'descr' (dtype) '<i8'", "valid: little-endian float64 or float32"]),
])
def test_a_npy_header_whose_shape_or_dtype_does_not_hold_is_refused_naming_the_field(tmp_path, shape, descr, values, words):
    path = write_npy(tmp_path / "map.npy", f"{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}",
                     np.zeros(values))
    refused(cli("surface", "--height-map", path, "--pixel", "0.05", *LOAD), f"{path}: ", *words)


def test_a_csv_map_with_decimal_commas_between_semicolons_is_the_same_map(tmp_path):
    """A spreadsheet's export in a decimal-comma locale ("-1,234;-0,5;..."): the 16 x 16 map
    and its two summits, as the same heights written with points; before, each value split at
    its comma into 32 x 16 pixels of integer and fraction parts."""
    l, n, dh = 0.75, 16, 0.03
    z = lattice_heights(l, n, dh) * 80.0
    np.savetxt(tmp_path / "points.csv", z, delimiter=",", fmt="%.9f")
    (tmp_path / "commas.csv").write_text("".join(";".join(f"{v:.9f}".replace(".", ",") for v in row) + ";\r\n" for row in z))
    (tmp_path / "tabs.csv").write_text("".join("\t".join(f"{v:.9f}".replace(".", ",") for v in row) + "\n" for row in z))
    common = ["--R", "80um", "--pixel", f"{l / n * 80}um", "--height-unit", "um", "--level-gap", "1.2um", *LOAD]
    points = surface_json("--height-map", tmp_path / "points.csv", *common)
    for name in ("commas.csv", "tabs.csv"):
        commas = surface_json("--height-map", tmp_path / name, *common)
        assert commas["grid"] == points["grid"] == [n, n] and commas["caps"] == points["caps"] == 2, name
        assert commas["levels"] == points["levels"], name
        assert commas["series"] == points["series"], name


def test_a_csv_map_in_an_ambiguous_layout_or_with_a_short_row_is_refused_naming_the_line(tmp_path):
    rows = ["1,5;2,25;3;2,25"] * 4
    (tmp_path / "short.csv").write_text("\n".join(rows[:2] + ["1,5;2,25;3"] + rows[3:]) + "\n")
    refused(cli("surface", "--height-map", tmp_path / "short.csv", "--pixel", "0.05", *LOAD),
            "short.csv:3: 3 values; the first row has 4 (row 3 of the map")
    # Blanks between values, a decimal comma in each: read at the commas, 1 | 5 2 | 25 ...
    (tmp_path / "blanks.csv").write_text("1,5 2,25 3,0 2,25\n" * 4)
    refused(cli("surface", "--height-map", tmp_path / "blanks.csv", "--pixel", "0.05", *LOAD),
            "blanks.csv:1: '5 2' between two commas: values separated by commas and by blanks")


def write_netcdf(path: Path, heights_xy: np.ndarray, length: float, unit: bytes) -> Path:
    """SurfaceTopography's NetCDF-3 map (heights(x, y); x and y with length, periodic and
    length_unit), the unit's bytes as given, by Debian's scipy."""
    from scipy.io import netcdf_file
    nx, ny = heights_xy.shape
    with netcdf_file(path, "w", version=2) as nc:
        nc.createDimension("x", nx)
        nc.createDimension("y", ny)
        for name, count in (("x", nx), ("y", ny)):
            v = nc.createVariable(name, "f8", (name,))
            v.length = length * count / nx
            v.periodic = 1
            v.length_unit = unit
            v[...] = (np.arange(count) + 0.5) * length / nx
        nc.createVariable("heights", "f8", ("x", "y"))[...] = heights_xy
    return path


def test_a_netcdf_map_in_micrometres_reads_either_micro_sign_as_um(tmp_path):
    """"µm" with the micro sign U+00B5 or Greek mu U+03BC (UTF-8), or Latin-1's one byte 0xB5
    (refused before as "'\ufffdm' is not a length unit"): the same answers as "um"."""
    l, n, dh = 0.75, 16, 0.03
    z = lattice_heights(l, n, dh).T * 80.0
    common = ["--R", "80um", "--level-gap", "1.2um", *LOAD]
    plain = surface_json("--height-map", write_netcdf(tmp_path / "um.nc", z, l * 80.0, b"um"), *common)
    for name, unit in (("micro", "\u00b5m".encode()), ("mu", "\u03bcm".encode()), ("latin1", b"\xb5m")):
        micro = surface_json("--height-map", write_netcdf(tmp_path / f"{name}.nc", z, l * 80.0, unit), *common)
        assert micro["levels"] == plain["levels"] and micro["series"] == plain["series"], name
        assert micro["caps"] == 2, name


def test_a_map_whose_opposite_edges_do_not_meet_is_read_with_a_note(tmp_path):
    """A map tilted by a plane (an unlevelled profilometer scan): its last row steps far more to
    its first than any row to the next, so it is no whole period; it is read, with a note. The
    lattice itself, one whole period, has none."""
    l, n, dh = 0.75, 16, 0.03
    z = lattice_heights(l, n, dh)
    np.savetxt(tmp_path / "period.csv", z, delimiter=",")
    np.savetxt(tmp_path / "tilted.csv", z + 0.01 * np.arange(n)[:, None], delimiter=",")
    common = ["--pixel", l / n, *LOAD]
    period = surface_json("--height-map", tmp_path / "period.csv", *common)
    tilted = surface_json("--height-map", tmp_path / "tilted.csv", *common)
    assert not any("edges do not meet" in note for note in period["notes"]), period["notes"]
    assert any("tilted.csv: its opposite edges do not meet (its last row to its first" in note for note in tilted["notes"]), \
        tilted["notes"]


@pytest.mark.parametrize("seed", ["-1", "1.5", "18446744073709551616", "1e3"])
def test_a_negative_fractional_or_too_large_seed_is_refused_with_its_range(seed):
    """--seed -1 wrapped round to 2^64 - 1 before (an unsigned conversion)."""
    refused(cli("surface", "--l", "1", "--dh", "0.02", "--s", "2", *LOAD, "--supercell", "2", "--scatter", "normal:0.001",
                "--grid", "16", "--seed", seed),
            f"--seed = '{seed}' is outside its range: an integer in [0, 2^64-1")


def design_run(*args) -> subprocess.CompletedProcess:
    return cli("design", "--material", TRUTH, *GEOMETRY, *args)


def design_json(*args) -> dict:
    run = design_run(*args, "--format", "json")
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_design_takes_every_time_unit_its_docs_list():
    """docs/design.md: times take ms, s, min, h. 5 ms is 0.005 s, the same window to the bit."""
    ms = design_json("--require", "touch within 5ms at 30kPa")
    s = design_json("--require", "touch within 0.005s at 30kPa")
    assert ms["upper"] == s["upper"] and ms["requirements"][0]["time"] == s["requirements"][0]["time"]
    assert design_json("--require", "touch within 1min at 30kPa")["upper"] == design_json("--require", "touch within 60s at 30kPa")["upper"]


@pytest.mark.parametrize("twice, words", [
    (["--format", "json", "--format", "table"], ["option '--format' cannot be specified more than once"]),
    (["--temperature", "20C", "--temperature", "40C"], ["option '--temperature' cannot be specified more than once"]),
    (["--tolerance", "dh=0.5um", "--tolerance", "dh=1um"], ["option '--tolerance' cannot be specified more than once"]),
    (["--l", "200um"], ["option '--l' cannot be specified more than once"]),
])
def test_design_refuses_an_option_given_twice_naming_it(twice, words):
    refused(design_run("--require", "touch within 1s at 30kPa", *twice), *words)


def test_design_refuses_the_pressure_given_as_both_pbar_and_pressure():
    refused(design_run("--require", "touch within 1min", "--find", "pressure", "--dh", "8um",
                       "--pressure", "1kPa..200kPa", "--pbar", "1e-4..1e-2"),
            "--pbar beside --pressure: the pressure is given twice")


@pytest.mark.parametrize("temperature", ["20..1e300C", "1e300", "-300C..40C", "20..1e5K", "20..10001C"])
def test_design_refuses_a_temperature_outside_the_physical_range(temperature):
    """The material's [shift] has no T_min/T_max: its own bounds are absolute zero and none
    above; the design takes at most 1e4 C."""
    refused(design_run("--require", "touch within 1s at 30kPa", "--temperature", temperature),
            f"--temperature {temperature}: ", "is outside its range: a temperature above absolute zero (-273.15 C) and at most 10000 C")


def test_design_says_how_it_read_a_bare_pressure_beside_a_material():
    """docs/cli.md, Units: a bare number is in the scale, E0* with a material; 30 is then
    500 MPa for this material, which a note says (a unit is what the user most likely meant)."""
    bare = design_json("--require", "touch within 1s at 30")
    assert any("its pressure 30 has no unit, so it is in E0*" in note and "500 MPa" in note for note in bare["notes"]), \
        bare["notes"]
    with_unit = design_json("--require", "touch within 1s at 30kPa")
    assert not any("has no unit" in note for note in with_unit["notes"])
    # Without a material every pressure is in E0* (the paper's scales): nothing to say.
    paper = cli("design", "--l", "0.75", "--T", "2.5", "--s", "2", "--require", "touch within 1 at 0.06", "--format", "json")
    assert paper.returncode == 0, paper.stderr
    assert not any("has no unit" in note for note in json.loads(paper.stdout)["notes"])
