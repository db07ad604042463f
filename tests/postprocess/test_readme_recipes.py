"""The README's Python recipes run as written against the real engine."""
from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
ENGINE = os.environ.get("PUNCHSWEEP", str(REPO / "build/src/app/punchsweep"))


def readme_block(containing: str) -> str:
    """The README's ```python block that contains `containing`."""
    blocks = re.findall(r"```python\n(.*?)```", (REPO / "README.md").read_text(), flags=re.S)
    matches = [b for b in blocks if containing in b]
    assert len(matches) == 1, f"expected one README python block with {containing!r}, found {len(matches)}"
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
    # The level-1 load before touchdown is pbar0 l^2 exactly (refined t* = 0.83 > 0.5).
    assert table[1, 3] == 0.06 * 0.75 * 0.75 and frame["P1"][1] == table[1, 3]
