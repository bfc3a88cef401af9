#!/usr/bin/env bash
# Packs every example with one animpak-solve binary and keeps each state.bin, so that two builds can be
# compared byte for byte: a change meant to leave the packing alone (a rename, a move, a refactor) must
# write the same bytes on the reference and on every OpenCL device.
#
#   scripts/state-identity.sh BINARY OUT_DIR [ITERATIONS] [DEVICES]
#
# ITERATIONS caps each pack (default 400; "full" packs to the stop), DEVICES is a space-separated list
# (default "reference pocl"). Compare two runs with `cmp` or `scripts/state-identity.sh --compare A B`.
# OUT_DIR must lie at the same depth for both runs: state.bin records the scene's path relative to it.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "${1:-}" = "--compare" ]; then
  [ $# -eq 3 ] || { echo "usage: $0 --compare DIR_A DIR_B" >&2; exit 1; }
  status=0
  for a in "$2"/*/state.bin; do
    name=$(basename "$(dirname "$a")")
    b="$3/$name/state.bin"
    if [ ! -f "$b" ]; then echo "$name: missing in $3"; status=1
    elif cmp -s "$a" "$b"; then echo "$name: identical ($(stat -c %s "$a") bytes)"
    else echo "$name: DIFFERENT"; status=1
    fi
  done
  exit $status
fi

[ $# -ge 2 ] || { echo "usage: $0 BINARY OUT_DIR [ITERATIONS] [DEVICES]" >&2; exit 1; }
binary=$(realpath "$1")
out=$2
iterations=${3:-400}
devices=${4:-reference pocl}
mkdir -p "$out"
cap=()
[ "$iterations" = full ] || cap=(--max-iterations "$iterations")
for scene in examples/*/scene.json; do
  example=$(basename "$(dirname "$scene")")
  for device in $devices; do
    dir="$out/$example-$device"
    rm -rf "$dir"
    start=$SECONDS
    "$binary" pack "$scene" --out "$dir" --device "$device" "${cap[@]}" >"$dir.log" 2>&1 ||
      { echo "$example on $device: pack failed, see $dir.log" >&2; exit 1; }
    echo "$example on $device: $(stat -c %s "$dir/state.bin") bytes in $((SECONDS - start)) s"
  done
done
