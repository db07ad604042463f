#!/usr/bin/env bash
# The summary, pictures and explorer page of a run folder whose map is complete, as the job
# scripts make them at the end of a run (for a folder whose job ran where Python lacked
# numpy, h5py or matplotlib):  bash jobs/finish_run.sh RUN_FOLDER
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# = 1 ] || { echo "usage: bash jobs/finish_run.sh RUN_FOLDER" >&2; exit 2; }
[ -f "$1/map.h5" ] || { echo "finish_run.sh: $1/map.h5: no complete map there" >&2; exit 2; }
# shellcheck source=jobs/run_folder.sh
source "$root/jobs/run_folder.sh"
finish_run "$(realpath "$1")"
