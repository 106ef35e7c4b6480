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

import collections.abc as _abc
import copy as _copy
import difflib as _difflib
import html as _html
import inspect as _inspect
import json as _json
import math as _math
import numbers as _numbers
import os as _os
import re as _re
import tempfile as _tempfile
import types as _types
import typing as _typing
import warnings as _warnings

import numpy as _np

from . import _rollviz as _core
from ._rollviz import ComputationError, Model, Scene, __version__
from ._rollviz import _tools
from ._rollviz import _session_page
from ._rollviz import sweep as _sweep_file

__all__ = ["ComputationError", "Model", "PageView", "Result", "Scene", "Session", "SweepResult", "Table",
           "Trajectory", "__version__",
           "describe", "integrators", "modules", "problems", "rolling_body", "scenes_directory", "sweep", "tools"]


# ---------------------------------------------------------------------------------------------------- results

class Result:
    """A tool's result: a read-only mapping (a collections.abc.Mapping) whose keys are also attributes
    (r.exponents is r["exponents"]); a key wins over a method of its name (a sweep's r.values is its values, not
    a method). dict(r) gives a plain dict."""

    __slots__ = ("_fields",)

    def __init__(self, fields=None):
        object.__setattr__(self, "_fields", dict(fields or {}))

    def __getattribute__(self, name):
        if not name.startswith("_"):
            fields = object.__getattribute__(self, "_fields")
            if name in fields:
                return fields[name]
        return object.__getattribute__(self, name)

    def __getattr__(self, name):
        raise AttributeError(f"{type(self).__name__} has no field {name!r} (fields: {', '.join(self._fields)})")

    def __getitem__(self, key):
        return self._fields[key]

    def __iter__(self):
        return iter(self._fields)

    def __len__(self):
        return len(self._fields)

    def __contains__(self, key):
        return key in self._fields

    def __eq__(self, other):
        return isinstance(other, (Result, dict)) and self._fields == dict(other)

    __hash__ = None

    def keys(self):
        """The fields' names."""
        return self._fields.keys()

    def items(self):
        """(name, value) of each field."""
        return self._fields.items()

    def values(self):
        """The fields' values."""
        return self._fields.values()

    def get(self, key, default=None):
        """The field `key`, or `default`."""
        return self._fields.get(key, default)

    def as_dict(self):
        """A plain copy ready for json.dumps: nested results as dicts, tables as dicts of their columns, NumPy
        arrays and numbers as lists and Python numbers (a Result is a Mapping, not a dict: json.dumps(r) alone
        refuses it)."""
        return _plain(self)

    def __dir__(self):
        return [k for k in self._fields if isinstance(k, str)] + list(super().__dir__())

    def __reduce__(self):
        return (type(self), (self._fields,))

    def __repr__(self):
        return f"{type(self).__name__}({', '.join(f'{k}={_brief(v)}' for k, v in self._fields.items())})"

    def _repr_html_(self):
        """Jupyter's view: the fields in a small table (arrays by their shape)."""
        rows = "".join(f"<tr><th style='text-align: left'>{_html.escape(str(k))}</th>"
                       f"<td style='text-align: left'>{_html.escape(_brief(v))}</td></tr>"
                       for k, v in self._fields.items())
        return f"<table><caption>rollviz.{type(self).__name__}</caption><tbody>{rows}</tbody></table>"


_abc.Mapping.register(Result)


def _brief(value):
    """A value in a line: arrays and long lists by their shape, dicts by their keys, long text cut."""
    if isinstance(value, _np.ndarray):
        return f"array{value.shape}" if value.size > 6 else repr(value.tolist())
    if isinstance(value, (list, tuple)) and len(value) > 6:
        return f"[{len(value)} items]"
    if isinstance(value, (dict, Result)):
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
        self._next, self._t0 = 0, 0.0
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
    coordinates, axis_names the axes' names (a map axis, map.0, by its map coordinate: x, px), columns the flat
    columns as the CSV has them (first axis fastest), shape, status per point (whole), seconds, quantity,
    complete. to_xarray() gives a Dataset over the axes."""

    __slots__ = ()

    def to_xarray(self):
        """The values as an xarray Dataset, its dimensions named after the axes (map axes by their map
        coordinates)."""
        xarray = _optional("xarray", "to_xarray()")
        ids = list(self.axes)
        dims = list(self._fields.get("axis_names") or ids)
        return xarray.Dataset({k: (dims, v) for k, v in self["values"].items()},
                              coords={d: self.axes[i] for d, i in zip(dims, ids)})

    def __repr__(self):
        names = self._fields.get("axis_names") or list(self.axes)
        grid = " x ".join(f"{n}({c})" for n, c in zip(names, self.shape))
        done = "complete" if self.complete else f"{list(self.status).count('ok')} computed, incomplete"
        return f"<rollviz.SweepResult {self.quantity} over {grid}: {done}>"

    def _repr_html_(self):
        names = self._fields.get("axis_names") or list(self.axes)
        rows = "".join(
            f"<tr><th style='text-align: left'>{_html.escape(k)}</th><td>{_np.nanmin(v):.6g}</td>"
            f"<td>{_np.nanmax(v):.6g}</td></tr>" if _np.isfinite(v).any() else
            f"<tr><th style='text-align: left'>{_html.escape(k)}</th><td colspan=2>not computed</td></tr>"
            for k, v in self["values"].items())
        grid = " &times; ".join(f"{_html.escape(n)} ({c})" for n, c in zip(names, self.shape))
        return (f"<table><caption>rollviz.SweepResult: {_html.escape(self.quantity)} over {grid}</caption>"
                f"<thead><tr><th></th><th>min</th><th>max</th></tr></thead><tbody>{rows}</tbody></table>")


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
    fields = {k: _wrap(v) for k, v in value.items()}
    if table and isinstance(value.get(table), dict):
        h = value[table]
        names = ["t"] + [n for n in h if n != "t"] if "t" in h else list(h)
        fields[table] = Table(names, _np.column_stack([_np.asarray(h[n], dtype=float) for n in names]))
    return Result(fields)


# ------------------------------------------------------------------------------------------ the keyword rule

def _is_flag(choices):
    """A choice of no/yes: a flag, which takes True/False."""
    return choices is not None and sorted(choices) == ["no", "yes"]


def _flag_value(value):
    """A flag's value as the scene takes it: True/False (and NumPy's bools); 'yes'/'no', the scene files'
    spelling, are still taken as they are."""
    if isinstance(value, (bool, _np.bool_)):
        return "yes" if value else "no"
    return value


def _check_type(call, name, kind, value, choices=None):
    """A keyword's value against what it takes: TypeError for the wrong type, ValueError for NaN or a choice
    not offered."""
    def number(v):
        return isinstance(v, _numbers.Real) and not isinstance(v, (bool, _np.bool_))

    if kind == "choice" and _is_flag(choices):
        if not isinstance(value, (bool, _np.bool_)) and value not in ("yes", "no"):
            raise TypeError(f"{call}: {name} takes True or False, not {value!r}")
    elif kind in ("number", "integer"):
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
        _check_finite(call, name, value)


def _check_finite(call, name, value):
    """ValueError naming the argument for a NaN or an infinity anywhere in `value` (a scene is JSON)."""
    if isinstance(value, dict):
        for k, v in value.items():
            _check_finite(call, f"{name}: {k}" if name else str(k), v)
    elif isinstance(value, (list, tuple, _np.ndarray)):
        for v in _np.ravel(_np.asarray(value, dtype=object)):
            _check_finite(call, name, v)
    elif isinstance(value, _numbers.Real) and not isinstance(value, (bool, _np.bool_)):
        if not _math.isfinite(value):
            raise ValueError(f"{call}: {name} must be a finite number, got {float(value)}")


def _plain(value):
    """A value as the scene loader and json read it (NumPy scalars and arrays as Python's, results as dicts, a
    table as a dict of its columns)."""
    if isinstance(value, _np.ndarray):
        return value.tolist()
    if isinstance(value, _np.generic):
        return value.item()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, (dict, Result)):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, Table):
        return {c: _plain(value[c]) for c in value.columns}
    return value


def _did_you_mean(key, known):
    """ "did you mean 'time'?" for the nearest known names, or ""."""
    near = _difflib.get_close_matches(key, known, n=3, cutoff=0.6)
    if not near:
        return ""
    quoted = [repr(n) for n in near]
    return "did you mean " + (quoted[0] if len(quoted) == 1 else ", ".join(quoted[:-1]) + " or " + quoted[-1]) + "?"


def _unknown(call, key, known, what):
    """Python's own TypeError for an unexpected keyword, with the nearest known ones."""
    near = _did_you_mean(key, known)
    return TypeError(f"{call} got an unexpected keyword argument {key!r}" + (f"; {near}" if near else "")
                     + f" ({what})")


def _deprecated(call, old, new):
    _warnings.warn(f"{call}: {old} is deprecated; use {new}", DeprecationWarning, stacklevel=3)


def _in_python_words(call, scene, places, error):
    """The scene loader's message about a keyword's value ("scenes/x.json:lyapunov.time: ...") as the call's
    ("lyapunov(): time: ..."); `places` maps each scene key of the call to the keyword the user wrote."""
    text = str(error)
    source = getattr(scene, "source", scene)
    for place, keyword in places.items():
        for prefix in (f"{source}:{place}: ", f"--set {place}: "):
            if text.startswith(prefix):
                return ValueError(f"{call}: {keyword}: {text[len(prefix):]}")
        if scene is None and f":{place}: " in text:  # a scene read for the call (Scene(problem)): its file
            return ValueError(f"{call}: {keyword}: {text.split(f':{place}: ', 1)[1]}")
    if text.startswith("--set "):  # no keyword of the call: the command line's wording all the same
        return ValueError(f"{call}: {text[len('--set '):]}")
    return error


def _settings_keys(call, problem, parameters, state_names, kw):
    """Plain model parameters and dotted keys as set() takes them; TypeError for anything else, ValueError
    naming the argument for a NaN or an infinity."""
    out = {}
    for key, value in kw.items():
        if "." in key:
            if key == "initial.state" and not isinstance(value, dict):
                values = _np.ravel(_np.asarray(value, float))
                if len(values) != len(state_names):
                    raise ValueError(f"{call}: initial.state: {len(values)} values for the {len(state_names)} "
                                     f"components of {problem}'s state ({', '.join(state_names)})")
                value = dict(zip(state_names, _plain(values)))
            _check_finite(call, key, value)
            out[key] = _plain(value)
        elif key in parameters:
            _check_type(call, key, "number", value)
            out[key] = _plain(value)
        else:
            raise _unknown(call, key, list(parameters),
                           f"takes the parameters of {problem} ({', '.join(parameters)}) and dotted scene "
                           "keys such as **{'integrator.method': 'verner9'}")
    return out


def _model_parameter_keys(scene, call, kw):
    return _settings_keys(call, scene.problem, scene.parameters, scene.state_names, kw)


# ------------------------------------------------------------------- the lists and models (with signatures)

def describe(problem):
    """A problem's parameters, state, first integrals, map coordinates and observables (rollviz describe):
    `problem` a problem's id or a model file's path."""
    return _core.describe(_os.fspath(problem))


def integrators():
    """The integrators: a list of {id, title, parameters}."""
    return _core.integrators()


def modules():
    """The modules loaded (ROLLVIZ_MODULE_PATH, ~/.local/lib/rollviz/modules): path, problems, tools,
    integrators each added."""
    return _core.modules()


def problems():
    """The problems (models): a list of {id, title}."""
    return _core.problems()


def scenes_directory():
    """The folder of the shipped scene files."""
    return _core.scenes_directory()


_cpp_model_init = Model.__init__
_cpp_model_load = Model.load
_cpp_model_describe = Model.describe


def _model_init(self, model):
    """A model from a dict with the content of a model file (docs/models.md)."""
    if not isinstance(model, _abc.Mapping):
        raise TypeError(f"Model(): model takes a dict (a model file's content), not {type(model).__name__}; "
                        "Model.load(path) reads a file")
    _check_finite("Model()", "model", dict(model))
    _cpp_model_init(self, dict(model))


def _model_load(path):
    """Loads a model file (docs/models.md)."""
    return _cpp_model_load(_os.fspath(path))


def _model_describe(self):
    """Its parameters, state, integrals, map coordinates and observables (as rollviz.describe)."""
    return _cpp_model_describe(self)


Model.__init__ = _model_init
Model.load = staticmethod(_model_load)
Model.describe = _model_describe


def _expression(value, where):
    """A number, an expression (a string) or, for a vector or a matrix, a sequence of them, as a rolling
    description's value: numbers stay numbers, sequences become the expression "[a, b, c]"."""
    if isinstance(value, (str, _numbers.Real)) and not isinstance(value, bool):
        return value
    if isinstance(value, (_abc.Sequence, _np.ndarray)) and not isinstance(value, (str, bytes)):
        parts = [_expression(v, where) for v in value]
        return "[" + ", ".join(p if isinstance(p, str) else repr(float(p)) for p in parts) + "]"
    raise TypeError(f"rolling_body(): {where} takes a number, an expression (a string) or a sequence of them, "
                    f"not {type(value).__name__}")


def rolling_body(shape, *, mass, inertia, id="rolling_body", title=None, centre=None, axis=None,
                 principal_axes=None, gyrostat=None, support=None, contact="marble", friction=None, gravity=1,
                 potential=None, parameters=None, definitions=None, observables=None, initial=None, **sizes):
    """A rolling body from its geometry (docs/rolling.md): rollviz derives its equations. A Model.

        top = rollviz.rolling_body("sphere", radius=1, centre=[0, 0, 0.3], axis=[0, 0, 1], mass=1,
                                   inertia=["I1", "I1", 0.4], contact="sliding", friction="mu",
                                   parameters={"I1": 0.35, "mu": 1.0})

    `shape` is sphere, ellipsoid, paraboloid, disk, superellipsoid, revolution or implicit, its sizes given as
    keywords (radius, semi_axes, p, q, height, exponent, bulge, profile, profile_squared, heights, F, size). A
    value is a number, an expression of the parameters (a string) or, for a vector or a matrix, a sequence of
    them; `inertia` three principal moments (along the body axes, or the rows of `principal_axes`), a 3x3
    matrix or one expression. `support` "plane" (the default) or a dict such as {"surface": "sphere",
    "radius": 5, "side": "inside"}; `contact` marble, rubber or sliding (with `friction`); `parameters`
    {name: default} or {name: {"default": ..., "min": ..., "description": ...}}; `initial` a start {state
    name: value}. A bad description raises ValueError naming the field."""
    body = {"shape": shape}
    for key, value in sizes.items():
        body[key] = value if key in ("F", "profile", "profile_squared") else _expression(value, key)
    for key, value in (("centre", centre), ("axis", axis), ("principal_axes", principal_axes),
                       ("gyrostat", gyrostat)):
        if value is not None:
            body[key] = _expression(value, key)
    body["mass"] = _expression(mass, "mass")
    if isinstance(inertia, (_abc.Sequence, _np.ndarray)) and not isinstance(inertia, str):
        body["inertia"] = [_expression(row, "inertia") if not isinstance(row, (_abc.Sequence, _np.ndarray))
                           or isinstance(row, str) else [_expression(v, "inertia") for v in row]
                           for row in inertia]
    else:
        body["inertia"] = _expression(inertia, "inertia")
    doc = {"kind": "rolling", "id": id, "body": body, "contact": contact, "gravity": _expression(gravity, "gravity")}
    if title is not None:
        doc["title"] = title
    if support is not None:
        doc["support"] = support if isinstance(support, str) else {
            k: v if k in ("surface", "side", "describes", "F", "height") else _expression(v, "support." + k)
            for k, v in dict(support).items()}
    if friction is not None:
        doc["friction"] = _expression(friction, "friction")
    if potential is not None:
        doc["potential"] = potential
    if parameters:
        doc["parameters"] = {name: value if isinstance(value, _abc.Mapping) else {"default": value}
                             for name, value in parameters.items()}
    for key, value in (("definitions", definitions), ("observables", observables)):
        if value:
            doc[key] = dict(value)
    if initial:
        doc["initial"] = {"state": dict(initial)}
    return Model(doc)


# ------------------------------------------------------------------------------------------ scenes as values

_cpp_init = Scene.__init__
_cpp_load = Scene.load
_cpp_from_json = Scene.from_json
_cpp_copy = Scene.copy
_cpp_to_json = Scene.to_json
_cpp_save = Scene.save
_cpp_export_view = Scene.export_view
_cpp_chart = Scene.chart
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


def _scene_init(self, problem, **settings):
    """A scene of `problem`: a problem's id (its shipped scene, scenes/<problem>.json) or a Model (a system
    written as equations; give its start as **{'initial.state': {...}} unless its file has one), with model
    parameters (energy=0.4) and dotted scene keys (**{'integrator.method': 'verner9'}) set."""
    if isinstance(problem, Model):
        info = problem.describe()
    elif isinstance(problem, str):
        info = describe(problem)  # ValueError listing the problems
    else:
        raise TypeError(f"Scene(): problem takes a problem's id (str) or a Model, not {type(problem).__name__}")
    keys = _settings_keys("Scene()", info["id"], [p["id"] for p in info["parameters"]], info["state"], settings)
    try:
        _cpp_init(self, problem, **keys)
    except ValueError as e:
        raise _in_python_words("Scene()", None, {("parameters." + k if "." not in k else k): k for k in keys},
                               e) from None


def _load(path, **settings):
    """Reads a scene file; keywords (model parameters, dotted scene keys) as for set()."""
    path = _os.fspath(path)
    if not settings:
        return _cpp_load(path)
    try:
        scene = _cpp_load(path)
    except ValueError:  # perhaps what the keywords give is missing (a model without a start): as the CLI reads it
        keys = {}
        for k, v in settings.items():
            if "." in k:
                _check_finite("Scene.load()", k, v)
            else:
                _check_type("Scene.load()", k, "number", v)
            keys[k] = _plain(v)
        try:
            return _cpp_load(path, **keys)
        except ValueError as e:
            raise _in_python_words("Scene.load()", None, {("parameters." + k if "." not in k else k): k
                                                          for k in keys}, e) from None
    return _set_for("Scene.load()", scene, settings)


def _from_json(text, source="<json>"):
    """A scene from its JSON text (what to_json() gives); `source` names it in messages."""
    if not isinstance(text, str):
        raise TypeError(f"Scene.from_json(): text takes a str, not {type(text).__name__}")

    def no_constant(name):
        raise ValueError(f"Scene.from_json(): {name} is not a number a scene can hold (JSON has no NaN or infinity)")

    try:
        _json.loads(text, parse_constant=no_constant)
    except _json.JSONDecodeError as e:
        raise ValueError(f"Scene.from_json(): not JSON: {e}") from None
    return _cpp_from_json(text, source)


def _copy_scene(self):
    """An independent copy (a Scene is a value: set() and with_state() already return new ones)."""
    return _cpp_copy(self)


def _to_json(self):
    """The scene file's text (what save() writes)."""
    return _cpp_to_json(self)


def _save(self, path):
    """Writes the scene file (through a temporary name, so a reader never sees half of it)."""
    return _cpp_save(self, _os.fspath(path))


def _export_view(self, path, time=10.0):
    """Writes the 3D view at `time` as a ParaView multiblock (.vtm: bodies, plane, traces; rollviz render -o
    view.vtm)."""
    return _cpp_export_view(self, _os.fspath(path), time)


class Picture(_np.ndarray):
    """An H x W x 3 uint8 image (a NumPy array) that Jupyter shows as a PNG: what render() and chart() give."""

    def _repr_png_(self):
        return _png_bytes(_np.asarray(self))


def _picture(pixels):
    return _np.asarray(pixels).view(Picture)


def _chart(self, view="poincare", size=None, points=0, diagram="", *, path=None, style="screen", scale=1,
           progress=None):
    """A chart of the scene (rollviz chart --view VIEW) as an H x W x 3 uint8 array (a Picture, shown in
    Jupyter); with path, also written as a figure in the format its extension names (.png, or .svg or .pdf:
    vectors, text as text). size: (width, height), default (800, 800); style 'paper': white, black axes and
    text, the type of a 3.5-inch journal column at 300 dpi (1050 x 788 unless size is given); scale N: N x the
    pixels with text and pens N x as large."""
    if size is not None:
        size = _picture_size("chart()", size)
    return _picture(_cpp_chart(self, view, size, points, diagram, path=None if path is None else _os.fspath(path),
                               style=style, scale=scale, progress=progress))


def _with_initial(scene, initial):
    doc = _json.loads(scene.to_json())
    kept = {k: v for k, v in doc.get("initial", {}).items() if k not in ("map", "state", "root", "exact")}
    doc["initial"] = {**kept, **initial}
    return doc


def _from_document(scene, doc, keys=None):
    new = Scene.from_json(_json.dumps(doc), scene.source)
    if keys:
        _cpp_set(new, **keys)
    return new


def _with_state(self, state, **settings):
    """A new scene that starts from `state`: an array of the state's components (Scene.state_names, as
    Trajectory.final) or a mapping {name: value}; other keywords as for set(). A whole state (every component)
    is taken exactly as given, none projected by the model, so s.with_state(r.final).integrate(..., t0=r.t[-1])
    goes on from where r ended (a fixed-step method bit for bit where the step divides the time); a partial
    mapping is completed by the model as a scene file's "initial.state" is."""
    if isinstance(state, _abc.Mapping):
        state = dict(state)
    else:
        values = _np.ravel(_np.asarray(state, dtype=float))
        if len(values) != len(self.state_names):
            raise ValueError(f"with_state(): {len(values)} values for the {len(self.state_names)} components of "
                             f"{self.problem}'s state ({', '.join(self.state_names)})")
        state = dict(zip(self.state_names, values))
    for k, v in state.items():
        _check_type("with_state()", f"state {k}" if not isinstance(k, str) else k, "number", v)
    state = {k: float(v) for k, v in state.items()}  # repr() of a float reads back exactly: no digit lost
    keys = _model_parameter_keys(self, "with_state()", settings)
    try:
        doc = _with_initial(self, {"state": state, **({"exact": True} if set(state) == set(self.state_names) else {})})
        return _from_document(self, doc, keys)
    except ValueError as e:
        raise _in_python_words("with_state()", self, {("parameters." + k if "." not in k else k): k for k in keys},
                               e) from None


def _integrate(self, time=None, every=None, columns=None, *, t_eval=None, events=None, after=None, t0=0.0,
               progress=None, **settings):
    """Integrates and samples observables at t = 0, every, 2 every, ... up to time (rollviz integrate); a
    negative time integrates backward (t = 0, -every, ...); t_eval gives the times instead (ascending from 0, or
    descending from 0 for a backward run), from the dense output of one integration. columns: observable ids, a
    list or one name (default: all). after=r (a Trajectory of this scene) goes on from where r ended: the
    samples after r's last one, bit for bit what one longer call gives. events=(observable, level) or
    (observable, level, "positive"|"negative"|"both"): the crossings of that level on the way, located on the
    dense output as the Poincare map locates them (r.events, a Trajectory of the same columns at the crossing
    times). t0: the time the scene's state is at (samples at t0, t0 + every, ...; time is the span and t_eval
    absolute times): s.with_state(r.final).integrate(time, every, t0=r.t[-1]) goes on where r ended, its clock
    too. Other keywords: model parameters and dotted scene keys for this call (as set()). Returns a
    Trajectory: r["E"] a column, r.t the times, np.asarray(r) the rows, r.final the whole state at the last
    sample (Scene.with_state(r.final) is a new scene that starts there)."""
    for key in settings:
        if "." not in key and key not in self.parameters:
            raise _unknown("integrate()", key, ["time", "every", "columns", "t_eval", "events", "after", "t0",
                                                "progress"] + list(self.parameters),
                           f"takes time, every, columns, t_eval, events, after, t0, progress, the parameters of "
                           f"{self.problem} ({', '.join(self.parameters)}) and dotted scene keys")
    _check_type("integrate()", "t0", "number", t0)
    t0 = float(t0)
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
        if after._scene != document or after._t0 != t0:
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
        times = [t0 + sign * k * every for k in range(first, count)]
    r = _sampled(scene, times, names, None if after is None else after._resume, progress, t0)
    if not times and after is not None:
        r.final, r.final_named = after.final, after.final_named
    r._scene, r._every, r._next, r._t0 = document, every, first + len(times), t0
    r._source = scene
    if events is not None:
        r.events = _events(scene, events, (times[-1] if times else t0) - t0, names, progress, t0)
    return r


def _events(scene, events, end, names, progress, t0=0.0):
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
    # the models are autonomous: a crossing tau after the start is at t0 + tau
    return _sampled(scene, [t0 + t for t in section.poincare()["t"] if abs(t) <= abs(end)], names, None, progress,
                    t0)


def _sampled(scene, times, names, resume, progress, t0=0.0):
    """The named columns at `times` from one integration from t0 (going on from `resume`, an integrator's
    snapshot). The state's components ride along as columns (each is an observable): the last row gives the
    final state."""
    X, snapshot = scene._integrate_at(times, names + list(scene.state_names), resume=resume, progress=progress,
                                      t0=t0)
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
    return _picture(_cpp_render(scene, _picture_size("render()", size), time, 1, transparent))


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


Scene.__init__ = _scene_init
Scene.load = staticmethod(_load)
Scene.from_json = staticmethod(_from_json)
Scene.copy = _copy_scene
Scene.to_json = _to_json
Scene.save = _save
Scene.export_view = _export_view
Scene.chart = _chart
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
Scene._repr_png_ = lambda self: _png_bytes(self.render(size=(480, 360)))
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


# Names the tool calls took besides their settings' own, kept for a while: (argument, the keyword to use, its
# value from the old one's; None: nothing set)
_DEPRECATED_ARGUMENTS = {
    "param": ("parameter", lambda v: v),
    "arclength": ("method='arclength'", lambda v: ("method", "arclength") if v else None),
    "doubled": ("switch=1", lambda v: ("switch", 1) if v else None),
}
# keywords a call took that never did anything there, ignored with a warning: (tool, keyword) -> why
_IGNORED = {("megno", "accuracy"): "it was the Poincare section's crossing accuracy (poincare.accuracy), which "
                                   "MEGNO, following the whole trajectory, never used"}
# keywords a call has beyond its scene sections': id -> (type, default, description)
_EXTRA_KEYWORDS = {
    "megno": {"transient": ("number", 0.0,
                            "time integrated first and discarded (the orbit settles, e.g. on its attractor); "
                            "MEGNO then starts there from t = 0 with a fresh tangent vector (Python only: a sweep "
                            "integrates from its points)")},
}
# the Python result's fields where they differ from the CLI's JSON (the registry's outputs describe that)
_PYTHON_OUTPUTS = {
    "continuation": [
        ("parameter", "the continued parameter's name"),
        ("parameter_values", "the parameter at each of the family's N points (an array of N)"),
        ("coordinates", "the names of the map coordinates"),
        ("points", "the fixed points: an N x d array, row i the map coordinates (coordinates) at "
                   "parameter_values[i]"),
        ("multipliers", "their multipliers: an N x d complex array"),
        ("residual", "|Map^n(x) - x| at each point (an array of N)"),
        ("types", "each point's type (a list of N)"),
        ("changes", "where the type changes: a list of {kind, parameter, point, ...}"),
        ("end", "why the family ends"),
        ("failure", "what failed, or ''"),
        ("<columns>", "the CLI table's columns by name too (the parameter's, re1, im1, ..., type)"),
        ("order, parent", "with switch (branch switching): the doubled family's order, and the family it was "
                          "born from"),
    ],
}


def _settings_doc(tool):
    lines = [f"{tool['title']}: {tool['description']}.", ""]
    keywords = _keywords(tool)
    extra = _EXTRA_KEYWORDS.get(tool["id"], {})
    if keywords or extra:
        lines.append("Keyword settings, for this call only (omitted: the scene's value, which defaults to the one "
                     "shown):")
        for k in keywords:
            if _is_flag(k.get("choices")):
                kind, default = "bool", f" = {_default(k)!r}"
            else:
                kind = f"one of {', '.join(k['choices'])}" if k["type"] == "choice" else k["type"]
                default = "" if k["default"] is None else f" = {_default(k)!r}"
            lines.append(f"    {k['id']}{default} ({k['section']}.{k['id']}, {kind}): {k['description']}")
        for name, (kind, default, description) in extra.items():
            lines.append(f"    {name} = {default!r} ({kind}): {description}")
    arguments = [a for a in tool["arguments_help"].split("; ") if a and a.split(":")[0] not in _DEPRECATED_ARGUMENTS]
    if arguments:
        lines.append("Arguments: " + "; ".join(arguments))
    deprecated = [f"{a} (use {_DEPRECATED_ARGUMENTS[a][0]})" for a in tool["arguments"] if a in _DEPRECATED_ARGUMENTS]
    if deprecated:
        lines.append("Deprecated (a DeprecationWarning): " + ", ".join(deprecated) + ".")
    lines.append("Also: the model's parameters by name (energy=0.4) and dotted scene keys, for this call.")
    lines.append("progress: None or a callable taking the fraction done.")
    if tool["id"] == "plot":
        lines += ["", "Returns: a Table of the plotted points, its columns named after the observables on the axes."]
    elif tool["outputs"]:
        lines.append("")
        lines.append("Returns:" + (" a Table of the map's points (the map coordinates, t, sheet)"
                                   if tool["id"] in ("poincare", "map3d") else
                                   " a Result (a mapping whose keys are attributes):"))
        for name, description in _PYTHON_OUTPUTS.get(tool["id"], tool["outputs"]):
            lines.append(f"    {name}: {description}")
    if tool["reference"]:
        lines.append(f"Reference: {tool['reference']}")
    return "\n".join(lines)


def _signature(tool):
    P = _inspect.Parameter
    params = [P("self", P.POSITIONAL_ONLY)]
    for k in _keywords(tool):
        if _is_flag(k.get("choices")):
            params.append(P(k["id"], P.KEYWORD_ONLY, default=_default(k), annotation=bool))
            continue
        annotation = (_typing.Literal[tuple(k["choices"])] if k["type"] == "choice"
                      else _ANNOTATIONS.get(k["type"], _typing.Any))
        if k["default"] is None:
            annotation = _typing.Optional[annotation]
        params.append(P(k["id"], P.KEYWORD_ONLY, default=_default(k), annotation=annotation))
    for name, (kind, default, _) in _EXTRA_KEYWORDS.get(tool["id"], {}).items():
        params.append(P(name, P.KEYWORD_ONLY, default=default, annotation=_ANNOTATIONS[kind]))
    for a in tool["arguments"]:
        if a not in {p.name for p in params} and a not in _DEPRECATED_ARGUMENTS:
            params.append(P(a, P.KEYWORD_ONLY, default=None))
    params.append(P("progress", P.KEYWORD_ONLY, default=None,
                    annotation=_typing.Optional[_typing.Callable[[float], None]]))
    params.append(P("overrides", P.VAR_KEYWORD))
    return _inspect.Signature(params)


def _default(k):
    d = k["default"]
    if _is_flag(k.get("choices")):
        return d == "yes"
    return int(d) if k["type"] == "integer" and d is not None else d


def _make_method(tool):
    tool_id = tool["id"]
    keywords = {k["id"]: k for k in _keywords(tool)}
    extra = _EXTRA_KEYWORDS.get(tool_id, {})
    arguments = set(tool["arguments"])
    call = f"{tool_id}()"

    def method(self, *args, progress=None, **kw):
        if args:
            first = next(iter(keywords), "time")
            raise TypeError(f"{call} takes keyword arguments only ({len(args)} given by position): "
                            f"e.g. {tool_id}({first}=...)")
        settings, parameters, extras = {}, {}, {}
        for key, value in list(kw.items()):
            if key in arguments and key in _DEPRECATED_ARGUMENTS:
                use, convert = _DEPRECATED_ARGUMENTS[key]
                _deprecated(call, key, use)
                if key == "param":
                    key = "parameter"
                else:
                    given = convert(value)
                    if given is None:
                        continue
                    key, value = given
                if key in kw:
                    raise TypeError(f"{call}: give {key} only (not {key} and its deprecated name)")
            if (tool_id, key) in _IGNORED:
                _warnings.warn(f"{call}: {key} is deprecated and ignored: {_IGNORED[(tool_id, key)]}",
                               DeprecationWarning, stacklevel=2)
                continue
            if key in extra:
                _check_type(call, key, extra[key][0], value)
                extras[key] = value
            elif key in keywords and _is_flag(keywords[key].get("choices")):
                # by its scene key: a flag argument of the same name (fixedpoint's path) takes any value as set
                _check_type(call, key, "choice", value, keywords[key]["choices"])
                settings[f"{keywords[key]['section']}.{key}"] = _flag_value(value)
            elif key in arguments or "." in key:
                if "." in key:
                    _check_finite(call, key, value)
                settings[key] = _plain(value)
            elif key in keywords:
                k = keywords[key]
                _check_type(call, key, k["type"], value, k.get("choices"))
                settings[key] = _plain(value)
            elif key in self.parameters:
                parameters[key] = value
            else:
                raise _unknown(call, key, list(keywords) + list(extra) + list(arguments - set(_DEPRECATED_ARGUMENTS))
                               + list(self.parameters),
                               f"settings: {', '.join(list(keywords) + list(extra)) or 'none'}; the parameters of "
                               f"{self.problem}; or a dotted scene key")
        scene = _set_for(call, self, parameters) if parameters else self
        if extras.get("transient"):
            scene = _after_transient(call, scene, float(extras["transient"]))
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


def _after_transient(call, scene, transient):
    """The scene started where its trajectory is after `transient` (the whole state carried exactly)."""
    if transient < 0:
        raise ValueError(f"{call}: transient must not be negative, got {transient}")
    end = scene.integrate(t_eval=[transient], columns=[scene.observables[0]])
    return scene.with_state(end.final)


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
    for k, v in settings.items():
        _check_finite("sweep()", k, v)
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
        # the files are this call's own: its messages name the call and the scene, not where they lay
        said = {path + ":": "sweep(): ", path: "sweep()", _os.path.join(folder, "scene.json"): scene.source,
                folder + _os.sep: ""}
        return _run_sweep(path, threads, progress, checkpoint, said)


def _without_paths(text, said):
    for path, words in said.items():
        text = text.replace(path, words)
    # the temporary store of the points (no checkpoint): its name says nothing to the caller
    return _re.sub(r"\S*rollviz-\d+-\d+\.sweep-part", "the sweep's temporary store", text)


def _run_sweep(path, threads, progress, checkpoint, said=None):
    said = said or {}
    try:
        raw = _sweep_file(path, threads, progress=progress, checkpoint=checkpoint)
    except KeyboardInterrupt as stopped:
        if len(stopped.args) == 2 and isinstance(stopped.args[1], dict):
            stopped.partial = _sweep_result(stopped.args[1], said)
        raise
    except (ValueError, ComputationError) as e:
        text = _without_paths(str(e), said)
        if text == str(e):
            raise
        raise type(e)(text) from None
    return _sweep_result(raw, said)


def _sweep_result(raw, said=None):
    r = dict(raw)
    if said:
        r["status"] = [_without_paths(x, said) for x in r["status"]]
    shape = list(r["shape"])
    columns = dict(r["columns"])
    axis_ids = list(columns)[:len(shape)]
    # the flat columns run first axis fastest: Fortran order gives grid[i0, i1]
    r["values"] = {k: _np.asarray(v).reshape(shape, order="F") for k, v in columns.items() if k not in axis_ids}
    r["axes"] = {k: _np.asarray(columns[k]).reshape(shape, order="F")[
        tuple(slice(None) if j == i else 0 for j in range(len(shape)))] for i, k in enumerate(axis_ids)}
    return SweepResult(r)
