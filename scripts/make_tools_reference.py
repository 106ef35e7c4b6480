#!/usr/bin/env python3
"""Writes docs/tools.md, the tools reference, from the tool registry as `rollviz list tools` and
`rollviz describe-tool ID` print it. Usage: make_tools_reference.py ROLLVIZ [OUT]  (OUT: - for standard output).
tests/app/cli_test.py fails when the committed reference differs from what this writes."""
import os
import subprocess
import sys


def reference(rv):
    env = dict(os.environ, COLUMNS="200")
    run = lambda *a: subprocess.run([rv, *a], capture_output=True, text=True, check=True, env=env).stdout
    tree = run("list", "tools")
    ids = [l.split()[0] for l in tree.splitlines() if l.strip() and ":" in l and not l.startswith("rollviz")]
    out = ["# rollviz tools reference",
           "",
           "Generated from the tool registry (`dynamics/tools/ToolRegistry.cpp`) by",
           "`scripts/make_tools_reference.py build/dev/app/rollviz`; a test fails when it is stale.",
           "",
           "Every tool is one entry of the registry: its settings are one parameter table (the scene section of",
           "its name; every setting is also a `--set SECTION.ID=VALUE` and a field of the GUI's tab), its",
           "computation is the class named in the entry's file (dynamics/tools), its command and chart view run it.",
           "",
           "## The tool tree (manual §2.3)",
           "",
           "```",
           tree.rstrip(),
           "```",
           ""]
    for i in ids:
        out += ["## " + i, "", "```", run("describe-tool", i).rstrip(), "```", ""]
    return "\n".join(out)


if __name__ == "__main__":
    text = reference(sys.argv[1])
    target = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "docs", "tools.md")
    if target == "-":
        sys.stdout.write(text)
    else:
        with open(target + ".tmp", "w") as f:
            f.write(text)
        os.replace(target + ".tmp", target)
