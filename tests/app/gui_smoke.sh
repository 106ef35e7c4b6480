#!/bin/bash
# GUI smoke test: under Xvfb the window opens on the default scene, simulates for two seconds, and a
# screenshot of it is a real picture (not blank). Usage: gui_smoke.sh ROLLVIZ SRC ARTIFACT_DIR
set -euo pipefail
RV=$1 SRC=$2 OUT=$3
mkdir -p "$OUT"
shot="$OUT/gui_smoke.png"
rm -f "$shot"
export XDG_CONFIG_HOME=$(mktemp -d) # a fresh QSettings, so the last scene of a user does not leak in
xvfb-run -a -s '-screen 0 1400x900x24' "$RV" gui "$SRC/scenes/chaplygin_ball.json" --quit-after 2.5 --screenshot "$shot"
[ -f "$shot" ] || { echo "no screenshot written"; exit 1; }
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
