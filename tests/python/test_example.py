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
    for name in ("poincare.png", "lyapunov.png", "frame.png"):
        img = np.asarray(Image.open(os.path.join(out, name)).convert("RGB"), dtype=float)
        assert img.std() > 5, f"{name} is blank"
    summary = json.load(open(os.path.join(out, "summary.json")))
    assert summary["map_points"] == 1200
    assert summary["frame_shape"] == [360, 480, 3]
    lam = np.array(summary["largest_lyapunov"])
    # integrable: the estimates at t = 500 are small and positive, of the order of ln(t)/t = 0.012
    assert lam.shape == (5,) and np.isfinite(lam).all() and (lam > 0).all() and (lam < 0.03).all(), lam
