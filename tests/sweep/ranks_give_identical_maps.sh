#!/usr/bin/env bash
# The map is bit-identical for 1, 2, 3 and 4 ranks (oversubscribed) and for any tile size.
source "$(dirname "$0")/common.sh"
grid=(--grid.l 0.5,0.75,1 --grid.dh 'linspace(0.02, 0.12, 11)' --grid.T 2,5 --grid.pbar 'logspace(0.005, 0.08, 8)' --grid.s 1,2,3 --quiet)
for q in full regime; do
  run_ranks 0 sweep "${grid[@]}" --quantities "$q" --output "one_$q.h5"
  for n in 1 2 3 4; do
    run_ranks "$n" sweep "${grid[@]}" --quantities "$q" --output "np${n}_$q.h5"
    same_maps "one_$q.h5" "np${n}_$q.h5"
  done
  run_ranks 2 sweep "${grid[@]}" --quantities "$q" --chunk 7 --output "chunk7_$q.h5"
  same_maps "one_$q.h5" "chunk7_$q.h5"
done
# The regime variables do not depend on the quantities either.
same_maps one_regime.h5 one_full.h5
test "$(h5dump -a /completed -y one_full.h5 | grep -o '[0-9]' | tail -1)" = 1
echo "PASS: identical maps for 1-4 ranks, tile sizes and quantities"
