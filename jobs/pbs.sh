#!/bin/bash
# A punchsweep regime map on a PBS/Torque cluster:  qsub -v CONFIG=sweeps/production.ini jobs/pbs.sh
# One run folder per job (runs/<config>-<job id>), --resume always (a rerun continues the
# map). PBS sends SIGTERM before the walltime kill; the sweep stops cleanly (exit 3) and the
# job asks to be rerun (qrerun) where the site allows it.
#PBS -N punchsweep
#PBS -l select=1:ncpus=32:mpiprocs=32
#PBS -l walltime=04:00:00
#PBS -r y
#PBS -j oe
set -euo pipefail

root=${PBS_O_WORKDIR:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
config=$(realpath "${CONFIG:-$root/sweeps/production.ini}")
job=${PBS_JOBID:-local-$(date -u +%Y%m%d-%H%M%S)}
run=${PUNCHSWEEP_RUN:-$root/runs/$(basename "$config" .ini)-${job%%.*}}
binary=${PUNCHSWEEP:-$root/build/src/app/punchsweep}
extra=(${PUNCHSWEEP_EXTRA_ARGS:-})
ranks=$( [ -n "${PBS_NODEFILE:-}" ] && wc -l < "$PBS_NODEFILE" || getconf _NPROCESSORS_ONLN )
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi

mkdir -p "$run"
# The config and its material files, copied once (a requeued job resumes from the copy).
[ -f "$run/config.ini" ] || /usr/bin/python3 "$root/jobs/record_config.py" "$config" "$run"
echo "start $(date -u +%Y-%m-%dT%H:%M:%SZ) job ${PBS_JOBID:-none} host $(hostname) ranks $ranks $("$binary" --version)" >> "$run/provenance.txt"

hostfile=()
[ -n "${PBS_NODEFILE:-}" ] && hostfile=(--hostfile "$PBS_NODEFILE")
mpirun "${hostfile[@]}" -np "$ranks" --bind-to core "$binary" sweep --config "$run/config.ini" \
  --output "$run/map.h5" --resume "${extra[@]}" &
step=$!
# mpirun passes USR1 to every rank and lets the sweep's exit code 3 through; on TERM it
# would end with 1 (after the ranks drained), and the job would not be rerun.
trap 'kill -USR1 "$step" 2>/dev/null || true' TERM USR1
status=0
wait "$step" || status=$?
while kill -0 "$step" 2>/dev/null; do wait "$step" || status=$?; done
echo "end $(date -u +%Y-%m-%dT%H:%M:%SZ) status $status" >> "$run/provenance.txt"
if [ "$status" = 3 ] && [ -n "${PBS_JOBID:-}" ] && command -v qrerun > /dev/null; then qrerun "$PBS_JOBID"; fi
exit "$status"
