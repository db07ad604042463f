"""A measured map's caps told from its land's roughness (issue 51): summits by topographic
prominence, a note where most summits look like roughness, each cap's place, drop, shape
and touch listed, and a Fortran-order .npy read as the array it is. The expected summits
come from a flood written here (best-first from each summit down to higher ground), not
from the engine's union of grounds; the expected touch times from the same map read with
the explicit options that found its caps before (--summit-radius 40um)."""
from __future__ import annotations

import heapq
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("PUNCHSWEEP", str(REPO / "build" / "src" / "app" / "punchsweep"))

# Lengths in um with R = 80 um; a question whose second level is delayed and resolved.
QUESTION = dict(R="80um", height_unit="um", level_gap="0.3um", T=8, pbar=0.004, times=[0, 1, 2, 5, 20])


def scan(n: int = 96, pitch: float = 100.0, tip: float = 80.0, land: float = 12.0, dh: float = 8.0,
         rough: float = 0.02, seed: int = 7) -> tuple[np.ndarray, float]:
    """A profilometer's period (um): 2 x 2 spherical caps of tip radius `tip` on a square of
    `pitch`, two tall ones and two `dh` lower, on a land `land` below the tall tips whose
    pixels scatter by `rough` (normal, standard deviation). Rows along y."""
    L = 2 * pitch
    x = np.arange(n) * (L / n)
    X, Y = np.meshgrid(x, x)
    z = -land + np.random.default_rng(seed).normal(0.0, rough, (n, n))
    for cx, cy, drop in [(0, 0, 0.0), (pitch, pitch, 0.0), (pitch, 0, dh), (0, pitch, dh)]:
        dx = (X - cx + L / 2) % L - L / 2
        dy = (Y - cy + L / 2) % L - L / 2
        z = np.maximum(z, -drop - (dx**2 + dy**2) / (2 * tip))
    return z, L / n


def flood_prominence(z: np.ndarray, i: int, j: int) -> float:
    """How far pixel (row j, column i) rises above the highest saddle on any path to higher
    ground (8-connected, periodic; ties: the earlier pixel in row order is higher): flood
    down from it, always into the highest pixel next to the flooded ground, until a higher
    pixel is reached; the lowest pixel flooded by then is the saddle. +inf for the highest."""
    ny, nx = z.shape
    start = j * nx + i
    flat = z.ravel()

    def higher(a: int, b: int) -> bool:
        return flat[a] > flat[b] or (flat[a] == flat[b] and a < b)

    seen = {start}
    front = [(-flat[start], start)]
    lowest = flat[start]
    while front:
        _, q = heapq.heappop(front)
        if higher(q, start):
            return float(flat[start] - lowest)
        lowest = min(lowest, flat[q])
        qj, qi = divmod(q, nx)
        for dj in (-1, 0, 1):
            for di in (-1, 0, 1):
                r = ((qj + dj) % ny) * nx + (qi + di) % nx
                if r not in seen:
                    seen.add(r)
                    heapq.heappush(front, (-flat[r], r))
    return float("inf")


def local_tops(z: np.ndarray) -> list[tuple[int, int]]:
    """Pixels higher than their four nearest neighbours (a summit radius of one pixel), ties
    to the earlier in row order."""
    ny, nx = z.shape
    flat = z.ravel()
    tops = []
    for j in range(ny):
        for i in range(nx):
            k = j * nx + i
            nbrs = [((j + dj) % ny) * nx + (i + di) % nx for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))]
            if all(flat[k] > flat[r] or (flat[k] == flat[r] and k < r) for r in nbrs):
                tops.append((i, j))
    return tops


def test_summits_are_the_tops_that_rise_by_the_prominence_asked(tmp_path):
    """A smooth random periodic field (eight Fourier modes): with a summit radius of one
    pixel, the caps are the tops whose prominence by the flood reaches --prominence, each
    with the flood's prominence; 0 keeps every top."""
    n, pixel = 48, 0.02
    rng = np.random.default_rng(3)
    x = np.arange(n) * 2 * np.pi / n
    X, Y = np.meshgrid(x, x)
    z = sum(rng.normal() * np.cos(kx * X + ky * Y + rng.uniform(0, 2 * np.pi))
            for kx, ky in rng.integers(-4, 5, size=(8, 2)) if (kx, ky) != (0, 0)) * 0.01
    np.save(tmp_path / "field.npy", z)
    tops = local_tops(z)
    rises = {top: flood_prominence(z, *top) for top in tops}
    height_range = float(z.max() - z.min())
    threshold = 0.1 * height_range
    assert sum(r >= threshold for r in rises.values()) < len(tops)  # the threshold drops some
    for asked in (threshold, 0.0):
        out = punchsweep.surface(height_map=str(tmp_path / "field.npy"), pixel=pixel, summit_radius=pixel,
                                 prominence=asked, T=2.5, pbar=0.01, times=[0, 1])
        found = {(round(c["x"] / pixel), round(c["y"] / pixel)): c["prominence"] for c in out["cap_list"]}
        expected = {top: rise for top, rise in rises.items() if rise >= asked}
        assert set(found) == set(expected)
        for top, rise in expected.items():
            assert found[top] == (pytest.approx(rise, rel=1e-12) if np.isfinite(rise) else None)  # JSON: inf as null
        assert out["summits"]["below_prominence"] == len(tops) - len(expected)
        assert out["summits"]["height_range"] == pytest.approx(height_range, rel=1e-12)


def test_a_scan_finds_its_caps_not_its_land_roughness(tmp_path):
    """Four caps on a land 12 um below with 0.02 um roughness: by default (a summit must rise
    2% of the map's relief, 0.24 um) the four caps and no note; every top kept
    (--prominence 0), the land's bumps become caps, and the note says so; each cap's touch
    time as the explicit options give it (--summit-radius 40um, which found the four)."""
    z, pixel = scan()
    np.save(tmp_path / "scan.npy", z)
    common = dict(height_map=str(tmp_path / "scan.npy"), pixel=f"{pixel}um", **QUESTION)
    default = punchsweep.surface(**common)
    assert default["caps"] == 4 and default["notes"] == []
    assert default["summits"]["least_prominence"] * 80 == pytest.approx(0.02 * float(z.max() - z.min()), rel=1e-12)
    explicit = punchsweep.surface(summit_radius="40um", **common)
    assert explicit["caps"] == 4
    assert [lv["regime"] for lv in default["levels"]] == ["immediate", "delayed"]
    for mine, theirs in zip(default["cap_list"], explicit["cap_list"]):
        assert (mine["x"], mine["y"], mine["level"], mine["regime"]) == (theirs["x"], theirs["y"], theirs["level"], theirs["regime"])
        assert mine["t_star"] == pytest.approx(theirs["t_star"], rel=1e-3)
    # Each cap's touch is its level's where it is the level's first.
    for level in default["levels"]:
        caps = [c for c in default["cap_list"] if c["level"] == level["level"]]
        assert min(c["X_star"] for c in caps) == level["X_star"]
    every = punchsweep.surface(prominence=0, **common)
    assert every["caps"] > 10
    assert any("land roughness taken for caps" in note for note in every["notes"])


def test_a_scan_of_rougher_land_warns_by_default(tmp_path):
    """Twenty times the land's roughness (0.4 um): its bumps rise past 2% of the relief, so
    the defaults keep them and the note says that most summits lie far below the highest
    and rise little."""
    z, pixel = scan(rough=0.4)
    np.save(tmp_path / "rough.npy", z)
    out = punchsweep.surface(height_map=str(tmp_path / "rough.npy"), pixel=f"{pixel}um", **QUESTION)
    assert out["caps"] > 8
    notes = [note for note in out["notes"] if "land roughness taken for caps" in note]
    assert len(notes) == 1 and "--prominence" in notes[0]


def test_the_table_lists_each_cap_of_a_measured_map(tmp_path):
    """The table says what a summit had to rise and gives each cap's level, place, drop, tip
    radius (80 um, the scan's) and touch."""
    z, pixel = scan()
    np.save(tmp_path / "scan.npy", z)
    run = subprocess.run([BINARY, "surface", "--height-map", tmp_path / "scan.npy", "--pixel", f"{pixel}um", "--R", "80um",
                          "--height-unit", "um", "--level-gap", "0.3um", "--T", "8", "--pbar", "0.004", "--times", "0,1,20"],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    lines = [line for line in run.stdout.splitlines() if line.strip().startswith("cap ")]
    assert len(lines) == 4
    assert "summits: those rising at least 0.24" in run.stdout
    for line in lines:
        assert float(line.split("tip radius ")[1].split()[0]) == pytest.approx(80.0, rel=1e-6)
    assert sum("the highest" in line for line in lines) == 1


def test_a_fortran_order_npy_is_the_array_it_holds(tmp_path):
    """numpy writes Z.T's storage (np.asfortranarray) with fortran_order True: the engine
    reads the same array as from its C-order copy, so the same answer, bit for bit."""
    z, pixel = scan(n=64, dh=6.0)
    np.save(tmp_path / "c.npy", np.ascontiguousarray(z))
    np.save(tmp_path / "f.npy", np.asfortranarray(z))
    assert np.load(tmp_path / "f.npy").flags.f_contiguous
    header = (tmp_path / "f.npy").read_bytes()[:128]
    assert b"'fortran_order': True" in header
    common = dict(pixel=f"{pixel}um", **QUESTION)
    c_order = punchsweep.surface(height_map=str(tmp_path / "c.npy"), **common)
    fortran = punchsweep.surface(height_map=str(tmp_path / "f.npy"), **common)
    assert fortran["cap_list"] == c_order["cap_list"]
    assert fortran["series"].keys() == c_order["series"].keys()
    for key, values in c_order["series"].items():
        np.testing.assert_array_equal(fortran["series"][key], values)
    assert [level.to_dict() for level in fortran["levels"]] == [level.to_dict() for level in c_order["levels"]]


def test_each_cap_in_physical_units_with_a_material(tmp_path):
    """With --R and a material, `physical.caps` gives each cap's place, drop and tip radius in
    um and its touchdown load in Pa: the cap list's values (R, E0*) times R and times the
    scale the levels' own physical X* use."""
    z, pixel = scan()
    np.save(tmp_path / "scan.npy", z)
    truth = REPO / "examples" / "dma_exports" / "tpe_a_truth.ini"
    out = punchsweep.surface(height_map=str(tmp_path / "scan.npy"), pixel=f"{pixel}um", R="80um", height_unit="um",
                             level_gap="0.3um", material=str(truth), temperature=20, pressure="20kPa", times="1s, 1min")
    caps = out.physical["caps"]
    assert out.physical["units"]["drop"] == "um"
    np.testing.assert_allclose(caps["x"], [80 * c["x"] for c in out.cap_list], rtol=1e-12)
    np.testing.assert_allclose(caps["drop"], [80 * c["drop"] for c in out.cap_list], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(caps["tip_radius"], 80.0, rtol=1e-6)
    level = next(lv for lv in out.levels if lv.level == 1)
    per = out.physical["levels"][1]["X_star"] / level.X_star
    touched = [k for k, c in enumerate(out.cap_list) if c["X_star"] is not None]
    np.testing.assert_allclose([caps["X_star"][k] for k in touched], [per * out.cap_list[k]["X_star"] for k in touched],
                               rtol=1e-12)
