#!/usr/bin/env bash
# Every #include "LAYER/..." in src/ names the file's own layer or one below it. The
# layers and what each may include (docs/development.md, "Layout"); CMake's library links say the same.
set -euo pipefail
src=$(cd "$(dirname "$0")/../../src" && pwd)

declare -A allowed=(
  [model]="model"
  [reference]="reference model"
  [map]="map model"
  [input]="input map model"
  [io]="io map model"
  [sweep]="sweep map model reference"
  [run]="run io sweep map model reference"
  [app]="app run io sweep input map model reference"
  [python]="python app run io sweep input map model reference"
)

status=0
checked=0
for dir in "$src"/*/; do
  layer=$(basename "$dir")
  if [[ -z "${allowed[$layer]+set}" ]]; then
    echo "src/$layer: a folder that is no known layer (add it here and to docs/development.md)"
    status=1
    continue
  fi
  while IFS= read -r line; do
    file=${line%%:*}
    target=$(sed -E 's/.*#include "([a-z_]+)\/.*/\1/' <<<"$line")
    checked=$((checked + 1))
    if [[ " ${allowed[$layer]} " != *" $target "* ]]; then
      echo "${file#"$src"/}: includes $target/, which layer $layer may not (allowed: ${allowed[$layer]})"
      status=1
    fi
  done < <(grep -H -E '^#include "[a-z_]+/' "$dir"*.hpp "$dir"*.cpp 2>/dev/null || true)
done
if [[ $status -eq 0 ]]; then
  echo "$checked project includes checked: every one follows the layers"
fi
exit $status
