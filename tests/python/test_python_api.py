"""The Python API as researchers expect it (issue 39): real signatures from the registry, one keyword rule for
every call, named results, scenes as values (pickle, copy, multiprocessing), a trajectory to step on from,
sweeps defined in Python, honest media calls."""

import copy
import inspect
import multiprocessing
import os
import pickle
import re

import numpy as np
import pytest

from conftest import SOURCE, scene_path

rollviz = pytest.importorskip("rollviz")


def test_the_version_is_the_projects():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        version = re.search(r"project\(rollviz VERSION ([0-9.]+)", f.read()).group(1)
    assert rollviz.__version__ == version


def test_every_tool_method_has_a_signature_with_every_setting_of_its_sections():
    for tool in rollviz.tools():
        if tool.id == "sweep":
            continue
        method = getattr(rollviz.Scene, tool.id)
        sig = inspect.signature(method)
        params = sig.parameters
        assert list(params)[0] == "self" and params["self"].kind == inspect.Parameter.POSITIONAL_ONLY
        assert params["progress"].kind == inspect.Parameter.KEYWORD_ONLY and params["progress"].default is None
        assert any(p.kind == inspect.Parameter.VAR_KEYWORD for p in params.values())
        # every setting of every section the call takes (the tool's own and its parents'), keyword-only
        for section in tool.sections:
            owner = next((t for t in rollviz.tools() if t.section == section), None)
            for setting in owner.settings if owner else []:
                assert setting["id"] in params, (tool.id, section, setting["id"])
        for k in tool.keywords:
            p = params[k["id"]]
            assert p.kind == inspect.Parameter.KEYWORD_ONLY
            if k["type"] == "integer":
                assert type(p.default) is int, (tool.id, k["id"], p.default)
            assert k["id"] in method.__doc__
        if tool.outputs:
            assert "Returns:" in method.__doc__
    # the text keys that no table holds are there too, where they belong
    cont = inspect.signature(rollviz.Scene.continuation).parameters
    assert {"guess", "parameter", "to"} <= set(cont)
    assert "continuation.to" in rollviz.Scene.continuation.__doc__
    lyap = inspect.signature(rollviz.Scene.lyapunov).parameters
    assert type(lyap["count"].default) is int and lyap["count"].default == 0


def test_one_keyword_rule_for_every_call():
    s = rollviz.Scene.load(scene_path("henon_heiles.json"))
    # a model parameter by its plain name in a tool's call is set() for that call
    a = s.lyapunov(time=50, energy=0.1)
    b = s.set(energy=0.1).lyapunov(time=50)
    assert np.array_equal(a.exponents, b.exponents)
    assert s.parameters["energy"] == 0.125  # the call changed nothing
    assert not np.array_equal(a.exponents, s.lyapunov(time=50).exponents)
    # unknown keywords: TypeError naming the nearest; positional arguments: TypeError
    with pytest.raises(TypeError, match=r"lyapunov\(\) got an unexpected keyword argument 'tme'.*did you mean 'time'\?"):
        s.lyapunov(tme=10)
    with pytest.raises(TypeError, match=r"did you mean 'energy'\?"):
        s.set(energi=0.1)
    with pytest.raises(TypeError, match=r"did you mean 'energy'\?"):
        s.integrate(1, 0.5, energi=0.1)
    with pytest.raises(TypeError, match=r"keyword arguments only"):
        s.lyapunov(10)
    # wrong types: TypeError saying what was expected; NaN and choices not offered: ValueError
    with pytest.raises(TypeError, match=r"time takes a number, not str"):
        s.lyapunov(time="long")
    with pytest.raises(TypeError, match=r"count takes an integer"):
        s.lyapunov(count=1.5)
    with pytest.raises(ValueError, match=r"mode = 'fast' is not one of tangent, perturbed"):
        s.lyapunov(mode="fast")
    with pytest.raises(ValueError, match=r"time must be a finite number, got nan"):
        s.megno(time=float("nan"))
    with pytest.raises(ValueError, match=r"energy must be a finite number, got inf"):
        s.set(energy=1e400)
    # a bad value: the scene loader's reason, in the call's words (the keyword, not the scene key)
    with pytest.raises(ValueError, match=r"^lyapunov\(\): time: time = -1 is out of range"):
        s.lyapunov(time=-1)
    with pytest.raises(ValueError, match=r"^integrate\(\): energy: energy = -1 is out of range"):
        s.integrate(1, 0.5, energy=-1)
    with pytest.raises(TypeError, match=r"size takes \(width, height\)"):
        s.render(size=[640, 480, 3])
    # ints given as floats where the value is whole, NumPy numbers, one column as a str
    assert s.megno(time=np.float64(20), **{"megno.output_period": 5}).time == 20
    assert s.integrate(1, 0.5, "E").columns == ["E"]


def test_results_have_names_and_convert_to_pandas_and_xarray():
    s = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    r = s.integrate(2, 0.5, ["t", "E", "M1"])
    assert r.columns == ["t", "E", "M1"] and list(r) == r.columns and len(r) == 5
    assert np.array_equal(r.E, r["E"]) and np.array_equal(r["t"], r.t)
    with pytest.raises(KeyError, match="did you mean E"):
        r["EE"]
    P = rollviz.Scene.load(scene_path("henon_heiles.json")).poincare(points=20)
    assert P.columns[-2:] == ["t", "sheet"] and np.asarray(P).shape == (20, len(P.columns))
    m = rollviz.Scene.load(scene_path("henon_heiles.json")).megno(time=50)
    assert m.history.columns[0] == "t" and "megno" in m.history
    pandas = pytest.importorskip("pandas")
    df = r.to_pandas()
    assert isinstance(df, pandas.DataFrame) and list(df.columns) == r.columns
    assert np.array_equal(df["M1"].to_numpy(), r["M1"])
    xarray = pytest.importorskip("xarray")
    ds = r.to_xarray()
    assert isinstance(ds, xarray.Dataset) and np.array_equal(ds["E"].values, r["E"])
    assert np.array_equal(ds.coords["t"].values, r.t)


def test_a_scene_is_a_value():
    s = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    with pytest.raises(TypeError):
        s.parameters["energy"] = 0.1  # read-only: set() gives a scene with another value
    for other in (copy.copy(s), copy.deepcopy(s), pickle.loads(pickle.dumps(s))):
        assert other is not s and other.to_json() == s.to_json() and other.parameters == s.parameters
        assert np.array_equal(np.asarray(other.integrate(1, 0.5)), np.asarray(s.integrate(1, 0.5)))
    m = rollviz.Model.load(os.path.join(SOURCE, "examples", "models", "lorenz.json"))
    lorenz = rollviz.Scene(m, rho=28, **{"initial.state": {"x": 1, "y": 1, "z": 1}})
    again = pickle.loads(pickle.dumps(lorenz))
    assert np.array_equal(np.asarray(again.integrate(1, 0.5)), np.asarray(lorenz.integrate(1, 0.5)))


def _largest_exponent(scene):
    return float(scene.lyapunov(time=100, count=1).exponents[0])


def test_scenes_go_through_a_multiprocessing_pool():
    base = rollviz.Scene.load(scene_path("henon_heiles.json"))
    scenes = [base.set(energy=e) for e in (0.08, 0.1, 0.12, 0.14)]
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        parallel = pool.map(_largest_exponent, scenes)
    assert parallel == [_largest_exponent(s) for s in scenes]


def test_a_trajectory_steps_on_from_where_it_ended():
    s = rollviz.Scene.load(scene_path("henon_heiles.json"), **{"integrator.method": "rk4", "integrator.step": 0.01})
    whole = s.integrate(10, 0.5)
    first = s.integrate(5, 0.5)
    assert first.final.shape == (len(s.state_names),) and set(first.final_named) == set(s.state_names)
    second = s.with_state(first.final).integrate(5, 0.5)
    # the second run starts at the first's last sample: the same trajectory to the integrator's rounding (not
    # bit for bit: the restart rounds the sample time into the step)
    assert np.allclose(np.asarray(second)[:, 1:], np.asarray(whole)[10:, 1:], rtol=0, atol=1e-10)
    # a mapping is a state too, and initial.state takes an array
    named = s.with_state(first.final_named)
    assert np.array_equal(named.initial_state, s.set(**{"initial.state": first.final}).initial_state)
    with pytest.raises(ValueError, match="components"):
        s.with_state([1.0, 2.0])


def test_a_sweep_defined_in_python_equals_the_sweep_file(tmp_path):
    sweep = tmp_path / "s.json"
    sweep.write_text(
        '{"scene": "%s", "axes": [{"id": "a", "min": 1.0, "max": 1.4, "count": 5}, '
        '{"id": "b", "min": 0.2, "max": 0.3, "count": 3}], "quantity": "lyapunov.max",'
        ' "set": {"lyapunov.time": 200}}' % scene_path("henon_map.json"))
    from_file = rollviz.sweep(str(sweep), threads=2)
    s = rollviz.Scene.load(scene_path("henon_map.json"))
    r = rollviz.sweep(s, axes={"a": np.linspace(1.0, 1.4, 5), "b": (0.2, 0.3, 3)}, quantity="lyapunov.max",
                      threads=2, **{"lyapunov.time": 200})
    assert r.shape == [5, 3] and r.complete
    assert np.array_equal(r.columns["lyapunov.max"], from_file.columns["lyapunov.max"])
    grid = r["values"]["lyapunov.max"]
    assert grid.shape == (5, 3)
    assert r.values is r["values"]  # the key, not dict.values (the docstring's r.values["megno"])
    assert len(repr(r)) < 100 and repr(r).startswith("<rollviz.SweepResult ")
    flat = from_file.columns["lyapunov.max"]
    for i in range(5):
        for j in range(3):
            assert grid[i, j] == flat[i + 5 * j]  # first axis fastest in the file
    assert np.allclose(r.axes["a"], np.linspace(1.0, 1.4, 5)) and np.allclose(r.axes["b"], [0.2, 0.25, 0.3])
    with pytest.raises(ValueError, match="evenly spaced"):
        rollviz.sweep(s, axes={"a": [1.0, 1.1, 1.4]}, quantity="lyapunov.max")


def test_a_refined_sweep_gives_the_finest_grid_each_computed_point_a_plain_sweeps(tmp_path):
    """options={"refine": 2}: the Henon map's basin (escape: failed) at 4x the resolution along its boundary; the
    grid is the finest one, the points computed equal a plain sweep's there, the others painted"""
    s = rollviz.Scene.load(scene_path("henon_map.json"))
    axes = {"map.0": (-2.5, 2.5, 9), "map.1": (-2.5, 2.5, 9)}
    r = rollviz.sweep(s, axes=axes, quantity="observable.x", threads=2,
                      options={"time": 40, "refine": 2, "refine_threshold": 10})
    assert r.shape == [33, 33] and r.complete
    fine = rollviz.sweep(s, axes={k: (a, b, 33) for k, (a, b, _) in axes.items()}, quantity="observable.x",
                         threads=2, options={"time": 40})
    computed = [i for i, st in enumerate(r.status) if st != "painted"]
    assert 81 < len(computed) < 33 * 33 // 2
    assert "painted" in r.status
    x, y = r.columns["observable.x"], fine.columns["observable.x"]
    for i in computed:
        assert r.status[i] == fine.status[i]
        assert (np.isnan(x[i]) and np.isnan(y[i])) or x[i] == y[i]
    with pytest.raises(TypeError, match="options takes a dict"):
        rollviz.sweep(s, axes=axes, quantity="observable.x", options=2)


def test_a_sweep_on_simd_lanes_equals_one_point_at_a_time():
    """MEGNO over Henon-Heiles initial points with rk4: four points at once (the default) and lanes=1 give the
    same numbers bit for bit"""
    s = rollviz.Scene.load(scene_path("henon_heiles.json"))
    settings = {"megno.time": 40, "integrator.method": "rk4", "integrator.step": 0.02}
    axes = {"map.0": (-0.3, 0.5, 5), "map.1": (-0.3, 0.3, 3)}
    batched = rollviz.sweep(s, axes=axes, quantity="megno", threads=2, **settings)
    single = rollviz.sweep(s, axes=axes, quantity="megno", threads=2, lanes=1, **settings)
    assert batched.status == single.status
    assert np.array_equal(batched.columns["megno"], single.columns["megno"], equal_nan=True)


def test_media_calls_refuse_what_they_cannot_write(tmp_path):
    s = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    with pytest.raises(ValueError, match=r"encoder 'h265' is not supported \(supported: libx264, mpeg4\)"):
        s.video(str(tmp_path / "v.mp4"), duration=0.2, fps=10, size=(96, 64), encoder="h265")
    with pytest.raises(ValueError, match=r"\.mp4"):
        s.video(str(tmp_path / "v.avi"), duration=0.2, fps=10, size=(96, 64))
    assert not list(tmp_path.iterdir())


def test_the_type_stub_checks_a_study_with_mypy(tmp_path):
    """The stub (scripts/make_stub.py, written beside the module) lets mypy check calls: a study that is right
    passes, a setting of the wrong type is an error naming it."""
    pytest.importorskip("mypy")
    import subprocess
    import sys
    package = os.path.dirname(os.path.dirname(rollviz.__file__))
    assert os.path.exists(os.path.join(package, "rollviz", "__init__.pyi"))
    good = tmp_path / "good.py"
    good.write_text(
        "import numpy as np\nimport rollviz\n"
        "s = rollviz.Scene.load('scenes/henon_heiles.json').set(energy=0.1)\n"
        "r = s.lyapunov(time=100, count=1, mode='tangent')\n"
        "t: np.ndarray = s.integrate(1.0, 0.5, ['t', 'E']).t\n"
        "p = s.poincare(points=10)['t']\n"
        "g = rollviz.sweep(s, axes={'energy': np.linspace(0.08, 0.12, 3)}, quantity='megno')\n"
        "n: int = s.page('m.html', duration=2.0)\n"
        "v = rollviz.Session.load('s.json').show()\n"
        "html: str = v.html if v is not None else ''\n")
    bad = tmp_path / "bad.py"
    bad.write_text("import rollviz\n"
                   "s = rollviz.Scene.load('scenes/henon_heiles.json')\n"
                   "s.lyapunov(time='long', mode='fast')\n")
    env = dict(os.environ, MYPYPATH=package)
    run = [sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache")]
    ok = subprocess.run(run + [str(good)], capture_output=True, text=True, env=env, timeout=600)
    assert ok.returncode == 0, ok.stdout + ok.stderr
    wrong = subprocess.run(run + [str(bad)], capture_output=True, text=True, env=env, timeout=600)
    assert wrong.returncode == 1, wrong.stdout
    assert '"time"' in wrong.stdout and '"mode"' in wrong.stdout, wrong.stdout


def test_the_stub_matches_the_built_module_and_checks_correct_calls(tmp_path):
    """stubtest: every public callable of the module is in the stub with the runtime's keywords (t_eval, events,
    after, t0, chart's style and scale, sweep's checkpoint, options and lanes, every tool's settings); mypy passes
    a study that uses them."""
    pytest.importorskip("mypy")
    import subprocess
    import sys
    package = os.path.dirname(os.path.dirname(rollviz.__file__))
    allowlist = os.path.join(os.path.dirname(__file__), "stubtest_allowlist.txt")
    env = dict(os.environ, MYPYPATH=package, ROLLVIZ_MODULE_PATH="")
    run = subprocess.run([sys.executable, "-m", "mypy.stubtest", "rollviz", "--allowlist", allowlist,
                          "--mypy-config-file", os.devnull], capture_output=True, text=True, env=env, cwd=package,
                         timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    good = tmp_path / "calls.py"
    good.write_text(
        "import numpy as np\nimport rollviz\n"
        "s = rollviz.Scene('henon_heiles', energy=0.1)\n"
        "r = s.integrate(t_eval=[0.5, 1.0], columns=['t', 'E'], events=('y', 0.0, 'positive'))\n"
        "r2 = s.integrate(2.0, 0.5, after=r)\n"
        "s2 = s.with_state(r.final if r.final is not None else s.initial_state)\n"
        "r3 = s2.integrate(1.0, 0.5, t0=float(r.t[-1]))\n"
        "img: np.ndarray = s.chart('poincare', size=(200, 200), style='paper', scale=2, path='c.svg')\n"
        "lyap = s.lyapunov(time=100, renormalize=True, transient=10.0)\n"
        "m = s.megno(time=100, transient=10.0)\n"
        "c = s.continuation(parameter='energy', to=0.12, method='arclength', switch=1)\n"
        "g = rollviz.sweep(s, axes={'map.0': (-0.1, 0.1, 3)}, quantity='megno', checkpoint='g.part',\n"
        "                  options={'refine': 1}, lanes=1)\n"
        "v = g.values['megno']\n"
        "m2 = rollviz.Model.load('examples/models/lorenz.json')\n")
    ok = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
                         str(good)], capture_output=True, text=True, env=env, timeout=600)
    assert ok.returncode == 0, ok.stdout + ok.stderr


def test_a_sweep_keeps_its_points_in_a_checkpoint_and_goes_on_from_them(tmp_path):
    sweep = tmp_path / "s.json"
    sweep.write_text(
        '{"scene": "%s", "axes": [{"id": "a", "min": 1.0, "max": 1.4, "count": 400}], "quantity": "lyapunov.max",'
        ' "set": {"lyapunov.time": 20000}}' % scene_path("henon_map.json"))
    whole = rollviz.sweep(str(sweep), threads=1)
    checkpoint = tmp_path / "s.sweep-part"

    def stop_early(fraction):
        if fraction > 0.2:
            raise RuntimeError("enough for now")

    with pytest.raises(RuntimeError, match="enough for now"):
        rollviz.sweep(str(sweep), threads=1, progress=stop_early, checkpoint=checkpoint)
    assert checkpoint.exists()  # the finished points are kept
    again = rollviz.sweep(str(sweep), threads=1, checkpoint=checkpoint)
    assert again.complete and again.status == ["ok"] * 400
    assert np.array_equal(again.columns["lyapunov.max"], whole.columns["lyapunov.max"])
    assert not checkpoint.exists()  # removed once complete


def test_ctrl_c_in_a_sweep_gives_the_points_finished_so_far():
    import signal
    import subprocess
    import sys
    import textwrap
    import time
    code = textwrap.dedent(f"""
        import sys, rollviz
        s = rollviz.Scene.load({scene_path('henon_map.json')!r})
        said = [False]
        def progress(f):
            if f > 0 and not said[0]:
                said[0] = True
                print("computing", flush=True)
        try:
            rollviz.sweep(s, axes={{"a": (1.0, 1.4, 2000)}}, quantity="lyapunov.max", threads=1, progress=progress,
                          **{{"lyapunov.time": 20000}})
        except KeyboardInterrupt as e:
            p = e.partial
            ok = p.status.count("ok")
            left = p.status.count("not computed")
            assert ok + left == 2000 and ok > 0 and left > 0, (ok, left)
            assert not p.complete and p["values"]["lyapunov.max"].shape == (2000,)
            print("partial", ok, left, flush=True)
            sys.exit(0)
        sys.exit(3)
    """)
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True, env=os.environ.copy())
    assert p.stdout.readline().strip() == "computing"
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=120)
    assert p.returncode == 0, out
    assert out.startswith("partial")


def test_output_at_given_times_backward_runs_and_events():
    s = rollviz.Scene.load(scene_path("henon_heiles.json"), **{"integrator.method": "verner9"})
    uniform = s.integrate(5, 0.5, ["t", "x", "y", "E"])
    # t_eval at the uniform times: the same samples of the same dense output, bit for bit
    at = s.integrate(t_eval=[0.5 * k for k in range(11)], columns=["t", "x", "y", "E"])
    assert np.array_equal(np.asarray(at), np.asarray(uniform)) and np.array_equal(at.t, uniform.t)
    odd = s.integrate(t_eval=[0.3, 1.7, 4.1], columns=["t", "y"])
    assert np.array_equal(odd["t"], [0.3, 1.7, 4.1])
    with pytest.raises(ValueError, match="t_eval"):
        s.integrate(t_eval=[1.0, 0.5])
    # backward, then forward from where it ended: back at the start to the integrator's accuracy
    back = s.integrate(-5, 0.5, ["t", "E"])
    assert back.t[-1] == -5 and np.all(np.diff(back.t) < 0)
    again = s.with_state(back.final).integrate(5, 0.5)
    assert np.max(np.abs(again.final - s.initial_state)) < 1e-9
    assert np.max(np.abs(back["E"] - back["E"][0])) < 1e-11  # the energy kept going backward
    # events on y = 0 upward: the Poincare tool's crossings of that section, the states on it
    r = s.integrate(30, 1.0, ["t", "x", "y", "px", "py"], events=("y", 0.0, "positive"))
    crossings = s.poincare(section="y", value=0.0, direction="positive", points=10 ** 6, max_time=30)
    assert len(r.events) == len(crossings) >= 3
    assert np.array_equal(r.events.t, crossings["t"])
    assert np.max(np.abs(r.events["y"])) < 1e-10 and np.all(r.events["t"] == r.events.t)


def test_continuing_a_trajectory_in_two_calls_equals_one_call_bit_for_bit():
    ids = [i["id"] for i in rollviz.integrators()]
    assert {"rk4", "verner9", "everhart", "adams"} <= set(ids)
    for method in ids:
        s = rollviz.Scene.load(scene_path("chaplygin_ball.json"), **{"integrator.method": method})
        whole = s.integrate(6, 0.5)
        first = s.integrate(2.5, 0.5)
        second = s.integrate(6, 0.5, after=first)
        third = s.integrate(6, 0.5, after=s.integrate(1, 0.5))  # any split
        assert np.array_equal(np.vstack([np.asarray(first), np.asarray(second)]), np.asarray(whole)), method
        assert np.array_equal(np.concatenate([first.t, second.t]), whole.t), method
        assert np.array_equal(third.final, whole.final), method
        back = s.integrate(-3, 0.5)
        assert np.array_equal(np.asarray(s.integrate(-6, 0.5, after=back))[-1], np.asarray(s.integrate(-6, 0.5))[-1])
    with pytest.raises(ValueError, match="another scene"):
        s.set(energy=0.4).integrate(6, 0.5, after=first)
    with pytest.raises(ValueError, match="sampled every 0.5"):
        s.integrate(6, 0.25, after=s.integrate(1, 0.5))


def test_a_failed_points_status_is_whole():
    """The sweep store keeps 120 bytes of a failure's reason; the points a call computes get it whole."""
    s = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    r = rollviz.sweep(s, axes={"K1": (0.66, 0.7, 3)}, quantity="fixedpoint.type",
                      **{"fixedpoint.guess": [-1.6661, 0.1045], "fixedpoint.max_iterations": 2})
    long = [x for x in r.status if len(x) > 130]
    assert long, r.status
    assert long[0].startswith("failed: ") and long[0].endswith("(the point lies outside the region of allowed motion))")


def test_a_motion_as_a_web_page_and_jupyters_rich_display(tmp_path):
    """Scene.page / show, Session.page, and what Jupyter displays (issue 63)."""
    import json
    s = rollviz.Scene.load(scene_path("ellipsoid_on_plane.json"))
    path = tmp_path / "m.html"
    frames = s.page(path, duration=1, fps=10)
    assert frames == 11
    text = path.read_text(encoding="utf-8")
    data = json.loads(re.search(r'id="rollviz-data">(.*?)</script>', text, re.S).group(1))
    assert data["frames"] == 11 and data["fps"] == 10 and data["variables"] == list(s.state_names)
    with pytest.raises(ValueError, match=r"\.html"):
        s.page(tmp_path / "m.png")
    with pytest.raises(ValueError, match="duration"):
        s.page(tmp_path / "n.html", duration=-1)
    assert not (tmp_path / "n.html").exists()
    # outside IPython, show() returns the view; Jupyter shows it as the page in an iframe
    view = s.show(duration=1, fps=5)
    assert isinstance(view, rollviz.PageView) and 'id="rollviz-data"' in view.html
    assert view._repr_html_().startswith("<iframe srcdoc=") and "&lt;script" in view._repr_html_()
    assert s._repr_html_().startswith("<iframe srcdoc=")
    assert s._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    # a trajectory plays its own time span; its table shows as HTML
    r = s.integrate(time=2, every=0.5, columns=["t", "E"])
    assert "<table>" in r._repr_html_() and "<th>E</th>" in r._repr_html_()
    shown = r.show(duration=1)
    played = json.loads(re.search(r'id="rollviz-data">(.*?)</script>', shown.html, re.S).group(1))
    assert played["speed"] == pytest.approx(2.0)
    # a session: its scene's motion beside its map
    ring = [(0.2 + 0.05 * np.cos(k / 10), 0.05 * np.sin(k / 10)) for k in range(63)]
    with open(scene_path("henon_heiles.json")) as f:
        hh = json.load(f)
    session = {"rollviz_session": 1, "scene": hh, "scene_path": "", "results": "", "tools": [],
               "trajectories": [{"start": [0, 0.1, 0.1, 0.3], "parameters": {}, "integrator": {},
                                 "colour": [1, 0, 0], "x": [p[0] for p in ring], "y": [p[1] for p in ring],
                                 "z": [], "state": [], "running": False, "first": 1, "last": 0, "origin": ""}]}
    (tmp_path / "s.json").write_text(json.dumps(session))
    se = rollviz.Session.load(tmp_path / "s.json")
    assert se.scene.problem == "henon_heiles"
    se.page(tmp_path / "s.html", duration=1)
    page = (tmp_path / "s.html").read_text(encoding="utf-8")
    m = json.loads(re.search(r'id="rollviz-data">(.*?)</script>', page, re.S).group(1))["map"]
    assert [m["x"], m["y"]] == ["y", "py"] and len(m["series"]) == 1
    with pytest.raises(ValueError, match="henon_heiles.json: not a rollviz session"):
        rollviz.Session.load(scene_path("henon_heiles.json"))


def test_a_rolling_body_described_in_python_turns_over_as_the_tippe_top_does():
    """A dozen lines of geometry (docs/rolling.md): rollviz derives the equations; every call works on them."""
    top = rollviz.Model({
        "kind": "rolling", "id": "python_tippe_top",
        "parameters": {"I1": {"default": 0.35}, "mu": {"default": 1.0}},
        "body": {"shape": "sphere", "radius": 1, "centre": "[0, 0, 0.3]", "axis": "[0, 0, 1]",
                 "mass": 1, "inertia": ["I1", "I1", 0.4]},
        "gravity": 1, "contact": "sliding", "friction": "mu"})
    start = {"omega1": 0, "omega2": 0, "omega3": 6, "gamma1": np.sin(0.1), "gamma2": 0, "gamma3": np.cos(0.1)}
    scene = rollviz.Scene(top, **{"initial.state": start, "integrator.method": "verner9",
                                  "integrator.tolerance": 1e-12})
    run = scene.integrate(50, 0.5, columns=["t", "axis_up", "jellett", "E"])
    up, jellett, energy = (np.asarray(run[c]) for c in ("axis_up", "jellett", "E"))
    assert up[0] > 0.99 and up.min() < -0.95 and up[-1] < -0.9
    assert np.ptp(jellett) < 1e-9 * abs(jellett[0]) and energy[-1] < energy[0]
    # outside the inertia window (I1/I3 > 1 + 0.3) the same top never stands on its stem
    tilted = scene.set(I1=0.6).integrate(50, 0.5, columns=["t", "axis_up"])
    assert np.asarray(tilted["axis_up"]).min() > -0.8


def test_rolling_body_builds_the_description_from_keywords():
    """rollviz.rolling_body: the same tippe top from keywords (vectors as sequences) runs as the dict's."""
    described = rollviz.Model({
        "kind": "rolling", "id": "dict_top",
        "parameters": {"I1": {"default": 0.35}, "mu": {"default": 1.0}},
        "body": {"shape": "sphere", "radius": 1, "centre": "[0, 0, 0.3]", "axis": "[0, 0, 1]",
                 "mass": 1, "inertia": ["I1", "I1", 0.4]},
        "gravity": 1, "contact": "sliding", "friction": "mu"})
    built = rollviz.rolling_body("sphere", id="built_top", radius=1, centre=[0, 0, 0.3], axis=np.array([0, 0, 1]),
                                 mass=1, inertia=["I1", "I1", 0.4], contact="sliding", friction="mu",
                                 parameters={"I1": 0.35, "mu": 1.0})
    assert isinstance(built, rollviz.Model) and built.id == "built_top"
    start = {"omega1": 0, "omega2": 0, "omega3": 6, "gamma1": np.sin(0.1), "gamma2": 0, "gamma3": np.cos(0.1)}
    runs = [rollviz.Scene(m, **{"initial.state": start, "integrator.method": "verner9"}).integrate(
        5, 0.5, columns=["t", "axis_up", "E"]) for m in (described, built)]
    for c in ("axis_up", "E"):
        assert np.array_equal(np.asarray(runs[0][c]), np.asarray(runs[1][c]))
    # in a bowl given by its implicit surface, rolling
    bowl = rollviz.rolling_body("ellipsoid", id="egg_in_a_bowl", semi_axes=[0.5, 0.4, 0.3], mass=1,
                                inertia=[0.05, 0.06, 0.08], gravity=9.81,
                                support={"surface": "implicit", "F": "z - (x^2 + y^2)/4", "size": 2},
                                initial={"M1": 0.01, "M2": 0, "M3": 0.1, "gamma1": 0.1, "gamma2": 0,
                                         "gamma3": np.sqrt(0.99)})
    E = np.asarray(rollviz.Scene(bowl, **{"integrator.method": "verner9", "integrator.tolerance": 1e-12})
                   .integrate(5, 0.5, columns=["t", "E"])["E"])
    assert np.ptp(E) < 1e-9 * abs(E[0])
    with pytest.raises(ValueError, match="body.semi_axes: a sphere has no \"semi_axes\""):
        rollviz.rolling_body("sphere", radius=1, semi_axes=[1, 2, 3], mass=1, inertia=[1, 1, 1])
    with pytest.raises(TypeError, match="rolling_body\\(\\): centre takes a number"):
        rollviz.rolling_body("sphere", radius=1, centre={"x": 0}, mass=1, inertia=[1, 1, 1])
