"""rollviz: bodies rolling without slipping, and the tools of nonlinear dynamics, from Python.

    import rollviz
    s = rollviz.Scene.load("scenes/chaplygin_ball.json")      # or rollviz.Scene("chaplygin_ball", energy=0.4)
    m = rollviz.Model.load("examples/models/lorenz.json")      # a system written as equations (docs/models.md)
    s = rollviz.Scene(m, rho=28, **{"initial.state": {"x": 1, "y": 1, "z": 1}})
    s2 = s.set(energy=0.4, **{"integrator.method": "everhart"})  # a new scene; s is unchanged
    r = s.integrate(time=100, every=0.1, columns=["t", "E", "M1"])
    r["E"], r.t, r.final                     # named columns, the times, the whole state at the end
    r.to_pandas()                            # a DataFrame (pandas), r.to_xarray() a Dataset (xarray)
    s3 = s.with_state(r.final)               # a scene that starts where the run ended
    P = s.poincare(points=2000)              # P["l"], P["L/G"], P.t, P.sheet; np.asarray(P) the rows
    r = s.lyapunov(time=1000, energy=0.45)   # r.exponents, r.converged, r.history["L1"]
    img = s.render(size=(640, 480), time=5)  # H x W x 3 uint8
    g = rollviz.sweep(s, axes={"energy": np.linspace(0.3, 0.6, 31)}, quantity="lyapunov.max")  # g.values[...]

Every registered tool (rollviz.tools()) is a Scene method, those of the modules loaded at import
(rollviz.modules(): ROLLVIZ_MODULE_PATH, ~/.local/lib/rollviz/modules; docs/modules.md) too. One keyword rule
holds for every call: a tool's setting by its name (s.megno(time=1e4) is megno.time for that call, and
s.continuation(guess=[...]) is fixedpoint.guess: the sections of the tools it hangs under), a model parameter by
its plain name (energy=0.4), any scene key dotted (**{"integrator.method": "verner9"}). Arguments are
keyword-only; an unknown keyword is a TypeError naming the nearest known ones, a value of the wrong type a
TypeError saying what was expected, a bad value a ValueError; a failed computation raises
rollviz.ComputationError. Long calls release the GIL, take progress=callable(fraction) and stop on Ctrl-C with
KeyboardInterrupt. A Scene is a value: set() and with_state() return new scenes, and scenes pickle (as their
JSON), so multiprocessing, joblib and Dask can take them.
"""

import copy as _copy
import difflib as _difflib
import html as _html
import inspect as _inspect
import json as _json
import math as _math
import numbers as _numbers
import os as _os
import tempfile as _tempfile
import types as _types
import typing as _typing

import numpy as _np

from ._rollviz import ComputationError, Model, Scene, __version__, describe, integrators, modules, problems
from ._rollviz import scenes_directory
from ._rollviz import _tools
from ._rollviz import _session_page
from ._rollviz import sweep as _sweep_file

__all__ = ["ComputationError", "Model", "PageView", "Result", "Scene", "Session", "SweepResult", "Table",
           "Trajectory", "__version__",
           "describe", "integrators", "modules", "problems", "scenes_directory", "sweep", "tools"]


# ---------------------------------------------------------------------------------------------------- results

class Result(dict):
    """A tool's result: a dict whose keys are also attributes (r.exponents is r["exponents"]); a key wins over a
    dict method of its name (a sweep's r.values is its values, not dict.values)."""

    def __getattribute__(self, name):
        if not name.startswith("_") and dict.__contains__(self, name):
            return dict.__getitem__(self, name)
        return super().__getattribute__(name)

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return list(dict.keys(self)) + list(super().__dir__())

    def __repr__(self):
        return f"{type(self).__name__}({', '.join(f'{k}={_brief(v)}' for k, v in dict.items(self))})"


def _brief(value):
    """A value in a line: arrays and long lists by their shape, dicts by their keys, long text cut."""
    if isinstance(value, _np.ndarray):
        return f"array{value.shape}" if value.size > 6 else repr(value.tolist())
    if isinstance(value, (list, tuple)) and len(value) > 6:
        return f"[{len(value)} items]"
    if isinstance(value, dict):
        keys = list(value)
        return "{" + ", ".join(map(str, keys[:6])) + (", ..." if len(keys) > 6 else "") + "}"
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def _optional(module, what):
    try:
        return __import__(module)
    except ImportError:
        raise ImportError(f"{what} needs {module} (Debian: apt install python3-{module})") from None


class Table:
    """Named columns of equal length: t["E"] (or t.E where the name is an identifier) is a column,
    t.columns the names in order, len(t) the rows, np.asarray(t) the rows x columns array, iterating gives the
    names (as a dict or a DataFrame does); t.to_pandas() and t.to_xarray() give a DataFrame and a Dataset."""

    _dimension = "point"

    def __init__(self, columns, data):
        data = _np.asarray(data)
        if data.ndim != 2 or data.shape[1] != len(columns):
            raise ValueError(f"Table: {data.shape} does not fit the columns {columns}")
        self._columns = list(columns)
        self._data = data

    @property
    def columns(self):
        """The column names, in order."""
        return list(self._columns)

    @property
    def shape(self):
        return self._data.shape

    def keys(self):
        return self.columns

    def __iter__(self):
        return iter(self._columns)

    def __len__(self):
        return self._data.shape[0]

    def __contains__(self, name):
        return name in self._columns

    def __getitem__(self, key):
        if isinstance(key, str):
            if key not in self._columns:
                near = _difflib.get_close_matches(key, self._columns, n=3)
                raise KeyError(f"{key!r}: no such column (columns: {', '.join(self._columns)}"
                               + (f"; did you mean {', '.join(near)}?" if near else "") + ")")
            return self._data[:, self._columns.index(key)]
        return self._data[key]

    def __getattr__(self, name):
        if not name.startswith("_") and name in self.__dict__.get("_columns", ()):
            return self[name]
        raise AttributeError(name)

    def __dir__(self):
        return [c for c in self._columns if c.isidentifier()] + list(super().__dir__())

    def __array__(self, dtype=None, copy=None):
        return self._data if dtype is None else self._data.astype(dtype)

    def __repr__(self):
        return f"<rollviz.{type(self).__name__}: {len(self)} rows of {', '.join(self._columns)}>"

    def _repr_html_(self):
        """Jupyter's view: an HTML table of the first and last rows."""
        rows = list(range(len(self))) if len(self) <= 12 else list(range(5)) + [None] + list(range(len(self) - 5, len(self)))
        head = "".join(f"<th>{_html.escape(c)}</th>" for c in self._columns)
        body = "".join(
            "<tr>" + "".join("<td>&#8942;</td>" for _ in self._columns) + "</tr>" if k is None else
            "<tr>" + "".join(f"<td>{v:.10g}</td>" for v in self._data[k]) + "</tr>" for k in rows)
        return (f"<table><caption>rollviz.{type(self).__name__}: {len(self)} rows</caption>"
                f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>")

    def to_pandas(self):
        """The columns as a pandas DataFrame."""
        pandas = _optional("pandas", "to_pandas()")
        return pandas.DataFrame({c: self._data[:, k] for k, c in enumerate(self._columns)})

    def to_xarray(self):
        """The columns as an xarray Dataset of one dimension."""
        xarray = _optional("xarray", "to_xarray()")
        return xarray.Dataset({c: (self._dimension, self._data[:, k]) for k, c in enumerate(self._columns)})


class Trajectory(Table):
    """Samples of a trajectory: the named columns asked for (Table), r.t the times, r.final the whole state at
    the last sample (named: r.final_named), which Scene.with_state takes to go on from there."""

    _dimension = "t"

    def __init__(self, columns, data, t, final=None, state_names=()):
        super().__init__(columns, data)
        self.t = _np.asarray(t)
        self.final = None if final is None else _np.asarray(final)
        self.final_named = None if final is None else dict(zip(state_names, (float(v) for v in final)))
        self._resume = self._scene = self._every = None  # where integrate(after=this) goes on from
        self._next = 0
        self._source = None  # the Scene it ran in: show() plays it

    def show(self, duration=10.0, *, height=600):
        """Plays the trajectory's motion in its scene as an interactive 3D view (Scene.show): its time span in
        `duration` seconds. In Jupyter it is shown inline; elsewhere the PageView is returned."""
        if self._source is None or not len(self.t):
            raise ValueError("show(): this trajectory carries no scene (integrate() results do)")
        span = float(_np.max(_np.abs(self.t)))
        if not span > 0:
            raise ValueError("show(): the trajectory spans no time")
        return self._source.show(duration=duration, speed=span / duration, height=height)

    def to_xarray(self):
        """The columns as an xarray Dataset over the coordinate t."""
        xarray = _optional("xarray", "to_xarray()")
        return xarray.Dataset({c: ("t", self._data[:, k]) for k, c in enumerate(self._columns) if c != "t"},
                              coords={"t": self.t})


class SweepResult(Result):
    """A sweep's result: values[name] an array shaped like the grid (the first axis first), axes[id] each axis'
    coordinates, columns the flat columns as the CSV has them (first axis fastest), shape, status per point
    (whole), seconds, quantity, complete. to_xarray() gives a Dataset over the axes."""

    def to_xarray(self):
        xarray = _optional("xarray", "to_xarray()")
        dims = list(self.axes)
        return xarray.Dataset({k: (dims, v) for k, v in self["values"].items()},
                              coords={d: self.axes[d] for d in dims})


def _wrap(value):
    if isinstance(value, dict):
        return Result({k: _wrap(v) for k, v in value.items()})
    if isinstance(value, list):
        return [_wrap(v) for v in value]
    return value


def _shaped(value, table=""):
    """A tool's raw result with names: a table that is the result (a map's points) as a Table, the table the
    runner names (megno's history) as a Table."""
    if "_table" in value:
        return Table(value["_table"]["columns"], value["_table"]["rows"])
    r = _wrap(value)
    if table and isinstance(r.get(table), dict):
        h = r[table]
        names = ["t"] + [n for n in h if n != "t"] if "t" in h else list(h)
        r[table] = Table(names, _np.column_stack([_np.asarray(h[n], dtype=float) for n in names]))
    return r


# ------------------------------------------------------------------------------------------ the keyword rule

def _check_type(call, name, kind, value, choices=None):
    """A keyword's value against what it takes: TypeError for the wrong type, ValueError for NaN or a choice
    not offered."""
    def number(v):
        return isinstance(v, _numbers.Real) and not isinstance(v, bool)

    if kind in ("number", "integer"):
        if not number(value):
            raise TypeError(f"{call}: {name} takes a number, not {type(value).__name__} ({value!r})")
        if not _math.isfinite(value):  # a scene is JSON: no NaN, no infinity
            raise ValueError(f"{call}: {name} must be a finite number, got {value}")
        if kind == "integer" and not float(value).is_integer():
            raise TypeError(f"{call}: {name} takes an integer, not {value!r}")
    elif kind == "choice":
        if not isinstance(value, str):
            raise TypeError(f"{call}: {name} takes one of {', '.join(choices)} (a str), not {value!r}")
        if value not in choices:
            raise ValueError(f"{call}: {name} = {value!r} is not one of {', '.join(choices)}")
    elif kind == "text":
        if not isinstance(value, str):
            raise TypeError(f"{call}: {name} takes a str, not {type(value).__name__} ({value!r})")
    elif kind == "numbers":
        if isinstance(value, (str, bytes)) or not all(number(v) for v in _np.ravel(_np.asarray(value, object))):
            raise TypeError(f"{call}: {name} takes a sequence of numbers, not {value!r}")


def _plain(value):
    """A value as the scene loader reads it (NumPy scalars and arrays as Python's)."""
    if isinstance(value, _np.ndarray):
        return value.tolist()
    if isinstance(value, _np.generic):
        return value.item()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return value


def _unknown(call, key, known, what):
    near = _difflib.get_close_matches(key, known, n=3, cutoff=0.6)
    return TypeError(f"{call} got an unexpected keyword argument {key!r}"
                     + (f" (did you mean {', '.join(near)}?" if near else " (")
                     + (" " if near else "") + f"{what})")


def _in_python_words(call, scene, places, error):
    """The scene loader's message about a keyword's value ("scenes/x.json:lyapunov.time: ...") as the call's
    ("lyapunov(): time: ..."); `places` maps each scene key of the call to the keyword the user wrote."""
    text = str(error)
    for place, keyword in places.items():
        for prefix in (f"{scene.source}:{place}: ", f"--set {place}: "):
            if text.startswith(prefix):
                return ValueError(f"{call}: {keyword}: {text[len(prefix):]}")
    return error


def _model_parameter_keys(scene, call, kw):
    """Plain model parameters and dotted keys as set() takes them; TypeError for anything else."""
    out = {}
    parameters = scene.parameters
    for key, value in kw.items():
        if "." in key:
            if key == "initial.state" and not isinstance(value, dict):
                value = dict(zip(scene.state_names, _plain(_np.ravel(_np.asarray(value, float)))))
            out[key] = _plain(value)
        elif key in parameters:
            _check_type(call, key, "number", value)
            out[key] = _plain(value)
        else:
            raise _unknown(call, key, list(parameters),
                           f"takes the parameters of {scene.problem} ({', '.join(parameters)}) and dotted scene "
                           "keys such as **{'integrator.method': 'verner9'}")
    return out


# ------------------------------------------------------------------------------------------ scenes as values

_cpp_set = Scene.set
_cpp_parameters = Scene.parameters
_cpp_render = Scene.render
_cpp_snapshot = Scene.snapshot
_cpp_video = Scene.video
_cpp_page = Scene.page


def _set(self, **settings):
    """A new scene with model parameters (energy=0.4) and dotted scene keys (**{"integrator.method":
    "everhart"}, **{"initial.state": array or {name: value}}) set, as --set does; this scene is unchanged.
    TypeError for an unknown keyword (naming the nearest), ValueError for a bad value."""
    return _set_for("set()", self, settings)


def _set_for(call, scene, settings):
    """set() on behalf of `call` (its messages name that call)."""
    keys = _model_parameter_keys(scene, call, settings)
    places = {("parameters." + k if "." not in k else k): k for k in keys}
    places.update({k: k for k in keys if "." not in k})
    try:
        if "initial.state" in keys:  # a state replaces the scene's map point (and its root) or state
            return _from_document(scene, _with_initial(scene, {"state": keys.pop("initial.state")}), keys)
        new = scene.copy()
        _cpp_set(new, **keys)
        return new
    except ValueError as e:
        raise _in_python_words(call, scene, places, e) from None


def _with_initial(scene, initial):
    doc = _json.loads(scene.to_json())
    kept = {k: v for k, v in doc.get("initial", {}).items() if k not in ("map", "state", "root")}
    doc["initial"] = {**kept, **initial}
    return doc


def _from_document(scene, doc, keys=None):
    new = Scene.from_json(_json.dumps(doc), scene.source)
    if keys:
        _cpp_set(new, **keys)
    return new


def _with_state(self, state, **settings):
    """A new scene that starts from `state`: an array of the state's components (Scene.state_names, as
    Trajectory.final) or a mapping {name: value}; other keywords as for set()."""
    if not isinstance(state, dict):
        values = _np.ravel(_np.asarray(state, dtype=float))
        if len(values) != len(self.state_names):
            raise ValueError(f"with_state(): {len(values)} values for the {len(self.state_names)} components of "
                             f"{self.problem}'s state ({', '.join(self.state_names)})")
        state = dict(zip(self.state_names, values))
    return _set(self, **{"initial.state": {k: float(v) for k, v in state.items()}}, **settings)


def _integrate(self, time=None, every=None, columns=None, *, t_eval=None, events=None, after=None, progress=None,
               **settings):
    """Integrates and samples observables at t = 0, every, 2 every, ... up to time (rollviz integrate); a
    negative time integrates backward (t = 0, -every, ...); t_eval gives the times instead (ascending from 0, or
    descending from 0 for a backward run), from the dense output of one integration. columns: observable ids, a
    list or one name (default: all). after=r (a Trajectory of this scene) goes on from where r ended: the
    samples after r's last one, bit for bit what one longer call gives. events=(observable, level) or
    (observable, level, "positive"|"negative"|"both"): the crossings of that level on the way, located on the
    dense output as the Poincare map locates them (r.events, a Trajectory of the same columns at the crossing
    times). Other keywords: model parameters and dotted scene keys for this call (as set()). Returns a
    Trajectory: r["E"] a column, r.t the times, np.asarray(r) the rows, r.final the whole state at the last
    sample (Scene.with_state(r.final) is a new scene that starts there)."""
    scene = _set_for("integrate()", self, settings) if settings else self
    if isinstance(columns, str):
        columns = [columns]
    if columns is not None and not all(isinstance(c, str) for c in columns):
        raise TypeError(f"integrate(): columns takes observable names (str), not {columns!r}")
    names = list(columns) if columns is not None else list(scene.observables)
    document = scene.to_json()
    first = 0
    if after is not None:
        if not isinstance(after, Trajectory) or after._resume is None:
            raise TypeError("integrate(): after takes a Trajectory that integrate() returned")
        if after._scene != document:
            raise ValueError("integrate(after=r): r comes from another scene (its parameters, integrator or start "
                             "differ); Scene.with_state(r.final) starts a new one there")
    if t_eval is not None:
        times = [float(v) for v in _np.asarray(t_eval, dtype=float).ravel()]
        every = None
    elif time is None or every is None:
        raise TypeError("integrate(): give time and every (a sample every `every` up to `time`), or t_eval")
    else:
        _check_type("integrate()", "time", "number", time)
        _check_type("integrate()", "every", "number", every)
        if not _math.isfinite(time):
            raise ValueError("time: must be a finite number")
        if not (every > 0) or not _math.isfinite(every):
            raise ValueError("every: must be positive")
        if after is not None:
            if after._every != every:
                raise ValueError(f"integrate(after=r): r was sampled every {after._every}, not every {every}")
            first = after._next
        sign = -1.0 if time < 0 else 1.0
        # t_k = k every, as the CLI's sampler computes them (rollviz integrate gives the same rows)
        count = int(_math.floor(abs(time) / every * (1 + 1e-12))) + 1
        times = [0.0 + sign * k * every for k in range(first, count)]
    r = _sampled(scene, times, names, None if after is None else after._resume, progress)
    if not times and after is not None:
        r.final, r.final_named = after.final, after.final_named
    r._scene, r._every, r._next = document, every, first + len(times)
    r._source = scene
    if events is not None:
        r.events = _events(scene, events, times[-1] if times else 0.0, names, progress)
    return r


def _events(scene, events, end, names, progress):
    """The crossings of an observable's level up to time `end`: the Poincare tool's section on that level."""
    if not isinstance(events, (tuple, list)) or len(events) not in (2, 3) or not isinstance(events[0], str):
        raise TypeError(f"integrate(): events takes (observable, level) or (observable, level, direction), "
                        f"not {events!r}")
    observable, level = events[0], events[1]
    direction = events[2] if len(events) == 3 else "both"
    _check_type("integrate()", "events' level", "number", level)
    _check_type("integrate()", "events' direction", "choice", direction, ["positive", "negative", "both"])
    section = scene.set(**{"poincare.section": observable, "poincare.value": float(level),
                           "poincare.direction": direction, "poincare.points": 10 ** 15,
                           "poincare.max_time": abs(end), "poincare.integrate": "backward" if end < 0 else "forward"})
    return _sampled(scene, [t for t in section.poincare()["t"] if abs(t) <= abs(end)], names, None, progress)


def _sampled(scene, times, names, resume, progress):
    """The named columns at `times` from one integration (going on from `resume`, an integrator's snapshot). The
    state's components ride along as columns (each is an observable): the last row gives the final state."""
    X, snapshot = scene._integrate_at(times, names + list(scene.state_names), resume=resume, progress=progress)
    final = X[-1, len(names):] if len(times) else None
    r = Trajectory(names, _np.ascontiguousarray(X[:, :len(names)]), _np.asarray(times), final, scene.state_names)
    r._resume = snapshot
    return r


def _png_bytes(pixels):
    """An H x W x 3 uint8 array as PNG bytes (PIL where present)."""
    import io
    try:
        from PIL import Image as image
    except ImportError:
        raise ImportError("a picture's PNG needs PIL (Debian: apt install python3-pil)") from None
    out = io.BytesIO()
    image.fromarray(_np.ascontiguousarray(pixels)).save(out, format="PNG")
    return out.getvalue()


def _picture_size(call, size):
    if (not isinstance(size, (tuple, list)) or len(size) != 2
            or not all(isinstance(v, _numbers.Integral) and not isinstance(v, bool) and v > 0 for v in size)):
        raise TypeError(f"{call}: size takes (width, height), two positive ints, not {size!r}")
    return (int(size[0]), int(size[1]))


def _render(self, size=(640, 480), time=10.0, *, transparent=False, **settings):
    """The 3D view at `time` (the trace covers [0, time]) as an H x W x 3 uint8 array, rendered headless as
    rollviz render draws it. Other keywords: model parameters and dotted scene keys for this call."""
    scene = _set_for("render()", self, settings) if settings else self
    return _cpp_render(scene, _picture_size("render()", size), time, 1, transparent)


def _snapshot(self, path, size=(1280, 720), time=10.0, *, transparent=False, **settings):
    """Writes the 3D view at `time` as a PNG (rollviz render -o PATH). Other keywords as for set()."""
    scene = _set_for("snapshot()", self, settings) if settings else self
    return _cpp_snapshot(scene, _os.fspath(path), _picture_size("snapshot()", size), time, 1, transparent)


_VIDEO_ENCODERS = ("libx264", "mpeg4")  # what render/video/Mp4Writer configures: H.264, or MPEG-4 Part 2


def _video(self, path, duration=None, fps=None, size=None, speed=0.0, encoder="libx264", *, progress=None,
           **settings):
    """Records the 3D view into an MP4 (rollviz video); duration, fps and size default to the scene's video
    section, speed 0 to its view.speed; encoder libx264 (H.264) or mpeg4. Returns the number of frames."""
    path = _os.fspath(path)
    if not path.lower().endswith(".mp4"):
        raise ValueError(f"video(): {path}: a video is written as MP4 (.mp4); "
                         f"'{_os.path.splitext(path)[1] or path}' is not supported")
    if encoder not in _VIDEO_ENCODERS:
        raise ValueError(f"video(): encoder {encoder!r} is not supported (supported: {', '.join(_VIDEO_ENCODERS)})")
    if size is not None:
        size = _picture_size("video()", size)
    scene = _set_for("video()", self, settings) if settings else self
    return _cpp_video(scene, path, duration, fps, size, speed, encoder, progress=progress)


class PageView:
    """An interactive 3D view of a motion (the page rollviz page writes, in an iframe): Jupyter shows it inline and
    it plays offline (the viewer is inside it). .html is the page, save(path) writes it."""

    def __init__(self, html, height=600):
        self.html = html
        self.height = height

    def _repr_html_(self):
        return (f'<iframe srcdoc="{_html.escape(self.html, quote=True)}" style="width: 100%; '
                f'height: {int(self.height)}px; border: 0" sandbox="allow-scripts"></iframe>')

    def save(self, path):
        """Writes the page (a self-contained .html file)."""
        with open(_os.fspath(path), "w", encoding="utf-8") as f:
            f.write(self.html)

    def __repr__(self):
        return f"<rollviz.PageView: a page of {len(self.html)} characters>"


def _page_text(write):
    """The page `write(path)` writes, read back."""
    with _tempfile.TemporaryDirectory() as d:
        path = _os.path.join(d, "page.html")
        write(path)
        with open(path, encoding="utf-8") as f:
            return f.read()


def _shown(view):
    """In a Jupyter (IPython) session the view is displayed and nothing returned; elsewhere the view."""
    try:
        from IPython import get_ipython
        from IPython.display import display
    except ImportError:
        return view
    if get_ipython() is None:
        return view
    display(view)
    return None


def _checked_page_path(call, path):
    path = _os.fspath(path)
    if not path.lower().endswith((".html", ".htm")):
        raise ValueError(f"{call}: {path}: a web page is written as .html; "
                         f"'{_os.path.splitext(path)[1] or path}' is not supported")
    return path


def _page(self, path, duration=None, fps=None, speed=None, *, progress=None, **settings):
    """Writes the motion as one self-contained web page that plays, turns and scrubs in any browser, offline
    (rollviz page): duration (seconds at 1x) and fps default to the scene's video section, speed (simulation
    seconds per second) to its view.speed. Other keywords as for set(). Returns the number of frames."""
    path = _checked_page_path("page()", path)
    scene = _set_for("page()", self, settings) if settings else self
    return _cpp_page(scene, path, duration, fps, speed, progress=progress)


def _show(self, duration=None, fps=None, speed=None, *, height=600, **settings):
    """The motion as an interactive 3D view (the page of page()): in Jupyter shown inline, working offline;
    elsewhere a PageView is returned (.html, .save(path))."""
    return _shown(PageView(_page_text(lambda p: _page(self, p, duration, fps, speed, **settings)), height))


class Session:
    """A GUI session (File > Save session): its scene, and its Poincare map, which its page shows beside the
    motion. Session(path) or Session.load(path)."""

    def __init__(self, path):
        self.path = _os.fspath(path)
        self.scene = Scene.load(self.path)  # ValueError naming the file and field for what cannot be read
        with open(self.path, encoding="utf-8") as f:
            if "rollviz_session" not in _json.load(f):
                raise ValueError(f"{self.path}: not a rollviz session (a scene: Scene.load reads it)")

    @classmethod
    def load(cls, path):
        """Reads a session file (ValueError when it is not one)."""
        return cls(path)

    def page(self, path, duration=None, fps=None, speed=None, *, progress=None):
        """Writes the session as one self-contained web page: its scene's motion beside its map (rollviz page
        SESSION). Returns the number of frames."""
        return _session_page(self.path, _checked_page_path("page()", path), duration, fps, speed, progress=progress)

    def show(self, duration=None, fps=None, speed=None, *, height=700):
        """The session's page inline in Jupyter (elsewhere a PageView is returned)."""
        return _shown(PageView(_page_text(lambda p: self.page(p, duration, fps, speed)), height))

    def _repr_html_(self):
        return PageView(_page_text(lambda p: self.page(p)), 700)._repr_html_()

    def __repr__(self):
        return f"<rollviz.Session {self.path}: {self.scene.problem}>"


Scene.set = _set
Scene.with_state = _with_state
Scene.integrate = _integrate
Scene.render = _render
Scene.snapshot = _snapshot
Scene.video = _video
Scene.page = _page
Scene.show = _show
# Jupyter's rich display: the interactive view, or the 3D view as a picture where HTML is not shown
Scene._repr_html_ = lambda self: PageView(_page_text(lambda p: _page(self, p)))._repr_html_()
Scene._repr_png_ = lambda self: _png_bytes(self.render())
Scene.parameters = property(lambda self: _types.MappingProxyType(_cpp_parameters.fget(self)),
                            doc="The model parameters' values (read-only: set() returns a scene with others).")
Scene.__copy__ = lambda self: self.copy()
Scene.__deepcopy__ = lambda self, memo: self.copy()
Scene.__reduce__ = lambda self: (_scene_from_json, (self.to_json(), self.source))


def _scene_from_json(text, source):
    """What a pickled scene is rebuilt with (its JSON and where it was read from)."""
    return Scene.from_json(text, source)


# ------------------------------------------------------------------------------------------------ the tools

def tools():
    """The registered tools in the order of the manual's tree: id, title, parent, settings, keywords (every
    setting a call takes, section by section), outputs, ..."""
    return [_wrap(t) for t in _tools()]


_ANNOTATIONS = {"number": float, "integer": int, "text": str, "numbers": _typing.Sequence[float]}


def _keywords(tool):
    """The tool's keywords, each once (the first section that has it wins, as the scene loader places it)."""
    seen, out = set(), []
    for k in tool["keywords"]:
        if k["id"] not in seen:
            seen.add(k["id"])
            out.append(k)
    return out


def _default(k):
    d = k["default"]
    return int(d) if k["type"] == "integer" and d is not None else d


def _settings_doc(tool):
    lines = [f"{tool['title']}: {tool['description']}.", ""]
    keywords = _keywords(tool)
    if keywords:
        lines.append("Keyword settings, for this call only (omitted: the scene's value, which defaults to the one "
                     "shown):")
        for k in keywords:
            kind = f"one of {', '.join(k['choices'])}" if k["type"] == "choice" else k["type"]
            default = "" if k["default"] is None else f" = {_default(k)!r}"
            lines.append(f"    {k['id']}{default} ({k['section']}.{k['id']}, {kind}): {k['description']}")
    if tool["arguments_help"]:
        lines.append("Arguments: " + tool["arguments_help"])
    lines.append("Also: the model's parameters by name (energy=0.4) and dotted scene keys, for this call.")
    lines.append("progress: None or a callable taking the fraction done.")
    if tool["id"] == "plot":
        lines += ["", "Returns: a Table of the plotted points, its columns named after the observables on the axes."]
    elif tool["outputs"]:
        lines.append("")
        lines.append("Returns:" + (" a Table of the map's points (the map coordinates, t, sheet)"
                                   if tool["id"] in ("poincare", "map3d") else
                                   " a Result (a dict whose keys are attributes):"))
        for name, description in tool["outputs"]:
            lines.append(f"    {name}: {description}")
    if tool["reference"]:
        lines.append(f"Reference: {tool['reference']}")
    return "\n".join(lines)


def _signature(tool):
    P = _inspect.Parameter
    params = [P("self", P.POSITIONAL_ONLY)]
    for k in _keywords(tool):
        annotation = (_typing.Literal[tuple(k["choices"])] if k["type"] == "choice"
                      else _ANNOTATIONS.get(k["type"], _typing.Any))
        if k["default"] is None:
            annotation = _typing.Optional[annotation]
        params.append(P(k["id"], P.KEYWORD_ONLY, default=_default(k), annotation=annotation))
    for a in tool["arguments"]:
        if a not in {p.name for p in params}:
            params.append(P(a, P.KEYWORD_ONLY, default=None))
    params.append(P("progress", P.KEYWORD_ONLY, default=None,
                    annotation=_typing.Optional[_typing.Callable[[float], None]]))
    params.append(P("overrides", P.VAR_KEYWORD))
    return _inspect.Signature(params)


def _make_method(tool):
    tool_id = tool["id"]
    keywords = {k["id"]: k for k in _keywords(tool)}
    arguments = set(tool["arguments"])
    call = f"{tool_id}()"

    def method(self, *args, progress=None, **kw):
        if args:
            first = next(iter(keywords), "time")
            raise TypeError(f"{call} takes keyword arguments only ({len(args)} given by position): "
                            f"e.g. {tool_id}({first}=...)")
        settings, parameters = {}, {}
        for key, value in kw.items():
            if key in arguments or "." in key:
                settings[key] = _plain(value)
            elif key in keywords:
                k = keywords[key]
                _check_type(call, key, k["type"], value, k.get("choices"))
                settings[key] = _plain(value)
            elif key in self.parameters:
                parameters[key] = value
            else:
                raise _unknown(call, key, list(keywords) + list(arguments) + list(self.parameters),
                               f"settings: {', '.join(keywords) or 'none'}; the parameters of {self.problem}; "
                               "or a dotted scene key")
        scene = _set_for(call, self, parameters) if parameters else self
        try:
            raw = scene._run(tool_id, progress=progress, **settings)
        except ValueError as e:
            places = {f"{keywords[k]['section']}.{k}": k for k in settings if k in keywords}
            places.update({k: k for k in settings if "." in k})
            raise _in_python_words(call, scene, places, e) from None
        return _shaped(raw, tool["table"])

    method.__name__ = tool_id
    method.__qualname__ = f"Scene.{tool_id}"
    method.__doc__ = _settings_doc(tool)
    method.__signature__ = _signature(tool)
    return method


# one method per registered tool that runs on a scene (a sweep runs over many: rollviz.sweep)
for _tool in _tools():
    if _tool["id"] != "sweep":
        setattr(Scene, _tool["id"], _make_method(_tool))
del _tool


# ---------------------------------------------------------------------------------------------------- sweeps

def _axis(name, values):
    """A sweep axis from evenly spaced values (np.linspace) or (min, max, count)."""
    if isinstance(values, tuple) and len(values) == 3:
        lo, hi, count = values
    else:
        v = _np.asarray(values, dtype=float).ravel()
        if v.size < 1 or not _np.all(_np.isfinite(v)):
            raise ValueError(f"sweep(): axes[{name!r}]: give finite values (np.linspace) or (min, max, count)")
        lo, hi, count = float(v[0]), float(v[-1]), int(v.size)
        if v.size > 1 and not _np.allclose(v, _np.linspace(lo, hi, v.size), rtol=0, atol=1e-12 * max(1, abs(hi))):
            raise ValueError(f"sweep(): axes[{name!r}]: the values must be evenly spaced (a sweep's axis is min, "
                             "max, count: np.linspace)")
    return {"id": name, "min": float(lo), "max": float(hi), "count": int(count)}


def sweep(scene, axes=None, quantity=None, threads=0, progress=None, checkpoint=None, options=None, lanes=None,
          **settings):
    """A quantity over a grid of points (rollviz sweep; docs/sweeps.md), on threads. Either a sweep file's path,
    or a Scene with axes={"energy": np.linspace(0.3, 0.6, 31), "map.0": (-0.4, 0.4, 41)} (model parameters,
    "map.0"/"map.1" for the start's map coordinates, dotted scene keys; evenly spaced values or (min, max,
    count)) and quantity ("lyapunov.max", "megno", "fixedpoint.type", ...: rollviz.tools()' sweep_quantities);
    further keywords are set on every point (energy=0.125, **{"megno.time": 400}). Returns a SweepResult:
    values[name] shaped like the grid (the first axis first), axes[id] the coordinates, to_xarray().
    checkpoint: a file that keeps the finished points (a later call with the same sweep goes on from them; removed
    once the sweep is complete). Ctrl-C raises KeyboardInterrupt whose `partial` is a SweepResult of the points
    finished so far (NaN and status "not computed" elsewhere). options: the sweep's own options (a dict, as a
    sweep file's "options": {"refine": 2} computes the grid, then twice halves the cells where the regimes meet;
    the grid is then the finest one, its points not computed "painted" from the nearest computed one). lanes=1
    computes one point at a time (the scalar path; options["lanes"]), for comparison with the default, several
    points at once on SIMD lanes where the quantity can (as many as the CPU's registers take: 8 with AVX-512,
    else 4); lanes=4 or lanes=8 asks for that many."""
    checkpoint = None if checkpoint is None else _os.fspath(checkpoint)
    if isinstance(scene, (str, _os.PathLike)):
        if axes is not None or quantity is not None or settings or options is not None or lanes is not None:
            raise TypeError("sweep(path): a sweep file holds its axes, quantity, options (lanes too) and settings")
        return _run_sweep(_os.fspath(scene), threads, progress, checkpoint)
    if not isinstance(scene, Scene):
        raise TypeError(f"sweep(): give a Scene or a sweep file's path, not {type(scene).__name__}")
    if not axes or not isinstance(axes, dict):
        raise TypeError("sweep(scene): axes takes a dict {name: values}, one or two entries")
    if not isinstance(quantity, str):
        raise TypeError("sweep(scene): quantity takes the name of a sweep quantity (str), e.g. 'megno'")
    if options is not None and not isinstance(options, dict):
        raise TypeError("sweep(scene): options takes a dict of the sweep's options, e.g. {'refine': 2}")
    with _tempfile.TemporaryDirectory(prefix="rollviz-sweep-") as folder:
        scene.save(_os.path.join(folder, "scene.json"))
        spec = {"scene": "scene.json", "axes": [_axis(k, v) for k, v in axes.items()], "quantity": quantity,
                "set": {k: _plain(v) for k, v in settings.items()}}
        options = dict(options or {})
        if lanes is not None:
            options["lanes"] = lanes
        if options:
            spec["options"] = {k: _plain(v) for k, v in options.items()}
        path = _os.path.join(folder, "sweep.json")
        with open(path, "w") as f:
            _json.dump(spec, f)
        return _run_sweep(path, threads, progress, checkpoint)


def _run_sweep(path, threads, progress, checkpoint):
    try:
        return _sweep_result(_sweep_file(path, threads, progress=progress, checkpoint=checkpoint))
    except KeyboardInterrupt as stopped:
        if len(stopped.args) == 2 and isinstance(stopped.args[1], dict):
            stopped.partial = _sweep_result(stopped.args[1])
        raise


def _sweep_result(raw):
    r = SweepResult(_wrap(raw))
    shape = list(r.shape)
    names = list(r.columns)
    axis_ids = names[:len(shape)]
    # the flat columns run first axis fastest: Fortran order gives grid[i0, i1]
    r["values"] = {k: _np.asarray(v).reshape(shape, order="F") for k, v in r.columns.items() if k not in axis_ids}
    r["axes"] = {k: _np.asarray(r.columns[k]).reshape(shape, order="F")[
        tuple(slice(None) if j == i else 0 for j in range(len(shape)))] for i, k in enumerate(axis_ids)}
    return r
