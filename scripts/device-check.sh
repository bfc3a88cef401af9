#!/usr/bin/env bash
# The OpenCL portability check for one machine, run from the repository root with a bundle made by
# scripts/solver-bundle.sh: registers the NVIDIA OpenCL driver beside the listed vendors when it is
# installed, lists the devices, runs the equivalence suite on every device, validates the default
# example on every device, benchmarks each GPU against the reference, packs the default example's
# first 1,000 steps on the GPU and on the reference and compares the state bytes (the whole pack took
# the reference longer than the device's budget allows), packs the aquatic-loop example (the
# paper's Fig. 1 scale) to its stop on the GPU with --profile (its time and where it goes), and
# validates 1,000 steps of that scene bit for bit against the reference. DEVICE picks the device
# (default nvidia); GRID_SORT the bench's --grid-sort (default both); SKIP_AQUATIC=1 leaves out the
# two aquatic-loop checks.
# Usage: scripts/device-check.sh BUNDLE_DIR OUT_DIR [BENCH_SIZES]
# Writes to OUT_DIR: devices.txt, equivalence.txt, validate.txt, bench.json, bench.txt, pack-gpu/ (the
# reference pack goes to a scratch folder; only the comparison is reported), aquatic-gpu/ (its
# stats.json and state.bin; render it on a machine with the full build), aquatic-gpu.txt (the pack's
# last lines and its profile) and validate-aquatic.txt.
set -uo pipefail
bundle="$(cd "$1" && pwd)"
out="$(mkdir -p "$2" && cd "$2" && pwd)"
sizes="${3:-10000,50000,100000,200000}"
export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# Scratch folders (a PoCL cache unless one is given, the reference pack, the vendor list) go when the
# script ends, however it ends.
temporary=()
# scratch_dir NAME: a new folder in $NAME, removed at exit (not "$(...)": a subshell would lose the list).
scratch_dir() { local d; d="$(mktemp -d)"; temporary+=("$d"); printf -v "$1" '%s' "$d"; }
cleanup() {
  if [ -n "${reference_pack:-}" ]; then kill "$reference_pack" 2>/dev/null; wait "$reference_pack" 2>/dev/null; fi
  if [ -n "${aquatic_validate:-}" ]; then kill "$aquatic_validate" 2>/dev/null; wait "$aquatic_validate" 2>/dev/null; fi
  if [ ${#temporary[@]} -gt 0 ]; then rm -rf "${temporary[@]}"; fi
}
trap cleanup EXIT
if [ -z "${POCL_CACHE_DIR:-}" ]; then scratch_dir POCL_CACHE_DIR; fi
export POCL_CACHE_DIR
solve="$bundle/bin/animpak-solve"
status=0
scratch_dir scratch
note() { printf '\n== %s\n' "$*"; }

# The ICD loader reads one folder of vendor files; make one with the system's vendors plus NVIDIA's.
scratch_dir vendors
cp /etc/OpenCL/vendors/*.icd "$vendors/" 2>/dev/null || true
nvidia_lib="$(ldconfig -p | awk '/libnvidia-opencl\.so\.1/ {print $NF; exit}')"
if [ -n "$nvidia_lib" ] && ! grep -qs nvidia-opencl "$vendors"/*.icd; then echo "$nvidia_lib" >"$vendors/nvidia.icd"; fi
export OCL_ICD_VENDORS="$vendors"
note "OpenCL vendors ($OCL_ICD_VENDORS)"; head -n1 "$vendors"/*.icd

# The reference pack takes minutes on one core: run it beside the checks below (the bench times one
# core at a time, so one more busy core on a many-core machine barely moves its numbers).
"$solve" pack examples/default/scene.json --max-iterations 1000 --device reference --out "$scratch/pack-reference" \
  >"$scratch/pack-reference.log" 2>&1 &
reference_pack=$!
# The 1,000-step validation of the aquatic-loop steps the reference on one core too: beside the rest.
device="${DEVICE:-nvidia}"
if [ "${SKIP_AQUATIC:-0}" != 1 ]; then
  "$solve" validate examples/aquatic-loop/scene.json --device "$device" --steps 1000 >"$out/validate-aquatic.txt" 2>&1 &
  aquatic_validate=$!
fi

note "animpak-solve devices --verbose"
"$solve" devices --verbose 2>&1 | tee "$out/devices.txt" || status=1

note "equivalence suite on every device"
"$bundle/bin/test_equivalence" -r compact -d yes 2>&1 | tee "$out/equivalence.txt"
[ "${PIPESTATUS[0]}" -eq 0 ] || status=1

note "validate examples/default --all-devices --steps 50"
"$solve" validate examples/default/scene.json --all-devices --steps 50 2>&1 | tee "$out/validate.txt"
[ "${PIPESTATUS[0]}" -eq 0 ] || status=1

note "bench --device $device --sizes $sizes --grid-sort ${GRID_SORT:-both}"
"$solve" bench --device "$device" --sizes "$sizes" --steps 20 --warmup 3 --grid-sort "${GRID_SORT:-both}" --json "$out/bench.json" 2>&1 |
  tee "$out/bench.txt"
[ "${PIPESTATUS[0]}" -eq 0 ] || status=1

note "pack examples/default on $device (1,000 steps), and the reference pack started at the beginning"
"$solve" pack examples/default/scene.json --max-iterations 1000 --device "$device" --out "$out/pack-gpu" 2>&1 |
  tail -n 5 || status=1
wait "$reference_pack" || status=1
tail -n 3 "$scratch/pack-reference.log"
if cmp "$out/pack-gpu/state.bin" "$scratch/pack-reference/state.bin"; then
  echo "state.bin: identical ($(stat -c %s "$out/pack-gpu/state.bin") bytes)"
else
  echo "state.bin: DIFFERENT"; status=1
fi

if [ "${SKIP_AQUATIC:-0}" != 1 ]; then
  note "pack examples/aquatic-loop on $device to its stop, --profile"
  "$solve" pack examples/aquatic-loop/scene.json --device "$device" --out "$out/aquatic-gpu" --profile 2>&1 |
    grep -v '^animpak: iter ' | tee "$out/aquatic-gpu.txt"
  [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
  note "validate examples/aquatic-loop --device $device --steps 1000 (started at the beginning)"
  wait "$aquatic_validate" || status=1
  aquatic_validate=
  tail -n 8 "$out/validate-aquatic.txt"
fi
exit "$status"
