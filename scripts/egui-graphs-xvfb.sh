#!/usr/bin/env bash
# Drives the egui_graphs example under Xvfb: waits for the layout to rest, takes a
# screenshot (docs/egui_graphs.png), drags the node farthest from the centre 200 pixels
# outward over 10 frames with xdotool and lets go, waits for rest again, takes a second
# screenshot (docs/egui_graphs_throw.png) and prints what the node did.
#
#   scripts/egui-graphs-xvfb.sh        # needs Xvfb, xdotool and ImageMagick's import
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -p graph-canvas-layout-egui-graphs --example les_miserables
log=target/egui-graphs-xvfb.log   # kept: every frame of the run
Xvfb :97 -screen 0 1024x800x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true' EXIT
sleep 1
DISPLAY=:97 LIBGL_ALWAYS_SOFTWARE=1 target/release/examples/les_miserables --log >"$log" 2>/dev/null &
app=$!
wait_for_rest() {
    for _ in $(seq 1 600); do
        if tail -n 1 "$log" | grep -q "converged true"; then return 0; fi
        sleep 0.1
    done
    echo "the layout did not rest"; exit 1
}
wait_for_rest
sleep 0.5
DISPLAY=:97 import -window root docs/egui_graphs.png
rest=$(tail -n 1 "$log")
echo "at rest:  $rest"
read -r node x y wx wy <<<"$(echo "$rest" | sed -E 's/.*tracked Some\(([0-9]+)\) at ([-0-9.]+) ([-0-9.]+) window ([-0-9]+) ([-0-9]+).*/\1 \2 \3 \4 \5/')"
# The window's origin on the screen.
win=$(DISPLAY=:97 xdotool search --name "graph-canvas-layout in egui_graphs" | head -n 1)
eval "$(DISPLAY=:97 xdotool getwindowgeometry --shell "$win")"
sx=$((X + wx)); sy=$((Y + wy))
# Outward: away from the window's centre, 200 pixels; where the window's edge is nearer
# than that, along whichever axis leads away from the centre with the most room, as far
# as the window allows.
read -r stepx stepy <<<"$(awk -v sx="$wx" -v sy="$wy" -v w="$WIDTH" -v h="$HEIGHT" 'BEGIN {
    dx = sx - w / 2; dy = sy - h / 2; l = sqrt(dx*dx + dy*dy); if (l < 1) { dx = 1; l = 1 }
    ux = dx / l; uy = dy / l; m = 20
    room = 1e9
    if (ux > 0) room = (w - m - sx) / ux; else if (ux < 0) room = (sx - m) / -ux
    if (uy > 0) { r = (h - m - sy) / uy; if (r < room) room = r }
    else if (uy < 0) { r = (sy - m) / -uy; if (r < room) room = r }
    if (room < 200) {
        best = 0
        if (dx >= 0 && w - m - sx > best) { best = w - m - sx; ux = 1; uy = 0 }
        if (dx <= 0 && sx - m > best) { best = sx - m; ux = -1; uy = 0 }
        if (dy >= 0 && h - m - sy > best) { best = h - m - sy; ux = 0; uy = 1 }
        if (dy <= 0 && sy - m > best) { best = sy - m; ux = 0; uy = -1 }
    }
    if (best > 0) room = best
    if (room > 200) room = 200
    printf "%d %d\n", room / 10 * ux, room / 10 * uy
}')"
start_frame=$(tail -n 1 "$log" | awk '{ print $2 }')
DISPLAY=:97 xdotool mousemove "$sx" "$sy"
sleep 0.2
DISPLAY=:97 xdotool mousedown 1
sleep 0.1
for k in $(seq 1 10); do
    DISPLAY=:97 xdotool mousemove "$((sx + k * stepx))" "$((sy + k * stepy))"
    sleep 0.016
done
DISPLAY=:97 xdotool mouseup 1
release=$(tail -n 1 "$log")
echo "released: $release"
sleep 0.5
wait_for_rest
sleep 0.3
DISPLAY=:97 import -window root docs/egui_graphs_throw.png
end=$(tail -n 1 "$log")
echo "at rest:  $end"
# What the dragged node did, from the log: where it was let go and the farthest out it
# got afterwards, in graph units from where it rested before.
awk -v node="$node" -v x0="$x" -v y0="$y" -v from="$start_frame" '
    $2 > from && $0 ~ "tracked Some\\(" node "\\)" {
        dxv = $10 - x0; dyv = $11 - y0; d = sqrt(dxv*dxv + dyv*dyv);
        if ($0 ~ /dragged Some/) { dragged = d; frames_dragged++ }
        else if (dragged > 0) { if (d > far) far = d; after++ }
        if ($4 == "true" && after > 0 && rest == 0) rest = $2 - from
    }
    END {
        printf "node %s: %d frames dragged, let go %.0f units out, flew to %.0f units, %d frames after release logged, at rest %d frames after the drag began\n",
            node, frames_dragged, dragged, far, after, rest
    }' "$log"
