#!/usr/bin/env bash
# Drags a control point of the designer's window as a user would, under an X server:
#   design_drag.sh ECOFOREST OUT_DIR GRAPH POINT PIXELS
# opens `ecoforest design beech`, waits for its layout report (ECOFOREST_DESIGN_LAYOUT),
# presses the left button on point POINT of graph GRAPH, moves it PIXELS up in steps, lets
# go, presses Ctrl+S (saving OUT_DIR/dragged.toml) and closes the window.
set -euo pipefail
eco=$1 out=$2 graph=$3 index=$4 pixels=$5
export ECOFOREST_DESIGN_LAYOUT=$out/layout.json
"$eco" design beech --no-row --size 1600x900 --save "$out/dragged.toml" > "$out/design.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
for _ in $(seq 300); do [ -s "$out/layout.json" ] && break; sleep 0.1; done
[ -s "$out/layout.json" ] || { echo "no layout report"; cat "$out/design.log"; exit 1; }
read -r x y < <(python3 -c "import json,sys; p = json.load(open(sys.argv[1]))['graphs'][sys.argv[2]][int(sys.argv[3])]; print(int(round(p[0])), int(round(p[1])))" "$out/layout.json" "$graph" "$index")
window=$(xdotool search --sync --name "ecoforest design")
xdotool windowfocus --sync "$window"
# Each step waits long enough for a frame of llvmpipe: GLFW samples the pointer per frame.
xdotool mousemove "$x" "$y"; sleep 0.4
xdotool mousedown 1; sleep 0.4
for step in 1 2 3 4; do xdotool mousemove "$x" $((y - pixels * step / 4)); sleep 0.3; done
xdotool mouseup 1; sleep 0.4
xdotool key ctrl+s
for _ in $(seq 100); do [ -s "$out/dragged.toml" ] && break; sleep 0.1; done
cat "$out/design.log"
