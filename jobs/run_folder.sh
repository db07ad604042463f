# The run folder's steps that every job script shares (local.sh, slurm.sbatch, pbs.sh), and
# the ranks' environment.
# Sourced, with $root (the checkout) set; /usr/bin/python3 with numpy, h5py and matplotlib
# draws the pictures (PUNCHSWEEP_PYTHON names another).
python=${PUNCHSWEEP_PYTHON:-/usr/bin/python3}

# check_config CONFIG [BINARY]: whether CONFIG is a file and, given the engine, one it accepts
# (sweep --dry-run, which writes nothing): asked before a run folder is made or anything is
# written into one, so that a missing or refused config leaves nothing behind; the engine's
# own message says why.
check_config() {
  local config=$1 binary=${2:-}
  if [ ! -f "$config" ]; then
    echo "punchsweep: config $config: $([ -e "$config" ] && echo "not a file" || echo "no such file");" \
      "nothing was written" >&2
    return 2
  fi
  [ -z "$binary" ] || "$binary" sweep --config "$config" --dry-run > /dev/null || {
    echo "punchsweep: config $config was refused by the engine (above); nothing was written" >&2
    return 2
  }
}

# prepare_run CONFIG RUN BINARY: RUN/config.ini, RUN/materials/ and (a texture's cell file or
# height map) RUN/inputs/, copied from CONFIG and the files it names (relative paths taken
# from the config's own folder), so that
# the folder runs and resumes by itself. Into a folder that holds a run already, the copy is
# staged first and the engine asked whether the map would resume from it (sweep --resume
# --dry-run): a different configuration is refused (exit 2) before the folder's config or
# materials are touched. A requeued job passes the same way (its config is the same).
prepare_run() {
  local config=$1 run=$2 binary=$3 staged saved_traps
  mkdir -p "$run"
  # Ctrl-C or a kill while staging leaves no .config-* behind; the caller's traps come back.
  saved_traps=$(trap -p INT TERM)
  staged=$(mktemp -d "$run/.config-XXXXXX")
  trap 'rm -rf "$staged"; exit 130' INT
  trap 'rm -rf "$staged"; exit 143' TERM
  "$python" "$root/jobs/record_config.py" "$config" "$staged" || { rm -rf "$staged"; trap - INT TERM; eval "$saved_traps"; return 2; }
  if [ -e "$run/config.ini" ] || [ -e "$run/map.h5" ] || [ -e "$run/map.h5.partial.journal" ]; then
    (cd "$staged" && "$binary" sweep --config config.ini --output "$run/map.h5" --resume --dry-run > /dev/null) || {
      rm -rf "$staged"
      trap - INT TERM
      eval "$saved_traps"
      echo "punchsweep: $run was left as it was (its config, materials and map); choose another run folder" >&2
      return 2
    }
  fi
  rm -rf "$run/materials" "$run/inputs"
  [ ! -d "$staged/materials" ] || mv "$staged/materials" "$run/materials"
  [ ! -d "$staged/inputs" ] || mv "$staged/inputs" "$run/inputs"
  mv "$staged/config.ini" "$run/config.ini"
  rm -rf "$staged"
  trap - INT TERM
  eval "$saved_traps"
}

# finish_run RUN: the summary, the pictures and the explorer page, from the map alone (the
# pictures fix the axes they do not show at values the map has: a material map has no T).
# Without the Python packages it says so and what to run; the map is whole either way.
finish_run() {
  local run=$1
  if ! "$python" -c 'import numpy, h5py, matplotlib' 2> /dev/null; then
    echo "punchsweep: no summary or pictures: $python lacks numpy, h5py or matplotlib;" \
      "on a machine that has them: bash $root/jobs/finish_run.sh $run" >&2
    return 0
  fi
  "$python" "$root/postprocess/summary.py" "$run/map.h5" > "$run/summary.txt"
  "$python" "$root/postprocess/run_pictures.py" "$run/map.h5" "$run" > /dev/null
  echo "finished: $(date -u +%Y-%m-%dT%H:%M:%SZ)" >> "$run/provenance.txt"
  local pictures=
  for p in regime_map.png critical_dh.png texture.png; do [ ! -f "$run/$p" ] || pictures+="${pictures:+, }$run/$p"; done
  echo "punchsweep: pictures $pictures; explorer $run/explore.html; summary $run/summary.txt"
}

# rank_environment: single-threaded ranks (one per core), and root allowed to launch MPI
# jobs where it says so (containers, CI machines).
rank_environment() {
  export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1
  if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
}

# log_to_run RUN: the script's output from here on to RUN/job.log; the line before says so
# (a batch system's own log file then holds only that line).
log_to_run() {
  echo "punchsweep: run folder $1, log $1/job.log"
  exec >> "$1/job.log" 2>&1
}

# wait_step PID: waits for the sweep's launcher PID, again after each signal the script
# traps while it runs; its exit status in $status.
wait_step() {
  status=0
  wait "$1" || status=$?
  while kill -0 "$1" 2> /dev/null; do wait "$1" || status=$?; done
}
