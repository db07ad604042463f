#!/usr/bin/env python3
"""punchsweep.classify against the command line run once per point, side by side in one run
(issue 14: classify at C++ speed, >= 1e6 points/s on one core).

Rows, one core, interleaved repeats, the median:
  grid       classify over a 7 x 111 x 9 x 200 x 3 grid of (l, dh, T, pbar, s) (4.2e6
             points): the default grid's ranges, finer, as a design loop or a notebook
             asks them; points share (l, s, dh) as in a sweep's tile, 1,800 a curve
  dense      7 x 23 x 20 x 400 x 3 (3.9e6 points, 8,000 (T, pbar) points a curve)
  scattered  classify at 2,000 random points (every (l, dh) its own); 200,000 for the
             periodic model and the paper's (issue 23: periodic >= 1e6 points/s on one core)
  cli        `punchsweep point --format json` in a subprocess per point, 200 points (the
             route before the module: process start, parsing, one point, JSON)
under the refined model, the paper's and the periodic model.

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_classify.py [--repeats 3]
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import punchsweep

REPO = Path(__file__).resolve().parent.parent


def grid_rate(localization: str, shape=(7, 111, 9, 200)) -> float:
    l = np.linspace(0.5, 1.25, shape[0])[:, None, None, None, None]
    dh = np.linspace(0.01, 0.12, shape[1])[None, :, None, None, None]
    T = np.linspace(2, 10, shape[2])[None, None, :, None, None]
    pbar = np.geomspace(0.005, 0.08, shape[3])[None, None, None, :, None]
    s = np.array([1.0, 2.0, 3.0])[None, None, None, None, :]
    start = time.perf_counter()
    c = punchsweep.classify(l, dh, T, pbar, s, localization=localization)
    return c["regime"].size / (time.perf_counter() - start)


def scattered_rate(localization: str, count: int = 2000) -> float:
    rng = np.random.default_rng(1)
    args = (rng.uniform(0.5, 1.25, count), rng.uniform(0.01, 0.12, count), rng.uniform(2, 10, count),
            np.exp(rng.uniform(np.log(0.005), np.log(0.08), count)), rng.integers(1, 4, count).astype(float))
    start = time.perf_counter()
    punchsweep.classify(*args, localization=localization)
    return count / (time.perf_counter() - start)


def cli_rate(binary: str, localization: str, count: int = 200) -> float:
    rng = np.random.default_rng(2)
    start = time.perf_counter()
    for _ in range(count):
        args = [binary, "point", "--l", repr(rng.uniform(0.5, 1.25)), "--dh", repr(rng.uniform(0.01, 0.12)),
                "--T", repr(rng.uniform(2, 10)), "--pbar", repr(float(np.exp(rng.uniform(np.log(0.005), np.log(0.08))))),
                "--s", str(int(rng.integers(1, 4))), "--times", "0", "--localization", localization, "--format", "json"]
        json.loads(subprocess.run(args, capture_output=True, text=True, check=True).stdout)
    return count / (time.perf_counter() - start)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--binary", default=os.environ.get("PUNCHSWEEP", str(REPO / "build/src/app/punchsweep")))
    args = parser.parse_args()
    os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})  # one core, for the module and the CLI alike
    print(f"{'route':<10} {'model':<8} {'points/s (median of ' + str(args.repeats) + ')':>28}   runs")
    for localization in ("refined", "paper", "periodic"):
        rows = {"grid": [], "dense": [], "scattered": [], "cli": []}
        for _ in range(args.repeats):
            rows["grid"].append(grid_rate(localization))
            rows["dense"].append(grid_rate(localization, (7, 23, 20, 400)))
            rows["scattered"].append(scattered_rate(localization, 2000 if localization == "refined" else 200_000))
            rows["cli"].append(cli_rate(args.binary, localization))
        for route, rates in rows.items():
            print(f"{route:<10} {localization:<8} {statistics.median(rates):>28.4g}   "
                  + ", ".join(f"{r:.3g}" for r in rates))
        print(f"{'':<10} {localization:<8} classify on the grid / the CLI per point: "
              f"{statistics.median(rows['grid']) / statistics.median(rows['cli']):.3g}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
