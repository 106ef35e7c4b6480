#!/usr/bin/env python3
"""Copies the guide's pages into OUT and adds the reference pages generated from the program itself:
command-line.md from `rollviz --help` and every subcommand's help, and gallery.md with the gallery's pictures
rendered by rollviz (scripts/make_gallery.py); and runs every `rollviz ...` line of the tutorials' ```sh blocks in
the page's folder, so the pictures a tutorial shows are what its commands wrote (a failing command fails the
guide). Usage: generate.py DOCS_DIR OUT_DIR ROLLVIZ"""
import os
import re
import shlex
import shutil
import subprocess
import sys

docs, out, rollviz = sys.argv[1], sys.argv[2], sys.argv[3]
if os.path.isdir(out):
    shutil.rmtree(out)
shutil.copytree(docs, out, ignore=shutil.ignore_patterns("generate.py", "__pycache__"))
# the pictures the pages share with the README: ../assets/readme/ in docs/ (so both read them in place on a
# repository's page), copied into the guide and pointed at there
shutil.copytree(os.path.join(os.path.dirname(os.path.abspath(docs)), "assets", "readme"), os.path.join(out, "_readme"))
for name in os.listdir(out):
    if name.endswith(".md"):
        with open(os.path.join(out, name)) as f:
            text = f.read()
        if "../assets/readme/" in text:
            with open(os.path.join(out, name), "w") as f:
                f.write(text.replace("../assets/readme/", "_readme/"))

env = dict(os.environ)
env.pop("DISPLAY", None)


def help_of(*args):
    r = subprocess.run([rollviz, *args, "--help"], capture_output=True, text=True, env=env, timeout=60)
    if r.returncode != 0:
        sys.exit(f"generate.py: `rollviz {' '.join(args)} --help` failed: {r.stderr}")
    return r.stdout.replace(rollviz, "rollviz")


top = help_of()
commands = []
for line in top.split("Subcommands:", 1)[1].splitlines():
    m = re.match(r"^  (\S+)\s+(.*)$", line)
    if m:
        commands.append((m.group(1), m.group(2)))
if not commands:
    sys.exit("generate.py: no subcommands in `rollviz --help`")

with open(os.path.join(out, "command-line.md"), "w") as f:
    f.write("# The command line\n\n")
    f.write("Generated from the program's own help (`rollviz --help`, `rollviz COMMAND --help`) when the guide "
            "is built, so it is the help of the build it documents. Exit status: 0 done, 1 a computation failed "
            "(the reason on standard error), 2 bad input (naming the file, field or flag), 130 interrupted.\n\n")
    f.write("```text\n" + top.rstrip() + "\n```\n\n")
    for name, summary in commands:
        f.write(f"## {name}\n\n{summary}\n\n```text\n{help_of(name).rstrip()}\n```\n\n")


# the problems: each one's parameters (the scene's "parameters" keys, their defaults and ranges), state, map
# coordinates and observables, from `rollviz describe` -- the parameter tables themselves
problems = subprocess.run([rollviz, "list", "problems"], capture_output=True, text=True, env=env,
                          check=True).stdout.split()
with open(os.path.join(out, "problems.md"), "w") as f:
    f.write("# The problems\n\nGenerated from each problem's own tables (`rollviz describe PROBLEM`) when the guide "
            "is built: the keys of a scene's `\"parameters\"` with their defaults, ranges and meaning, the state "
            "(`\"initial\": {\"state\": ...}`), the map coordinates (`\"initial\": {\"map\": [...]}`) and the "
            "observables a section, a plot or `--columns` can name. The tools' settings are [the tools](tools.md); "
            "the rest of a scene file is [scene files](scenes.md).\n\n")
    for problem in problems:
        r = subprocess.run([rollviz, "describe", problem], capture_output=True, text=True, env=env, timeout=60)
        if r.returncode != 0:
            sys.exit(f"generate.py: `rollviz describe {problem}` failed: {r.stderr}")
        f.write(f"## {problem}\n\n```text\n{r.stdout.rstrip()}\n```\n\n")

# the gallery: each scene's picture rendered now, by this build
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(docs)), "scripts"))
import make_gallery  # noqa: E402

scenes = make_gallery.make(rollviz, os.path.join(out, "gallery"))
source = os.path.dirname(os.path.abspath(docs))
with open(os.path.join(out, "gallery.md"), "w") as f:
    f.write("# Gallery\n\n")
    f.write("Famous motions, ready to watch: in the GUI open them with **File > Gallery**; on the command line "
            "`rollviz list gallery` lists them. Each picture is the 3D view at the end of the scene's "
            "10-second video, rendered by this build when the guide was made; "
            "`scripts/make_gallery.py ROLLVIZ OUT --videos` makes the pictures and the videos.\n\n")
    for s in scenes:
        rel = os.path.relpath(s["path"], source)
        f.write(f"## {s['title']}\n\n![{s['title']}](gallery/{s['id']}.png)\n\n{s['description']}\n\n")
        f.write(f"```sh\nrollviz gui {rel}\nrollviz video {rel} -o {s['id']}.mp4\n"
                f"rollviz render {rel} -o {s['id']}.png --time {s['time']:g}\n```\n\n")

# the tutorials' commands, each run as written (scene paths are the project's) in the page's folder
tutorials = os.path.join(out, "tutorials")
for page in sorted(p for p in os.listdir(tutorials) if p.endswith(".md")):
    with open(os.path.join(tutorials, page)) as f:
        blocks = re.findall(r"```sh\n(.*?)```", f.read(), re.S)
    for line in (line for block in blocks for line in block.splitlines() if line.startswith("rollviz ")):
        args = [os.path.join(source, a) if a.startswith("scenes/") else a for a in shlex.split(line)[1:]]
        r = subprocess.run([rollviz, *args], cwd=tutorials, capture_output=True, text=True, env=env, timeout=600)
        if r.returncode != 0:
            sys.exit(f"generate.py: tutorials/{page}: `{line}` failed ({r.returncode}): {r.stderr}")
