# %% [markdown]
# # The Chaplygin ball with a gyrostat: a study in Python
#
# A Poincaré map drawn with matplotlib, the largest Lyapunov exponent against the energy, and a frame of the
# 3D view, all from the `rollviz` module. Run it as a script (`python3 examples/chaplygin_study.py OUT_DIR`)
# or open `chaplygin_study.ipynb` in Jupyter (the same cells). Import the module from a build tree with
# `PYTHONPATH=build/dev/python`, or after `cmake --install`.

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
print(ball, "parameters:", ball.parameters)

# %% [markdown]
# ## The Poincaré map
# Three trajectories started at different points of the section `g = 0`, each a cloud of crossings.

# %%
fig, ax = plt.subplots(figsize=(6, 5))
starts = [[0.5, 0.2], [-1.2, 0.1], [1.5, -0.3]]
points = 0
for start in starts:
    P = ball.copy().set(**{"initial.map": start}).poincare(points=400)
    points += len(P)
    ax.plot(P[:, 0], P[:, 1], ".", markersize=1.5, label=f"from {start}")
x, y = ball.map_coordinates
ax.set(xlabel=x, ylabel=y, title="Chaplygin ball: Poincaré map (g = 0)")
ax.legend(loc="upper right", fontsize=7)
fig.savefig(os.path.join(out, "poincare.png"), dpi=100)

# %% [markdown]
# ## The largest Lyapunov exponent against the energy
# `lyapunov(count=1, time=...)`: the settings of the scene's `lyapunov` section, for this call only. The
# Chaplygin ball with a gyrostat is integrable (Borisov & Mamaev), so the estimate falls towards zero like
# ln(t)/t on every energy level: a chaotic system would level off at a positive value instead.

# %%
energies = np.linspace(0.3, 0.7, 5)
largest = []
for h in energies:
    r = ball.copy().set(energy=float(h)).lyapunov(count=1, time=500)
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

with open(os.path.join(out, "summary.json"), "w") as f:
    json.dump({"map_points": points, "energies": energies.tolist(), "largest_lyapunov": largest,
               "frame_shape": list(frame.shape)}, f)
print("wrote", sorted(os.listdir(out)))
