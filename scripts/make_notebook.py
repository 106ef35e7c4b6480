#!/usr/bin/env python3
"""Writes a Jupyter notebook from a script in the percent format (`# %%` code cells, `# %% [markdown]` text
cells), so that the example study exists once: examples/chaplygin_study.py -> examples/chaplygin_study.ipynb.

Usage: scripts/make_notebook.py SCRIPT.py [NOTEBOOK.ipynb]   (tests/python/test_example.py checks they agree)
"""
import json
import sys


def cells_of(text):
    """The script's cells: a list of (kind, source lines)."""
    cells = []
    for line in text.splitlines():
        if line.startswith("# %%"):
            cells.append(("markdown" if "[markdown]" in line else "code", []))
        elif cells:
            kind, lines = cells[-1]
            lines.append(line[2:] if kind == "markdown" and line.startswith("# ") else
                         "" if kind == "markdown" and line == "#" else line)
    return [(k, "\n".join(lines).strip("\n")) for k, lines in cells]


def notebook(text):
    cells = []
    for number, (kind, source) in enumerate(cells_of(text)):
        # nbformat 4.5 wants an id per cell: stable ones, so the notebook only changes with the script
        cell = {"cell_type": kind, "id": f"cell-{number}", "metadata": {}, "source": source.splitlines(keepends=True)}
        if kind == "code":
            cell.update(execution_count=None, outputs=[])
        cells.append(cell)
    return {"cells": cells, "nbformat": 4, "nbformat_minor": 5,
            "metadata": {"kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
                         "language_info": {"name": "python"}}}


if __name__ == "__main__":
    script = sys.argv[1]
    target = sys.argv[2] if len(sys.argv) > 2 else script.rsplit(".", 1)[0] + ".ipynb"
    with open(script) as f:
        nb = notebook(f.read())
    with open(target, "w") as f:
        json.dump(nb, f, indent=1, ensure_ascii=False)
        f.write("\n")
