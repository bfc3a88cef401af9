#!/usr/bin/env bash
# Builds the solver-only preset and stages a self-contained solver bundle for a machine that has an
# OpenCL driver but none of our build dependencies (a rented GPU, a cluster node): animpak-solve, the
# equivalence and solver test executables, the examples, and every shared library they need beyond
# glibc and libstdc++ (Clipper, GMP, libxml2 and ICU, the OpenCL ICD loader), stripped.
# Usage: scripts/solver-bundle.sh [BUNDLE_DIR]   (default .gpu-bundle; run scripts/device-check.sh there)
set -euo pipefail
cd "$(dirname "$0")/.."
bundle="${1:-.gpu-bundle}"
cmake --preset solver-only >/dev/null
cmake --build --preset solver-only
rm -rf "$bundle"
mkdir -p "$bundle/bin" "$bundle/lib"
for exe in animpak-solve tests/test_equivalence tests/test_solver; do
  strip -o "$bundle/bin/$(basename "$exe")" "build/solver-only/$exe"
done
# Every library ldd resolves, except the C and C++ runtimes the target system has in a newer version.
ldd "$bundle"/bin/* | awk '/=> \// {print $3}' | sort -u | while read -r lib; do
  case "$(basename "$lib")" in
    libc.so.*|libm.so.*|libstdc++.so.*|libgcc_s.so.*|ld-linux*|libpthread.so.*|libdl.so.*|librt.so.*) ;;
    *) cp -L "$lib" "$bundle/lib/" ;;
  esac
done
du -sh "$bundle"
