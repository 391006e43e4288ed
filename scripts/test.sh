#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (ctest) on the OpenCL devices
# present (PoCL's CPU device on a machine without a GPU).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
cd build
ctest --output-on-failure --timeout 900 -j "$(nproc)"
