"""The Python module against the CLI: the same numbers to the last digit, NumPy shapes and dtypes, the lists,
the exceptions with the CLI's messages, the GIL released during a computation, Ctrl-C, pictures."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

from conftest import SOURCE, cli, cli_json, read_csv, scene_path

rollviz = pytest.importorskip("rollviz")


def test_integrate_equals_the_cli(tmp_path):
    out = tmp_path / "cli.csv"
    cli("integrate", scene_path("chaplygin_ball.json"), "--time", 5, "--every", 0.5, "--columns", "t,E,M1,gamma3",
        "-o", out)
    header, expected = read_csv(out)
    r = rollviz.Scene.load(scene_path("chaplygin_ball.json")).integrate(time=5, every=0.5, columns=header)
    X = np.asarray(r)
    assert r.t.dtype == np.float64 and X.dtype == np.float64
    assert r.t.shape == (11,) and X.shape == (11, 4) and r.columns == header
    assert np.array_equal(X, expected)  # bit for bit: the same computation, %.17g round-trips
    assert np.array_equal(r.t, expected[:, 0])
    for k, name in enumerate(header):  # named columns are the array's
        assert np.array_equal(r[name], expected[:, k])


def test_a_set_scene_equals_the_cli_with_set(tmp_path):
    out = tmp_path / "cli.csv"
    cli("integrate", scene_path("chaplygin_ball.json"), "--set", "energy=0.4", "--set", "integrator.method=everhart",
        "--time", 2, "--every", 0.25, "--columns", "t,E,M2", "-o", out)
    _, expected = read_csv(out)
    s = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    s2 = s.set(energy=0.4, **{"integrator.method": "everhart"})
    assert s2 is not s and s.parameters["energy"] == 0.5  # a new scene; this one is unchanged
    assert s2.parameters["energy"] == 0.4
    assert np.array_equal(np.asarray(s2.integrate(2, 0.25, ["t", "E", "M2"])), expected)
    # the same keywords in the call itself
    assert np.array_equal(np.asarray(s.integrate(2, 0.25, ["t", "E", "M2"], energy=0.4,
                                                 **{"integrator.method": "everhart"})), expected)


def test_scene_of_a_problem_is_its_shipped_scene():
    a = rollviz.Scene("henon_heiles", E=0.1) if "E" in rollviz.Scene("henon_heiles").parameters else None
    s = rollviz.Scene("chaplygin_ball", energy=0.4)
    assert s.problem == "chaplygin_ball" and s.parameters["energy"] == 0.4
    assert s.parameters["c"] == rollviz.Scene.load(scene_path("chaplygin_ball.json")).parameters["c"]
    del a


def test_poincare_equals_the_cli(tmp_path):
    out = tmp_path / "map.csv"
    cli("poincare", scene_path("henon_heiles.json"), "--points", 150, "-o", out)
    header, expected = read_csv(out)
    P = rollviz.Scene.load(scene_path("henon_heiles.json")).poincare(points=150)
    assert isinstance(P, rollviz.Table) and P.columns == header
    assert np.asarray(P).dtype == np.float64 and P.shape == expected.shape == (150, len(header))
    assert np.array_equal(np.asarray(P), expected)
    assert np.array_equal(P["t"], expected[:, header.index("t")]) and len(P) == 150


def test_lyapunov_and_megno_equal_the_cli():
    s = rollviz.Scene.load(scene_path("henon_map.json"))
    expected = cli_json("lyapunov", scene_path("henon_map.json"), "--time", 500)
    r = s.lyapunov(time=500)
    assert list(r.exponents) == expected["exponents"] and r.converged == expected["converged"]
    assert r.time == expected["time"] and r.sum == expected["sum"]
    assert r.history.columns == ["t", "L1", "L2"] and r.history["t"][-1] <= r.time
    m = rollviz.Scene.load(scene_path("henon_heiles.json")).megno(time=200)
    e = cli_json("megno", scene_path("henon_heiles.json"), "--time", 200)
    assert (m.megno, m.fli, m.y, m.time) == (e["megno"], e["fli"], e["y"], e["time"])
    assert m.history["t"].shape == m.history["megno"].shape


def test_fixedpoint_equals_the_cli():
    e = cli_json("fixedpoint", scene_path("henon_map.json"), "--guess", "0.63,0.19")
    r = rollviz.Scene.load(scene_path("henon_map.json")).fixedpoint(guess=[0.63, 0.19])
    assert list(r.point) == e["point"] and r.type == e["type"] and r.residual == e["residual"]
    assert r.multipliers.dtype == np.complex128
    assert [[z.real, z.imag] for z in r.multipliers] == e["multipliers"]
    # the Henon map's fixed point, independently: x = (b - 1 + sqrt((1 - b)^2 + 4a)) / 2a, y = b x
    a, b = 1.4, 0.3
    x = (b - 1 + np.sqrt((1 - b) ** 2 + 4 * a)) / (2 * a)
    assert np.allclose(r.point, [x, b * x], atol=1e-12)


def test_continuation_routes_its_keywords_to_the_sections():
    s = rollviz.Scene.load(scene_path("henon_map.json"))
    # guess belongs to fixedpoint (the tool's parent), parameter/to/step to continuation
    r = s.continuation(guess=[0.63, 0.19], parameter="a", to=1.3, step=-0.05)
    assert r.parameter == "a" and len(r.parameter_values) == r.points.shape[0] >= 2
    assert np.isclose(r.parameter_values[0], 1.4) and np.isclose(r.parameter_values[-1], 1.3)
    for av, (x, y) in zip(r.parameter_values, r.points):
        assert np.isclose(x, (0.3 - 1 + np.sqrt(0.49 + 4 * av)) / (2 * av), atol=1e-9)


def test_every_problem_and_tool_is_listed():
    problems = [line.split()[0] for line in cli("list", "problems").stdout.splitlines()]
    assert [p["id"] for p in rollviz.problems()] == problems
    for p in problems:
        d = rollviz.describe(p)
        assert d["id"] == p and d["observables"] and d["parameters"] is not None
    ids = [line.split()[0] for line in cli("list", "tools").stdout.splitlines()
           if line.strip() and not line.startswith("rollviz")]
    tools = rollviz.tools()
    assert [t.id for t in tools] == ids
    for t in tools:
        if t.id == "sweep":
            continue
        method = getattr(rollviz.Scene, t.id)
        assert t.title in method.__doc__
        for setting in t.settings:  # every setting of its section is documented on the method
            assert setting["id"] in method.__doc__


def test_bad_input_raises_valueerror_with_the_cli_message():
    s = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    p = cli("integrate", scene_path("chaplygin_ball.json"), "--set", "no_such_param=1", "--time", 1, "--every", 1,
            check=False)
    assert p.returncode == 2
    with pytest.raises(TypeError, match="no_such_param"):  # Python's words for a keyword it does not take
        s.set(no_such_param=1)
    bad = cli("integrate", scene_path("chaplygin_ball.json"), "--set", "integrator.method=nope", "--time", 1,
              "--every", 1, check=False)
    assert bad.returncode == 2
    with pytest.raises(ValueError) as e:  # a bad value of a scene key: the scene loader's words, the call's name
        s.set(**{"integrator.method": "nope"})
    said = bad.stderr.strip().removeprefix("rollviz: ")
    assert str(e.value) == "set(): " + said[said.index("integrator.method: "):]
    assert s.parameters["energy"] == 0.5  # left as it was
    with pytest.raises(TypeError, match=r"megno\(\) got an unexpected keyword argument 'foo'"):
        s.megno(foo=1)
    with pytest.raises(ValueError, match="columns: unknown observable 'nope'"):
        s.integrate(1, 0.1, ["t", "nope"])
    with pytest.raises(ValueError, match="no_such_problem"):
        rollviz.Scene("no_such_problem")
    with pytest.raises(ValueError, match="time must be a finite number, got nan"):
        s.integrate(float("nan"), 0.1)
    with pytest.raises(ValueError, match="every: must be positive"):
        s.integrate(1, 0)


def test_a_failed_computation_raises_computationerror():
    args = ["fixedpoint", scene_path("henon_map.json"), "--guess", "5,5", "--set", "fixedpoint.max_iterations=2"]
    p = cli(*args, check=False)
    assert p.returncode == 1
    with pytest.raises(rollviz.ComputationError) as e:
        rollviz.Scene.load(scene_path("henon_map.json")).fixedpoint(guess=[5, 5], max_iterations=2)
    assert str(e.value) == p.stderr.strip().removeprefix("rollviz: failed: ")
    assert issubclass(rollviz.ComputationError, RuntimeError)


def test_the_gil_is_released_during_a_computation():
    # another thread takes the GIL back 2000 times while one call computes, and the call ends (its progress
    # callback raises) once it has: no rate measured. Were the GIL held while computing, that thread would get
    # it only at the caller's progress polls (one every 50 ms): 100 s, past the generous deadline
    s = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    under_way, spun = threading.Event(), threading.Event()
    turns = [0]

    def spin():
        under_way.wait()
        while turns[0] < 2000:
            turns[0] += 1
            time.sleep(0.0001)  # lets the GIL go: the next turn takes it again
        spun.set()

    class Enough(Exception):
        pass

    deadline = time.monotonic() + 60

    def progress(_):
        under_way.set()  # (called on the caller's thread, inside the call)
        if spun.is_set() or time.monotonic() > deadline:
            raise Enough

    th = threading.Thread(target=spin)
    th.start()
    try:
        with pytest.raises(Enough):  # 10^6 time units: the call would go on for a minute or more
            s.integrate(time=1e6, every=10, columns=["t"], progress=progress)
    finally:
        under_way.set()
        th.join()
    assert spun.is_set(), f"{turns[0]} turns of 2000 while the call computed"


def test_progress_is_reported_on_the_calling_thread():
    seen = []
    caller = threading.get_ident()
    rollviz.Scene.load(scene_path("chaplygin_ball.json")).integrate(
        3000, 1, ["t"], progress=lambda f: seen.append((f, threading.get_ident())))
    fractions = [f for f, _ in seen]
    assert fractions[-1] == 1.0 and fractions == sorted(fractions) and len(fractions) >= 2
    assert all(tid == caller for _, tid in seen)


def test_an_exception_in_the_progress_callback_stops_the_call():
    def stop(_):
        raise RuntimeError("enough")

    # 10^8 time units (hours of work): the call returns at all only because the exception stopped it (no
    # clock: were it not stopped, ctest's timeout says so)
    with pytest.raises(RuntimeError, match="enough"):
        rollviz.Scene.load(scene_path("chaplygin_ball.json")).integrate(1e8, 1000, ["t"], progress=stop)


def test_ctrl_c_stops_a_long_call_with_keyboardinterrupt():
    # "started" is said from inside the call (its first progress report), so the signal cannot come before
    # it, however slowly the child starts; 10^9 time units: it returns at all only because Ctrl-C stopped it
    code = textwrap.dedent(f"""
        import sys, time, rollviz
        s = rollviz.Scene.load({scene_path('chaplygin_ball.json')!r})
        said = []

        def started(_):
            if not said:
                said.append(1)
                print("started", flush=True)

        t0 = time.time()
        try:
            s.lyapunov(time=1e9, progress=started)
        except KeyboardInterrupt:
            print("interrupted after", time.time() - t0, flush=True)
            sys.exit(0)
        sys.exit(3)
    """)
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True, env=os.environ.copy())
    assert p.stdout.readline().strip() == "started"
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=120)
    assert p.returncode == 0, out
    assert "interrupted" in out


def test_render_is_the_clis_picture(tmp_path):
    from PIL import Image
    png = tmp_path / "cli.png"
    cli("render", scene_path("chaplygin_ball.json"), "--size", "320x240", "--time", 2, "-o", png)
    img = rollviz.Scene.load(scene_path("chaplygin_ball.json")).render(size=(320, 240), time=2)
    assert img.shape == (240, 320, 3) and img.dtype == np.uint8
    assert img.std() > 5, "blank picture"
    expected = np.asarray(Image.open(png).convert("RGB"))
    diff = np.abs(img.astype(int) - expected.astype(int))
    assert diff.mean() < 0.5 and (diff > 40).mean() < 0.002, (diff.mean(), (diff > 40).mean())


def test_chart_and_video(tmp_path):
    s = rollviz.Scene.load(scene_path("henon_map.json"))
    img = s.chart("poincare", size=(200, 160), points=500)
    assert img.shape == (160, 200, 3) and img.std() > 5
    # written as a figure in the format its extension names: SVG with the text as text, PDF; another is refused
    svg, pdf = tmp_path / "map.svg", tmp_path / "map.pdf"
    again = s.chart("poincare", size=(200, 160), points=500, path=str(svg))
    assert again.shape == img.shape
    assert b"<svg" in svg.read_bytes()
    s.chart("poincare", size=(200, 160), points=500, path=str(pdf))
    assert pdf.read_bytes()[:5] == b"%PDF-"
    with pytest.raises(ValueError, match=r"map\.jpg.*\.png, \.svg, \.pdf"):
        s.chart("poincare", size=(200, 160), points=500, path=str(tmp_path / "map.jpg"))
    assert not (tmp_path / "map.jpg").exists()
    # for print: the paper style's column (1050 x 788 unless size), a scale of the pixels; others refused
    assert s.chart("poincare", points=500, style="paper").shape == (788, 1050, 3)
    assert s.chart("poincare", size=(200, 160), points=500, scale=2).shape == (320, 400, 3)
    with pytest.raises(ValueError, match="screen or paper"):
        s.chart("poincare", size=(200, 160), points=500, style="print")
    with pytest.raises(ValueError, match="1..8"):
        s.chart("poincare", size=(200, 160), points=500, scale=9)
    # a file's format follows its extension: another is refused, nothing written
    with pytest.raises(ValueError, match=r"\.mp4"):
        s.video(str(tmp_path / "v.avi"), duration=0.2, fps=10, size=(96, 64))
    assert not (tmp_path / "v.avi").exists()
    with pytest.raises(ValueError, match=r"\.png"):
        rollviz.Scene.load(scene_path("chaplygin_ball.json")).snapshot(str(tmp_path / "s.jpg"), size=(64, 48))
    assert not (tmp_path / "s.jpg").exists()
    out = tmp_path / "v.mp4"
    frames = rollviz.Scene.load(scene_path("chaplygin_ball.json")).video(str(out), duration=0.4, fps=10,
                                                                         size=(96, 64))
    assert frames == 4 and out.stat().st_size > 0


def test_sweep_equals_the_cli(tmp_path):
    sweep = tmp_path / "s.json"
    sweep.write_text(
        '{"scene": "%s", "axes": [{"id": "a", "min": 1.0, "max": 1.4, "count": 5}], "quantity": "lyapunov.max",'
        ' "set": {"lyapunov.time": 200}}' % scene_path("henon_map.json"))
    out = tmp_path / "s.csv"
    cli("sweep", sweep, "-o", out, "--threads", 2)
    import csv
    rows = list(csv.DictReader(open(out)))
    r = rollviz.sweep(str(sweep), threads=2)
    assert r.complete and r.shape == [5] and r.status == ["ok"] * 5
    assert list(r.columns["a"]) == [float(x["a"]) for x in rows]
    assert list(r.columns["lyapunov.max"]) == [float(x["lyapunov.max"]) for x in rows]


def test_every_tool_runs_from_python():
    """Each tool of the registry answers on a small case (the ones above check numbers)."""
    hm = rollviz.Scene.load(scene_path("henon_map.json"))
    m = rollviz.Scene.load(scene_path("henon_heiles.json")).map3d(points=10)  # a 2D map: the first 3 state variables
    assert m.shape == (10, 3) and m.columns == ["x", "y", "px"]
    assert hm.spectrum(function="x", samples=256).frequency.size > 0
    assert hm.plot(**{"plot.x": "x", "plot.y": "y", "plot.time_limit": 50}).shape[1] == 2
    r = hm.multipliers(guess=[0.63, 0.19], parameter="a", to=1.35, step=-0.05)
    assert r.multipliers.dtype == np.complex128 and r.multipliers.shape[0] >= 2 == r.multipliers.shape[1]
    assert np.allclose(np.prod(r.multipliers, axis=1), -0.3)  # det of the Henon map's Jacobian: -b
    assert np.array_equal(r.re1, r.multipliers[:, 0].real) and r.step.size == r.multipliers.shape[0]
    sep = hm.separatrix(guess=[0.63, 0.19], branches=[1], points=50)
    assert sep.fixedpoint.type.startswith("hyperbolic") and sep.branches[1].points.shape[1] == 2
    g = hm.surface(step_x=0.5, step_y=0.5, x_min=-1, x_max=1, y_min=-1, y_max=1)
    assert g.distance.shape == (g.y.size, g.x.size) == (5, 5)
    # the CLI's arguments as keywords (--x MIN,MAX is x=(MIN, MAX)): the same grid, the same numbers
    h = hm.surface(x=(-1, 1), y=(-1, 1), step=0.5)
    assert np.array_equal(h.distance, g.distance) and np.array_equal(h.x, np.linspace(-1, 1, 5))
    assert h.nodes == 25 and h.coordinates == ["x", "y"]
    with pytest.raises(ValueError, match="x=.*MIN <= MAX"):
        hm.surface(x=(1, -1))
    cb = rollviz.Scene.load(scene_path("chaplygin_ball.json"))
    d = cb.diagram()
    # rows of (branch, parameter, the two axes), the scene's point last; the branches described
    assert len(d.branch) == d.parameter.size == d[d.axes[0]].size == d[d.axes[1]].size
    assert d.branch[-1] == "state" and list(d[d.axes[0]][-1:]) == [d.state[0]]
    assert d.branch[:-1] and set(d.branch[:-1]) <= {b["id"] for b in d.branches}  # some may have no points
    one = cb.diagram(branch="tau", min=0.5, max=0.6, step=0.05)
    assert one.branch == ["tau", "tau", "tau", "state"] and np.allclose(one.parameter[:3], [0.5, 0.55, 0.6])
    assert cb.diagram(diagram="ch").axes == [d.diagrams[1][0], "h"] == ["c", "h"]
    assert cb.ram(step_x=0.5, step_y=0.5).allowed.ndim == 2
    # the standard map's fixed point (pi, 0) doubles its period at K = 4 (trace of the Jacobian 2 - K = -2)
    sm = rollviz.Scene.load(scene_path("standard_map.json"), K=3.5)
    # parameter, to, step: the continuation section's (the tool reads it, ToolEntry::alsoSections)
    tree = sm.bifurcation_tree(guess=[np.pi, 0], parameter="K", to=4.5, step=0.05, levels=1)
    assert tree.rows.shape[1] == len(tree.columns)
    assert tree.doublings and abs(tree.doublings[0].parameter - 4) < 1e-6


def test_arclength_continuation_and_a_bifurcation_curve_from_python():
    """The Henon map's fold, passed by arclength; its period-doubling curve a = 3 (1 - b)^2 / 4 in (a, b)."""
    hm = rollviz.Scene.load(scene_path("henon_map.json"), a=0)
    x0 = 1 / 0.7
    c = hm.continuation(guess=[x0, 0.3 * x0], parameter="a", to=-0.5, step=-0.01, method="arclength", points=250)
    assert [ch["kind"] for ch in c.changes] == ["fold"]
    assert abs(c.changes[0]["parameter"] + 0.1225) < 1e-9
    assert "250 points" in c.end and c.parameter_values.size == 250
    hm = rollviz.Scene.load(scene_path("henon_map.json"))
    d = hm.continuation(guess=[0.63, 0.19], parameter="a", to=0, step=-0.05, switch=1)  # branch switching
    assert d.order == 2 and abs(d.parent.changes[0].parameter - 0.3675) < 1e-9
    a, x = d.parameter_values, d.points[:, 0]
    assert np.max(np.abs(x * x - 0.7 / a * x + (0.49 - a) / a ** 2)) < 1e-9 and abs(a[-1] - 1.4) < 1e-12
    # a plain keyword is the tool's own setting first (step, points), then its parents' (parameter, to, guess)
    r = hm.bifurcation_curve(guess=[0.63, 0.19], parameter="a", to=0, second_parameter="b", kind="period_doubling",
                             second_min=-0.5, second_max=0.5, **{"continuation.step": -0.05})
    assert r["kind"] == "period doubling" and r["parameters"] == ["a", "b"]
    assert r["a"].size == r["points"] > 10
    assert np.max(np.abs(r["a"] - 0.75 * (1 - r["b"]) ** 2)) < 1e-8
    assert np.max(np.abs(r["x"] - 2 / (3 * (1 - r["b"])))) < 1e-8


def test_a_model_file_from_python_equals_the_cli(tmp_path, monkeypatch):
    # interpreted here (the compiled path has its own tests): the same numbers as `rollviz integrate` on the file
    monkeypatch.setenv("ROLLVIZ_COMPILE_MODELS", "0")
    path = os.path.join(SOURCE, "examples", "models", "henon_heiles.json")
    scene = tmp_path / "hh.json"
    scene.write_text('{"problem": "%s", "parameters": {"energy": 0.1}, "initial": {"map": [0.1, 0.05]}}' % path)
    out = tmp_path / "cli.csv"
    cli("integrate", scene, "--time", 3, "--every", 1, "--columns", "t,x,y,px,py,E", "-o", out)
    header, expected = read_csv(out)
    m = rollviz.Model.load(path)
    assert m.id == "henon_heiles_equations" and m.path == path
    assert [p["id"] for p in m.describe()["parameters"]] == ["energy"]
    X = np.asarray(rollviz.Scene(m, energy=0.1, **{"initial.map": [0.1, 0.05]}).integrate(time=3, every=1,
                                                                                          columns=header))
    assert np.array_equal(X, expected)
    # a dict with the same content is the same model; a bad expression is a ValueError naming the place
    import json
    with open(path) as f:
        content = json.load(f)
    content["id"] = "hh_from_a_dict"
    X2 = np.asarray(rollviz.Scene(rollviz.Model(content), energy=0.1, **{"initial.map": [0.1, 0.05]}).integrate(
        time=3, every=1, columns=header))
    assert np.array_equal(X2, expected)
    content["id"] = "hh_broken"
    content["equations"]["px"] = "-x - 2*x*yy"
    with pytest.raises(ValueError, match=r"equations.px: column 10: unknown name 'yy'"):
        rollviz.Model(content)


def test_the_fixed_point_family_in_python_is_its_runners():
    """The runners' flags as keywords, and the table's columns beside the family's arrays."""
    sm = rollviz.Scene.load(scene_path("tools/continuation.json"))
    with pytest.warns(DeprecationWarning, match="use switch=1"):
        a = sm.continuation(to=4.2, doubled=True)  # the deprecated flag argument: continuation.switch = 1
    b = sm.continuation(to=4.2, switch=1)
    assert a.order == 2 and np.array_equal(a.parameter_values, b.parameter_values)
    assert a.parent.parameter_values[0] == 3.5
    with pytest.warns(DeprecationWarning):
        c = sm.continuation(doubled=False)  # a flag given False is not given
    assert "order" not in c and c.multipliers.dtype == np.complex128
    # the columns of the CLI's CSV, by name: the trace of the Jacobian at (pi, 0) is 2 - K
    assert np.array_equal(c.K, c.parameter_values) and c.type == c.types
    assert np.allclose(c.re1 + c.re2, 2 - c.K, atol=1e-9)
    assert np.allclose(c.multipliers.real.sum(axis=1), 2 - c.parameter_values, atol=1e-9)
    t = rollviz.Scene.load(scene_path("tools/bifurcation_tree.json")).bifurcation_tree()
    assert np.array_equal(t.level, t.rows[:, 0]) and abs(t.doublings[0].parameter - 4) < 1e-6
    assert len(t.type) == t.rows.shape[0]
    f = rollviz.Scene.load(scene_path("tools/fixedpoint.json")).fixedpoint()
    assert f.path.shape[1] == 2 and np.allclose(f.path[-1], f.point)
