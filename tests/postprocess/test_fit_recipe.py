"""docs/fitting.md's recipe, from a DMA file to a map and its pictures, run as written
(each command of its sh block, `punchsweep` the engine under test) in a scratch folder,
and its Python block; the outputs checked against the map file and the engine."""
from __future__ import annotations

import os
import re
import shlex
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
ENGINE = os.environ.get("PUNCHSWEEP", str(REPO / "build/src/app/punchsweep"))
DOC = REPO / "docs" / "fitting.md"


def block(kind: str, containing: str) -> str:
    blocks = [b for b in re.findall(rf"```{kind}\n(.*?)```", DOC.read_text(), flags=re.S) if containing in b]
    assert len(blocks) == 1, f"expected one {kind} block with {containing!r} in docs/fitting.md"
    return blocks[0]


def commands(text: str) -> list[list[str]]:
    """The block's commands, continuation lines joined."""
    return [shlex.split(c) for c in text.replace("\\\n", " ").splitlines() if c.strip()]


@pytest.fixture(scope="module")
def recipe(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("recipe")
    (tmp / "materials").symlink_to(REPO / "materials")
    (tmp / "postprocess").symlink_to(REPO / "postprocess")
    ran = []
    for argv in commands(block("sh", "punchsweep fit --dma materials/dma/nrel_pyvisco_ems_ca.csv")):
        if argv[0] == "punchsweep":
            argv = [ENGINE, *argv[1:]]
        done = subprocess.run(argv, cwd=tmp, capture_output=True, text=True)
        assert done.returncode == 0, (argv, done.stderr)
        ran.append(argv)
    assert len(ran) == 5
    return tmp


def test_the_recipe_writes_a_material_a_map_and_pictures(recipe):
    text = (recipe / "ems_ca.ini").read_text()
    assert "name = EMS-CA (NREL, pyvisco)" in text and "kind = wlf" in text and "T_ref = 25" in text
    with h5py.File(recipe / "ems_ca_map.h5") as f:
        assert list(f["temperature"][...]) == [20, 30, 40, 50]
        assert f.attrs["material"].startswith("EMS-CA") if isinstance(f.attrs["material"], str) else \
            f.attrs["material"].decode().startswith("EMS-CA")
        regime = f["regime"][...]
        t_star = f["t_star"][...]
        codes = dict(zip(f["regime"].attrs["flag_meanings"].split(), f["regime"].attrs["flag_values"]))
        # A map of this material that reads: both immediate and delayed cells, t* spanning
        # seconds to days, and shorter the warmer (a WLF material creeps faster).
        delayed = regime == codes["delayed"]
        assert (regime == codes["immediate"]).any() and delayed.any()
        temperature_axis = [d[0].name.rsplit("/", 1)[-1] for d in f["t_star"].dims].index("temperature")
        finite = np.where(delayed, t_star, np.nan)
        med = np.nanmedian(np.moveaxis(finite, temperature_axis, 0).reshape(4, -1), axis=1)
        assert (np.diff(med) < 0).all()
    for png in ("ems_ca_fit.png", "ems_ca_regime_map.png", "ems_ca_critical_dh.png"):
        assert (recipe / png).stat().st_size > 30_000, png


def test_the_python_block_runs(recipe, monkeypatch):
    punchsweep = pytest.importorskip("punchsweep")
    monkeypatch.chdir(recipe)
    scope: dict = {}
    exec(block("python", "punchsweep.fit_material("), scope)  # noqa: S102 - the doc's own text
    r, fit = scope["r"], scope["fit"]
    assert fit.material is not None and fit.kind == "dma"
    assert r.regime == "delayed" and r.units["t_star"] == "s"
    # The same t* as the command line on the file the recipe wrote.
    done = subprocess.run([ENGINE, "point", "--material", "ems_ca_python.ini", "--R", "50um", "--l", "150um", "--dh", "3um",
                           "--pressure", "5MPa", "--s", "2", "--temperature", "40", "--format", "json"],
                          capture_output=True, text=True, check=True)
    assert f'"t_star": {r.t_star!r}' in done.stdout or str(r.t_star) in done.stdout
