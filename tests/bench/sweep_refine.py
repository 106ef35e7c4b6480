#!/usr/bin/env python3
"""What refinement buys (sweep option `refine`): the Henon-Heiles MEGNO chart (scenes/sweeps/henon_heiles_megno.json)
computed refined, L levels from a coarse grid, beside the full grid at the finest resolution, in one run: the
points each computes, their CPU cost (the sum of the points' own seconds, --timing), and how many points of the
finest grid the refined chart puts in the same regime as the full one (torus: <Y> < threshold; chaos; outside the
energy surface). A figure, not a test: nothing here passes or fails.
It also prints the least that any refinement must compute to reach the full grid's boundary resolution: the corners
of every finest cell whose corners the full grid puts in different regimes (a refinement that skips one of them
cannot place that boundary to the finest cell).
Usage: sweep_refine.py ROLLVIZ [--count N] [--levels L] [--time T] [--energy E] [--threads K]
                       [--threshold X | --at Y]
(--at: options.refine_by value, refine_at Y -- cells are halved where the regimes meet, <Y> on either side of Y,
not where chaotic neighbours merely differ)"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))


def run_sweep(rollviz, doc, folder, name, threads):
    path = os.path.join(folder, name + ".json")
    with open(path, "w") as f:
        json.dump(doc, f)
    out = os.path.join(folder, name + ".csv")
    subprocess.run([rollviz, "sweep", path, "-o", out, "--timing", "--threads", str(threads)], check=True,
                   capture_output=True, text=True)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    return rows, path, out


def regime(value, torus):
    if value is None or math.isnan(value):
        return "outside"
    return "torus" if value < torus else "chaos"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("rollviz")
    p.add_argument("--count", type=int, default=11, help="the coarse grid's count per axis")
    p.add_argument("--levels", type=int, default=3)
    p.add_argument("--time", type=float, default=100, help="megno.time")
    p.add_argument("--energy", type=float, help="the energy (default: the sweep file's, 1/8)")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--threshold", type=float, default=0.05, help="options.refine_threshold")
    p.add_argument("--at", type=float, help="refine by value: options.refine_by value, refine_at AT")
    p.add_argument("--torus", type=float, default=2.5, help="<Y> below this: a torus")
    a = p.parse_args()
    with open(os.path.join(SOURCE, "scenes", "sweeps", "henon_heiles_megno.json")) as f:
        doc = json.load(f)
    doc["scene"] = os.path.join(SOURCE, "scenes", "henon_heiles.json")
    doc["set"]["megno.time"] = a.time
    if a.energy is not None:
        doc["set"]["energy"] = a.energy
    fine_count = (a.count - 1) * 2 ** a.levels + 1
    with tempfile.TemporaryDirectory() as folder:
        refined = json.loads(json.dumps(doc))
        for axis in refined["axes"]:
            axis["count"] = a.count
        refined["options"] = {"refine": a.levels, "refine_threshold": a.threshold}
        if a.at is not None:
            refined["options"] = {"refine": a.levels, "refine_by": "value", "refine_at": a.at}
        full = json.loads(json.dumps(doc))
        for axis in full["axes"]:
            axis["count"] = fine_count
        r_rows, r_path, r_csv = run_sweep(a.rollviz, refined, folder, "refined", a.threads)
        f_rows, _, _ = run_sweep(a.rollviz, full, folder, "full", a.threads)
        # the refined chart on the finest grid as `-o .vti` writes it (the points not computed painted from the
        # nearest computed one): computed once more for that, not counted
        vti = os.path.join(folder, "refined.vti")
        subprocess.run([a.rollviz, "sweep", r_path, "-o", vti, "--threads", str(a.threads)], check=True,
                       capture_output=True)
        painted = read_vti_values(vti, "megno")
    cost = lambda rows: sum(float(r["seconds"]) for r in rows)  # noqa: E731
    full_values = [float(r["megno"]) for r in f_rows]
    same = sum(regime(x, a.torus) == regime(y, a.torus) for x, y in zip(full_values, painted))
    least_points, least_cost = least_refinement(f_rows, fine_count, a.torus)
    print(f"Henon-Heiles MEGNO at E = {doc['set']['energy']:g}, megno.time = {a.time:g}, coarse {a.count}x{a.count}, {a.levels} levels "
          f"({f'refine_at {a.at:g}' if a.at is not None else f'threshold {a.threshold:g}'}) -> finest "
          f"{fine_count}x{fine_count}")
    print(f"full grid:    {len(f_rows)} points, {cost(f_rows):.1f} s of CPU")
    print(f"refined:      {len(r_rows)} points ({100 * len(r_rows) / len(f_rows):.1f} %), {cost(r_rows):.1f} s "
          f"of CPU ({100 * cost(r_rows) / cost(f_rows):.1f} % of the full grid's)")
    print(f"same regime as the full grid: {same} of {len(f_rows)} points ({100 * same / len(f_rows):.2f} %)")
    print(f"the least any refinement computes to resolve every boundary of the full grid: {least_points} points "
          f"({100 * least_points / len(f_rows):.1f} %), {100 * least_cost / cost(f_rows):.1f} % of its CPU")


def least_refinement(rows, count, torus):
    """The points (and their CPU seconds) at the corners of the full grid's finest cells whose corners lie in
    different regimes: what a refinement must compute to place each boundary to the finest cell."""
    index = {}
    for r in rows:
        index[(float(r["map.0"]), float(r["map.1"]))] = r
    xs = sorted({k[0] for k in index})
    ys = sorted({k[1] for k in index})
    assert len(xs) == count and len(ys) == count
    at = lambda i, j: index[(xs[i], ys[j])]  # noqa: E731
    needed = set()
    for i in range(count - 1):
        for j in range(count - 1):
            corners = [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)]
            if len({regime(float(at(*c)["megno"]), torus) for c in corners}) > 1:
                needed.update(corners)
    return len(needed), sum(float(at(*c)["seconds"]) for c in needed)


def read_vti_values(path, name):
    """The named point-data array of an ASCII or appended-raw VTK image file, through VTK's Python reader."""
    try:
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError:
        sys.exit("sweep_refine.py: needs VTK's Python modules (Debian's python3-vtk9)")
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    return list(vtk_to_numpy(reader.GetOutput().GetPointData().GetArray(name)))


if __name__ == "__main__":
    main()
