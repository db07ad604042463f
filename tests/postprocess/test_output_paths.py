"""The rule for every file punchsweep writes (issue 35 item 1; postprocess/punchsweep_maps.py
output_problem, the engine's io::output_file_problem): a picture, a page or a JSON file is
never written through a symbolic link, over a folder, a pipe or a device, or over one of
the script's inputs (by inode: a hard link is caught). Each script refuses with exit 2
before any work and leaves every path as it was. Run as subprocesses with a time limit: a
script that opened the pipe would block."""
from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
ENGINE = os.environ.get("PUNCHSWEEP", str(REPO / "build/src/app/punchsweep"))
POSTPROCESS = REPO / "postprocess"


def run(*args) -> subprocess.CompletedProcess:
    try:
        return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        pytest.fail(f"{args[0]} blocked (it opened a pipe?)")


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("outputs")
    m = tmp / "map.h5"
    subprocess.run([ENGINE, "sweep", "--grid.l", "0.75", "--grid.dh", "linspace(0.01,0.2,4)", "--grid.T", "2.5",
                    "--grid.pbar", "logspace(0.01,0.1,4)", "--grid.s", "2", "--output", m, "--quiet"], check=True)
    return tmp, m


def hostile(folder: Path, suffix: str, source: Path) -> dict[str, Path]:
    """The paths no script may write: a link (to a file that must stay as it is), a folder,
    a pipe, and a hard link to the script's input."""
    folder.mkdir()
    (folder / "target").write_text("the link's target")
    paths = {k: folder / f"{k}{suffix}" for k in ("link", "folder", "pipe", "input")}
    paths["link"].symlink_to(folder / "target")
    paths["folder"].mkdir()
    os.mkfifo(paths["pipe"])
    os.link(source, paths["input"])
    return paths


def assert_untouched(folder: Path, paths: dict[str, Path], source: Path, source_digest: str):
    assert paths["link"].is_symlink() and (folder / "target").read_text() == "the link's target"
    assert paths["folder"].is_dir()
    assert paths["pipe"].is_fifo()
    assert digest(source) == source_digest
    assert sorted(p.name for p in folder.iterdir()) == sorted([*(p.name for p in paths.values()), "target"])


SCRIPTS = {
    "regime_map": (".png", lambda m, out: [POSTPROCESS / "regime_map.py", m, "--x", "pbar", "--y", "dh",
                                          "-o", out]),
    "critical_dh": (".png", lambda m, out: [POSTPROCESS / "critical_dh.py", m, "-o", out]),
    "explore": (".html", lambda m, out: [POSTPROCESS / "explore.py", m, "-o", out]),
    "evolution": (".png", lambda m, out: [POSTPROCESS / "evolution.py", "--map", m, "--at", "dh=0.01", "--at", "pbar=0.01",
                                          "-o", out]),
}


@pytest.mark.parametrize("script", SCRIPTS)
def test_a_script_refuses_every_hostile_output_and_changes_nothing(inputs, script):
    tmp, m = inputs
    suffix, command = SCRIPTS[script]
    folder = tmp / script
    paths = hostile(folder, suffix, m)
    before = digest(m)
    for kind, path in paths.items():
        done = run(*command(m, path))
        assert done.returncode == 2, (kind, done.stdout, done.stderr)
        expected = {"link": "is a symbolic link", "folder": "is a folder", "pipe": "is a pipe",
                    "input": f"is the input '{m}'"}[kind]
        assert expected in done.stderr, (kind, done.stderr)
    assert_untouched(folder, paths, m, before)
    good = folder / f"good{suffix}"
    assert run(*command(m, good)).returncode == 0
    assert good.stat().st_size > 0
    good.unlink()
    assert_untouched(folder, paths, m, before)


def test_evolution_json_may_not_replace_its_map_or_picture(inputs):
    tmp, m = inputs
    folder = tmp / "evolution_json"
    paths = hostile(folder, ".json", m)
    before = digest(m)
    for kind, path in paths.items():
        done = run(POSTPROCESS / "evolution.py", "--map", m, "--at", "dh=0.01", "--at", "pbar=0.01", "-o", folder / "e.png",
                   "--json", path)
        assert done.returncode == 2, (kind, done.stderr)
        assert str(path) in done.stderr, (kind, done.stderr)
    assert not (folder / "e.png").exists()
    assert_untouched(folder, paths, m, before)


def test_fit_picture_may_not_replace_the_fit_details(tmp_path):
    rows = ["temperature [C],frequency [Hz],storage [MPa],loss [MPa]"]
    for T, shift in ((0, 2.0), (23, 0.0), (50, -1.5)):
        for k in range(8):
            f = 10 ** (-1 + 3 * k / 7)
            wt = [2 * 3.141592653589793 * f * 10 ** shift * tau for tau in (1e-3, 1e-1, 10.0)]
            storage = 1 + sum(e * x * x / (1 + x * x) for e, x in zip((4, 3, 2), wt))
            loss = sum(e * x / (1 + x * x) for e, x in zip((4, 3, 2), wt))
            rows.append(f"{T},{f!r},{storage!r},{loss!r}")
    (tmp_path / "d.csv").write_text("\n".join(rows) + "\n")
    subprocess.run([ENGINE, "fit", "--dma", tmp_path / "d.csv", "--reference-temperature", "23", "--poisson", "0.5",
                    "-o", tmp_path / "m.ini"], check=True, capture_output=True)
    details = tmp_path / "m.fit.json"
    folder = tmp_path / "pictures"
    paths = hostile(folder, ".png", details)
    before = digest(details)
    for kind, path in paths.items():
        done = run(POSTPROCESS / "fit_picture.py", details, "-o", path)
        assert done.returncode == 2, (kind, done.stderr)
        assert str(path) in done.stderr, (kind, done.stderr)
    assert_untouched(folder, paths, details, before)
