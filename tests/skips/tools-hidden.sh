#!/usr/bin/env bash
# The skip convention (docs/testing.md, "Skipped tests") on the test cases that need a tool: run through
# ctest with an empty PATH (no rsvg-convert, chromium or ffmpeg) and ANIMPAK_OPENCLIPART_DIR naming a
# missing folder, ctest must list each of them as skipped and none as passed; with CI=true each must fail.
# The inner ctest reads the build's own test list from a scratch folder, so that its logs stay there.
# Usage: tools-hidden.sh CTEST TESTS_BINARY_DIR   (a ctest test)
set -uo pipefail
ctest="$1"
tests_dir="$2"
# Every test case that needs one of the hidden tools; one renamed or gone changes the count.
cases='openclipart: a sample from every category|svg fidelity: |gif and mp4 through ffmpeg|svg-anim and Chromium: '
expected=4
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/empty-path" "$scratch/run"
echo "include(\"$tests_dir/CTestTestfile.cmake\")" >"$scratch/run/CTestTestfile.cmake"
status=0
fail() { echo "tools-hidden: FAIL: $*"; status=1; }
# hidden [VAR=VALUE...]: the cases with the tools hidden; ctest's output in $scratch/out, its status returned.
hidden() {
  env -u CI "$@" PATH="$scratch/empty-path" ANIMPAK_OPENCLIPART_DIR="$scratch/no-openclipart" \
    "$ctest" --test-dir "$scratch/run" -R "$cases" --output-on-failure >"$scratch/out" 2>&1
}
count() { grep -c -E "$1" "$scratch/out"; }

hidden
cat "$scratch/out"
[ "$(count 'Test +#')" -eq "$expected" ] || fail "ctest ran $(count 'Test +#') test cases, not $expected"
[ "$(count 'Test +#.*\*\*\*Skipped')" -eq "$expected" ] || fail "not every case was reported Skipped"
[ "$(count 'Test +#.* Passed ')" -eq 0 ] || fail "a case passed with its tool hidden"

hidden CI=true
ci_status=$?
cat "$scratch/out"
[ "$ci_status" -ne 0 ] || fail "ctest succeeded under CI=true with the tools hidden"
[ "$(count 'Test +#.*\*\*\*Failed')" -eq "$expected" ] || fail "not every case failed under CI=true"

[ "$status" -eq 0 ] && echo "tools-hidden: every case skipped with its tool hidden, and failed under CI=true"
exit "$status"
