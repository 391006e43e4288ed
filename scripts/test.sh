#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (ctest) on the OpenCL devices
# present (PoCL's CPU device on a machine without a GPU), then fuzzes the scene loader for a
# bounded time ($GDR_FUZZ_SECONDS, default 40; 0 skips it).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
(cd build && ctest --output-on-failure --timeout 900 -j "$(nproc)")
fuzz_seconds=${GDR_FUZZ_SECONDS:-40}
if [ "$fuzz_seconds" -gt 0 ]; then
  scripts/fuzz "$fuzz_seconds"
fi
