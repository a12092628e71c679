#!/usr/bin/env bash
# Kills gloss-cli renders with SIGKILL while they write their outputs and counts what is left in
# the output folder besides finished files: temporaries that outlived their process.
# Usage: scripts/measure_kill_debris.sh GLOSS_CLI [RUNS=30] [MAX_DELAY_MS=1500]
#        [SCENE=assets/scenes/spheres.json]
# Each run renders 4096x4096 to a PNG and a 201 MB PFM; once the process holds a file open in
# the output folder (it is writing), it is killed after a random 0 to MAX_DELAY_MS ms, which
# spans the PNG's encoding and the PFM's write.
set -u
cli=$1
runs=${2:-30}
max_delay_ms=${3:-1500}
scene=${4:-"$(dirname "$0")/../assets/scenes/spheres.json"}
out=$(mktemp -d /tmp/gloss-kill-XXXXXX)
killed_writing=0
for ((i = 0; i < runs; i++)); do
  "$cli" render "$scene" --width 4096 --height 4096 -o "$out/r$i.png" --pfm "$out/r$i.pfm" \
    >/dev/null 2>&1 &
  pid=$!
  writing=0
  for ((t = 0; t < 3000; t++)); do  # up to 30 s
    if ls -l "/proc/$pid/fd" 2>/dev/null | grep -q "$out"; then writing=1; break; fi
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
  done
  if ((writing)); then
    delay=$((RANDOM % (max_delay_ms + 1)))
    sleep "$((delay / 1000)).$(printf '%03d' $((delay % 1000)))"
    killed_writing=$((killed_writing + 1))
  fi
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
done
left=$(find "$out" -name '.*tmp-*' | wc -l)
bytes=$(find "$out" -name '.*tmp-*' -printf '%s\n' | awk '{s += $1} END {print s + 0}')
finished=$(find "$out" -name 'r*.p?m' -o -name 'r*.png' | wc -l)
echo "runs $runs, killed while writing $killed_writing, leftover temporaries $left" \
  "($((bytes / 1000000)) MB), finished outputs $finished"
rm -rf "$out"
