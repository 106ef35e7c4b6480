#!/usr/bin/env python3
"""Writes the type stub of the rollviz package (rollviz/__init__.pyi and py.typed) from the module itself: the
hand-written calls from the signatures below, one method per registered tool from the signature the package gives
it (every setting of its sections, typed), so Jupyter, IDEs and mypy complete and check calls.

Usage: scripts/make_stub.py PACKAGE_DIR   (the build tree's python/rollviz; CMake runs it after the module links)
"""
import inspect
import os
import sys
import typing

HEADER = '''# The type stub of rollviz, written by scripts/make_stub.py from the tool registry: do not edit.
from typing import Any, Callable, Dict, Iterator, List, Literal, Mapping, Optional, Sequence, Tuple, Union
import os
import numpy as np
import numpy.typing as npt

__version__: str
Progress = Optional[Callable[[float], None]]

class ComputationError(RuntimeError): ...

class Result(Dict[str, Any]):
    def __getattr__(self, name: str) -> Any: ...

class Table:
    columns: List[str]
    shape: Tuple[int, int]
    def __init__(self, columns: Sequence[str], data: npt.ArrayLike) -> None: ...
    def keys(self) -> List[str]: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...
    def __contains__(self, name: object) -> bool: ...
    def __getitem__(self, key: Any) -> npt.NDArray[np.float64]: ...
    def __getattr__(self, name: str) -> npt.NDArray[np.float64]: ...
    def __array__(self, dtype: Any = ..., copy: Any = ...) -> npt.NDArray[Any]: ...
    def to_pandas(self) -> Any: ...
    def to_xarray(self) -> Any: ...

class Trajectory(Table):
    t: npt.NDArray[np.float64]
    final: Optional[npt.NDArray[np.float64]]
    final_named: Optional[Dict[str, float]]
    def show(self, duration: float = ..., *, height: int = ...) -> Optional[PageView]: ...

class PageView:
    html: str
    height: int
    def __init__(self, html: str, height: int = ...) -> None: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> None: ...

class SweepResult(Result):
    def to_xarray(self) -> Any: ...

class Model:
    id: str
    path: str
    def __init__(self, model: Dict[str, Any]) -> None: ...
    @staticmethod
    def load(path: str) -> Model: ...
    def describe(self) -> Dict[str, Any]: ...

class Scene:
    problem: str
    source: str
    initial_state: npt.NDArray[np.float64]
    state_names: List[str]
    observables: List[str]
    map_coordinates: List[str]
    @property
    def parameters(self) -> Mapping[str, float]: ...
    def __init__(self, problem: Union[str, Model], **settings: Any) -> None: ...
    @staticmethod
    def load(path: str, **settings: Any) -> Scene: ...
    @staticmethod
    def from_json(text: str, source: str = ...) -> Scene: ...
    def set(self, **settings: Any) -> Scene: ...
    def with_state(self, state: Union[npt.ArrayLike, Mapping[str, float]], **settings: Any) -> Scene: ...
    def copy(self) -> Scene: ...
    def to_json(self) -> str: ...
    def save(self, path: str) -> None: ...
    def integrate(self, time: float, every: float, columns: Union[None, str, Sequence[str]] = ..., *,
                  progress: Progress = ..., **settings: Any) -> Trajectory: ...
    def render(self, size: Tuple[int, int] = ..., time: float = ..., *, transparent: bool = ...,
               **settings: Any) -> npt.NDArray[np.uint8]: ...
    def snapshot(self, path: Union[str, os.PathLike[str]], size: Tuple[int, int] = ..., time: float = ..., *,
                 transparent: bool = ..., **settings: Any) -> None: ...
    def export_view(self, path: str, time: float = ...) -> None: ...
    def video(self, path: Union[str, os.PathLike[str]], duration: Optional[float] = ..., fps: Optional[int] = ...,
              size: Optional[Tuple[int, int]] = ..., speed: float = ...,
              encoder: Literal["libx264", "mpeg4"] = ..., *, progress: Progress = ..., **settings: Any) -> int: ...
    def page(self, path: Union[str, os.PathLike[str]], duration: Optional[float] = ..., fps: Optional[int] = ...,
             speed: Optional[float] = ..., *, progress: Progress = ..., **settings: Any) -> int: ...
    def show(self, duration: Optional[float] = ..., fps: Optional[int] = ..., speed: Optional[float] = ..., *,
             height: int = ..., **settings: Any) -> Optional[PageView]: ...
    def chart(self, view: str = ..., size: Tuple[int, int] = ..., points: int = ..., diagram: str = ..., *,
              path: Optional[str] = ..., progress: Progress = ...) -> npt.NDArray[np.uint8]: ...
'''

FOOTER = '''
class Session:
    path: str
    scene: Scene
    def __init__(self, path: Union[str, os.PathLike[str]]) -> None: ...
    @classmethod
    def load(cls, path: Union[str, os.PathLike[str]]) -> Session: ...
    def page(self, path: Union[str, os.PathLike[str]], duration: Optional[float] = ..., fps: Optional[int] = ...,
             speed: Optional[float] = ..., *, progress: Progress = ...) -> int: ...
    def show(self, duration: Optional[float] = ..., fps: Optional[int] = ..., speed: Optional[float] = ..., *,
             height: int = ...) -> Optional[PageView]: ...

def describe(problem: str) -> Dict[str, Any]: ...
def integrators() -> List[Dict[str, Any]]: ...
def modules() -> List[Dict[str, Any]]: ...
def problems() -> List[Dict[str, Any]]: ...
def scenes_directory() -> str: ...
def tools() -> List[Result]: ...
def sweep(scene: Union[str, os.PathLike[str], Scene], axes: Optional[Mapping[str, Any]] = ...,
          quantity: Optional[str] = ..., threads: int = ..., progress: Progress = ...,
          **settings: Any) -> SweepResult: ...
'''


def annotation(a):
    """A parameter's annotation as stub text."""
    if a is inspect.Parameter.empty:
        return "Any"
    if a in (int, float, str, bool):
        return a.__name__
    text = repr(a).replace("typing.", "").replace("NoneType", "None")
    return text


def method(name, sig, returns):
    parts = ["self", "*"]
    for p in list(sig.parameters.values())[1:]:
        if p.kind == inspect.Parameter.VAR_KEYWORD:
            parts.append(f"**{p.name}: Any")
        else:
            parts.append(f"{p.name}: {annotation(p.annotation)} = ...")
    return f"    def {name}({', '.join(parts)}) -> {returns}: ...\n"


def main(package):
    sys.path.insert(0, os.path.dirname(os.path.abspath(package)))
    import rollviz
    lines = [HEADER]
    for tool in rollviz.tools():
        if tool.id == "sweep" or not hasattr(rollviz.Scene, tool.id):
            continue
        returns = "Table" if tool.id in ("poincare", "map3d", "plot") else "Result"
        lines.append(method(tool.id, inspect.signature(getattr(rollviz.Scene, tool.id)), returns))
    lines.append(FOOTER)
    text = "".join(lines)
    for name, content in (("__init__.pyi", text), ("py.typed", "")):
        path = os.path.join(package, name)
        with open(path + ".part", "w") as f:
            f.write(content)
        os.replace(path + ".part", path)


if __name__ == "__main__":
    main(sys.argv[1])
