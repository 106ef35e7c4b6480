#!/usr/bin/env python3
"""The guide's pictures of the GUI, taken by rollviz itself: each is `rollviz gui SCENE --quit-after T
--screenshot OUT/NAME.png` on the display of the caller (DISPLAY), or on a virtual one (xvfb-run) where there is
none. Usage: make_screenshots.py ROLLVIZ SOURCE_DIR OUT_DIR. The guide's GUI page shows them (docs/generate.py).
A picture that comes out one flat colour (a window that did not draw) fails the script."""
import os
import shutil
import subprocess
import sys
import tempfile

# name, scene (relative to the source), seconds shown before the picture, what it shows
SHOTS = [
    ("gui_rattleback", "scenes/gallery/rattleback_reversal.json", 4,
     "The rattleback reversing: the control panel (the problem's parameters), the 3D view, the Poincaré map "
     "filling as it rolls, the tool manager with the running map and the Results dock."),
    ("gui_chaplygin", "scenes/chaplygin_ball.json", 6,
     "The Chaplygin ball: its Poincaré map in Andoyer–Deprit variables (l, L/G) beside the rolling ball."),
    ("gui_henon_heiles", "scenes/henon_heiles.json", 5,
     "Hénon–Heiles: the orbit in the 3D view and its section x = 0 in the map window."),
]


def is_picture(path):
    """Not one flat colour: a few hundred bytes of PNG hold a blank window."""
    with open(path, "rb") as f:
        data = f.read()
    return data.startswith(b"\x89PNG") and len(data) > 20000


def make(rollviz, source, out):
    """Takes every screenshot into OUT/NAME.png; returns [(name, caption)]."""
    os.makedirs(out, exist_ok=True)
    prefix = []
    if not os.environ.get("DISPLAY"):
        xvfb = shutil.which("xvfb-run")
        if not xvfb:
            sys.exit("make_screenshots.py: no DISPLAY and no xvfb-run (Debian's xvfb) to take the GUI's pictures")
        prefix = [xvfb, "-a", "-s", "-screen 0 1400x900x24"]
    env = dict(os.environ)
    # a settings folder of its own: the user's last scene, recent files and docks stay out of the pictures
    env["XDG_CONFIG_HOME"] = tempfile.mkdtemp(prefix="rollviz-shots-")
    shots = []
    for name, scene, seconds, caption in SHOTS:
        path = os.path.join(out, name + ".png")
        r = subprocess.run([*prefix, rollviz, "gui", os.path.join(source, scene), "--quit-after", str(seconds),
                            "--screenshot", path], capture_output=True, text=True, env=env, timeout=300)
        if r.returncode != 0 or not os.path.exists(path) or not is_picture(path):
            sys.exit(f"make_screenshots.py: `rollviz gui {scene}` gave no picture ({r.returncode}): {r.stderr}")
        shots.append((name, caption))
    shutil.rmtree(env["XDG_CONFIG_HOME"], ignore_errors=True)
    return shots


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    for name, _ in make(sys.argv[1], sys.argv[2], sys.argv[3]):
        print(os.path.join(sys.argv[3], name + ".png"))
