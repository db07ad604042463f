#!/usr/bin/env bash
# Evaluates every point of sweeps/paper-points.csv (the paper's figures) with
# `punchsweep point`, writes its JSON and evolution picture into a run folder, and checks
# the regime the paper states. Installs and builds what is missing first.
# Usage: bash jobs/paper-points.sh [run-folder]   (default: runs/paper-points-<date>)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
run=${1:-"$root/runs/paper-points-$(date +%Y%m%d-%H%M%S)"}
binary=${PUNCHSWEEP:-"$root/build/src/app/punchsweep"}

if [ ! -x "$binary" ]; then
  bash "$root/cmake/install-deps.sh"
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$root/build" -j "$(nproc 2>/dev/null || echo 2)" --target punchsweep >/dev/null
fi
mkdir -p "$run"
status=0
while IFS=, read -r label l dh T pbar s regime; do
  case "$label" in ''|'#'*|label) continue ;; esac
  /usr/bin/python3 "$root/postprocess/evolution.py" --binary "$binary" --l "$l" --dh "$dh" \
    --T "$T" --pbar "$pbar" --s "$s" -o "$run/$label.png" --json "$run/$label.json" >/dev/null
  got=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["regime"])' "$run/$label.json")
  if [ "$got" = "$regime" ]; then mark=ok; else mark="MISMATCH (paper: $regime)"; status=1; fi
  printf '%-28s %-10s %s\n' "$label" "$got" "$mark"
done < "$root/sweeps/paper-points.csv"
echo "results in $run"
exit $status
