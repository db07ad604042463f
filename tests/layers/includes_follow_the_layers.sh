#!/usr/bin/env bash
# Every #include "LAYER/..." in src/ names the file's own layer or one below it. The
# layers and what each may include (docs/development.md, "Layout"); CMake's library links say the same.
set -euo pipefail
src=$(cd "$(dirname "$0")/../../src" && pwd)

declare -A allowed=(
  [model]="model"
  [fit]="fit model"
  [reference]="reference model"
  [map]="map model"
  [input]="input run io sweep map fit model reference"
  [io]="io map model"
  [sweep]="sweep map model reference"
  [run]="run io sweep map model reference"
  [app]="app run io sweep input map fit model reference"
  [python]="python app run io sweep input map fit model reference"
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
  done < <(find "$dir" -name '*.hpp' -o -name '*.cpp' | sort | xargs grep -H -E '^#include "[a-z_]+/' 2>/dev/null || true)
done

# Inside src/model, the parts in their order (src/model/CMakeLists.txt): a file includes
# its own part or one before it, never one after.
model_parts=(numerics problem laws load localization two_level point)
declare -A part_rank=()
for k in "${!model_parts[@]}"; do part_rank[${model_parts[$k]}]=$k; done
for dir in "$src"/model/*/; do
  part=$(basename "$dir")
  if [[ -z "${part_rank[$part]+set}" ]]; then
    echo "src/model/$part: a folder that is no part of the model (add it to model_parts here and to src/model/CMakeLists.txt)"
    status=1
    continue
  fi
  while IFS= read -r line; do
    file=${line%%:*}
    target=$(sed -E 's/.*#include "model\/([a-z_]+)\/.*/\1/' <<<"$line")
    checked=$((checked + 1))
    if [[ -z "${part_rank[$target]+set}" ]]; then
      echo "${file#"$src"/}: includes model/$target/, which is no part of the model"
      status=1
    elif (( part_rank[$target] > part_rank[$part] )); then
      echo "${file#"$src"/}: includes model/$target/, a part after $part (order: ${model_parts[*]})"
      status=1
    fi
  done < <(grep -H -E '^#include "model/' "$dir"*.hpp "$dir"*.cpp 2>/dev/null || true)
done
for file in "$src"/model/*.hpp "$src"/model/*.cpp; do
  [[ -e "$file" ]] || continue
  echo "${file#"$src"/}: a file directly in src/model; it belongs in one of its parts (${model_parts[*]})"
  status=1
done
if [[ $status -eq 0 ]]; then
  echo "$checked project includes checked: every one follows the layers"
fi
exit $status
