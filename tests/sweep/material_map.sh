#!/usr/bin/env bash
# [model] material = FILE: a map over l, dh, temperature, pbar, s (and ramp_time when set)
# whose times are in the file's unit, with the material's text, E_0 and E0* in its
# attributes; the WLF shift holds across the temperature axis (t* at th = a_T t* at T_ref);
# a ramp_time axis of 0 reproduces the step map; the same map on 1 and 3 ranks; --resume
# refuses a map made with a different material file; a bad file or temperature is refused.
repo=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/common.sh"
PY=/usr/bin/python3
fail() { echo "FAIL: $*"; exit 1; }
cat > wlf.ini <<'INI'
# a made-up WLF material for the test
[material]
name = test polymer, made up for this test
law = prony
modulus_unit = MPa
time_unit = s
poisson = 0.4
E_inf = 1.0
E_i = 2.0, 1.5, 0.5
tau_i = 0.5, 20, 600
[shift]
kind = wlf
C1 = 17.44
C2 = 51.6
T_ref = 105
INI
grid=(--grid.l 0.75,1 --grid.dh 'linspace(0.01, 0.08, 8)' --grid.temperature 105,110,120
      --grid.pbar 'logspace(0.005, 0.04, 4)' --grid.s 2 --time.times 0,1,10,100)
run_ranks 0 sweep --model.material wlf.ini "${grid[@]}" --quiet --output one.h5 || fail "material sweep"
run_ranks 3 sweep --model.material wlf.ini "${grid[@]}" --quiet --chunk 40 --output three.h5 || fail "3 ranks"
same_maps one.h5 three.h5 || fail "1 and 3 ranks differ"

"$PY" - one.h5 wlf.ini <<'PY' || fail "map contents"
import sys, numpy as np, xarray as xr
d = xr.open_dataset(sys.argv[1], engine="h5netcdf")
assert list(d.regime.dims) == ["l", "dh", "temperature", "pbar", "s"], d.regime.dims
assert d.attrs["time_unit"] == "s" and d.t_star.attrs["units"] == "s" and d.time.attrs["units"] == "s"
assert d.temperature.attrs["units"] == "degC", d.temperature.attrs
assert d.attrs["material_file"] == open(sys.argv[2]).read()
assert abs(d.attrs["E0_Pa"] - 5.0e6) < 1e-6 and abs(d.attrs["E0_star_Pa"] - 5.0e6 / (1 - 0.16)) < 1e-6
assert d.pbar.attrs["scaled_by"] == "E0/(1-nu^2)"
# WLF: log10 a_T = -C1 (th - T_ref) / (C2 + th - T_ref); t* scales with a_T, h does not.
t = d.t_star.values
for k, th in enumerate(d.temperature.values):
    a_T = 10 ** (-17.44 * (th - 105) / (51.6 + th - 105))
    ok = np.isfinite(t[:, :, 0]) & (t[:, :, 0] > 0)
    assert ok.sum() > 10, ok.sum()
    rel = np.abs(t[:, :, k][ok] - a_T * t[:, :, 0][ok]) / (a_T * t[:, :, 0][ok])
    assert rel.max() < 1e-10, (th, rel.max())
    assert (d.regime.values[:, :, k] == d.regime.values[:, :, 0]).all()
    assert np.array_equal(d.h_inf.values[:, :, k], d.h_inf.values[:, :, 0])
print("material map ok")
PY

# A ramp_time axis: 0 is the step (bit for bit), and a longer ramp touches no earlier.
run_ranks 0 sweep --model.material wlf.ini "${grid[@]}" --grid.ramp_time 0,50 --quiet --output ramp.h5 || fail "ramp"
"$PY" - one.h5 ramp.h5 <<'PY' || fail "ramp map"
import sys, numpy as np, xarray as xr
step = xr.open_dataset(sys.argv[1], engine="h5netcdf")
ramp = xr.open_dataset(sys.argv[2], engine="h5netcdf")
assert ramp.regime.dims[-1] == "ramp_time" and ramp.ramp_time.attrs["units"] == "s"
for v in ["regime", "t_star", "h_inf", "a1_inf", "a2_inf", "a1", "a2", "P1", "P2"]:
    assert np.array_equal(ramp[v].isel(ramp_time=0).values, step[v].values, equal_nan=True), v
t0 = ramp.t_star.isel(ramp_time=0).values
t1 = ramp.t_star.isel(ramp_time=1).values
ok = np.isfinite(t0)
assert (t1[ok] >= t0[ok]).all()
print("ramp map ok")
PY

# Several materials: a categorical material axis (after dh) labelled by the files' names,
# each slice bit for bit the single-material map, on 2 ranks as on 1.
cp "$repo/materials/nbr_linder2011.ini" nbr.ini
small=(--grid.l 0.75,1 --grid.dh 'linspace(0.01, 0.08, 8)' --grid.pbar 'logspace(0.005, 0.04, 4)' --grid.s 2
       --time.times 0,1,10,100)
run_ranks 0 sweep --model.material "wlf.ini, nbr.ini" "${small[@]}" --grid.temperature 105 --quiet --output both.h5 \
  2> mixed.log && fail "a material with a [shift] beside one without was accepted"
grep -q "some materials have a \[shift\] and some do not" mixed.log || { cat mixed.log; fail "mixed shift message"; }
sed '/^\[shift\]/,$d' wlf.ini > plain.ini
run_ranks 2 sweep --model.material "plain.ini, nbr.ini" "${small[@]}" --quiet --output both.h5 || fail "two materials"
run_ranks 0 sweep --model.material plain.ini "${small[@]}" --quiet --output plain.h5 || fail "plain"
run_ranks 0 sweep --model.material nbr.ini "${small[@]}" --quiet --output nbr.h5 || fail "nbr"
"$PY" - both.h5 plain.h5 nbr.h5 <<'PY' || fail "material axis"
import sys, numpy as np, xarray as xr
both = xr.open_dataset(sys.argv[1], engine="h5netcdf")
assert list(both.regime.dims) == ["l", "dh", "material", "pbar", "s"], both.regime.dims
assert list(both.material.values) == ["plain", "nbr"], both.material.values
assert "E0_star_Pa" not in both.attrs  # two pressure scales: none claimed for the map
for label, path in (("plain", sys.argv[2]), ("nbr", sys.argv[3])):
    one = xr.open_dataset(path, engine="h5netcdf")
    for v in ["regime", "valid", "t_star", "h_0", "h_inf", "a1_inf", "a2_inf", "a1", "a2", "P1", "P2"]:
        assert np.array_equal(both[v].sel(material=label).values, one[v].values, equal_nan=True), (label, v)
print("material axis ok")
PY

# A load table: a map equal to `punchsweep point --load-table` at its points, and one equal
# to the ramp map when the table is that ramp.
table=(--model.material nbr.ini "${small[@]}" --model.load_table "0:0, 50:1")
run_ranks 0 sweep "${table[@]}" --quiet --output table.h5 || fail "load table"
run_ranks 0 sweep --model.material nbr.ini "${small[@]}" --grid.ramp_time 50 --quiet --output ramp1.h5 || fail "ramp 50"
"$PY" - table.h5 ramp1.h5 <<'PY' || fail "table map"
import sys, numpy as np, xarray as xr
table = xr.open_dataset(sys.argv[1], engine="h5netcdf")
ramp = xr.open_dataset(sys.argv[2], engine="h5netcdf").isel(ramp_time=0)
for v in ["regime", "t_star", "a1", "a2", "P1", "P2"]:
    assert np.allclose(table[v].values, ramp[v].values, rtol=1e-12, atol=0, equal_nan=True), v
print("table map ok")
PY
"$PUNCHSWEEP" point --material nbr.ini --l 1 --dh 0.05 --pbar 0.04 --s 2 --times 0,1,10,100 \
  --load-table "0:0, 50:1" --format json > point.json
"$PY" - table.h5 point.json <<'PY' || fail "table point"
import json, sys, numpy as np, xarray as xr
table = xr.open_dataset(sys.argv[1], engine="h5netcdf").sel(l=1, dh=0.05, pbar=0.04, s=2)
point = json.load(open(sys.argv[2]))
assert float(table.t_star) == point["t_star"], (float(table.t_star), point["t_star"])
assert np.array_equal(table.P1.values, np.array(point["series"]["P1"]))
print("table point ok")
PY
run_ranks 0 sweep "${table[@]}" --grid.ramp_time 10 --dry-run 2> bad.log && fail "table with a ramp axis"
grep -q "one of grid.ramp_time and model.load_table" bad.log || { cat bad.log; fail "table + ramp message"; }
run_ranks 0 sweep --model.material nbr.ini --model.load_table "0:0, 5:0.8, 9:0.5, 10:1" --dry-run 2> bad.log &&
  fail "a falling load table accepted"
grep -q "model.load_table = .*the load decreases; refused because" bad.log || { cat bad.log; fail "falling table"; }

# A relative material path in a config file is taken from the config file's folder, run
# from anywhere; the shipped worked example runs so.
mkdir -p configs/sub
printf '[grid]\nl = 0.75\ndh = 0.02\npbar = 0.005\ns = 2\n[model]\nmaterial = ../../nbr.ini\n' > configs/sub/c.ini
run_ranks 0 sweep --config configs/sub/c.ini --quiet --output rel.h5 || fail "relative material path in a config"
run_ranks 0 sweep --config "$repo/sweeps/materials/nbr.ini" --quiet --output example.h5 || fail "sweeps/materials/nbr.ini"
# The PLA example (a published WLF above T_g = 65 C and Arrhenius below): t* scales with
# a_T, log10 a_T = -17.4 (th - 65)/(51.6 + th - 65) above T_g and 35000 K (1/T - 1/T_g)
# below it (the paper's constants, not the code's), at every dh that touches late.
run_ranks 0 sweep --config "$repo/sweeps/materials/pla.ini" --quiet --output pla.h5 || fail "sweeps/materials/pla.ini"
"$PY" - pla.h5 <<'PYEOF' || fail "PLA t* does not scale with the published shift"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
t = np.squeeze(f["t_star"][...])          # (dh, temperature)
T = f["temperature"][...]
regime = np.squeeze(f["regime"][...])
def log10_aT(th):
    return -17.4 * (th - 65) / (51.6 + th - 65) if th >= 65 else 35000.0 * (1 / (th + 273.15) - 1 / 338.15)
ref = int(np.argmin(abs(T - 65)))
checked = 0
for j in (int(np.argmin(abs(T - 55))), int(np.argmin(abs(T - 75))), int(np.argmin(abs(T - 40)))):
    for i in range(t.shape[0]):
        if regime[i, ref] == 1 and regime[i, j] == 1:  # delayed at both
            expect = 10 ** (log10_aT(T[j]) - log10_aT(T[ref]))
            assert abs(t[i, j] / t[i, ref] / expect - 1) < 1e-9, (T[j], i, t[i, j] / t[i, ref], expect)
            checked += 1
assert checked > 100, checked
PYEOF
run_ranks 0 sweep --model.material configs/sub/missing.ini --dry-run 2> bad.log && fail "a missing material accepted"
grep -q "^punchsweep sweep: model.material = configs/sub/missing.ini: material file configs/sub/missing.ini does not exist" \
  bad.log || { cat bad.log; fail "missing material message"; }

# --resume compares the material's content.
sed 's/E_inf = 1.0/E_inf = 1.1/' wlf.ini > other.ini
cp other.ini wlf2.ini
run_ranks 0 sweep --model.material wlf2.ini "${grid[@]}" --quiet --output one.h5 --resume 2> resume.log &&
  fail "--resume accepted a map of another material"
grep -q "model.material" resume.log || { cat resume.log; fail "the refusal does not name model.material"; }

# Bad inputs: a temperature below T_ref - C2, a bad file, creep_law beside material.
run_ranks 0 sweep --model.material wlf.ini --grid.temperature 40 --dry-run 2> bad.log && fail "40 degC accepted"
grep -q "grid.temperature = 40: value 40 is outside its range for test polymer.*: temperature > 61.0626703" bad.log || { cat bad.log; fail "temperature"; }
# Issue 22: just above the divergence (a_T overflows at 54 degC) a sweep and its dry run
# end with exit 2 naming the value, before any work (they ended in MPI_ABORT and "internal
# error").
for mode in --dry-run --quiet; do
  set +e; run_ranks 2 sweep --model.material wlf.ini --grid.temperature 54,60,105 $mode --output t54.h5 2> bad.log; code=$?; set -e
  [ "$code" = 2 ] || { cat bad.log; fail "temperature 54 ($mode): exit $code, expected 2"; }
  grep -q "grid.temperature = 54,60,105: value 54 is outside its range" bad.log || { cat bad.log; fail "temperature 54 message"; }
  [ ! -e t54.h5 ] && [ ! -e t54.h5.partial ] || fail "a refused sweep wrote files"
done
sed 's/tau_i = 0.5, 20, 600/tau_i = 0.5, 20, 20/' wlf.ini > bad.ini
run_ranks 0 sweep --model.material bad.ini --dry-run 2> bad.log && fail "repeated tau accepted"
test $? -ne 0
grep -q "bad.ini:.*tau_i = 0.5, 20, 20.*strictly increasing" bad.log || { cat bad.log; fail "bad file message"; }
run_ranks 0 sweep --model.material wlf.ini --model.creep_law sls --dry-run 2> bad.log && fail "both accepted"
grep -q "model.material is given too" bad.log || { cat bad.log; fail "creep_law with material"; }
test ! -e regime_map.h5 || fail "a refused run left a map"
echo "material_map: ok"
