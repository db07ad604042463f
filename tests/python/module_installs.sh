#!/usr/bin/env bash
# `cmake --install` puts the package punchsweep under PREFIX/PUNCHSWEEP_PYTHON_DIR, and it
# imports from there (no build tree on the path) and evaluates a point.
# Usage: module_installs.sh BUILD_DIR PYTHON
set -euo pipefail
build=$1 python=$2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > "$prefix/install.log"
core=$(find "$prefix" -name '_core*.so' | head -1)
[ -n "$core" ] || { echo "no _core module under $prefix"; cat "$prefix/install.log"; exit 1; }
site=$(dirname "$(dirname "$core")")
case "$site" in "$prefix"/lib/python3*/site-packages) ;; *) echo "installed in $site, not PREFIX/lib/python3.X/site-packages"; exit 1 ;; esac
cd "$prefix"
PYTHONPATH="$site" PUNCHSWEEP_CACHE=off "$python" - "$site" <<'PY'
import sys
import punchsweep
assert punchsweep.__file__.startswith(sys.argv[1]), punchsweep.__file__
r = punchsweep.point(l=0.75, dh=0.075, T=2.5, pbar=0.06, s=2, localization="paper")
assert r.regime == "delayed" and abs(r.t_star - 1.028) < 0.01, (r.regime, r.t_star)
print("installed package imports from", sys.argv[1], "and gives t* =", r.t_star)
PY
