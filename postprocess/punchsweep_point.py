"""Run `punchsweep point --format json` and read its result (the JSON contract)."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def find_binary(explicit: str | None = None) -> str:
    """The punchsweep executable: explicit path, $PUNCHSWEEP, PATH, or the build folders."""
    candidates = [explicit, os.environ.get("PUNCHSWEEP"), shutil.which("punchsweep"),
                  REPO / "build" / "src" / "app" / "punchsweep",
                  REPO / "build-ci" / "src" / "app" / "punchsweep"]
    for c in candidates:
        if c and Path(c).is_file() and os.access(c, os.X_OK):
            return str(c)
    raise FileNotFoundError("punchsweep binary not found: build it (bash tests/run-all.sh) "
                            "or pass --binary / set $PUNCHSWEEP")


def run_point(binary: str, l: float, dh: float, T: float, pbar: float, s: int,
              C: float = 0.5, times: list[float] | None = None, localization: str | None = None) -> dict:
    """Evaluate one point; returns the parsed JSON (keys: regime, t_star, h_0, ..., series,
    and localization first unless it is the paper's). `localization`: paper, refined,
    shells:D or point-shells:D; None for the engine's default (refined)."""
    args = [binary, "point", "--l", repr(l), "--dh", repr(dh), "--T", repr(T),
            "--pbar", repr(pbar), "--s", str(s), "--C", repr(C), "--format", "json"]
    if times:
        args += ["--times", ",".join(repr(t) for t in times)]
    if localization:
        args += ["--localization", localization]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise ValueError(done.stderr.strip())
    return json.loads(done.stdout)
