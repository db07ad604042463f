#!/usr/bin/env bash
# The project's test command: installs what is missing (Debian 12 packages), builds
# warning-clean in Release, and runs every test through CTest.
# Usage: bash tests/run-all.sh [build-dir]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
jobs=$(nproc 2>/dev/null || echo 2)

bash "$root/cmake/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" --output-on-failure -j "$jobs"
