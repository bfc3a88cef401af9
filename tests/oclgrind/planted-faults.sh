#!/usr/bin/env bash
# Proves that scripts/oclgrind-check.sh catches what it is for: plants one fault at a time in a copy of
# the kernels (loaded through ANIMPAK_KERNEL_DIR), runs one small equivalence test on Oclgrind through
# the check, and expects it to fail naming the kernel and the fault. The faults are ones the equivalence
# tests alone miss (the planted runs pass them): a read one element past a buffer, a read of a private
# value never written, and the grid sort's scatter claiming slots without its atomic.
# Usage: planted-faults.sh SOURCE_DIR TEST_EQUIVALENCE   (a ctest test; 77 = skipped, as the check)
set -uo pipefail
source_dir="$1"
test_binary="$2"
check="$source_dir/scripts/oclgrind-check.sh"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
status=0

# plant NAME TEST FILE OLD NEW EXPECTED: copies the kernels, replaces the one line OLD of FILE with NEW,
# runs the equivalence TEST and expects the check to report EXPECTED ("kernel NAME: what").
plant() {
  local name="$1" test="$2" file="$3" old="$4" new="$5" expected="$6"
  local dir="$scratch/$name"
  mkdir -p "$dir" && cp "$source_dir"/kernels/* "$dir/"
  if ! OLD="$old" NEW="$new" perl -0pi -e '(s/\Q$ENV{OLD}\E/$ENV{NEW}/g == 1) or die' "$dir/$file"; then
    echo "planted-faults: $name: the line to change is not once in kernels/$file: $old"
    status=1
    return
  fi
  ANIMPAK_KERNEL_DIR="$dir" "$check" "$test_binary" "$test" >"$scratch/$name.log" 2>&1
  local rc=$?
  if [ "$rc" -eq 77 ]; then
    cat "$scratch/$name.log"
    exit 77
  fi
  if [ "$rc" -ne 0 ] && grep -qF "  $expected" "$scratch/$name.log"; then
    echo "planted-faults: $name: reported as expected:"
    grep '^  kernel \|^  API call ' "$scratch/$name.log"
  else
    echo "planted-faults: $name: FAIL: expected the check to fail reporting '$expected'; it exited $rc:"
    tail -n 40 "$scratch/$name.log"
    status=1
  fi
}

# The last triangle reads env_a[triangles], one past the buffer; the value is multiplied by zero so that
# only the check can tell.
plant out-of-bounds "forces: one element alone" grid.cl \
  "  const float pt = (t[a] + t[b] + t[c]) / 3.0f;" \
  "  const float pt = (t[a] + t[b] + t[c] + 0.0f * (float)env_a[i + 1]) / 3.0f;" \
  "kernel envelope_cells: Invalid read of size 4"
# Odd triangles read planted[1], never written (an array, so the compiler cannot fold the read away).
plant uninitialized "forces: one element alone" grid.cl \
  "  const float pt = (t[a] + t[b] + t[c]) / 3.0f;" \
  "  float planted[2];
  planted[0] = 0.0f;
  const float pt = (t[a] + t[b] + t[c] + planted[i & 1]) / 3.0f;" \
  "kernel envelope_cells: Uninitialized value written"
# Two triangles of one cell can read the same cursor and take the same slot. Oclgrind runs work-items
# one at a time, so the sort still comes out right there; the grid test's coarse cells share slots.
plant data-race "grid:*" grid.cl \
  "  sorted_triangles[atomic_inc(&cursor[triangle_cell[i]])] = i;" \
  "  const int slot = cursor[triangle_cell[i]];
  cursor[triangle_cell[i]] = slot + 1;
  sorted_triangles[slot] = i;" \
  "kernel grid_scatter: Write-write data race"
exit "$status"
