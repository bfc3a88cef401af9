#!/usr/bin/env bash
# One command per result figure of the AnimationPak paper (docs/gallery.md): packs the figure's scene into
# out/paper/FIGURE/ (80 frames, so that the paper's times t = 0, 0.125, … 0.5 are frames 0, 10, … 40),
# writes its report page, and draws the frames at the paper's times side by side into
# docs/images/gallery/FIGURE.png, the picture the gallery shows.
#
#   bash examples/paper/make.sh fig13            # one figure
#   bash examples/paper/make.sh fig16            # Fig. 1 beside Fig. 16b, and one fish's path in both
#   bash examples/paper/make.sh fig11 --redraw   # the report and picture again from the packing there
#   bash examples/paper/make.sh all              # every figure, one after another (hours on two cores)
#
# ANIMPAK names the animpak executable (default build/release/animpak, built by scripts/quickstart.sh);
# extra arguments after the figure go to `animpak pack` (e.g. --device reference, --max-iterations 500).
set -euo pipefail
cd "$(dirname "$0")/../.."
animpak=${ANIMPAK:-build/release/animpak}
if [ $# -lt 1 ]; then
  sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'
  echo "figures: fig1 fig11 fig12 fig13 fig14 fig16a fig16b fig16 fig17, or all" >&2
  exit 1
fi
[ -x "$animpak" ] || { echo "make.sh: $animpak not found; run bash scripts/quickstart.sh first (or set ANIMPAK)" >&2; exit 2; }
command -v ffmpeg >/dev/null || { echo "make.sh: ffmpeg not found; run bash scripts/install-deps.sh" >&2; exit 2; }

# The scene of each figure and the frames (of 80) at the paper's times.
scene_of() {
  case "$1" in
    fig1|fig16a) echo examples/aquatic-loop/scene.json ;;
    fig11) echo examples/paper/fig11-snake-bird.json ;;
    fig12) echo examples/paper/fig12-penguins.json ;;
    fig13) echo examples/paper/fig13-heart-stars.json ;;
    fig14) echo examples/paper/fig14-mane-mirror.json ;;
    fig16b) echo examples/paper/fig16b-weak-time-springs.json ;;
    fig17) echo examples/paper/fig17-blender.json ;;
    *) return 1 ;;
  esac
}
frames_of() {
  case "$1" in
    fig11) echo "0 20 40" ;;        # t = 0, 0.25, 0.5: the chase a quarter turn at a time
    fig12) echo "0 10 20 30 40" ;;  # t = 0, 0.125, 0.25, 0.375, 0.5
    fig13) echo "0 40" ;;           # t = 0 and 0.5
    fig17) echo "0 10 20 30" ;;     # an eighth of the beam's turn apart
    *) echo "0" ;;                  # the first frame
  esac
}

make_figure() {
  local figure=$1
  shift
  local scene
  scene=$(scene_of "$figure") || { echo "make.sh: unknown figure $figure" >&2; exit 1; }
  local out=out/paper/$figure
  local start=$SECONDS
  if [ "${1:-}" = --redraw ]; then
    [ -f "$out/state.bin" ] || { echo "make.sh: $out holds no packing to redraw; run make.sh $figure" >&2; exit 1; }
    echo "make.sh: $figure: redrawing from $out" >&2
  else
    echo "make.sh: $figure: packing $scene into $out" >&2
    "$animpak" pack "$scene" --out "$out" --force --frames 80 --size 480 --format png,gif,svg-anim "$@"
  fi
  "$animpak" report "$out"
  mkdir -p docs/images/gallery
  local inputs=() filter="" n=0
  for f in $(frames_of "$figure"); do
    inputs+=(-i "$(printf '%s/frames/frame_%04d.png' "$out" "$f")")
    filter+="[$n:v]scale=-2:240[v$n];"
    n=$((n + 1))
  done
  if [ "$n" -gt 1 ]; then
    for ((k = 0; k < n; k++)); do filter+="[v$k]"; done
    filter+="hstack=inputs=$n"
  else
    filter+="[v0]null"
  fi
  ffmpeg -nostdin -hide_banner -loglevel error -y "${inputs[@]}" -filter_complex "$filter" -frames:v 1 \
    "docs/images/gallery/$figure.png"
  echo "make.sh: $figure: done in $((SECONDS - start)) s: $out/report.html, docs/images/gallery/$figure.png" >&2
}

# Fig. 16: the Fig. 1 scene (a) beside the same with time springs 1 % as stiff (b), each packed unless its
# folder holds a packing already; frame 0 of each side by side, and the spacetime path of one fish in both
# (`animpak trajectory`), the paper's Fig. 16c.
fig16_fish=fish#10
make_fig16() {
  for figure in fig1 fig16b; do
    [ -f "out/paper/$figure/state.bin" ] || make_figure "$figure" "$@"
  done
  ffmpeg -nostdin -hide_banner -loglevel error -y -i out/paper/fig1/frames/frame_0000.png \
    -i out/paper/fig16b/frames/frame_0000.png -filter_complex "[0:v]scale=-2:320[a];[1:v]scale=-2:320[b];[a][b]hstack=inputs=2" \
    -frames:v 1 docs/images/gallery/fig16.png
  "$animpak" trajectory out/paper/fig1 out/paper/fig16b --element "$fig16_fish" \
    --out docs/images/gallery/fig16-trajectory.svg
  echo "make.sh: fig16: docs/images/gallery/fig16.png, docs/images/gallery/fig16-trajectory.svg" >&2
}

if [ "$1" = all ]; then
  shift
  for figure in fig1 fig11 fig12 fig13 fig14 fig16b fig17; do make_figure "$figure" "$@"; done
  make_fig16 "$@"
elif [ "$1" = fig16 ]; then
  shift
  make_fig16 "$@"
else
  make_figure "$@"
fi
