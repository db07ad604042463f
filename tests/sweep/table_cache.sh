#!/usr/bin/env bash
# The refined model's neighbour tables kept between runs (PUNCHSWEEP_CACHE, README "A
# refined localization model"): a run without the cache, the run that builds and saves the
# tables and the runs that read them give the same bytes; a later run reads the file rather
# than rewriting it; a damaged file is rebuilt; three ranks saving at once leave one whole
# file and no pieces, and their map equals one rank's without the cache.
source "$(dirname "$0")/common.sh"
export PUNCHSWEEP_CACHE="$work/cache"
table="$PUNCHSWEEP_CACHE/shell_sums-s2-shells_200"
args=(point --l 1 --dh 0.05 --T 5 --pbar 0.02 --s 2 --times 0,1,5 --localization refined --format json)
fail() { echo "FAIL: $*"; exit 1; }

PUNCHSWEEP_CACHE=off "$PUNCHSWEEP" "${args[@]}" > built.json
[ ! -e "$PUNCHSWEEP_CACHE" ] || fail "PUNCHSWEEP_CACHE=off wrote a cache"
"$PUNCHSWEEP" "${args[@]}" > first.json
[ -s "$table" ] || fail "no table file after the first run: $(ls -la "$PUNCHSWEEP_CACHE" 2>&1)"
inode=$(stat -c %i "$table")
"$PUNCHSWEEP" "${args[@]}" > second.json
[ "$(stat -c %i "$table")" = "$inode" ] || fail "the second run rewrote the table instead of reading it"
cmp built.json first.json || fail "the run that built and saved the tables differs from the one without a cache"
cmp built.json second.json || fail "the run that read the tables differs from the one that built them"

# A damaged file: its checksum fails, the tables are built again and saved whole.
truncate -s 5000 "$table"
"$PUNCHSWEEP" "${args[@]}" > third.json
cmp built.json third.json || fail "the run after a damaged table differs"
[ "$(stat -c %s "$table")" -gt 5000 ] || fail "the damaged table was not rebuilt"
inode=$(stat -c %i "$table")
"$PUNCHSWEEP" "${args[@]}" > fourth.json
[ "$(stat -c %i "$table")" = "$inode" ] || fail "the rebuilt table was not read back"

# Three ranks with an empty cache build and save at once.
rm -rf "$PUNCHSWEEP_CACHE"
grid=(sweep --grid.l 0.75,1 --grid.dh 0.05 --grid.T 2.5 --grid.pbar 0.025,0.06 --grid.s 2 --time.times 0,1,5
      --model.localization refined --quiet)
run_ranks 3 "${grid[@]}" --output three.h5
PUNCHSWEEP_CACHE=off run_ranks 0 "${grid[@]}" --output one.h5
same_maps one.h5 three.h5
[ "$(ls "$PUNCHSWEEP_CACHE")" = "shell_sums-s2-shells_200" ] || fail "the cache holds more than the table: $(ls "$PUNCHSWEEP_CACHE")"
"$PUNCHSWEEP" "${args[@]}" > fifth.json
cmp built.json fifth.json || fail "the table the ranks saved gives other numbers"
echo "table cache: ok"
