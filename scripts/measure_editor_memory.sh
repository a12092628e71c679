#!/usr/bin/env bash
# Resident memory of the editor on the default scene during a minute of edits (docs/editor.md,
# "Memory"). Runs build/src/editor/ui/gloss under xvfb-run with a generated script of edits
# (material, shininess, light, camera, presets, view modes, spp), samples VmRSS/VmHWM from
# /proc/PID/status every 0.5 s, and prints the settled and peak figures in MB.
#   scripts/measure_editor_memory.sh [BUILD_DIR] [LABEL] [memory|plain]
# plain: leave out the `memory` script lines (for editors built before they existed). The
# environment passes through (GLIBC_TUNABLES ...).
set -euo pipefail
build=${1:-build}
label=${2:-run}
memory_line=memory
[ "${3:-memory}" = plain ] && memory_line="# memory"
out=$(mktemp -d)
script=$out/edits.txt
{
  echo "wait"
  echo "sleep 2"
  echo "$memory_line"
  for i in $(seq 0 39); do
    g=$(awk -v i="$i" 'BEGIN { printf "%.3f", 0.2 + 0.015 * i }')
    echo "set 0 diffuse $g 0.4 0.2"
    echo "sleep 0.3"
    echo "set 1 shininess $((20 + 5 * i))"
    echo "sleep 0.3"
    echo "light 0 position $((3 + i % 5)) 7 6"
    echo "sleep 0.3"
    echo "camera orbit 4 0"
    echo "sleep 0.3"
    case $((i % 10)) in
      2) echo "view terms" ;;
      4) echo "view ab" ;;
      6) echo "view render" ;;
      7) echo "preset 0 $([ $((i % 20)) = 7 ] && echo copper || echo gold)" ;;
      8) echo "spp 16" ;;
      9) echo "spp 1" ;;
    esac
  done
  echo "view render"
  echo "wait"
  echo "sleep 3"
  echo "$memory_line"
  echo "quit"
} >"$script"
GLOSS_ASSETS=${GLOSS_ASSETS:-$PWD/assets} xvfb-run -a -s "-screen 0 1600x900x24" \
  "$build/src/editor/ui/gloss" --no-recovery --script "$script" >"$out/stdout" 2>&1 &
sleep 1
pid=""
for _ in $(seq 1 40); do
  pid=$(pgrep -n -x gloss -P "$(pgrep -n -f "xvfb-run.*$script" || echo 1)" 2>/dev/null || true)
  [ -z "$pid" ] && pid=$(pgrep -n -f "ui/gloss --no-recovery --script $script" || true)
  [ -n "$pid" ] && break
  sleep 0.25
done
start=$(date +%s.%N)
peak=0
last=0
while kill -0 "$pid" 2>/dev/null; do
  rss=$(awk '/^VmRSS/ {print $2}' /proc/"$pid"/status 2>/dev/null || echo 0)
  hwm=$(awk '/^VmHWM/ {print $2}' /proc/"$pid"/status 2>/dev/null || echo 0)
  [ -n "$rss" ] && [ "$rss" != 0 ] && last=$rss && peak=$hwm
  t=$(awk -v s="$start" -v n="$(date +%s.%N)" 'BEGIN { printf "%.1f", n - s }')
  echo "$t $rss $hwm" >>"$out/samples"
  # The end state: mappings by kind, for the attribution (before the process quits).
  [ -r /proc/"$pid"/smaps ] && cp /proc/"$pid"/smaps "$out/smaps" 2>/dev/null || true
  sleep 0.5
done
wait || true
grep '^memory:' "$out/stdout" || true
echo "$label: settled VmRSS $((last / 1024)) MB, VmHWM $((peak / 1024)) MB ($out)"
