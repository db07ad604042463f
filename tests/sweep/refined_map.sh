#!/usr/bin/env bash
# A sweep under [model] localization = refined: the map records the model, its numbers are
# the refined `punchsweep point` at the same points bit for bit (every field a pure function
# of the point, as for the paper's model), 1 and 3 ranks give the same map, and --resume of
# the same grid under the paper's model is refused.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 0.75,1 --grid.dh 0.05,0.075 --grid.T 2.5 --grid.pbar 0.025,0.06 --grid.s 2 --time.times 0,1,5
      --model.localization refined --quiet)
run_ranks 0 sweep "${grid[@]}" --output one.h5
run_ranks 3 sweep "${grid[@]}" --output three.h5
same_maps one.h5 three.h5
h5dump -a /localization one.h5 | grep -q '"shells:200"' || { h5dump -a /localization one.h5; echo "FAIL: localization attribute"; exit 1; }
for l in 0.75 1; do for dh in 0.05 0.075; do for p in 0.025 0.06; do
  "$PUNCHSWEEP" point --l $l --dh $dh --T 2.5 --pbar $p --s 2 --times 0,1,5 --localization refined --format json \
    > "point_${l}_${dh}_${p}.json"
done; done; done
/usr/bin/python3 - <<'PY'
import glob, json, math
import h5py
import numpy as np
f = h5py.File("one.h5", "r")
axes = {name: list(f[name][...]) for name in ("l", "dh", "pbar")}
regimes = {0: "immediate", 1: "delayed", 2: "never"}
checked = 0
for path in glob.glob("point_*.json"):
    _, l, dh, p = path[:-5].split("_")
    at = (axes["l"].index(float(l)), axes["dh"].index(float(dh)), 0, axes["pbar"].index(float(p)), 0)
    point = json.load(open(path))
    assert point["localization"] == "shells:200", path
    assert regimes[int(f["regime"][at])] == point["regime"], path
    t = f["t_star"][at]
    assert (point["t_star"] is None and math.isnan(t)) or t == point["t_star"], (path, t, point["t_star"])
    for name in ("a1", "a2", "P1", "P2"):
        assert np.array_equal(f[name][at], np.array(point["series"][name], dtype=float), equal_nan=True), (path, name)
    checked += 1
assert checked == 8, checked
PY
run_ranks 0 sweep "${grid[@]}" --output one.h5 --resume --model.localization paper 2> resume.log &&
  { echo "FAIL: --resume accepted a refined map as the paper's"; exit 1; }
grep -q "model.localization" resume.log || { cat resume.log; echo "FAIL: the refusal does not name model.localization"; exit 1; }
echo "PASS"
