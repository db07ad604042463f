#!/usr/bin/env bash
# Installs punchsweep's build, test and postprocess dependencies from Debian 12 packages.
# Idempotent: only packages that are not yet installed are fetched, and `apt-get update`
# runs only when something is missing. Needs root (or sudo) when it has to install.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libopenmpi-dev openmpi-bin
  libeigen3-dev libgsl-dev libfftw3-dev
  libhdf5-dev hdf5-tools zlib1g-dev libdeflate-dev
  libboost-program-options-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-h5py python3-matplotlib python3-xarray python3-h5netcdf
  python3-pytest python3-scipy python3-dev pybind11-dev
  udunits-bin
  python3-plotly chromium nodejs
)
# A single-node Slurm for tests/jobs/real_slurm.sh (the job scripts under a real Slurm, and
# jobs/pbs.sh through its Torque wrappers). Installed where no systemd runs (containers, CI
# machines) or with PUNCHSWEEP_TEST_SLURM=1: on a desktop with systemd the packages would
# enable and start their services. PUNCHSWEEP_TEST_SLURM=0 leaves them out; the test skips.
slurm_packages=(slurm-wlm munge slurm-wlm-torque)
case "${PUNCHSWEEP_TEST_SLURM:-auto}" in
  1) packages+=("${slurm_packages[@]}") ;;
  0) ;;
  *)
    if [ "$(cat /proc/1/comm 2>/dev/null)" != systemd ]; then
      packages+=("${slurm_packages[@]}")
    else
      echo "install-deps: left out ${slurm_packages[*]} (systemd would start them);" \
        "PUNCHSWEEP_TEST_SLURM=1 installs them for tests/jobs/real_slurm.sh, which skips without them" >&2
    fi
    ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# The explorer page's browser tests drive Debian's chromium with playwright-core (npm; it
# downloads no browser), pinned in tests/browser/package-lock.json. Without it those tests
# skip and say why; nothing else needs it.
browser_tests() {
  local dir
  dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/browser"
  if [ -d "$dir/node_modules/playwright-core" ]; then return 0; fi
  if ! command -v npm >/dev/null 2>&1 && [ "$(id -u)" -eq 0 ]; then
    apt-get install -y -qq --no-install-recommends npm >/dev/null 2>&1 || true
  fi
  if ! command -v npm >/dev/null 2>&1; then
    echo "install-deps: no npm (Debian's nodejs comes without it: apt-get install npm); the browser tests will skip" >&2
    return 0
  fi
  echo "install-deps: npm ci in tests/browser (playwright-core)"
  (cd "$dir" && timeout 300 npm ci --no-audit --no-fund --silent) ||
    echo "install-deps: npm ci failed (no registry?); the browser tests will skip" >&2
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  browser_tests
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else
    echo "install-deps: missing packages (${missing[*]}) and not root; install them with apt-get" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
browser_tests
