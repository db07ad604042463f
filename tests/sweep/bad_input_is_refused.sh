#!/usr/bin/env bash
# Every class of bad input: exit code 2, a message naming the key, value and range, and
# no output file created.
source "$(dirname "$0")/common.sh"
small=(--grid.l 0.75 --grid.dh 0.05 --grid.T 2.5 --grid.pbar 0.06 --grid.s 2 --quiet)
# (The map's files: F.h5, its .partial and journal. A stale F.h5.lock that a killed run
# left is the next run's to take and remove, so it is not counted.)
map_files() { ls -l --time-style=+%s.%N ./*.h5* 2>/dev/null | grep -v '\.lock$' || true; }
refused() {  # refused PATTERN ARGS...: exit 2, PATTERN on stderr, no file created or changed
  local pattern=$1; shift
  local before; before=$(map_files)
  set +e; "$@" > out.txt 2> err.txt; local code=$?; set -e
  if [ "$code" != 2 ]; then echo "FAIL ($*): exit $code, expected 2"; cat err.txt; exit 1; fi
  grep -qF -- "$pattern" err.txt || { echo "FAIL ($*): stderr lacks '$pattern'"; cat err.txt; exit 1; }
  local after; after=$(map_files)
  if [ "$before" != "$after" ]; then echo "FAIL ($*): files changed: $after"; exit 1; fi
}
refused "grid.l" "$PUNCHSWEEP" sweep "${small[@]}" --grid.l -0.5 --output x.h5
refused "grid.T" "$PUNCHSWEEP" sweep "${small[@]}" --grid.T 0.5 --output x.h5
refused "grid.s" "$PUNCHSWEEP" sweep "${small[@]}" --grid.s 2.5 --output x.h5
refused "grid.dh" "$PUNCHSWEEP" sweep "${small[@]}" --grid.dh -0.1 --output x.h5
refused "grid.pbar" "$PUNCHSWEEP" sweep "${small[@]}" --grid.pbar 0 --output x.h5
refused "model.C" "$PUNCHSWEEP" sweep "${small[@]}" --model.C 0 --output x.h5
refused "model.localization = shells:0: localization 'shells:0' is not one; valid range: periodic (" \
  "$PUNCHSWEEP" sweep "${small[@]}" --model.localization shells:0 --output x.h5
refused "time.times" "$PUNCHSWEEP" sweep "${small[@]}" --time.times 0,-1 --output x.h5
refused "output.quantities" "$PUNCHSWEEP" sweep "${small[@]}" --quantities lots --output x.h5
refused "grid.bogus" "$PUNCHSWEEP" sweep "${small[@]}" --grid.bogus 3 --output x.h5
refused "reference.grid = 33" "$PUNCHSWEEP" sweep "${small[@]}" --reference bem --bem-grid 33 --output x.h5
refused "reference.sample = 2: value 2 is more than the grid's 1 point;" "$PUNCHSWEEP" sweep "${small[@]}" --reference.sample 2 --output x.h5
printf '[grid]\nl = 0.75\nwidth = 3\n' > bad.ini
refused "width" "$PUNCHSWEEP" sweep --config bad.ini --output x.h5
refused "nothere.ini" "$PUNCHSWEEP" sweep --config nothere.ini --output x.h5
refused "not writable" "$PUNCHSWEEP" sweep "${small[@]}" --output /proc/x.h5
refused "does not exist" "$PUNCHSWEEP" sweep "${small[@]}" --output no/such/dir/x.h5
# Under mpirun too: one message (from rank 0), exit 2.
refused "grid.T" mpirun --oversubscribe -np 2 "$PUNCHSWEEP" sweep "${small[@]}" --grid.T 0.5 --output x.h5
test "$(grep -c 'grid.T' err.txt)" = 1 || { echo "FAIL: message printed by more than one rank"; exit 1; }
# Existing output without --resume/--overwrite, and --resume of another grid.
"$PUNCHSWEEP" sweep "${small[@]}" --output done.h5
mkdir keep && mv done.h5 keep/
refused "exists" "$PUNCHSWEEP" sweep "${small[@]}" --output keep/done.h5
"$PUNCHSWEEP" sweep "${small[@]}" --output keep/done.h5 --overwrite
"$PUNCHSWEEP" sweep "${small[@]}" --output keep/done.h5 --resume  # complete: nothing to do
# A finished map is compared like a partial one; a file that is no map is never resumed.
refused "the finished map keep/done.h5 was made with another configuration" \
  "$PUNCHSWEEP" sweep --grid.l 0.75 --grid.dh 0.05 --grid.T 3 --grid.pbar 0.06 --grid.s 2 --quiet --output keep/done.h5 --resume
echo "not hdf5" > junk.h5
refused "junk.h5 is not an HDF5 file" "$PUNCHSWEEP" sweep "${small[@]}" --output junk.h5 --resume
rm junk.h5
# The localization model is part of what a map is: a refined map (the default) is not
# resumed as the paper's.
refused "model.localization" "$PUNCHSWEEP" sweep "${small[@]}" --output keep/done.h5 --resume --model.localization paper
refused "give only one" "$PUNCHSWEEP" sweep "${small[@]}" --output keep/done.h5 --resume --overwrite
# An output that cannot become a regular file is refused before any work.
mkdir adir.h5
refused "adir.h5 is a folder" "$PUNCHSWEEP" sweep "${small[@]}" --output adir.h5 --overwrite
refused "adir.h5 is a folder" "$PUNCHSWEEP" sweep "${small[@]}" --output adir.h5
test ! -e adir.h5.partial || { echo "FAIL: a .partial was left beside the folder"; exit 1; }
rmdir adir.h5
refused "/dev/null is a character device" "$PUNCHSWEEP" sweep "${small[@]}" --output /dev/null --overwrite
# Issue 35: the rule for every written file: no pipe (the map would be renamed over it),
# no input of the run (the config file, a material file; by inode, so a hard link too).
mkfifo pipe.h5
refused "pipe.h5 is a pipe" "$PUNCHSWEEP" sweep "${small[@]}" --output pipe.h5 --overwrite
test -p pipe.h5 || { echo "FAIL: the pipe was replaced"; exit 1; }
rm pipe.h5
printf '[grid]\nl = 0.75\ndh = 0.05\nT = 2.5\npbar = 0.06\ns = 2\n' > self.ini
cp self.ini self.keep
refused "self.ini is the input self.ini" "$PUNCHSWEEP" sweep --config self.ini --output self.ini --overwrite --quiet
ln self.ini self-link.h5
refused "self-link.h5 is the input self.ini" "$PUNCHSWEEP" sweep --config self.ini --output self-link.h5 --overwrite --quiet
cmp -s self.ini self.keep || { echo "FAIL: the config file was changed"; exit 1; }
rm self-link.h5
printf '[material]\nname = sls\nlaw = prony\nmodulus_unit = Pa\ntime_unit = s\npoisson = 0.5\nE_inf = 1e6\nE_i = 1e6\ntau_i = 1\n' > mat.h5
cp mat.h5 mat.keep
refused "mat.h5 is the input mat.h5" "$PUNCHSWEEP" sweep --grid.l 0.75 --grid.dh 0.05 --grid.pbar 0.06 --grid.s 2 --quiet \
  --model.material mat.h5 --output mat.h5 --overwrite
cmp -s mat.h5 mat.keep || { echo "FAIL: the material file was changed"; exit 1; }
rm mat.h5 mat.keep
# Issue 22: a name that fits but whose .partial.journal would not (over 255 bytes) is
# refused at once with the limit, not with exit 1 once the journal is to be created.
long=$(printf 'm%.0s' $(seq 1 245)).h5
refused "the name is too long" "$PUNCHSWEEP" sweep "${small[@]}" --output "$long"
# A relative path to --material that is a device, a folder or a binary file: exit 2 naming
# it (a device was read without end, a binary file echoed back).
nomaterial=(--grid.l 0.75 --grid.dh 0.05 --grid.pbar 0.06 --grid.s 2 --quiet)
refused "/dev/zero is not a regular file" "$PUNCHSWEEP" sweep "${nomaterial[@]}" --model.material /dev/zero --output x.h5
printf '[material]\nname = x\n\001\002\n' > binary.ini
refused "binary.ini, line 3: byte 0x01 is a control character" "$PUNCHSWEEP" sweep "${nomaterial[@]}" --model.material binary.ini --output x.h5
printf '[run]\nchunk = 1\n' > slow.ini
"$PUNCHSWEEP" sweep --config slow.ini --grid.l 'linspace(0.5,1.25,40)' --grid.T 2,5 --quiet --output keep/part.h5 & pid=$!
wait_until 120 "$pid" "the journal of keep/part.h5" -- file_larger keep/part.h5.partial.journal 0 ||
  { echo "FAIL: the run ended before it could be killed"; exit 1; }
kill -9 "$pid"; wait "$pid" 2>/dev/null || true
cd keep
refused "grid.T" "$PUNCHSWEEP" sweep --config ../slow.ini --grid.l 'linspace(0.5,1.25,40)' --grid.T 2,6 --output part.h5 --resume
refused "pass --resume" "$PUNCHSWEEP" sweep --config ../slow.ini --grid.l 'linspace(0.5,1.25,40)' --grid.T 2,5 --output part.h5
cd ..
# A grid whose map cannot fit on the disk is refused before any work, with flat memory
# (a 1e12-point grid once grew rank 0 by 250 MB/s with no point done).
refused "but its file system has" /usr/bin/time -f "%M" -o rss.txt "$PUNCHSWEEP" sweep --grid.l 'linspace(0.5,1.5,10000)' \
  --grid.dh 'linspace(0,0.2,10000)' --grid.T 'linspace(1,10,100)' --grid.pbar 'logspace(0.001,0.1,100)' --grid.s 1 \
  --quantities regime --output huge.h5
test "$(tail -1 rss.txt)" -lt 200000 || { echo "FAIL: a 1e12-point grid took $(tail -1 rss.txt) KB before its refusal"; exit 1; }
# A million snapshot times: chunks stay bounded (chunk / times points a tile) and the map
# that would need terabytes is refused before it is created.
refused "the map and its journal need about" "$PUNCHSWEEP" sweep --time.times 'linspace(0,5,1000000)' --output many.h5
"$PUNCHSWEEP" sweep "${small[@]}" --time.times 'linspace(0,5,200000)' --dry-run > dry.txt
grep -q "points: 1 in 1 tiles" dry.txt || { echo "FAIL: dry run of 2e5 times"; cat dry.txt; exit 1; }
echo "PASS: bad input refused with exit 2 and nothing written"
