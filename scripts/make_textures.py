#!/usr/bin/python3
"""Makes the textures in assets/textures (run once; the PNGs are committed). Scenes name them by file stem:
"view": {"objects": {"ball": {"texture": "stripes"}}}."""
import math, os
from PIL import Image

out = os.path.join(os.path.dirname(__file__), "..", "assets", "textures")
os.makedirs(out, exist_ok=True)
n = 256

def save(name, f):
    im = Image.new("RGB", (n, n))
    im.putdata([f(i, j) for j in range(n) for i in range(n)])
    im.save(os.path.join(out, name + ".png"), optimize=True)

# graph paper: fine and bold lines on white, for planes and surfaces
save("graph", lambda i, j: (70, 110, 170) if i % 64 < 2 or j % 64 < 2 else
     (160, 190, 220) if i % 16 == 0 or j % 16 == 0 else (250, 250, 246))
# two-colour stripes along the longitude, for bodies: spin shows at a glance
save("stripes", lambda i, j: (230, 120, 30) if (i // 32) % 2 else (245, 235, 215))
# wood: rings around an off-centre axis
def wood(i, j):
    r = math.hypot(i - 40, j * 0.35 - 20) + 6 * math.sin(j * 0.05)
    s = 0.5 + 0.5 * math.sin(r * 0.6)
    return (int(150 + 60 * s), int(100 + 40 * s), int(50 + 25 * s))
save("wood", wood)
