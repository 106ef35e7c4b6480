#!/usr/bin/env python3
"""Parallel efficiency of `rollviz sweep` from 1 to 2 threads and from 1 to 2 MPI ranks on one sweep file: the
wall time of each, the efficiency T1 / (2 T2), the cost per point and the bytes sent per point between ranks.
Usage: sweep_scaling.py ROLLVIZ [SWEEP.json]  (default: scenes/sweeps/henon_heiles_megno.json)"""
import os
import re
import subprocess
import sys
import tempfile
import time

rv = sys.argv[1]
sweep = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "scenes",
                                                             "sweeps", "henon_heiles_megno.json")
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
with tempfile.TemporaryDirectory() as tmp:
    def wall(*command):
        start = time.time()
        r = subprocess.run(command, capture_output=True, text=True, env=env)
        if r.returncode:
            sys.exit(r.stdout + r.stderr)
        return time.time() - start, r.stderr

    out = os.path.join(tmp, "chart.csv")
    t1, _ = wall(rv, "sweep", sweep, "-o", out, "--threads", "1")
    points = sum(1 for _ in open(out)) - 1
    t2, _ = wall(rv, "sweep", sweep, "-o", out, "--threads", "2")
    m1, _ = wall("mpirun", "-n", "1", rv, "sweep", sweep, "-o", out)
    m2, log = wall("mpirun", "-n", "2", rv, "sweep", sweep, "-o", out)
    sent = re.search(r"(\d+) bytes sent per point", log)
    print("points %d, cost per point on 1 thread %.2f ms" % (points, 1000 * t1 / points))
    print("threads: 1 -> %.2f s, 2 -> %.2f s, efficiency %.0f %%" % (t1, t2, 100 * t1 / (2 * t2)))
    print("ranks:   1 -> %.2f s, 2 -> %.2f s, efficiency %.0f %%, %s bytes sent per point" %
          (m1, m2, 100 * m1 / (2 * m2), sent.group(1) if sent else "?"))
