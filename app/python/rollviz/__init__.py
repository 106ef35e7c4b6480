"""rollviz: bodies rolling without slipping, and the tools of nonlinear dynamics, from Python.

    import rollviz
    s = rollviz.Scene.load("scenes/chaplygin_ball.json")      # or rollviz.Scene("chaplygin_ball", energy=0.4)
    m = rollviz.Model.load("examples/models/lorenz.json")      # a system written as equations (docs/models.md)
    s = rollviz.Scene(m, rho=28, **{"initial.state": {"x": 1, "y": 1, "z": 1}})
    s.set(energy=0.4, **{"integrator.method": "everhart"})
    t, X = s.integrate(time=100, every=0.1, columns=["t", "E", "M1"])
    P = s.poincare(points=2000)              # map coordinates, t, sheet per row
    r = s.lyapunov(time=1000)                # r.exponents, r.converged, r.t, r.history
    img = s.render(size=(640, 480), time=5)  # H x W x 3 uint8

Every registered tool (rollviz.tools()) is a Scene method, those of the modules loaded at import
(rollviz.modules(): ROLLVIZ_MODULE_PATH, ~/.local/lib/rollviz/modules; docs/modules.md) too; its keyword arguments are the settings of its
scene section (s.megno(time=1e4) sets megno.time for that call), of the sections of the tools it hangs under
(s.continuation(guess=[...]) is fixedpoint.guess), or any dotted scene key. Bad input raises ValueError with
the command line's message, a failed computation rollviz.ComputationError; long calls release the GIL, take
progress=callable(fraction) and stop on Ctrl-C with KeyboardInterrupt.
"""

from ._rollviz import ComputationError, Model, Scene, describe, integrators, modules, problems, scenes_directory, sweep
from ._rollviz import _tools

__all__ = ["ComputationError", "Model", "Result", "Scene", "describe", "integrators", "modules", "problems",
           "scenes_directory", "sweep", "tools"]


class Result(dict):
    """A tool's result: a dict whose keys are also attributes (r.exponents is r["exponents"])."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return list(self.keys()) + list(super().__dir__())


def _wrap(value):
    if isinstance(value, dict):
        return Result({k: _wrap(v) for k, v in value.items()})
    if isinstance(value, list):
        return [_wrap(v) for v in value]
    return value


def tools():
    """The registered tools in the order of the manual's tree: id, title, parent, settings, outputs, ..."""
    return [_wrap(t) for t in _tools()]


def _settings_doc(tool):
    lines = [f"{tool['title']}: {tool['description']}.", ""]
    if tool["settings"]:
        lines.append(f"Keyword settings (scene section \"{tool['section']}\"; for this call only):")
        for s in tool["settings"]:
            lines.append(f"    {s['id']} = {s['default']!r}: {s['description']}")
    if len(tool["sections"]) > 1:
        lines.append("Also the settings of the sections " + ", ".join(tool["sections"][1:]) + ".")
    if tool["arguments_help"]:
        lines.append("Arguments: " + tool["arguments_help"])
    lines.append("progress: None or a callable taking the fraction done.")
    if tool["reference"]:
        lines.append(f"Reference: {tool['reference']}")
    return "\n".join(lines)


def _make_method(tool):
    tool_id = tool["id"]

    def method(self, progress=None, **settings):
        return _wrap(self._run(tool_id, progress=progress, **settings))

    method.__name__ = tool_id
    method.__qualname__ = f"Scene.{tool_id}"
    method.__doc__ = _settings_doc(tool)
    return method


# one method per registered tool that runs on a scene (a sweep runs a sweep file: rollviz.sweep)
for _tool in _tools():
    if _tool["id"] != "sweep":
        setattr(Scene, _tool["id"], _make_method(_tool))
del _tool

_sweep = sweep


def sweep(path, threads=0, progress=None):  # noqa: F811 -- the same call, its result as a Result
    """Runs a sweep file (rollviz sweep) on threads; see docs/sweeps.md. Returns a Result: columns (the
    axes and the quantity's columns as arrays, the first axis fastest), shape, seconds, status."""
    return _wrap(_sweep(path, threads, progress=progress))
