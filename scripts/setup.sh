#!/usr/bin/env bash
# Installs gdrender's dependencies from Debian's packages (only those missing) and builds it.
# Idempotent; uses sudo only when not root. Usage: scripts/setup.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}

packages=(
  build-essential cmake ninja-build pkg-config
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers clinfo
  libembree-dev libtbb-dev libopenimageio-dev openimageio-tools
  libpugixml-dev libtinyobjloader-dev libcli11-dev nlohmann-json3-dev zlib1g-dev
  libgtest-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
  clang libclang-rt-14-dev python3-venv
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# MPI is optional to gdrender but not here: the build this script makes renders across machines,
# and its test suite runs the MPI tests.
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGDR_REQUIRE_MPI=ON
cmake --build "$build_dir"
