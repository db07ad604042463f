#!/usr/bin/env bash
# The main job on one machine: installs what is missing, builds, runs the sweep on every
# core, then draws the map's pictures into the run folder (a texture's map: texture.png).
#   bash jobs/local.sh [CONFIG.ini] [RUN_FOLDER]
# Defaults: sweeps/default.ini, runs/<config name>-<UTC date and time>. Re-running with the
# same RUN_FOLDER resumes an interrupted sweep (or does nothing if the map is complete).
# PUNCHSWEEP=/path/to/punchsweep skips the install and build steps.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=jobs/run_folder.sh
source "$root/jobs/run_folder.sh"
config=$(realpath -m "${1:-$root/sweeps/default.ini}")
name=$(basename "$config" .ini)
run=${2:-"$root/runs/$name-$(date -u +%Y%m%d-%H%M%S)"}
cores=$(getconf _NPROCESSORS_ONLN)  # not nproc: it honours OMP_NUM_THREADS
# The config is checked before anything is built or written (the engine's check once it is
# built): a missing or refused config leaves no run folder, config.ini or provenance.txt.
check_config "$config" || exit 2

binary=${PUNCHSWEEP:-}  # an engine already built elsewhere (the tests use this)
if [ -z "$binary" ]; then
  bash "$root/cmake/install-deps.sh"
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$root/build" -j "$cores" --target punchsweep > /dev/null
  # The Python module too (README, "From Python"), where pybind11 was found to build it.
  if cmake --build "$root/build" --target help 2>/dev/null | grep -q punchsweep_python; then
    cmake --build "$root/build" -j "$cores" --target punchsweep_python > /dev/null
  fi
  binary="$root/build/src/app/punchsweep"
fi

check_config "$config" "$binary" || exit 2
mkdir -p "$run"
run=$(realpath "$run")
prepare_run "$config" "$run" "$binary" || exit 2
{
  echo "punchsweep run: $name"
  echo "started: $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(hostname), $cores cores"
  echo "engine: $("$binary" --version)"
  echo "config: $config (copied to config.ini, its material files to materials/)"
} >> "$run/provenance.txt"

rank_environment
mpirun -np "$cores" "$binary" sweep --config "$run/config.ini" --output "$run/map.h5" --resume

echo "punchsweep: map $run/map.h5"
finish_run "$run"
