#!/usr/bin/env bash
# Installs what is missing, builds, and renders the default scene to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
mkdir -p out
build/gdrender scenes/cornell-box.xml --spp 64 -o out/cornell-box.exr --stats out/cornell-box.stats.json "$@"
echo "demo: wrote out/cornell-box.exr, out/cornell-box.png and out/cornell-box.stats.json"
