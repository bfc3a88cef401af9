#!/usr/bin/env bash
# README quick start, command 1: installs what is missing, builds, and packs the default example to a
# finished animation in out/default/ (animation.gif, frames/, state.bin, stats.json, input/). Running it
# again packs anew: out/default is this script's own folder, so it passes --force.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release -DCMAKE_UNITY_BUILD=ON >/dev/null  # as scripts/test.sh: half the build time
cmake --build --preset release
./build/release/animpak pack examples/default/scene.json --out out/default --force --frames 60 --size 400
echo "quickstart: the animation is out/default/animation.gif"
