#!/usr/bin/env bash
# Checks cmake/Commit.cmake, which records the commit that stats.json and --version name: in a scratch
# git repository it must write the abbreviated hash, add "-dirty" while a tracked file has uncommitted
# changes, follow a new commit, leave the output untouched when nothing changed (so a rebuild compiles
# nothing for it), and write "unknown" outside a repository.
# Usage: commit-recorded.sh SOURCE_DIR CMAKE   (a ctest test; 77 = skipped without git, a failure
# instead under CI=true: docs/testing.md, "Skipped tests")
set -uo pipefail
script="$1/cmake/Commit.cmake"
cmake="$2"
command -v git > /dev/null || { echo "git not found: skipped"; [ "${CI:-}" = true ] && exit 1; exit 77; }
scratch="$(mktemp -d)"
export GIT_CEILING_DIRECTORIES="$scratch"  # "outside a repository" even when TMPDIR lies in one
trap 'rm -rf "$scratch"' EXIT
repo="$scratch/repo"
out="$scratch/build_commit.cpp"
status=0

record() { "$cmake" "-DSOURCE_DIR=$1" "-DOUTPUT=$out" -P "$script" || { echo "FAIL: cmake -P $script"; exit 1; }; }
expect() {  # expect WHAT VALUE
  if grep -qF "return \"$2\";" "$out"; then echo "ok: $1 ($2)"; else
    echo "FAIL: $1: expected \"$2\", got: $(grep return "$out")"; status=1; fi
}
commit() { git -C "$repo" -c user.name=animpak -c user.email=animpak@invalid commit -q -am "$1"; }

mkdir "$repo"
git -C "$repo" init -q
echo one > "$repo/file"
git -C "$repo" add file
commit first
record "$repo"
expect "a clean tree" "$(git -C "$repo" rev-parse --short=7 HEAD)"
first_hash="$(git -C "$repo" rev-parse --short=7 HEAD)"

echo two > "$repo/file"
record "$repo"
expect "a changed tracked file" "$first_hash-dirty"

echo untracked > "$repo/other"
git -C "$repo" checkout -q -- file
record "$repo"
expect "an untracked file only" "$first_hash"

echo three > "$repo/file"
commit second
record "$repo"
second_hash="$(git -C "$repo" rev-parse --short=7 HEAD)"
[ "$second_hash" != "$first_hash" ] || { echo "FAIL: the scratch commits share a hash"; status=1; }
expect "a new commit" "$second_hash"

touch -d '2000-01-01' "$out"
record "$repo"
if [ "$(stat -c %Y "$out")" = "$(date -d '2000-01-01' +%s)" ]; then echo "ok: unchanged output not rewritten"; else
  echo "FAIL: the output was rewritten although the commit is the same"; status=1; fi

mkdir "$scratch/plain"
record "$scratch/plain"
expect "outside a repository" "unknown"
exit $status
