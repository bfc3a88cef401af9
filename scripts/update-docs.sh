#!/usr/bin/env bash
# Rewrites the parts of docs/ that animpak prints from its own tables: the parameter table of
# docs/parameters.md (`animpak params --markdown`) and docs/scene.schema.json (`animpak schema`).
# The ctest tests `docs: ...` fail until this has been run after a change to those tables.
# Usage: scripts/update-docs.sh [ANIMPAK]   (default: build/release/animpak-solve, built first)
set -euo pipefail
cd "$(dirname "$0")/.."
animpak=${1:-build/release/animpak-solve}
if [ $# -eq 0 ]; then
  cmake --build build/release --target animpak-solve
fi
python3 tests/docs/generated_docs.py update "$animpak" . params schema
