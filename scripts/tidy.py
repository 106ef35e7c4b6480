#!/usr/bin/env python3
"""clang-tidy (the checks of .clang-tidy) over rollviz's own translation units: dynamics/, render/, scenes/, app/.

Usage: scripts/tidy.py [BUILD_DIR] [-j N]   (BUILD_DIR: a configured and built tree, default build/dev)

A unity build's batches (cmake/Unity.cmake) are checked file by file, each with its batch's command and dependencies.
A translation unit found clean is remembered in ~/.cache/rollviz-tidy under a key made of the contents of every
project file it depends on (ninja's dependency list), the compile command and .clang-tidy -- so, like ccache, a
clone or a later run checks again only what changed. Prints each finding; exits 1 when there is any, 0 when none,
with a closing line 'tidy: N passed, N failed'."""
import hashlib
import json
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OWN = ("dynamics/", "render/", "scenes/", "app/")


def main():
    args = sys.argv[1:]
    jobs = os.cpu_count() or 2
    if "-j" in args:
        i = args.index("-j")
        jobs = int(args[i + 1])
        del args[i:i + 2]
    build = Path(args[0] if args else ROOT / "build" / "dev").resolve()
    cache = Path(os.environ.get("ROLLVIZ_TIDY_CACHE", Path.home() / ".cache" / "rollviz-tidy"))
    cache.mkdir(parents=True, exist_ok=True)
    commands = expand_unity_batches(json.loads((build / "compile_commands.json").read_text()))
    # clang-tidy reads each file's command from this database: the build's, with the batches expanded
    database = build / "tidy"
    database.mkdir(exist_ok=True)
    (database / "compile_commands.json").write_text(json.dumps(commands, indent=1))
    units = {}
    for c in commands:
        src = Path(c["directory"], c["file"]).resolve()
        try:
            rel = src.relative_to(ROOT).as_posix()
        except ValueError:
            continue
        if rel.startswith(OWN) and rel.endswith(".cpp") and "/autogen" not in rel:
            units.setdefault(rel, c)
    deps = dependencies(build)
    config = (ROOT / ".clang-tidy").read_bytes()
    contents = {}

    def digest(path):
        if path not in contents:
            try:
                contents[path] = hashlib.sha256(Path(path).read_bytes()).hexdigest()
            except OSError:
                contents[path] = "missing"
        return contents[path]

    todo, clean = [], 0
    for rel, c in sorted(units.items()):
        obj = c.get("output") or object_of(c)
        own = sorted({str(Path(build, d).resolve()) for d in deps.get(obj, [])} | {str(ROOT / rel)})
        own = [p for p in own if p.startswith(str(ROOT) + "/") and "/build" not in p[len(str(ROOT)):]]
        h = hashlib.sha256(config)
        # the command with the checkout's path taken out: clones elsewhere (CI) share the cache; the level of
        # debug information (-g, -g1) says nothing to clang-tidy
        h.update(json.dumps(debug_level_alike(c.get("command") or c.get("arguments"))).replace(
            str(ROOT), "<root>").encode())
        for p in own:
            h.update(Path(p).relative_to(ROOT).as_posix().encode() + digest(p).encode())
        key = h.hexdigest()
        if (cache / key).exists():
            clean += 1
        else:
            todo.append((rel, key))
    print(f"tidy: {len(units)} translation units, {clean} unchanged since found clean, {len(todo)} to check",
          flush=True)

    def check(item):
        rel, key = item
        r = subprocess.run(["clang-tidy", "-p", str(database), "--quiet", str(ROOT / rel)], capture_output=True,
                           text=True)
        findings = [line for line in r.stdout.splitlines() if ": warning: " in line or ": error: " in line]
        if r.returncode == 0 and not findings:
            (cache / key).touch()
        return rel, r.returncode, findings, r.stdout

    failed = 0
    seen = set()
    with ThreadPoolExecutor(jobs) as pool:
        for rel, rc, findings, out in pool.map(check, todo):
            if rc == 0 and not findings:
                continue
            failed += 1
            print(f"== {rel}: {len(findings)} findings", flush=True)
            for f in findings or out.splitlines()[-20:]:
                if f not in seen:
                    seen.add(f)
                    print("  " + f.replace(str(ROOT) + "/", ""))
    print(f"tidy: {len(units) - failed} passed, {failed} failed")
    return 1 if failed else 0


def expand_unity_batches(commands):
    """the compile commands with each unity batch (cmake/Unity.cmake: a unit that #includes a target's .cpp files)
    written as one command per file it includes; the object, and so the dependencies, stay the batch's"""
    out = []
    for c in commands:
        path = Path(c["directory"], c["file"])
        if path.parent.name != "unity" or not path.name.endswith(".cpp"):
            out.append(c)
            continue
        for line in path.read_text().splitlines():
            m = re.fullmatch(r'#include "(.+)"', line)
            if m:
                e = dict(c, file=str(ROOT / m.group(1)))
                if "command" in c:
                    e["command"] = c["command"].replace(c["file"], e["file"])
                if "arguments" in c:
                    e["arguments"] = [e["file"] if a == c["file"] else a for a in c["arguments"]]
                if "output" not in c:
                    e["output"] = object_of(c)
                out.append(e)
    return out


def debug_level_alike(command):
    """the compile command (a string or a list) with any -g<level> written as -g"""
    if isinstance(command, str):
        return re.sub(r"(?<=\s)-g[0-3]?(?=\s|$)", "-g", command)
    return ["-g" if re.fullmatch(r"-g[0-3]?", a) else a for a in command]


def object_of(command):
    parts = command.get("arguments") or command["command"].split()
    return parts[parts.index("-o") + 1] if "-o" in parts else ""


def dependencies(build):
    """ninja's recorded headers of every object: {object: [paths relative to the build dir]}"""
    out = subprocess.run(["ninja", "-C", str(build), "-t", "deps"], capture_output=True, text=True).stdout
    deps, current = {}, None
    for line in out.splitlines():
        if not line.strip():
            current = None
        elif not line.startswith(" "):
            current = line.split(":")[0]
            deps[current] = []
        elif current is not None:
            deps[current].append(line.strip())
    return deps


if __name__ == "__main__":
    sys.exit(main())
