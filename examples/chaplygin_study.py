# %% [markdown]
# # The Chaplygin ball with a gyrostat: a study in Python
#
# A Poincaré map drawn with matplotlib, the largest Lyapunov exponent against the energy, and a frame of the
# 3D view, all from the `rollviz` module. Run it as a script (`python3 examples/chaplygin_study.py OUT_DIR`)
# or open `chaplygin_study.ipynb` in Jupyter (the same cells). Import the module from a build tree with
# `PYTHONPATH=build/release/python` (or build/dev/python), or after `cmake --install`. `help(rollviz.Scene.lyapunov)`
# and the guide's Python page (docs/python.md) say what every call takes and returns.

# %%
import json
import os
import sys

import matplotlib
import numpy as np

if "ipykernel" not in sys.modules:
    matplotlib.use("Agg")  # as a script: files only
import matplotlib.pyplot as plt
import rollviz

out = sys.argv[1] if len(sys.argv) > 1 and "ipykernel" not in sys.modules else "study_output"
os.makedirs(out, exist_ok=True)
here = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
scene_file = os.path.join(here, "..", "scenes", "chaplygin_ball.json")
if not os.path.exists(scene_file):
    scene_file = os.path.join(rollviz.scenes_directory(), "chaplygin_ball.json")
ball = rollviz.Scene.load(scene_file)
print(ball, "parameters:", dict(ball.parameters))

# %% [markdown]
# ## The Poincaré map
# Three trajectories started at different points of the section `g = 0`, each a cloud of crossings.

# %%
fig, ax = plt.subplots(figsize=(6, 5))
starts = [[0.5, 0.2], [-1.2, 0.1], [1.5, -0.3]]
points = 0
for start in starts:
    P = ball.set(**{"initial.map": start}).poincare(points=400)  # a new scene; `ball` stays as it is
    points += len(P)
    x, y = ball.map_coordinates
    ax.plot(P[x], P[y], ".", markersize=1.5, label=f"from {start}")  # the map's points by name
ax.set(xlabel=x, ylabel=y, title="Chaplygin ball: Poincaré map (g = 0)")
ax.legend(loc="upper right", fontsize=7)
fig.savefig(os.path.join(out, "poincare.png"), dpi=100)

# %% [markdown]
# ## The largest Lyapunov exponent against the energy
# `lyapunov(count=1, time=..., energy=h)`: settings of the `lyapunov` section and a model parameter, for this
# call only (`help(rollviz.Scene.lyapunov)` lists them all). The
# Chaplygin ball with a gyrostat is integrable (Borisov & Mamaev), so the estimate falls towards zero like
# ln(t)/t on every energy level: a chaotic system would level off at a positive value instead.

# %%
energies = np.linspace(0.3, 0.7, 5)
largest = []
for h in energies:
    r = ball.lyapunov(count=1, time=500, energy=h)
    largest.append(r.exponents[0])
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(energies, largest, "o-")
ax.set(xlabel="energy", ylabel="largest Lyapunov exponent", title="Chaplygin ball: chaos against the energy")
fig.savefig(os.path.join(out, "lyapunov.png"), dpi=100)

# %% [markdown]
# ## The 3D view at t = 5
# Rendered headless (EGL) into a NumPy image, shown inline.

# %%
frame = ball.render(size=(480, 360), time=5.0)
fig, ax = plt.subplots(figsize=(6, 4.5))
ax.imshow(frame)
ax.axis("off")
fig.savefig(os.path.join(out, "frame.png"), dpi=100)

# %% [markdown]
# ## The motion to turn around
# The same motion as an interactive 3D view: in Jupyter it plays inline (offline: the viewer is inside the
# page); `ball.page("motion.html")` writes it as a web page to send.

# %%
view = ball.show(duration=4)
ball.page(os.path.join(out, "motion.html"), duration=4)

# %%
with open(os.path.join(out, "summary.json"), "w") as f:
    json.dump({"map_points": points, "energies": energies.tolist(), "largest_lyapunov": largest,
               "frame_shape": list(frame.shape)}, f)
print("wrote", sorted(os.listdir(out)))
