#!/bin/bash
# A study, not a speed benchmark: how far Greenwood and Williamson's independent caps are
# from the engine's answer, which holds the caps' elastic interaction (docs/model.md, section
# 17.7). One level of 8 x 8 Hertz caps (a square cell of pitch l, s 2, C 1/2), heights normal
# with SD 0.01 R, seeds 1-3, at l = 3.33, 5, 10, 20 and 40 R, loads per cap the same at every
# pitch (pbar (l / 10 R)^2 = 1e-5), 16 nodes a pitch (the caps' touchdowns are the small-spot
# limit's, not the grid's); prints per pitch and seed the median, worst and mean of
# X*/X*_GW - 1 over the 63 caps below the tallest; then the study's mould (hexagonal, l 200 um,
# R 60 um, levels 2 and 5 um down, heights SD 0.3 um: 0.005 R) as 2 x 2 and 4 x 4 supercells
# of 24 and 96 caps, the same per level. About 50 s on one core here.
# Usage: benchmarks/greenwood_williamson.sh [path/to/punchsweep]
set -euo pipefail
BIN=${1:-build/src/app/punchsweep}
PY=/usr/bin/python3
OUT=$(mktemp -d)
"$PY" - "$BIN" "$OUT" <<'PY'
import json, subprocess, sys
import numpy as np
binary, out = sys.argv[1], sys.argv[2]
for l in [10 / 3, 5, 10, 20, 40]:
    cell = f"{out}/one.cell"
    with open(cell, "w") as f:
        f.write(f"[cell]\nLx = {l}\nLy = {l}\ns = 2\nC = 0.5\nsite = {l / 2}, {l / 2}, 0, 0\n")
    for seed in (1, 2, 3):
        run = subprocess.run([binary, "surface", "--cell", cell, "--supercell", "8", "--scatter", "normal:0.01",
                              "--seed", str(seed), "--T", "2.5", "--pbar", str(1e-5 * (10 / l) ** 2), "--grid", "16",
                              "--format", "json"], capture_output=True, text=True, check=True)
        caps = json.loads(run.stdout)["cap_list"]
        drops = np.array([c["drop"] for c in caps])
        X = np.array([c["X_star"] for c in caps], dtype=float)
        gw = np.array([4 / 3 * np.sum(np.clip(d - drops, 0, None) ** 1.5) for d in drops]) / (8 * l) ** 2
        below = drops > 0
        e = X[below] / gw[below] - 1
        limit = sum(c["touchdown_from"] == "small_spot_limit" for c in caps)
        print(f"l = {l:5.2f} R, seed {seed}: {limit} of {below.sum()} caps from the limit; X*/X*_GW - 1: "
              f"median {np.median(abs(e)):.2%}, worst {abs(e).max():.2%}, mean {e.mean():+.2%}")
for K, seed in [(K, seed) for K in (2, 4) for seed in (1, 2, 3)]:
    run = subprocess.run([binary, "surface", "--lattice", "hexagonal", "--l", "200um", "--dh", "2um", "--dh2", "5um",
                          "--R", "60um", "--s", "2", "--supercell", str(K), "--scatter", "normal:0.3um", "--seed", str(seed),
                          "--T", "2.5", "--pbar", "1e-3", "--grid", "16", "--format", "json"],
                         capture_output=True, text=True, check=True)
    result = json.loads(run.stdout)
    caps, (Lx, Ly) = result["cap_list"], result["cell"]
    drops = np.array([c["drop"] for c in caps])
    X = np.array([c["X_star"] for c in caps], dtype=float)
    gw = np.array([4 / 3 * np.sum(np.clip(d - drops, 0, None) ** 1.5) for d in drops]) / (Lx * Ly)
    levels = np.array([c["level"] for c in caps])
    parts = []
    for level in (0, 1, 2):
        at = (levels == level) & (drops > 0)
        e = X[at] / gw[at] - 1
        parts.append(f"level {level}: median {np.median(e):+.1%} ({e.min():+.1%} to {e.max():+.1%})")
    limit = sum(c["touchdown_from"] == "small_spot_limit" for c in caps)
    print(f"study's mould, {K} x {K}, seed {seed}: {limit} of {len(caps) - 1} caps from the limit; X*/X*_GW - 1, " + "; ".join(parts))
PY
rm -rf "$OUT"
