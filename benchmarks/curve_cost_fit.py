#!/usr/bin/python3
"""The data behind estimated_curve_seconds (src/engine/surface_evaluation.cpp): load curves built
on one core, each with an empty curve cache, and the power law fitted to them,

    seconds = scale x nodes^node_power x caps^cap_power x (mirrored if the grid is solved as its quarter,
              mirrored_x if as its half),

by least squares on the logarithms, with each curve's ratio to its estimate. The curves are
whole (--full-curve: the model is a whole curve's; a question's curve stops at its reach) and
built on one thread. Run it on an
idle machine to refit the constants for another one (docs/performance.md, "A curve's cost"):

    /usr/bin/python3 benchmarks/curve_cost_fit.py build/src/app/punchsweep [rows.json]
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

BASE = ["--l", "1.2", "--dh", "0.05", "--s", "2", "--T", "2.5", "--pbar", "0.02", "--full-curve", "--format", "json"]  # whole curves
SCATTER = ["--scatter", "normal:0.01"]


def cases():
    """(name, options, nodes a pitch, the grid solved: quarter, half or whole)."""
    for n in (32, 64, 128, 256):
        yield "square", ["--lattice", "square", "--curve", "cell"], n, "quarter"
        yield "hexagonal", ["--lattice", "hexagonal"], n, "quarter"
    yield "square", ["--lattice", "square", "--curve", "cell"], 512, "quarter"
    for n in (64, 128):  # the third level's sites leave the hexagonal cell its mirror in x alone
        yield "hexagonal 3 levels", ["--lattice", "hexagonal", "--dh2", "0.08"], n, "half"
    for n in (32, 64):
        yield "square 2x2 scattered", ["--lattice", "square", "--supercell", "2", *SCATTER], n, "whole"
        yield "square 4x4 scattered", ["--lattice", "square", "--supercell", "4", *SCATTER], n, "whole"
    yield "hexagonal 2x2 scattered", ["--lattice", "hexagonal", "--supercell", "2", *SCATTER], 32, "whole"
    yield "hexagonal 3 levels 2x2 scattered", ["--lattice", "hexagonal", "--dh2", "0.08", "--supercell", "2", *SCATTER], 32, "whole"


def measure(exe):
    rows = []
    for name, options, n, symmetry in cases():
        with tempfile.TemporaryDirectory() as cache:
            env = dict(os.environ, PUNCHSWEEP_CACHE=cache, OMP_NUM_THREADS="1")
            run = subprocess.run([exe, "surface", *BASE, *options, "--grid", str(n)], env=env, capture_output=True,
                                 text=True, check=True)
        d = json.loads(run.stdout)
        rows.append(dict(name=name, grid=n, nx=d["grid"][0], ny=d["grid"][1], caps=d["caps"], symmetry=symmetry,
                         seconds=d["curve"]["seconds"], samples=d["curve"]["samples"]))
        print(json.dumps(rows[-1]), file=sys.stderr, flush=True)
    return rows


def fit(rows):
    nodes = np.array([r["nx"] * r["ny"] for r in rows], float)
    caps = np.array([r["caps"] for r in rows], float)
    quarter = np.array([r["symmetry"] == "quarter" for r in rows], float)
    half = np.array([r["symmetry"] == "half" for r in rows], float)
    seconds = np.array([r["seconds"] for r in rows])
    A = np.column_stack([np.ones_like(nodes), np.log(nodes), np.log(caps), quarter, half])
    c, *_ = np.linalg.lstsq(A, np.log(seconds), rcond=None)
    estimate = np.exp(A @ c)
    print(f"scale {np.exp(c[0]):.3g}, node_power {c[1]:.3f}, cap_power {c[2]:.3f}, mirrored {np.exp(c[3]):.3f}, "
          f"mirrored_x {np.exp(c[4]):.3f}")
    print("| texture | nodes a pitch | nodes | caps | built (s) | estimate (s) | ratio |")
    print("|---|---|---|---|---|---|---|")
    for r, e in zip(rows, estimate):
        print(f"| {r['name']} | {r['grid']} | {r['nx']} x {r['ny']} | {r['caps']} | {r['seconds']:.3g} | {e:.3g} | "
              f"{r['seconds'] / e:.2f} |")
    print(f"largest factor between a curve and its estimate: {max(np.max(seconds / estimate), np.max(estimate / seconds)):.2f}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    rows = json.load(open(sys.argv[2])) if len(sys.argv) > 2 and os.path.exists(sys.argv[2]) else measure(sys.argv[1])
    if len(sys.argv) > 2 and not os.path.exists(sys.argv[2]):
        json.dump(rows, open(sys.argv[2], "w"), indent=1)
    fit(rows)
