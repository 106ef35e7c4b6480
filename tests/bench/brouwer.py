#!/usr/bin/env python3
"""Long-term energy error of Everhart 15 with compensated summation on chaplygin_ball over t = 10^6 (issue 15):
the relative errors |E(t) - E(0)| / E(0) of four orbits of the default scene, sampled every 1000 steps, and their
RMS on log-log axes beside sqrt(t) (Brouwer's law: rounding errors of an unbiased method walk at random, as REBOUND
shows for IAS15; a bias shows as a slope of 1 and errors of one sign).

    PYTHONPATH=build/bench/python tests/bench/brouwer.py [--time 1e6] [-o assets/readme/brouwer_everhart.png]

Uses the Python module (the package folder of any build with ROLLVIZ_PYTHON), NumPy and matplotlib."""
import argparse
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import rollviz  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--time", type=float, default=1e6)
ap.add_argument("--step", type=float, default=0.5)
ap.add_argument("--orbits", type=int, default=4, help="how many orbits (1-4); the RMS of their errors is fitted")
ap.add_argument("-o", "--output", default="brouwer_everhart.png")
a = ap.parse_args()

starts = [None, [1.0, 0.3], [1.5, -0.2], [-1.0, 0.1]][:a.orbits]  # None: the scene's own initial point
curves = []
start = time.time()
for point in starts:
    keys = {"integrator.method": "everhart", "integrator.step": a.step, "integrator.order": 15,
            "integrator.iterations": 12}
    if point is not None:
        keys["initial.map"] = point
    scene = rollviz.Scene("chaplygin_ball", **keys)
    t, X = scene.integrate(time=a.time, every=1000 * a.step, columns=["t", "E"])
    curves.append((point, (X[:, 1] - X[0, 1]) / abs(X[0, 1])))
elapsed = time.time() - start
keep = t > 0
tail = slice(len(t) // 10, None)
rms = np.sqrt(np.mean([c[keep] ** 2 for _, c in curves], axis=0))
slope = np.polyfit(np.log(t[keep][tail]), np.log(np.maximum(rms[tail], 1e-18)), 1)[0]
mean_signed = np.mean([c[-1] for _, c in curves])
print(f"{len(curves)} orbits to t = {a.time:g} in {elapsed:.1f} s: final relative energy errors "
      + ", ".join(f"{c[-1]:+.2g}" for _, c in curves)
      + f"; their mean {mean_signed:+.2g}; log-log slope of the RMS over the last 90% {slope:.2f} (random walk: 0.5)")

fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=120)
for point, c in curves:
    ax.loglog(t[keep], np.maximum(np.abs(c[keep]), 1e-18), lw=0.5, alpha=0.8,
              label="scene's start" if point is None else f"map point {point}")
ax.loglog(t[keep], np.maximum(rms, 1e-18), lw=1.4, color="k", label=f"RMS of the {len(curves)} orbits")
ref = t[keep] ** 0.5
ref *= np.median(rms[tail] / ref[tail])
ax.loglog(t[keep], ref, "--", color="0.4", label=r"$\propto\sqrt{t}$ (Brouwer's law)")
ax.set_xlabel("t")
ax.set_ylabel("|E(t) - E(0)| / E(0)")
ax.set_title(f"chaplygin_ball: Everhart 15, h = {a.step:g}, compensated summation")
ax.legend(loc="upper left", fontsize=7)
ax.grid(True, which="both", lw=0.3, alpha=0.5)
fig.tight_layout()
fig.savefig(a.output)
print("wrote", a.output)
