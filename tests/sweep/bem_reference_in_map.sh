#!/usr/bin/env bash
# --reference bem: the map gets the bem_* variables at exactly the sampled points (the rest
# not_computed), the same for 1 and 2 ranks and any tile size, equal to `punchsweep
# reference` at a sampled point, and kill -9 / --resume still gives the clean map.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 0.75,1 --grid.dh 'linspace(0.02, 0.1, 5)' --grid.T 2.5,6 --grid.pbar 'logspace(0.01, 0.06, 4)'
      --grid.s 1,2 --time.times 0,0.5,1,2,5)  # 160 points
bem=(--reference bem --bem-grid 32 --reference.sample 24 --reference.seed 1)

values() {  # values MAP VAR: every value of VAR in row-major order, one per line
  h5dump -A 0 -d "/$2" -y -w 0 -m %.17g "$1" | sed -n '/DATA {/,/^ *}/p' | sed '1d;$d' | tr ',' '\n' | tr -d ' ' |
    grep -v '^$'
}
attribute() {  # attribute MAP NAME: a scalar global attribute's value
  h5dump -a "/$2" -y -w 0 "$1" | sed -n '/DATA {/,/^ *}/p' | sed '1d;$d' | tr -d ' "'
}
fail() { echo "FAIL: $*"; exit 1; }

# 1) The map and its summary.
run_ranks 0 sweep "${grid[@]}" "${bem[@]}" --output one.h5 2> one.log || { cat one.log; exit 1; }
grep -q "^  bem: 24 points (immediate [0-9]*, delayed [0-9]*, never [0-9]*; regime agreement with the model" \
  one.log || { cat one.log; fail "no bem line in the summary"; }
for v in bem_regime bem_converged bem_iterations bem_residual bem_t_star bem_a1 bem_a2 bem_P1 bem_P2 \
         bem_area_fraction; do
  h5ls "one.h5/$v" >/dev/null || fail "one.h5 has no $v"
done
test "$(attribute one.h5 bem_grid)" = 32 || fail "bem_grid is $(attribute one.h5 bem_grid)"
test "$(attribute one.h5 bem_sample)" = 24 || fail "bem_sample is $(attribute one.h5 bem_sample)"
test "$(attribute one.h5 bem_seed)" = 1 || fail "bem_seed is $(attribute one.h5 bem_seed)"
values one.h5 bem_regime > regime.txt
values one.h5 bem_t_star > t_star.txt
test "$(wc -l < regime.txt)" = 160 || fail "bem_regime has $(wc -l < regime.txt) values"
test "$(grep -cv '^-1$' regime.txt)" = 24 || fail "$(grep -cv '^-1$' regime.txt) sampled points, expected 24"
# Not sampled: NaN everywhere; sampled: a radius at every time.
paste regime.txt t_star.txt | awk '$1 == -1 && $2 != "nan" { exit 1 }' || fail "bem_t_star outside the sample"
test "$(values one.h5 bem_a1 | grep -cv '^nan$')" = $((24 * 5)) || fail "bem_a1 is not set at exactly the sample"
# The solver's report: converged (1) with some CG iterations and a residual at most the
# solves' 1e-10 at every sampled point; not_computed (-1) and NaN elsewhere.
values one.h5 bem_converged > converged.txt
values one.h5 bem_iterations > iterations.txt
values one.h5 bem_residual > residual.txt
paste regime.txt converged.txt iterations.txt residual.txt |
  awk '($1 == -1) != ($2 == -1) || ($1 == -1 && ($3 != "nan" || $4 != "nan")) ||
       ($1 != -1 && ($2 != 1 || $3 + 0 < 1 || $4 + 0 > 1e-10 || $4 + 0 < 0)) { print "line " NR ": " $0; bad = 1 }
       END { exit bad }' || fail "bem_converged, bem_iterations, bem_residual do not match the sample"
# Without the reference, no bem_* variable.
run_ranks 0 sweep "${grid[@]}" --quantities regime --quiet --output plain.h5
h5ls plain.h5/bem_regime >/dev/null 2>&1 && fail "bem_regime in a map without the reference"

# 2) The same map for 1 and 2 ranks and other tile sizes, and the model's variables unchanged.
run_ranks 1 sweep "${grid[@]}" "${bem[@]}" --quiet --output np1.h5
run_ranks 2 sweep "${grid[@]}" "${bem[@]}" --quiet --output np2.h5
run_ranks 2 sweep "${grid[@]}" "${bem[@]}" --quiet --chunk 7 --output chunk7.h5
run_ranks 2 sweep "${grid[@]}" "${bem[@]}" --quiet --chunk 1 --output chunk1.h5
for m in np1.h5 np2.h5 chunk7.h5 chunk1.h5; do same_maps one.h5 "$m"; done
run_ranks 0 sweep "${grid[@]}" "${bem[@]}" --quantities regime --quiet --output regime.h5
same_maps regime.h5 one.h5  # the bem series are stored with --quantities regime too
same_maps plain.h5 one.h5

# 3) A sampled delayed point equals `punchsweep reference` there: regime and t* exactly.
g=$(awk '$1 == 1 { print NR - 1; exit }' regime.txt)
test -n "$g" || fail "no delayed point in the sample (choose another seed)"
declare -a at
rest=$g
for axis in s pbar T dh l; do
  n=$(values one.h5 "$axis" | wc -l)
  at+=("$(values one.h5 "$axis" | sed -n "$((rest % n + 1))p")")
  rest=$((rest / n))
done
"$PUNCHSWEEP" reference --l "${at[4]}" --dh "${at[3]}" --T "${at[2]}" --pbar "${at[1]}" --s "${at[0]}" \
  --bem-grid 32 --times 0,0.5,1,2,5 > point.json
grep -q '"regime": "delayed"' point.json || fail "reference says $(grep regime point.json) at point $g"
want=$(sed -n 's/^ *"t_star": \(.*\),$/\1/p' point.json)
got=$(sed -n "$((g + 1))p" t_star.txt)
awk -v a="$got" -v b="$want" 'BEGIN { exit !(a + 0 == b + 0) }' || fail "bem_t_star $got, reference $want"
# ... and its solver report: the same CG iterations and residual.
want=$(sed -n 's/^ *"cg_iterations": \(.*\),$/\1/p' point.json)
got=$(sed -n "$((g + 1))p" iterations.txt)
awk -v a="$got" -v b="$want" 'BEGIN { exit !(a + 0 == b + 0 && b + 0 > 0) }' || fail "bem_iterations $got, reference $want"
want=$(sed -n 's/^ *"max_residual": \(.*\),$/\1/p' point.json)
got=$(sed -n "$((g + 1))p" residual.txt)
awk -v a="$got" -v b="$want" 'BEGIN { exit !(a + 0 == b + 0) }' || fail "bem_residual $got, reference $want"

# 4) The dry run estimates the reference's cost.
"$PUNCHSWEEP" sweep "${grid[@]}" "${bem[@]}" --dry-run > dry.txt
grep -q "reference calibration: .* s per point at grid 32" dry.txt || { cat dry.txt; fail "no reference estimate"; }

# 5) kill -9 mid-run, a refused resume with another reference, then --resume: the clean map.
slow=("${grid[@]}" --reference bem --reference.sample all --chunk 8)  # 20 tiles
run_ranks 2 sweep "${slow[@]}" --bem-grid 32 --quiet --output clean.h5
start_ranks 2 sweep "${slow[@]}" --bem-grid 32 --quiet --output k.h5; pid=$!
while [ ! -s k.h5.partial.journal ] && kill -0 "$pid" 2>/dev/null; do sleep 0.01; done
header=$(stat -c %s k.h5.partial.journal 2>/dev/null || echo 0)
while [ "$(stat -c %s k.h5.partial.journal 2>/dev/null || echo 0)" -le "$header" ] && kill -0 "$pid" 2>/dev/null; do
  sleep 0.01
done
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
test -f k.h5.partial.journal || fail "the kill came too late to test anything"
wait_until 30 "" "the killed ranks to end" -- gone "--output k.h5"
set +e; "$PUNCHSWEEP" sweep "${slow[@]}" --bem-grid 16 --output k.h5 --resume 2> refused.log; code=$?; set -e
test "$code" = 2 && grep -q "reference.grid: the existing map has 32; this run asks for 16" refused.log ||
  { cat refused.log; fail "resume with another reference.grid was not refused (exit $code)"; }
run_ranks 2 sweep "${slow[@]}" --bem-grid 32 --output k.h5 --resume 2> resume.log || { cat resume.log; exit 1; }
grep -q "already done" resume.log || { cat resume.log; fail "resume did not restore tiles"; }
grep -q "^  bem: 160 points" resume.log || { cat resume.log; fail "resume summary lacks the bem count"; }
same_maps clean.h5 k.h5
echo "PASS: bem_* at the sampled points, identical for ranks and tiles, equal to punchsweep reference, resumable"
