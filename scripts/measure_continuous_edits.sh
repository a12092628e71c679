#!/usr/bin/env bash
# How often new images reach the screen while edits keep coming (docs/editor.md, "Continuous
# edits"): build/src/editor/ui/gloss under xvfb-run orbits the light for 4 s, then drags a
# slider by script (`set 0 shininess` lines 16 ms apart) for 2 s, each window ended by `stats`
# (new images, the largest and the median gap between them, the edits' delays), with BUSY
# CPU-bound processes (`sh -c 'while :; do :; done'`) started beside it and stopped after.
#   scripts/measure_continuous_edits.sh [BUILD_DIR] [SCENE] [BUSY] [WINDOW_WIDTH WINDOW_HEIGHT]
set -euo pipefail
build=${1:-build}
scene=${2:-assets/scenes/spheres.json}
busy=${3:-2}
width=${4:-1600}
height=${5:-1000}
out=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  rm -rf "$out"
}
trap cleanup EXIT
{
  echo "wait"
  echo "animate on"
  echo "sleep 1"
  echo "stats"  # the window starts here
  echo "sleep 4"
  echo "stats"
  echo "animate off"
  echo "wait"
  echo "stats"
  for step in $(seq 0 124); do
    echo "set 0 shininess $((20 + step))"
    echo "sleep 0.016"
  done
  echo "stats"
  echo "quit"
} > "$out/script.txt"
for _ in $(seq 1 "$busy"); do
  sh -c 'while :; do :; done' &
  pids+=($!)
done
echo "$busy busy processes; load: $(cut -d' ' -f1-3 /proc/loadavg); compilers running: $(pgrep -c cc1plus || true)"
XDG_CONFIG_HOME=$out/config XDG_STATE_HOME=$out/state \
  xvfb-run -a -s "-screen 0 ${width}x${height}x24" "$build/src/editor/ui/gloss" --no-recovery \
  --window-width "$width" --window-height "$height" --script "$out/script.txt" "$scene" |
  grep '^stats:' | sed -n '2p;4p' |
  sed 's/^stats: ui_frame_ms avg=\([0-9.]*\) median=\([0-9.]*\).*window_s=\([0-9.]*\) new_images=\([0-9]*\) image_gap_ms max=\([0-9.]*\) median=\([0-9.]*\) | edit_delay_ms median=\([0-9.]*\) max=\([0-9.]*\).*/  \3 s: \4 new images, gap max \5 ms median \6 ms, edit delay median \7 ms max \8 ms, UI frame median \2 ms/' |
  paste -d'\n' <(printf '  orbiting light:\n  shininess drag:\n') -
