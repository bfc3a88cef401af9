#!/usr/bin/env bash
# Runs a command on Oclgrind (Debian's `oclgrind`), the OpenCL implementation that simulates a device
# and checks every memory access: registers it beside the system's OpenCL vendors the way a user would
# (a vendors folder through OCL_ICD_VENDORS; /etc/OpenCL/vendors is left alone), turns on its API,
# data-race and uninitialized-value checks (its out-of-bounds checks are always on), and fails when it
# reports anything, naming each kernel it reported and what it found there. The command passing is not
# enough: a read past a buffer returns a value and the equivalence tests may still pass.
# ANIMPAK_TEST_DEVICE defaults to oclgrind, so the equivalence suite tests Oclgrind alone.
# Usage: scripts/oclgrind-check.sh COMMAND [ARGS...]   (docs/testing.md)
# Exit status: the command's when it failed, else 1 when Oclgrind reported a fault, else 0; 77 (ctest's
# SKIP_RETURN_CODE) when Oclgrind is not installed, 1 then under CI=true, where nothing may skip
# (docs/testing.md, "Skipped tests"). OCLGRIND_ICD names its liboclgrind-rt-icd.so.
set -uo pipefail

icd="${OCLGRIND_ICD:-}"
if [ -z "$icd" ]; then
  for candidate in /usr/lib/oclgrind/liboclgrind-rt-icd.so /usr/local/lib/liboclgrind-rt-icd.so; do
    if [ -f "$candidate" ]; then icd="$candidate" && break; fi
  done
fi
if [ -z "$icd" ] || [ ! -f "$icd" ]; then
  echo "oclgrind-check: skipped: Oclgrind is not installed (no liboclgrind-rt-icd.so; scripts/install-deps.sh" \
    "installs it, OCLGRIND_ICD names one elsewhere)"
  [ "${CI:-}" = true ] && exit 1
  exit 77
fi

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/vendors"
cp "${OCL_ICD_VENDORS:-/etc/OpenCL/vendors}"/*.icd "$scratch/vendors/" 2>/dev/null
echo "$icd" >"$scratch/vendors/oclgrind.icd"
export OCL_ICD_VENDORS="$scratch/vendors"
export ANIMPAK_TEST_DEVICE="${ANIMPAK_TEST_DEVICE:-oclgrind}"
# Every second seed of the suite's random worlds: the same kernel code, checked access by access, in
# half the time (the full set runs on PoCL, where the numbers are compared).
export ANIMPAK_EQUIVALENCE_SEED_STRIDE="${ANIMPAK_EQUIVALENCE_SEED_STRIDE:-2}"
export OCLGRIND_CHECK_API=1 OCLGRIND_DATA_RACES=1 OCLGRIND_UNINITIALIZED=1

# Oclgrind writes its reports to stderr and the tests write nothing there: keep it apart to judge it.
"$@" 2>"$scratch/stderr"
status=$?
head -n 200 "$scratch/stderr" >&2
lines=$(wc -l <"$scratch/stderr")
[ "$lines" -le 200 ] || echo "oclgrind-check: ($((lines - 200)) more lines of stderr not shown)" >&2
if [ -s "$scratch/stderr" ]; then
  # A report is a blank line, one line saying what happened ("Invalid read of size 4 at global memory
  # address 0x..."), then tab-indented details, the first "Kernel: NAME" (or "Function: clCALL" for an
  # API error). Listed once per kernel and kind, addresses dropped.
  echo "oclgrind-check: FAIL: Oclgrind (or the command) wrote to stderr; Oclgrind's reports by kernel:"
  awk '/^$/ { fresh = 1; next }
       fresh && !/^\t/ { what = $0; sub(/ (at |to |from )?(global|local|private|constant) memory address.*/, "", what)
                         fresh = 0; pending = 1; next }
       pending && /^\tKernel: / { n["kernel " substr($0, 10) ": " what]++; pending = 0 }
       pending && /^\tFunction: / { n["API call " substr($0, 12) ": " what]++; pending = 0 }
       END { for (k in n) printf "  %s (%d times)\n", k, n[k] }' "$scratch/stderr" | sort
  [ "$status" -ne 0 ] || status=1
fi
exit "$status"
