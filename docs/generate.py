#!/usr/bin/env python3
"""Copies the guide's pages into OUT and adds the reference pages generated from the program itself:
command-line.md from `rollviz --help` and every subcommand's help, and gallery.md with the gallery's pictures
rendered by rollviz (scripts/make_gallery.py); and runs every `rollviz ...` line of the tutorials' ```sh blocks in
the page's folder, so the pictures a tutorial shows are what its commands wrote (a failing command fails the
guide). Also the GUI's screenshots (scripts/make_screenshots.py), the Python API reference from the built
module (docs/python_api.py) and the benchmarks page. Usage: generate.py DOCS_DIR OUT_DIR ROLLVIZ [PYTHON_DIR]"""
import json
import os
import re
import shlex
import shutil
import subprocess
import sys

docs, out, rollviz = sys.argv[1], sys.argv[2], sys.argv[3]
if os.path.isdir(out):
    shutil.rmtree(out)
shutil.copytree(docs, out, ignore=shutil.ignore_patterns("generate.py", "python_api.py", "__pycache__"))
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

scenes = make_gallery.make(rollviz, os.path.join(out, "gallery"), pages=os.path.join(out, "pages", "gallery"))
source = os.path.dirname(os.path.abspath(docs))
with open(os.path.join(out, "gallery.md"), "w") as f:
    f.write("# Gallery\n\n")
    f.write("Famous motions, ready to watch: in the GUI open them with **File > Gallery**; on the command line "
            "`rollviz list gallery` lists them. Each picture is the 3D view at the end of the scene's "
            "10-second video, rendered by this build when the guide was made; "
            "`scripts/make_gallery.py ROLLVIZ OUT --videos --pages` makes the pictures, the videos and the web "
            "pages. Each motion's **web page** plays in your browser, offline: turn the bodies with the mouse, "
            "scrub with the slider (`rollviz page`, one self-contained file of "
            f"{min(s['page_bytes'] for s in scenes) / 1e6:.1f}-{max(s['page_bytes'] for s in scenes) / 1e6:.1f} MB "
            "here, 0.85 MB of it the viewer).\n\n")
    for s in scenes:
        rel = os.path.relpath(s["path"], source)
        f.write(f"## {s['title']}\n\n![{s['title']}](gallery/{s['id']}.png)\n\n{s['description']}\n\n")
        f.write(f'<a href="gallery/{s["id"]}.html">Turn it around in your browser</a> '
                f"(web page, {s['page_bytes'] / 1e6:.1f} MB)\n\n")
        f.write(f"```sh\nrollviz gui {rel}\nrollviz video {rel} -o {s['id']}.mp4\nrollviz page {rel} -o {s['id']}.html\n"
                f"rollviz render {rel} -o {s['id']}.png --time {s['time']:g}\n```\n\n")

# the GUI's pictures, taken by this build (scripts/make_screenshots.py), in place of the marker on the GUI page
import make_screenshots  # noqa: E402

shots = make_screenshots.make(rollviz, source, os.path.join(out, "screenshots"))
with open(os.path.join(out, "gui.md")) as f:
    text = f.read()
if "<!-- screenshots -->" not in text:
    sys.exit("generate.py: gui.md lost its <!-- screenshots --> marker")
figures = "".join(f"![{caption}](screenshots/{name}.png)\n\n*{caption}*\n\n" for name, caption in shots)
with open(os.path.join(out, "gui.md"), "w") as f:
    f.write(text.replace("<!-- screenshots -->", figures))

# the Python API reference, from the module of this build (docs/python_api.py), where it was built
python_package = sys.argv[4] if len(sys.argv) > 4 else ""
api = os.path.join(out, "python-api.md")
if python_package and os.path.isdir(python_package):
    r = subprocess.run([sys.executable, os.path.join(docs, "python_api.py"), api], capture_output=True, text=True,
                       env={**env, "PYTHONPATH": python_package, "ROLLVIZ_MODULE_PATH": ""}, timeout=120)
    if r.returncode != 0:
        sys.exit(f"generate.py: the Python API reference failed: {r.stderr}")
    # the integrators' scene keys (integrator.*), from the registry's parameter tables
    r = subprocess.run([sys.executable, "-c", "import json, rollviz; print(json.dumps(rollviz.integrators()))"],
                       capture_output=True, text=True, check=True, env={**env, "PYTHONPATH": python_package,
                                                                        "ROLLVIZ_MODULE_PATH": ""})
    keys = "The keys of a scene's `\"integrator\"` section (`--set integrator.KEY=VALUE`), from each method's " \
           "parameter table:\n\n"
    for method in json.loads(r.stdout):
        keys += f"### `{method['id']}`\n\n{method['title']}.\n\n| key | default | range | meaning |\n|---|---|---|---|\n"
        for p in method["parameters"]:
            span = " / ".join(p["choices"]) if "choices" in p else f"{p['min']:g} .. {p['max']:g}"
            default = p["default"] if isinstance(p["default"], str) else f"{p['default']:g}"
            keys += f"| `{p['id']}` | {default} | {span} | {p['description']} |\n"
        keys += "\n"
    numerics = os.path.join(out, "numerics.md")
    with open(numerics) as f:
        text = f.read()
    with open(numerics, "w") as f:
        f.write(text.replace("<!-- integrator keys -->", keys))
    # the study in Python: the notebook's cells as a page, with the pictures its script wrote now
    study = os.path.join(out, "tutorials", "study")
    r = subprocess.run([sys.executable, os.path.join(source, "examples", "chaplygin_study.py"), study],
                       capture_output=True, text=True, env={**env, "PYTHONPATH": python_package,
                                                           "ROLLVIZ_MODULE_PATH": ""}, timeout=600)
    if r.returncode != 0:
        sys.exit(f"generate.py: examples/chaplygin_study.py failed: {r.stderr}")
    with open(os.path.join(source, "examples", "chaplygin_study.ipynb")) as f:
        cells = json.load(f)["cells"]
    with open(os.path.join(out, "tutorials", "python-study.md"), "w") as f:
        for cell in cells:
            text = "".join(cell["source"]).rstrip()
            if cell["cell_type"] == "markdown":
                f.write(text + "\n\n")
                continue
            f.write("```python\n" + text + "\n```\n\n")
            for picture in re.findall(r'savefig\(os\.path\.join\(out, "([^"]+\.png)"\)', text):
                f.write(f"![{picture}](study/{picture})\n\n")
        f.write("The notebook is `examples/chaplygin_study.ipynb` (`./test` runs it cell by cell in a real kernel); "
                "the same cells as a script, `examples/chaplygin_study.py OUT_DIR`, made the pictures above when "
                "this guide was built. Every call is in the [Python API reference](../python-api.md).\n")
else:
    with open(os.path.join(out, "tutorials", "python-study.md"), "w") as f:
        f.write("# A study in Python\n\nThis build has no Python module: see `examples/chaplygin_study.ipynb`.\n")
    with open(api, "w") as f:
        f.write("# Python API reference\n\nThis build has no Python module (`-DROLLVIZ_PYTHON=OFF`): the reference "
                "is generated from the module when it is built.\n")

# the benchmarks' tables, as tests/bench/README.md keeps them
with open(os.path.join(source, "tests", "bench", "README.md")) as f:
    bench = f.read()
with open(os.path.join(out, "benchmarks.md"), "w") as f:
    f.write(bench.replace("# Benchmarks", "# Benchmarks\n\n(From `tests/bench/README.md`, where the benchmarks "
                          "live.)", 1))

# the commands of the tutorials and the workflow pages, each `rollviz ...` line of a ```sh block (a line ending in
# a backslash goes on) run as written in the page's folder, the project's paths (scenes/, examples/) read from the
# source; a comment after `#` is not part of the command
tutorials = os.path.join(out, "tutorials")
pages = [os.path.join("tutorials", p) for p in sorted(os.listdir(tutorials)) if p.endswith(".md")]
pages += ["getting-started.md", "continuation.md", "models.md", "rolling.md", "sweeps.md"]
for page in pages:
    with open(os.path.join(out, page)) as f:
        blocks = re.findall(r"```sh\n(.*?)```", f.read(), re.S)
    for block in blocks:
        for line in block.replace("\\\n", " ").splitlines():
            if not line.startswith("rollviz "):
                continue
            args = [os.path.join(source, a) if a.startswith(("scenes/", "examples/")) else a
                    for a in shlex.split(line, comments=True)[1:]]
            folder = os.path.dirname(os.path.join(out, page))
            r = subprocess.run([rollviz, *args], cwd=folder, capture_output=True, text=True, env=env, timeout=600)
            if r.returncode != 0:
                sys.exit(f"generate.py: {page}: `{line}` failed ({r.returncode}): {r.stderr}")
