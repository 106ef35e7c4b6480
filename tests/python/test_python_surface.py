"""The Python surface without traps (issue 60, item 6): one name per setting, real booleans, errors in Python's
own words, exact stepping on from a state, transients, meaningful exponents, signatures, short help and reprs,
Jupyter's views, sweep dimensions named after the map's coordinates."""

import inspect
import os
import pydoc
import warnings

import numpy as np
import pytest

from conftest import scene_path

rollviz = pytest.importorskip("rollviz")


def hh(**settings):
    return rollviz.Scene.load(scene_path("henon_heiles.json"), **settings)


def test_one_name_per_setting_the_others_warn_and_name_the_one_to_use():
    hm = rollviz.Scene.load(scene_path("henon_map.json"))
    plain = hm.continuation(guess=[0.63, 0.19], parameter="a", to=1.3, step=-0.05)
    with pytest.warns(DeprecationWarning, match=r"continuation\(\): param is deprecated; use parameter"):
        old = hm.continuation(guess=[0.63, 0.19], param="a", to=1.3, step=-0.05)
    assert np.array_equal(old.points, plain.points)
    x0 = 1 / 0.7
    fold = dict(guess=[x0, 0.3 * x0], parameter="a", to=-0.5, step=-0.01, points=250)
    with pytest.warns(DeprecationWarning, match=r"use method='arclength'"):
        old = rollviz.Scene.load(scene_path("henon_map.json"), a=0).continuation(arclength=True, **fold)
    new = rollviz.Scene.load(scene_path("henon_map.json"), a=0).continuation(method="arclength", **fold)
    assert np.array_equal(old.parameter_values, new.parameter_values)
    with pytest.raises(TypeError, match="not method and its deprecated name"):
        hm.continuation(arclength=True, method="natural", **fold)
    # the signatures name only the one to use
    for tool in ("continuation", "multipliers", "bifurcation_tree", "bifurcation_curve"):
        params = inspect.signature(getattr(rollviz.Scene, tool)).parameters
        assert not {"param", "arclength", "doubled"} & set(params), tool
        assert "parameter" in params
    # and the warning points at the caller's line
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        hm.continuation(guess=[0.63, 0.19], param="a", to=1.35, step=-0.05)
    assert caught and caught[0].filename == __file__


def test_flags_take_real_booleans():
    s = hh()
    sig = inspect.signature(rollviz.Scene.lyapunov).parameters["renormalize"]
    assert sig.annotation is bool and sig.default is False
    yes = s.lyapunov(time=20, renormalize=True)
    assert np.array_equal(yes.exponents, s.lyapunov(time=20, renormalize="yes").exponents)  # still taken
    assert np.array_equal(s.lyapunov(time=20, renormalize=False).exponents, s.lyapunov(time=20).exponents)
    assert np.array_equal(s.lyapunov(time=20, renormalize=np.bool_(True)).exponents, yes.exponents)
    with pytest.raises(TypeError, match="renormalize takes True or False"):
        s.lyapunov(time=20, renormalize=1)
    # a flag that is also a flag argument of the command (fixedpoint --path) takes False as no
    f = rollviz.Scene.load(scene_path("tools/fixedpoint.json"))
    assert f.fixedpoint(path=True).path.shape[1] == 2 and np.array_equal(f.fixedpoint(path=False).point, f.fixedpoint().point)
    assert np.array_equal(np.asarray(s.poincare(points=5, many_sheeted=False)), np.asarray(s.poincare(points=5)))


@pytest.mark.parametrize("call", [
    lambda: rollviz.Scene("henon_heiles", enrgy=0.1),
    lambda: rollviz.Scene.load(scene_path("henon_heiles.json"), enrgy=0.1),
    lambda: hh().set(enrgy=0.1),
    lambda: hh().with_state([0.1, 0, 0, 0.3], enrgy=0.1),
    lambda: hh().integrate(1, 0.5, enrgy=0.1),  # (or 'every')
    lambda: hh().lyapunov(enrgy=0.1),
    lambda: hh().render(enrgy=0.1),
])
def test_a_misspelled_keyword_is_a_type_error_that_suggests_everywhere(call):
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'enrgy'; did you mean 'energy'"):
        call()


def test_a_misspelled_keyword_of_a_call_suggests_its_own_names():
    s = hh()
    with pytest.raises(TypeError, match=r"integrate\(\) got an unexpected keyword argument 'tme'; did you mean 'time'\?"):
        s.integrate(tme=1, every=0.5)
    with pytest.raises(TypeError, match=r"did you mean 'time'\?"):
        s.megno(tme=10)


def test_non_finite_numbers_are_value_errors_naming_the_argument():
    nan = float("nan")
    with pytest.raises(ValueError, match=r"^Scene\(\): rho must be a finite number, got nan$"):
        rollviz.Scene("lorenz", rho=nan)
    with pytest.raises(ValueError, match=r"with_state\(\): y must be a finite number, got nan"):
        hh().with_state([0.1, nan, 0, 0.3])
    with pytest.raises(ValueError, match=r"with_state\(\): px must be a finite number, got inf"):
        hh().with_state({"x": 0, "y": 0.1, "px": float("inf"), "py": 0.3})
    with pytest.raises(ValueError, match=r"set\(\): initial.state: x must be a finite number, got nan"):
        hh().set(**{"initial.state": {"x": nan, "y": 0.1, "px": 0, "py": 0.3}})
    with pytest.raises(ValueError, match=r"Scene\(\): initial.state: z must be a finite number, got nan"):
        rollviz.Scene("lorenz", **{"initial.state": [1, 1, nan]})
    with pytest.raises(ValueError, match=r"lyapunov\(\): lyapunov.time must be a finite number, got inf"):
        hh().lyapunov(**{"lyapunov.time": float("inf")})
    with pytest.raises(ValueError, match=r"from_json\(\): NaN is not a number"):
        rollviz.Scene.from_json('{"problem": "lorenz", "initial": {"state": {"x": NaN, "y": 1, "z": 1}}}')
    # no command-line wording, no JSON parser's
    with pytest.raises(ValueError) as bad:
        rollviz.Scene("lorenz", **{"integrator.method": "no_such_method"})
    assert "--set" not in str(bad.value) and str(bad.value).startswith("Scene(): ")


def test_lyapunov_and_megno_take_no_poincare_keywords_and_accuracy_has_one_meaning():
    s = hh()
    for key, value in (("points", 10), ("section", "y"), ("direction", "both")):
        with pytest.raises(TypeError, match=f"lyapunov\\(\\) got an unexpected keyword argument '{key}'"):
            s.lyapunov(time=10, **{key: value})
        with pytest.raises(TypeError, match=f"megno\\(\\) got an unexpected keyword argument '{key}'"):
            s.megno(time=10, **{key: value})
    lyap = {t.id: t for t in rollviz.tools()}["lyapunov"]
    assert lyap.sections == ["lyapunov"]
    assert [k["section"] for k in lyap.keywords if k["id"] == "accuracy"] == ["lyapunov"]
    # megno's accuracy was the section's crossing accuracy, which it never read: ignored, with a warning
    with pytest.warns(DeprecationWarning, match=r"megno\(\): accuracy is deprecated and ignored"):
        m = s.megno(time=20, accuracy=1e-3)
    assert m.megno == s.megno(time=20).megno
    assert "accuracy" not in inspect.signature(rollviz.Scene.megno).parameters


def test_the_continuations_points_are_what_its_docstring_says():
    hm = rollviz.Scene.load(scene_path("henon_map.json"))
    r = hm.continuation(guess=[0.63, 0.19], parameter="a", to=1.3, step=-0.05)
    n = len(r.parameter_values)
    assert r.points.shape == (n, len(r.coordinates)) == (n, 2)
    doc = rollviz.Scene.continuation.__doc__
    assert "how many points" not in doc
    assert "points: the fixed points: an N x d array" in doc


@pytest.mark.parametrize("name, step", [("henon_heiles.json", 2 ** -6), ("chaplygin_ball.json", 2 ** -7)])
def test_stepping_on_from_a_state_continues_the_trajectory_exactly(name, step):
    """rk4 at a step that divides the times: a run to 5 and one from its final state (and time) to 10 are one
    run to 10, bit for bit -- the state is carried whole and exact (the Chaplygin ball's Poisson vector is not
    renormalised), the clock goes on from t0."""
    s = rollviz.Scene.load(scene_path(name), **{"integrator.method": "rk4", "integrator.step": step})
    whole = s.integrate(10, 0.5)
    first = s.integrate(5, 0.5)
    on = s.with_state(first.final)
    assert np.array_equal(on.initial_state, first.final)
    second = on.integrate(5, 0.5, t0=first.t[-1])
    assert np.array_equal(second.t, whole.t[10:])
    assert np.array_equal(np.asarray(second), np.asarray(whole)[10:])
    assert np.array_equal(second.final, whole.final)
    # and the scene keeps it through its JSON (pickle, save)
    again = rollviz.Scene.from_json(on.to_json())
    assert np.array_equal(again.initial_state, first.final)


def test_stepping_on_at_any_step_agrees_to_rounding():
    s = hh(**{"integrator.method": "rk4", "integrator.step": 0.01})
    whole = s.integrate(10, 0.5)
    first = s.integrate(5, 0.5)
    second = s.with_state(first.final).integrate(5, 0.5, t0=first.t[-1])
    assert np.array_equal(second.t, whole.t[10:])
    assert np.max(np.abs(np.asarray(second) - np.asarray(whole)[10:])) < 1e-14
    with pytest.raises(ValueError, match="t0 must be a finite number"):
        s.integrate(1, 0.5, t0=float("nan"))


def test_a_transient_is_discarded_in_lyapunov_and_megno():
    s = hh(**{"integrator.method": "rk4", "integrator.step": 2 ** -6})
    # megno(transient=T) is megno from where the trajectory is at T
    at = s.integrate(t_eval=[16.0], columns=["t"]).final
    assert s.megno(time=50, transient=16).megno == s.with_state(at).megno(time=50).megno
    assert s.megno(time=50, transient=16).megno != s.megno(time=50).megno
    with pytest.raises(ValueError, match="transient must not be negative"):
        s.megno(time=10, transient=-1)
    # lyapunov's own: its averages start after the transient
    r = s.lyapunov(time=50, transient=20)
    assert r.time == pytest.approx(70) and r.history.t[0] > 20
    assert "transient" in inspect.signature(rollviz.Scene.megno).parameters


def test_renormalized_exponents_are_the_meaningful_ones():
    """Kept on the energy level, Henon-Heiles' tangent vectors span three directions: three exponents, all finite,
    in pairs (lambda, 0, -lambda) whose sum vanishes -- not a fourth of -inf."""
    r = hh().lyapunov(time=200, renormalize=True)
    assert len(r.exponents) == 3 and np.all(np.isfinite(r.exponents)) and np.isfinite(r.sum)
    assert abs(r.sum) < 1e-3
    with pytest.raises(ValueError, match=r"at most 3 exponents with renormalize = yes"):
        hh().lyapunov(time=10, renormalize=True, count=4)


def test_every_public_callable_has_a_signature():
    callables = [rollviz.Scene, rollviz.Scene.load, rollviz.Scene.from_json, rollviz.Model, rollviz.Model.load,
                 rollviz.Session, rollviz.Table, rollviz.Trajectory, rollviz.PageView, rollviz.Result]
    callables += [getattr(rollviz, n) for n in rollviz.__all__ if inspect.isfunction(getattr(rollviz, n))]
    for cls in (rollviz.Scene, rollviz.Model, rollviz.Table, rollviz.Trajectory, rollviz.SweepResult,
                rollviz.Session, rollviz.PageView):
        callables += [getattr(cls, n) for n in dir(cls) if not n.startswith("_") and callable(getattr(cls, n))
                      and not isinstance(getattr(cls, n), type)]
    for c in callables:
        inspect.signature(c)  # raises where there is none
    assert list(inspect.signature(rollviz.Scene).parameters) == ["problem", "settings"]
    assert {"style", "scale", "path"} <= set(inspect.signature(rollviz.Scene.chart).parameters)
    assert list(inspect.signature(rollviz.Scene.save).parameters) == ["self", "path"]


def test_results_are_short_in_help_and_repr():
    assert not issubclass(rollviz.Result, dict)
    text = pydoc.render_doc(rollviz, renderer=pydoc.plaintext)
    assert "inherited from builtins.dict" not in text and "fromkeys" not in text
    s = rollviz.Scene.load(scene_path("henon_map.json"))
    g = rollviz.sweep(s, axes={"a": (1.0, 1.4, 40), "b": (0.2, 0.3, 30)}, quantity="lyapunov.max", threads=2,
                      **{"lyapunov.time": 20})
    assert repr(g) == "<rollviz.SweepResult lyapunov.max over a(40) x b(30): complete>"
    r = s.lyapunov(time=50)
    assert "\n" not in repr(r) and len(repr(r)) < 400
    assert r["exponents"] is r.exponents and dict(r)["max"] == r.max and "max" in r


def test_jupyter_shows_pictures_of_scenes_and_charts_and_tables_of_results():
    png = b"\x89PNG\r\n\x1a\n"
    s = hh()
    assert s._repr_png_()[:8] == png
    chart = s.chart("poincare", size=(120, 100), points=100)
    assert chart._repr_png_()[:8] == png and np.asarray(chart).shape == (100, 120, 3)
    assert s.render(size=(64, 48))._repr_png_()[:8] == png
    html = s.lyapunov(time=20)._repr_html_()
    assert html.startswith("<table>") and "<th style='text-align: left'>exponents</th>" in html
    t = s.integrate(1, 0.5, ["t", "E"])
    assert "<th>E</th>" in t._repr_html_()
    g = rollviz.sweep(s, axes={"map.0": (-0.1, 0.1, 3)}, quantity="megno", threads=1, **{"megno.time": 10})
    assert "<table>" in g._repr_html_() and "megno" in g._repr_html_()


def test_sweep_dimensions_are_the_maps_coordinates_and_errors_cite_no_temporary_paths():
    s = hh()
    assert s.map_coordinates or True
    g = rollviz.sweep(s, axes={"map.0": (-0.1, 0.1, 3), "energy": (0.1, 0.12, 2)}, quantity="megno", threads=1,
                      **{"megno.time": 10})
    names = rollviz.Scene.load(scene_path("henon_heiles.json")).poincare(points=1).columns[:2]
    assert g.axis_names == [names[0], "energy"]
    xarray = pytest.importorskip("xarray")
    ds = g.to_xarray()
    assert isinstance(ds, xarray.Dataset) and ds["megno"].dims == (names[0], "energy")
    assert np.array_equal(ds.coords[names[0]].values, g.axes["map.0"])
    with pytest.raises(ValueError) as bad:
        rollviz.sweep(s, axes={"map.0": (-0.1, 0.1, 3)}, quantity="megnoo")
    assert "rollviz-sweep-" not in str(bad.value) and str(bad.value).startswith("sweep(): quantity:")
    with pytest.raises(ValueError, match=r"sweep\(\): initial.state: x must be a finite number"):
        rollviz.sweep(s, axes={"map.0": (-0.1, 0.1, 3)}, quantity="megno", **{"initial.state": {"x": np.nan}})
    assert os.path.isdir(os.path.dirname(rollviz.__file__))


def test_a_result_is_json_ready_through_as_dict():
    """A Result is a Mapping, not a dict: json.dumps refuses it; as_dict() is the plain copy that it takes."""
    import json
    tools = rollviz.tools()
    with pytest.raises(TypeError):
        json.dumps(tools[0])
    back = json.loads(json.dumps([t.as_dict() for t in tools]))
    assert [t["id"] for t in back] == [t.id for t in tools]
    r = rollviz.Scene("henon_heiles").lyapunov(time=20)
    plain = json.loads(json.dumps(r.as_dict()))
    assert plain["exponents"] == [float(x) for x in r.exponents]
