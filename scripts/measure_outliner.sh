#!/usr/bin/env bash
# The editor's UI frame with an outliner of 200 objects (issue 24, Speed): a generated scene of
# 100 spheres, 60 boxes and 40 teapots on a floor, object 0 at the camera target (the image's
# centre, where its gizmo's centre disc is), under xvfb-run at 1600 x 900. Phases, each ending in
# a `stats` line: settle, idle (sleep 4), an orbit drag of the camera (a mouse drag from the
# image's corner, 120 moves 16 ms apart), and with GIZMO=1 a gizmo drag of object 0 (the same
# moves from its centre disc). Prints the medians of the UI frame per phase.
#   scripts/measure_outliner.sh [BUILD_DIR] [GIZMO=1|0]
set -euo pipefail
build=${1:-build}
gizmo=${2:-1}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 - "$out/outliner200.json" <<'PY'
import json, sys
objects, materials = [], {}
presets = ["gold", "silver", "copper", "jade", "ruby", "pearl", "chrome", "brass"]
for p in presets:
    materials[p] = {"preset": p}
materials["floor"] = {"diffuse": [0.5, 0.5, 0.5]}
for i in range(200):
    x, z = (i % 20 - 9.5) * 1.2, (i // 20 - 4.5) * 1.2
    m = presets[i % len(presets)]
    name = "object%03d" % i
    if i < 100:
        objects.append({"type": "sphere", "name": name, "center": [x, 0.4, z], "radius": 0.4,
                        "material": m})
    elif i < 160:
        objects.append({"type": "box", "name": name, "min": [x - 0.35, 0, z - 0.35],
                        "max": [x + 0.35, 0.7, z + 0.35], "material": m})
    else:
        objects.append({"type": "teapot", "name": name, "position": [x, 0, z], "scale": 0.12,
                        "tessellation": 4, "material": m})
objects.append({"type": "quad", "name": "floor", "material": "floor",
                "vertices": [[-14, 0, -8], [14, 0, -8], [14, 0, 8], [-14, 0, 8]]})
first = objects[0]["center"]
scene = {"camera": {"eye": [first[0], 6, first[2] + 9], "target": first, "fov_y": 45},
         "lights": [{"position": [4, 10, 8]}], "materials": materials, "objects": objects,
         "render": {"width": 640, "height": 480, "spp": 1}}
json.dump(scene, open(sys.argv[1], "w"))
PY
{
  echo "wait"; echo "sleep 2"; echo "stats"
  echo "sleep 4"; echo "stats"
  for start in corner gizmo; do
    [ "$start" = gizmo ] && [ "$gizmo" != 1 ] && continue
    if [ "$start" = corner ]; then x0=0.05; y0=0.95; else x0=0.5; y0=0.5; echo "select 0"; fi
    echo "wait"; echo "sleep 1"; echo "stats"
    echo "mouse press $x0 $y0"
    for step in $(seq 1 120); do
      echo "mouse move $(awk "BEGIN { printf \"%.4f\", $x0 + 0.0015 * $step }") $y0"
      echo "sleep 0.016"
    done
    echo "stats"; echo "mouse release"
  done
  echo "quit"
} > "$out/script.txt"
XDG_CONFIG_HOME=$out/config XDG_STATE_HOME=$out/state XDG_DATA_HOME=$out/data \
  xvfb-run -a -s "-screen 0 1600x900x24" "$build/src/editor/ui/gloss" --no-recovery \
  --window-width 1600 --window-height 900 --script "$out/script.txt" "$out/outliner200.json" |
  grep '^stats:' | sed -n 's/^stats: ui_frame_ms avg=\([0-9.]*\) median=\([0-9.]*\) max=\([0-9.]*\).*/median \2 ms (avg \1, max \3)/p' |
  paste -d' ' <(printf '%s\n' settle idle settle orbit-drag settle gizmo-drag) -
