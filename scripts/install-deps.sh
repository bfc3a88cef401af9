#!/usr/bin/env bash
# Installs every dependency animpak needs from Debian 12 packages. Idempotent: packages already present
# are left alone, and apt is not touched at all when nothing is missing. Runs as root or through sudo,
# never asks a question (CI has no standard input).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git clang-format
  # OpenCL: C headers, C++ bindings, ICD loader, the PoCL CPU device, clinfo for diagnosis, and the
  # Oclgrind simulator that checks the kernels (scripts/oclgrind-check.sh; it registers no ICD itself)
  opencl-headers opencl-clhpp-headers ocl-icd-opencl-dev pocl-opencl-icd clinfo oclgrind
  # geometry and maths
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libpolyclipping-dev
  # input: SVG (svgpp over libxml2), JSON, command line
  libsvgpp-dev libxml2-dev nlohmann-json3-dev libcli11-dev
  # output: vector rasterisation, image files, video
  libcairo2-dev libopenimageio-dev ffmpeg
  # the deflate of the dotLottie container (animation.lottie, a zip)
  zlib1g-dev
  # tests: Catch2 v2, the real-world SVG test bed, and rsvg-convert, the renderer `animpak check --png` is held to;
  # rlottie and Chromium, the players the Lottie and animated SVG exports are held to; python3-jsonschema,
  # the validator the example scenes are held to against docs/scene.schema.json
  catch2 openclipart-svg librsvg2-bin librlottie-dev chromium python3-jsonschema
)
# With --tests (scripts/test.sh), also what only the test suite needs: a real single-node Slurm
# (controller, node daemon, client commands, and munge, its authentication) that the sweep test submits an
# array job to. tests/sweep/slurm.sh starts and stops the daemons itself, with its own slurm.conf; the
# packages' own services are kept from starting while they install (policy-rc.d), so a workstation that
# runs the tests gets no scheduler running in the background.
test_packages=(slurmctld slurmd slurm-client munge)
tests=0
if [ "${1:-}" = "--tests" ]; then
  tests=1
  packages+=("${test_packages[@]}")
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: error: not root and no sudo; run as root" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
policy=/usr/sbin/policy-rc.d
if [ "$tests" -eq 1 ] && [ ! -e "$policy" ]; then
  # 101: "action not allowed" to invoke-rc.d and deb-systemd-invoke: installed services are not started.
  printf '#!/bin/sh\nexit 101\n' | "${sudo_cmd[@]}" tee "$policy" >/dev/null
  "${sudo_cmd[@]}" chmod 755 "$policy"
  trap '"${sudo_cmd[@]}" rm -f "$policy"' EXIT
fi
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
