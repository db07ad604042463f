#!/usr/bin/env bash
# The regression check (check.py) with Debian's python3, which has numpy and h5py.
# Usage: PUNCHSWEEP=build/src/app/punchsweep bash tests/regression/check.sh [check.py options]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
py=/usr/bin/python3
[ -x "$py" ] || py=$(command -v python3)
exec "$py" "$here/check.py" "$@"
