#!/usr/bin/env bash
# How soon a camera drag's full-size image reaches the screen in the editor, per renderer
# (docs/accuracy.md, "Speed: in the editor"). Runs build/src/editor/ui/gloss under xvfb-run on a
# scene with a generated script: for each of `renderer cpu`, `gl` and `auto`, two orbit drags of
# 20 `mouse move` steps 50 ms apart, each followed by `stats` (edit_to_first_image_ms and
# edit_to_full_image_ms of the drag's last step, the UI frame times) and, in Automatic, which
# renderer it chose and the figures it compared.
#   scripts/measure_drag.sh [BUILD_DIR] [SCENE] [WINDOW_WIDTH WINDOW_HEIGHT]
set -euo pipefail
build=${1:-build}
scene=${2:-assets/scenes/cornell-teapot.json}
width=${3:-1600}
height=${4:-1000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for renderer in cpu gl auto; do
  script=$out/drag-$renderer.txt
  {
    echo "renderer $renderer"
    echo "wait"
    for drag in 1 2; do
      echo "mouse press 0.5 0.5"
      for step in $(seq 1 20); do
        echo "mouse move 0.$((50 + step)) 0.5"
        echo "sleep 0.05"
      done
      echo "stats"
      echo "mouse release"
      echo "wait"
    done
    echo "quit"
  } > "$script"
  echo "renderer $renderer:"
  XDG_CONFIG_HOME=$out/config XDG_STATE_HOME=$out/state \
    xvfb-run -a -s "-screen 0 ${width}x${height}x24" "$build/src/editor/ui/gloss" --no-recovery \
    --window-width "$width" --window-height "$height" --script "$script" "$scene" |
    sed -n 's/^stats: ui_frame_ms avg=\([0-9.]*\).*edit_to_first_image_ms=\([0-9.]*\) edit_to_full_image_ms=\([0-9.]*\) | pass=[0-9]* spp=[0-9/]* size=\([0-9x]*\).* renderer=\([a-z]*\)\(.*\)/  drag: edit->first image \2 ms, edit->full-size image \3 ms, UI frame avg \1 ms, shown frame \4, drawn by \5\6/p'
done
