#!/bin/bash
# GUI smoke test under Xvfb: the window opens on the default scene and simulates; a real X Ctrl+click (xdotool) on
# the Poincare map starts a second trajectory whose points arrive, a Shift+click a fixed-point search; real keys:
# Ctrl+Shift+C continues the fixed point, Space pauses; a screenshot of the window is a real picture.
# Every step waits on what the window reports in its status file (rollviz gui --status-file), with a generous
# deadline, never on the clock: it passes on a busy machine.
# Usage: gui_smoke.sh ROLLVIZ SRC ARTIFACT_DIR
set -euo pipefail
RV=$1 SRC=$2 OUT=$3
mkdir -p "$OUT"
shot="$OUT/gui_smoke.png"
summary="$OUT/gui_smoke.txt"
status="$OUT/gui_smoke.status"
rm -f "$shot" "$summary" "$status" "$status.quit"
export XDG_CONFIG_HOME=$(mktemp -d) # a fresh QSettings, so the last scene of a user does not leak in
cat >"$OUT/gui_smoke_session.sh" <<SH
set -eu
# waits until the window's status says \$1 (120 s at most)
until_status() {
  for _ in \$(seq 600); do
    grep -q -- "\$1" "$status" 2>/dev/null && return 0
    sleep 0.2
  done
  echo "the window never reported '\$1'; last status: \$(cat "$status" 2>/dev/null)"
  exit 1
}
"$RV" gui "$SRC/scenes/chaplygin_ball.json" --quit-after 600 --status-file "$status" --screenshot "$shot" >"$summary" &
pid=\$!
trap 'kill \$pid 2>/dev/null || true' EXIT
until_status "map trajectories = 1,"
xdotool search --sync --onlyvisible --name "^rollviz" >/dev/null
# the window sits at the top left with no window manager; the map dock fills its right part
xdotool mousemove 1200 300 keydown ctrl click 1 keyup ctrl
until_status "map trajectories = 2,"
# Shift+click: a fixed-point search from that point of the map (a job; it may find a point or fail: both end)
xdotool mousemove 1250 400 keydown shift click 1 keyup shift
until_status "fixed point searches = 1,"
# keyboard shortcuts, with the pointer (and so the focus) over the 3D view
xdotool mousemove 300 400 key ctrl+shift+c
until_status "tool jobs = 1,"
xdotool key space
until_status "playing = no"
touch "$status.quit"
wait \$pid
trap - EXIT
SH
xvfb-run -a -s '-screen 0 1600x1000x24' bash "$OUT/gui_smoke_session.sh"
[ -f "$shot" ] || { echo "no screenshot written"; exit 1; }
cat "$summary"
grep -q "map trajectories = 2" "$summary" || { echo "the click on the map did not start a trajectory"; exit 1; }
grep -q "fixed point searches = 1" "$summary" || { echo "the Shift+click did not start a fixed-point search"; exit 1; }
grep -q "tool jobs = 1," "$summary" || { echo "Ctrl+Shift+C did not start the continuation"; exit 1; }
grep -q "playing = no" "$summary" || { echo "Space did not pause the run"; exit 1; }
/usr/bin/python3 - "$shot" <<'PY'
import sys
from PIL import Image
img = Image.open(sys.argv[1]).convert("RGB")
px = list(img.getdata())
n = len(px)
mean = sum(sum(p) for p in px) / (3 * n)
sd = (sum((c - mean) ** 2 for p in px for c in p) / (3 * n)) ** 0.5
colours = len(set(px))
print(f"screenshot {img.size}, sd {sd:.1f}, {colours} colours")
# the 3D view (gradient, checkerboard, textured ball) has thousands of colours; a blank widget has a few
sys.exit(0 if sd > 5 and colours > 500 else 1)
PY
echo "gui smoke: ok ($shot)"
