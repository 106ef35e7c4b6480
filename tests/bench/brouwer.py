#!/usr/bin/env python3
"""Long-term energy error of Everhart 15 with compensated summation on chaplygin_ball over t = 10^6 (issue 15):
the relative error |E(t) - E(0)| / E(0) of the default scene's motion, sampled every 1000, on log-log axes beside
sqrt(t) (Brouwer's law: rounding errors of an unbiased method walk at random, as REBOUND shows for IAS15).

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
ap.add_argument("-o", "--output", default="brouwer_everhart.png")
a = ap.parse_args()

scene = rollviz.Scene("chaplygin_ball", **{"integrator.method": "everhart", "integrator.step": a.step,
                                            "integrator.order": 15, "integrator.iterations": 12})
start = time.time()
t, X = scene.integrate(time=a.time, every=1000 * a.step, columns=["t", "E"])
elapsed = time.time() - start
E = X[:, 1]
err = np.abs(E - E[0]) / abs(E[0])
keep = t > 0
slope = np.polyfit(np.log(t[keep][len(t) // 10:]), np.log(np.maximum(err[keep][len(t) // 10:], 1e-18)), 1)[0]
print(f"t = {a.time:g} in {elapsed:.1f} s: final relative energy error {err[-1]:.3g}, "
      f"largest {err.max():.3g}, log-log slope over the last 90% {slope:.2f} (random walk: 0.5)")

fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=120)
ax.loglog(t[keep], np.maximum(err[keep], 1e-18), lw=0.6, color="#2060c0",
          label=f"Everhart 15, h = {a.step:g}, compensated summation")
ref = t[keep] ** 0.5
ref *= np.median(err[keep][len(t) // 10:] / ref[len(t) // 10:])
ax.loglog(t[keep], ref, "--", color="0.4", label=r"$\propto\sqrt{t}$ (Brouwer's law)")
ax.set_xlabel("t")
ax.set_ylabel("|E(t) - E(0)| / E(0)")
ax.set_title("chaplygin_ball, default scene: long-term energy error")
ax.legend(loc="upper left", fontsize=8)
ax.grid(True, which="both", lw=0.3, alpha=0.5)
fig.tight_layout()
fig.savefig(a.output)
print("wrote", a.output)
