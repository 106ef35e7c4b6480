"""The example study (examples/chaplygin_study.py) runs headless and produces its figures; the notebook holds
the same cells (scripts/make_notebook.py)."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import SOURCE

pytest.importorskip("rollviz")
pytest.importorskip("matplotlib")


def test_the_notebook_is_the_script():
    sys.path.insert(0, os.path.join(SOURCE, "scripts"))
    from make_notebook import notebook
    with open(os.path.join(SOURCE, "examples", "chaplygin_study.py")) as f:
        expected = notebook(f.read())
    with open(os.path.join(SOURCE, "examples", "chaplygin_study.ipynb")) as f:
        assert json.load(f) == expected, "run scripts/make_notebook.py examples/chaplygin_study.py"


def test_the_study_runs_headless(tmp_path):
    from PIL import Image
    out = os.environ.get("ROLLVIZ_TEST_OUTPUT")
    out = os.path.join(out, "study") if out else str(tmp_path / "study")
    env = dict(os.environ, MPLBACKEND="Agg")
    p = subprocess.run([sys.executable, os.path.join(SOURCE, "examples", "chaplygin_study.py"), out],
                       capture_output=True, text=True, env=env, timeout=300)
    assert p.returncode == 0, p.stderr
    with open(os.path.join(out, "motion.html"), encoding="utf-8") as f:
        assert 'id="rollviz-data"' in f.read()
    for name in ("poincare.png", "lyapunov.png", "frame.png"):
        img = np.asarray(Image.open(os.path.join(out, name)).convert("RGB"), dtype=float)
        assert img.std() > 5, f"{name} is blank"
    summary = json.load(open(os.path.join(out, "summary.json")))
    assert summary["map_points"] == 1200
    assert summary["frame_shape"] == [360, 480, 3]
    lam = np.array(summary["largest_lyapunov"])
    # integrable: the estimates at t = 500 are small and positive, of the order of ln(t)/t = 0.012
    assert lam.shape == (5,) and np.isfinite(lam).all() and (lam > 0).all() and (lam < 0.03).all(), lam


def test_the_notebook_runs_in_a_jupyter_kernel(tmp_path, monkeypatch):
    """The notebook itself, cell by cell, in a real IPython kernel (Debian's python3-nbclient and
    python3-ipykernel): its plots come back inline and it writes what the script writes."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    monkeypatch.delenv("MPLBACKEND", raising=False)  # the kernel's own inline backend, as in Jupyter
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the debugger's note about frozen modules
    with open(os.path.join(SOURCE, "examples", "chaplygin_study.ipynb")) as f:
        nb = nbformat.read(f, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()
    images = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if "image/png" in o.get("data", {})]
    assert len(images) >= 3, "the map, the exponents and the frame are shown inline"
    # the motion's interactive view: the page itself, inline, with its data and viewer
    pages = [o["data"]["text/html"] for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
             if "text/html" in o.get("data", {}) and "<iframe srcdoc=" in o["data"]["text/html"]]
    assert len(pages) == 1, "the motion is shown inline once"
    assert "rollviz-data" in pages[0] and "THREE" in pages[0]
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.output_type == "error"]
    assert not errors, errors
    summary = json.load(open(tmp_path / "study_output" / "summary.json"))
    assert summary["map_points"] == 1200 and summary["frame_shape"] == [360, 480, 3]
