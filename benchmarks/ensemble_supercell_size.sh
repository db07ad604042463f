#!/bin/bash
# A study, not a speed benchmark: how an ensemble's answer depends on the supercell's size K
# (docs/model.md, section 17.1, "One draw is one sample"). A hexagonal two-level mould
# (l 1.5 R, dh 0.06 R, s 2), each cap's height normal with SD 0.005 R, T 2.5, pbar 0.01,
# 32 nodes a pitch, eight draws (seeds 1-8) at K = 2, 4 and 8; prints, per K, level 1's
# first, median and last cap's t* and its share of caps in contact at each time (mean,
# standard error, sd). About 30 min on one core here (K = 8: 384 caps, 200 s a curve).
# Usage: benchmarks/ensemble_supercell_size.sh [path/to/punchsweep] [Ks]
set -euo pipefail
BIN=${1:-build/src/app/punchsweep}
KS=${2:-"2 4 8"}
PY=/usr/bin/python3
OUT=$(mktemp -d)
for K in $KS; do
  "$BIN" surface --lattice hexagonal --l 1.5 --dh 0.06 --s 2 --supercell "$K" --scatter normal:0.005 --seeds 8 \
    --grid 32 --T 2.5 --pbar 0.01 --times 0.1,0.3,1,3 --format json 2>/dev/null > "$OUT/k$K.json"
done
"$PY" - "$OUT" $KS <<'PY'
import json, sys
out, ks = sys.argv[1], sys.argv[2:]
for K in ks:
    d = json.load(open(f"{out}/k{K}.json"))
    e = d["ensemble"]
    def f(s):
        return "never" if s["mean"] is None else f"{s['mean']:.3g} +- {s['se']:.2g} (sd {s['sd']:.2g})"
    lv = e["levels"][1]
    print(f"K = {K}: {d['caps']} caps; level 1's cap t*: first {f(lv['first'])}, median {f(lv['median'])}, last {f(lv['last'])}")
    t = e["series"]["touched_1"]
    a = e["series"]["area_fraction"]
    print("  share of level 1 in contact at t = 0.1, 0.3, 1, 3:",
          ", ".join(f"{m:.3f} (sd {s:.3f})" for m, s in zip(t["mean"], t["sd"])))
    print("  area fraction:", ", ".join(f"{m:.4f} (sd {s:.4f})" for m, s in zip(a["mean"], a["sd"])))
PY
rm -rf "$OUT"
