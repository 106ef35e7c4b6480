"""Shared fixtures of the Python tests: the CLI they compare with, the source tree, a run helper.

ctest sets ROLLVIZ_EXE (the rollviz executable of the same build), ROLLVIZ_SOURCE_DIR and PYTHONPATH (the build
tree's python/ folder, which holds the rollviz package)."""

import csv
import json
import os
import subprocess

import numpy as np
import pytest

SOURCE = os.environ.get("ROLLVIZ_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
RV = os.environ.get("ROLLVIZ_EXE", "")


def scene_path(name):
    return os.path.join(SOURCE, "scenes", name)


def cli(*args, check=True):
    """Runs the rollviz CLI; returns the completed process (text)."""
    if not RV:
        pytest.skip("ROLLVIZ_EXE is not set")
    p = subprocess.run([RV, *map(str, args)], capture_output=True, text=True, cwd=SOURCE, timeout=600)
    if check and p.returncode != 0:
        raise AssertionError(f"rollviz {' '.join(map(str, args))}: exit {p.returncode}\n{p.stderr}")
    return p


def cli_json(*args):
    return json.loads(cli(*args, "--json").stdout)


def read_csv(path):
    """A CSV the CLI wrote: (header, float array of the numeric rows)."""
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:]])


@pytest.fixture(scope="session")
def source():
    return SOURCE
