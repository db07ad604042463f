# Sourced by the throughput benchmarks: rate ARGS... runs `$bin sweep ARGS` into $work/map.h5
# and prints the engine's points/s (the map's points_per_second: first tile handed out to
# last tile written) and the command's wall seconds. Needs $bin and $work.
rate() {
  local start end
  start=$(date +%s.%N)
  "$bin" sweep "$@" --quiet --overwrite --output "$work/map.h5"
  end=$(date +%s.%N)
  printf '%s %s' "$(h5dump -a /points_per_second "$work/map.h5" | sed -n 's/.*(0): \(.*\)/\1/p')" \
    "$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')"
}
