#!/usr/bin/env bash
# The refined model's neighbour tables kept between runs (PUNCHSWEEP_CACHE, docs/accuracy.md, "A
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
[ "$(ls "$PUNCHSWEEP_CACHE" | tr '\n' ' ')" = "key shell_sums-s2-shells_200 " ] || fail "the cache holds more than the table: $(ls "$PUNCHSWEEP_CACHE")"
"$PUNCHSWEEP" "${args[@]}" > fifth.json
cmp built.json fifth.json || fail "the table the ranks saved gives other numbers"

# Issues 22 and 35: what the cache trusts. A table forged in place (every near patch scaled by
# 1.002 except those holding the three radii the loader checks at fixed points), its
# signature kept, is refused (the signature, an HMAC under the cache's key, no longer
# verifies) and rebuilt; the answers are the honest ones.
cp "$table" honest.table
forge() {  # forge FILE FACTOR: scale the patches, keep the file's signature
  /usr/bin/python3 - "$1" "$2" <<'PY'
import struct, sys, math
path, factor = sys.argv[1], float(sys.argv[2])
raw = open(path, "rb").read()
n = struct.unpack_from("<Q", raw, 8)[0]
v = list(struct.unpack_from(f"<{n}d", raw, 16))
at, edge = 16, 0.98 / math.sqrt(2)
fixed = [(0.2, 0.2), (0.2 / (edge - 0.15), 0.3 / (edge - 0.3))]
for k in range(2):
    patches = int(v[at]); at += 1
    for _ in range(patches):
        lo, hi, size = v[at], v[at + 1], int(v[at + 2]); at += 3
        if not any(lo <= x <= hi for x in fixed[k]):
            for j in range(size):
                v[at + j] *= factor
        at += size
body = struct.pack(f"<{n}d", *v)
open(path, "wb").write(raw[:16] + body + raw[16 + 8 * n:])
PY
}
forge "$table" 1.002
cmp -s honest.table "$table" && fail "the forgery changed nothing"
"$PUNCHSWEEP" "${args[@]}" > forged.json
cmp built.json forged.json || fail "a forged table was believed"
cmp honest.table "$table" || fail "the forged table was not replaced by the honest one"

# A cache folder others can write is not trusted at all (not read, not written), with a
# warning; so is a table file others can write.
forge "$table" 1.002
chmod 0777 "$PUNCHSWEEP_CACHE"
inode=$(stat -c %i "$table")
"$PUNCHSWEEP" "${args[@]}" > shared.json 2> shared.err
cmp built.json shared.json || fail "the run with a shared cache folder differs"
grep -q "can be written by other users" shared.err || fail "no warning for a world-writable cache: $(cat shared.err)"
[ "$(stat -c %i "$table")" = "$inode" ] || fail "a table was written into a world-writable cache folder"
chmod 0755 "$PUNCHSWEEP_CACHE"
cp honest.table "$table"; chmod 0666 "$table"
inode=$(stat -c %i "$table")
"$PUNCHSWEEP" "${args[@]}" > shared_file.json
[ "$(stat -c %i "$table")" != "$inode" ] || fail "a world-writable table file was read"
cmp built.json shared_file.json || fail "the run after a world-writable table differs"

# A FIFO at the table's path does not block; a 24-byte file that claims 2^28 entries does
# not make the run allocate 2 GB (the size is checked against the file first).
rm -f "$table"; mkfifo "$table"
timeout 60 "$PUNCHSWEEP" "${args[@]}" > fifo.json || fail "a FIFO at the table's path blocked the run"
cmp built.json fifo.json || fail "the run with a FIFO in the cache differs"
rm -f "$table"
/usr/bin/python3 -c "import struct,sys; open(sys.argv[1],'wb').write(b'PSWTAB02' + struct.pack('<Q', 1 << 28) + bytes(32))" "$table"
/usr/bin/time -f "%M" -o rss.txt "$PUNCHSWEEP" "${args[@]}" > huge.json
cmp built.json huge.json || fail "the run after a lying table header differs"
[ "$(cat rss.txt)" -lt 400000 ] || fail "a lying table header made the run take $(cat rss.txt) kB"

# Cache folders are absolute or none: OFF, 0, '~/x', and relative XDG_CACHE_HOME or HOME
# create nothing in the working folder.
mkdir -p cwd && cd cwd
for setting in OFF 0 false '~/x' relative/cache; do
  PUNCHSWEEP_CACHE="$setting" "$PUNCHSWEEP" "${args[@]}" > out.json 2> err.txt || fail "PUNCHSWEEP_CACHE=$setting failed"
  cmp ../built.json out.json || fail "PUNCHSWEEP_CACHE=$setting changed the answer"
done
(unset PUNCHSWEEP_CACHE; XDG_CACHE_HOME=rel HOME=home "$PUNCHSWEEP" "${args[@]}" > out.json)
[ -z "$(ls -A)" ] || [ "$(ls -A)" = "out.json"$'\n'"err.txt" ] || [ "$(ls -A | sort | tr '\n' ' ')" = "err.txt out.json " ] ||
  fail "a relative cache setting created files in the working folder: $(ls -A)"
cd ..
echo "table cache: ok"
