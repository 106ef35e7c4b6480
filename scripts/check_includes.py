#!/usr/bin/python3
"""check_includes.py -- the project's include graph against its layering (design.md: app -> scenes -> render ->
dynamics): fails on a file that includes a higher layer, on a cycle between folders (dynamics/core <->
dynamics/integrators was one) and on a cycle between headers. Run by ./test; `--graph` prints the folders' graph.
(Modules that use each other through their .cpp files -- scenes' SceneLoader, Session and ModelFile -- are not
include cycles and are not checked here.)

Cycles that were there when the check came (issue 64) are listed in KNOWN with what breaks them; the check fails
on any other, and on a listed one that is gone (so that the list only shrinks).
"""
import os
import re
import sys
from collections import defaultdict

ROOTS = ["dynamics", "render", "scenes", "app"]  # in layer order, lowest first
INCLUDE = re.compile(r'\s*#\s*include\s+"([^"]+)"')

# cycles found on 2026-11-28, each the set of the nodes on it, with what breaks them. Empty since
# 2026-11-29: render/'s root <-> export <-> objects was broken by VisualScene's own folder (render/view, above
# objects) and hasExtension in dynamics/io/FileNames.h (BodyMeshes read a mesh's format from export/)
KNOWN = set()


def layer(path):
    return ROOTS.index(path.split("/")[0])


def sources(top):
    for root in ROOTS:
        for folder, _, files in os.walk(os.path.join(top, root)):
            for name in files:
                if name.endswith((".h", ".cpp", ".inl")):
                    yield os.path.relpath(os.path.join(folder, name), top)


def includes(top, path):
    with open(os.path.join(top, path), errors="replace") as f:
        for line in f:
            m = INCLUDE.match(line)
            if m and os.path.exists(os.path.join(top, m.group(1))) and m.group(1).split("/")[0] in ROOTS:
                yield m.group(1)


def cycles(graph):
    """The strongly connected components with more than one node (Tarjan)."""
    index, low, stack, on, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = set()
            while True:
                w = stack.pop()
                on.discard(w)
                component.add(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(frozenset(component))

    sys.setrecursionlimit(10000)
    for v in list(graph):
        if v not in index:
            visit(v)
    return found


def main():
    top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    files = defaultdict(set)
    folders = defaultdict(set)
    problems = []
    for path in sources(top):
        for inc in includes(top, path):
            if layer(inc) > layer(path):
                problems.append(f"{path} includes {inc}: an upward include ({ROOTS[layer(path)]} is below "
                                f"{ROOTS[layer(inc)]})")
            files[path].add(inc)
            a, b = os.path.dirname(path), os.path.dirname(inc)
            if a != b:
                folders[a].add(b)
    if "--graph" in sys.argv:
        for a in sorted(folders):
            print(a, "->", " ".join(sorted(folders[a])))
    # a .cpp is a leaf: only headers take part in file cycles
    headers = {p: {i for i in incs if not i.endswith(".cpp")} for p, incs in files.items() if not p.endswith(".cpp")}
    found = cycles(folders) + cycles(headers)
    for c in found:
        if c not in KNOWN:
            problems.append("an include cycle: " + " <-> ".join(sorted(c)))
    for c in KNOWN - set(found):
        problems.append("a known cycle is gone (remove it from KNOWN in scripts/check_includes.py): "
                        + " <-> ".join(sorted(c)))
    for p in problems:
        print("check_includes:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
