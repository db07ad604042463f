#!/usr/bin/env bash
# --reference.sample invalid | boundary: the BEM runs at exactly the points the rule names,
# computed here again from the map's own model variables (numpy): where the model flags the
# point invalid, or where its regime differs from a neighbour's one step along any axis.
# The map records the rule and the count; 1 and 2 ranks give the same map.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 0.5,0.75,1 --grid.dh 'linspace(0.02, 0.1, 5)' --grid.T 2.5,6 --grid.pbar 'logspace(0.01, 0.08, 4)'
      --grid.s 1,2 --time.times 0,1,5 --reference bem --bem-grid 32 --quiet
      --model.localization refined)  # 240 points; refined: the rule "invalid" needs flagged points
run_ranks 0 sweep "${grid[@]}" --reference.sample invalid --output invalid.h5
run_ranks 2 sweep "${grid[@]}" --reference.sample invalid --output invalid2.h5
same_maps invalid.h5 invalid2.h5
run_ranks 0 sweep "${grid[@]}" --reference.sample boundary --output boundary.h5
/usr/bin/python3 - <<'PY'
import h5py
import numpy as np

def picked(path):
    f = h5py.File(path, "r")
    return f, f["bem_regime"][...] != -1

f, got = picked("invalid.h5")
want = f["valid"][...] != 0
assert want.any() and not want.all(), "the grid should have valid and invalid points"
assert np.array_equal(got, want), f"invalid: {int(got.sum())} picked, {int(want.sum())} invalid"
assert f.attrs["bem_sample_rule"] == "invalid" and f.attrs["bem_sample"] == want.sum()
assert np.isfinite(f["bem_iterations"][...][want]).all() and (f["bem_converged"][...][want] == 1).all()
# The merged answer: the BEM where it ran (here: every invalid point), the model elsewhere.
source, answer, t_answer = f["answer_source"][...], f["answer_regime"][...], f["answer_t_star"][...]
assert np.array_equal(source, np.where(want, 1, 0)), "answer_source: bem exactly where the model is invalid"
assert np.array_equal(answer, np.where(want, f["bem_regime"][...], f["regime"][...]))
assert np.array_equal(t_answer, np.where(want, f["bem_t_star"][...], f["t_star"][...]), equal_nan=True)

f, got = picked("boundary.h5")
regime = f["regime"][...]
want = np.zeros(regime.shape, dtype=bool)
for axis in range(regime.ndim):
    step = np.diff(regime, axis=axis) != 0  # between index i and i + 1 along the axis
    lower = [slice(None)] * regime.ndim
    upper = [slice(None)] * regime.ndim
    lower[axis] = slice(0, -1)
    upper[axis] = slice(1, None)
    want[tuple(lower)] |= step
    want[tuple(upper)] |= step
assert want.any() and not want.all(), "the grid should have regime boundaries and interiors"
assert np.array_equal(got, want), f"boundary: {int(got.sum())} picked, {int(want.sum())} on a boundary"
assert f.attrs["bem_sample_rule"] == "boundary" and f.attrs["bem_sample"] == want.sum()
# The merged answer: the BEM at the boundary points, the model where it is valid, none else.
valid = f["valid"][...] == 0
source = f["answer_source"][...]
assert np.array_equal(source, np.where(want, 1, np.where(valid, 0, 2)))
assert np.array_equal(f["answer_regime"][...], np.where(want, f["bem_regime"][...], np.where(valid, regime, -1)))
assert (source == 2).any(), "some invalid point off the boundary is answered by neither"
print(f"invalid and boundary samples: ok ({int(want.sum())} boundary points)")
PY
# The rule is part of what the map is: a map of one rule is not resumed under another.
run_ranks 0 sweep "${grid[@]}" --reference.sample boundary --output invalid.h5 --resume 2> resume.log &&
  { echo "FAIL: --resume accepted an invalid-sample map as a boundary one"; exit 1; }
grep -q "reference.sample" resume.log || { cat resume.log; echo "FAIL: the refusal does not name reference.sample"; exit 1; }
