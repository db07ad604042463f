"""The Python recipes of README.md and docs/ run as written against the real engine."""
from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
ENGINE = os.environ.get("PUNCHSWEEP", str(REPO / "build/src/app/punchsweep"))


def readme_block(containing: str) -> str:
    """The ```python block of README.md or docs/*.md that contains `containing`."""
    pages = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
    blocks = [b for page in pages for b in re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S)]
    matches = [b for b in blocks if containing in b]
    assert len(matches) == 1, f"expected one python block with {containing!r}, found {len(matches)}"
    return matches[0]


def test_csv_recipe_reads_the_point_output(tmp_path, monkeypatch):
    csv = subprocess.run([ENGINE, "point", "--l", "0.75", "--dh", "0.075", "--T", "2.5", "--pbar", "0.06",
                          "--s", "2", "--format", "csv"], capture_output=True, text=True, check=True).stdout
    (tmp_path / "point.csv").write_text(csv)
    monkeypatch.chdir(tmp_path)
    scope: dict = {}
    exec(readme_block('F = "point.csv"'), scope)  # noqa: S102 - the README's own text
    frame, table = scope["frame"], scope["table"]
    assert list(frame.columns) == ["t", "a1", "a2", "P1", "P2", "area_fraction"]
    assert table.shape == (5, 6)
    assert (table[:, 0] == [0, 0.5, 1, 2, 5]).all()
    # The level-1 load before touchdown is pbar0 l^2 exactly (periodic t* = 0.874 > 0.5).
    assert table[1, 3] == 0.06 * 0.75 * 0.75 and frame["P1"][1] == table[1, 3]


def test_the_readme_python_recipe_runs(tmp_path, monkeypatch):
    """README.md's "From Python" block, as written, against a small map and the shipped PLA."""
    pytest = __import__("pytest")
    try:
        import punchsweep  # noqa: F401 - the module the recipe imports
    except ImportError:
        pytest.skip("the punchsweep module is not on PYTHONPATH (build/python)")
    subprocess.run([ENGINE, "sweep", "--grid.l", "0.75", "--grid.dh", "0.05,0.1", "--grid.T", "2.5", "--grid.pbar",
                    "0.02,0.06", "--grid.s", "2", "--quiet", "--output", str(tmp_path / "map.h5")], check=True)
    (tmp_path / "materials").symlink_to(REPO / "materials")
    (tmp_path / "examples").symlink_to(REPO / "examples")
    monkeypatch.chdir(tmp_path)
    scope: dict = {}
    exec(readme_block('punchsweep.Material("materials/'), scope)  # noqa: S102 - the README's own text
    r, c, m, ds = scope["r"], scope["c"], scope["m"], scope["ds"]
    t, w = scope["t"], scope["w"]
    # As the comments say: a texture's levels (typed) and a design window (typed).
    assert [level.regime for level in t.levels] == ["immediate", "immediate", "delayed"]
    assert abs(t.levels[2].t_star - 3.395) < 1e-3 and isinstance(t, punchsweep.SurfaceResult)
    assert isinstance(w, punchsweep.DesignResult) and abs(w.physical["upper"] - 9.93) < 5e-3
    # As the README's comment says (the periodic model's t* here; docs/model.md 14.4 has the BEM's 0.874).
    assert r.regime == "delayed" and abs(r.t_star - 0.873568135068006) < 1e-12
    assert c["regime"].shape == (111, 200)
    # A texture through classify: a curve per pitch, the levels last.
    h = scope["h"]
    assert isinstance(h, punchsweep.TextureClassification) and h.t_star.shape == (2, 50, 3)
    assert tuple(h.grid[1, 0]) == (64, 108)
    assert 0 < m.J(1.0, temperature=60) < 1  # a polymer's compliance in 1/Pa is far below 1
    assert ds["regime"].shape == (1, 2, 1, 2, 1)
