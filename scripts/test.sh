#!/usr/bin/env bash
# The whole test suite, from a clean clone: installs what is missing, builds the release and the
# sanitizer (ASan + UBSan) builds, and runs every test in both. README quick start, command 2.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
for preset in release debug; do
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset"
done
