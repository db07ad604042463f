"""One point of `punchsweep point` or `reference` as its --format json dict (the JSON
contract): through the Python module punchsweep where it is built, else the binary."""
from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
import sys
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


def engine_module():
    """The Python module punchsweep (src/python), importable from PYTHONPATH or the build
    folders; None where it was not built (then the binary runs per point)."""
    try:
        import punchsweep
        return punchsweep
    except ImportError:
        pass
    for folder in (REPO / "build" / "python", REPO / "build-ci" / "python"):
        if (folder / "punchsweep").is_dir():
            sys.path.insert(0, str(folder))
            try:
                import punchsweep
                return punchsweep
            except ImportError:
                sys.path.remove(str(folder))
    return None


def _json_form(result) -> dict:
    """A module result in the command's JSON form: its fields, the series as lists, NaN as
    None (the JSON's null); `localization` first and only where it is not the paper's."""
    out = {}
    fields = dict(vars(result))
    if fields.pop("localization", "paper") != "paper":
        out["localization"] = result.localization
    fields.pop("time_unit", None)
    listed = lambda series: {name: [None if math.isnan(x) else float(x) for x in column]  # noqa: E731
                             for name, column in series.items()}
    for k, v in fields.items():
        if k in ("physical", "units") and not v:
            continue  # the JSON has them only where a physical scale is known
        if k == "sensitivity":
            out.update(v)  # the JSON has dt_star_dNAME, dlog_t_star_dlog_NAME at the top
        elif k == "t_star_range":
            if v is not None:
                out["t_star_low"], out["t_star_high"] = v
        elif k == "corner_regimes":
            if v is not None:
                out.update({f"corners_{name}": n for name, n in v.items()})
        elif k == "other":
            out.update(v)  # the JSON's keys the result class does not name
        elif k == "notes":
            if v:
                out[k] = list(v)  # the JSON has them only where reading the inputs changed one
        elif k == "series":
            out[k] = listed(v)
        elif k == "physical":
            out[k] = {**v, "series": listed(v["series"])}
        else:
            out[k] = v
    return out


def run_command(binary: str, command: str, options: dict) -> dict:
    """`punchsweep point|reference` of one point as its --format json dict: through the
    module where it is built (in-process, the same numbers), else by running the binary.
    `options` are the command's (name -> value; None: its default)."""
    module = engine_module()
    options = {k: v for k, v in options.items() if v is not None}
    if module is not None:
        return _json_form(getattr(module, command)(**options))
    args = [binary, command, "--format", "json"]
    for name, value in options.items():
        text = ",".join(repr(float(t)) for t in value) if isinstance(value, (list, tuple)) else \
            (value if isinstance(value, str) else repr(value))
        args += ["--" + name.replace("_", "-"), text]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise ValueError(done.stderr.strip())
    return json.loads(done.stdout)


def run_point(binary: str, l: float, dh: float, T: float, pbar: float, s: int,
              C: float = 0.5, times: list[float] | None = None, localization: str | None = None) -> dict:
    """Evaluate one point; returns the JSON dict (keys: regime, t_star, h_0, ..., series,
    and localization first unless it is the paper's). `localization`: periodic, paper,
    refined, shells:D or point-shells:D; None for the engine's default (periodic)."""
    return run_command(binary, "point", dict(l=l, dh=dh, T=T, pbar=pbar, s=s, C=C, times=times or None,
                                             localization=localization))
