"""Runs a postprocess script's main() inside the test process (fast; no interpreter start)."""
from __future__ import annotations

import contextlib
import io
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "postprocess"))
import punchsweep_maps as pm  # noqa: E402


def call(module, *args) -> tuple[int, str, str]:
    """Runs `module`'s main with `args`; returns (exit code, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            rc = pm.run_cli(module.main, module.__name__ + ".py", [str(a) for a in args])
        except SystemExit as e:  # argparse
            rc = e.code
    return rc, out.getvalue(), err.getvalue()
