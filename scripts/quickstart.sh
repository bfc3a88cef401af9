#!/usr/bin/env bash
# README quick start, command 1: installs what is missing, builds, and runs the default example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
./build/release/animpak inspect examples/default/scene.json --out out/default
echo "quickstart: pictures in out/default/"
