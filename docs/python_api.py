#!/usr/bin/env python3
"""Writes the Python API reference (python-api.md) from the module itself: every public name of `rollviz`
(its __all__), each class's public methods -- the tool methods generated from the registry included -- with
their signatures and docstrings. Run with the built package importable (PYTHONPATH=<build>/python).
Usage: python_api.py OUT.md"""
import inspect
import sys

import rollviz


def signature(name, obj):
    """`name(args)`: from inspect where Python knows it, else from the first line pybind11 writes."""
    try:
        return name + str(inspect.signature(obj)).replace("self, /, ", "").replace("(self, ", "(").replace(
            "(self)", "()")
    except (TypeError, ValueError):
        doc = (obj.__doc__ or "").strip().splitlines()
        first = doc[0] if doc else ""
        if first.startswith(name.split(".")[-1] + "("):
            return name.rsplit(".", 1)[0] + "." + first if "." in name else first
        return name + "(...)"


def docstring(obj):
    """The docstring without pybind11's signature line (shown above it already)."""
    doc = inspect.getdoc(obj) or ""
    lines = doc.splitlines()
    if lines and "(" in lines[0] and "->" in lines[0]:
        lines = lines[1:]
    return "\n".join(lines).strip()


def block(out, heading, text, call=None):
    out.write(f"{heading}\n\n")
    if call:
        out.write("```python\n" + call + "\n```\n\n")
    if text:
        # the docstrings are plain text laid out for a terminal: kept as written
        out.write("```text\n" + text + "\n```\n\n")


def main():
    path = sys.argv[1]
    with open(path, "w") as out:
        out.write("# Python API reference\n\n")
        out.write(f"Generated from the module itself (`rollviz` {rollviz.__version__}: its `__all__`, each "
                  "signature and docstring) when the guide is built; the tool methods of `Scene` are generated "
                  "from the tool registry, so this lists the tools of this build. How to use them: "
                  "[Python](python.md).\n\n")
        block(out, "## The module", inspect.getdoc(rollviz))
        names = [n for n in rollviz.__all__ if not n.startswith("_")]
        classes = [n for n in names if inspect.isclass(getattr(rollviz, n))]
        functions = [n for n in names if callable(getattr(rollviz, n)) and n not in classes]
        out.write("## Functions\n\n")
        for n in functions:
            block(out, f"### `rollviz.{n}`", docstring(getattr(rollviz, n)), signature("rollviz." + n, getattr(rollviz, n)))
        for n in classes:
            cls = getattr(rollviz, n)
            block(out, f"## `rollviz.{n}`", docstring(cls))
            for m in sorted(vars(cls)):
                if m.startswith("_"):
                    continue
                member = getattr(cls, m)
                if isinstance(inspect.getattr_static(cls, m), property):
                    block(out, f"### `{n}.{m}` (property)", inspect.getdoc(member) or "")
                elif callable(member):
                    block(out, f"### `{n}.{m}`", docstring(member), signature(n + "." + m, member))


if __name__ == "__main__":
    main()
