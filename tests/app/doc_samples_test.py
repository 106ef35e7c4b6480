#!/usr/bin/env python3
"""The guide's C++ samples compile: every ```cpp block of docs/*.md after the line
`<!-- compiled: doc_samples_test.py -->` is checked by the compiler that builds rollviz, against the source and
build trees' headers. Usage: doc_samples_test.py CXX SOURCE_DIR BUILD_INCLUDE_DIR EIGEN_INCLUDE_DIR"""
import glob
import os
import re
import subprocess
import sys
import tempfile

CXX, SRC, BUILD_INCLUDE, EIGEN = sys.argv[1:5]
MARKER = "<!-- compiled: doc_samples_test.py -->"

samples = []
for doc in sorted(glob.glob(os.path.join(SRC, "docs", "*.md"))):
    text = open(doc, encoding="utf-8").read()
    for m in re.finditer(re.escape(MARKER) + r"\n```cpp\n(.*?)```", text, re.S):
        samples.append((doc, text.count("\n", 0, m.start()) + 1, m.group(1)))
    if text.count(MARKER) != len([s for s in samples if s[0] == doc]):
        sys.exit(f"{doc}: a '{MARKER}' line is not followed by a ```cpp block")
if not samples:
    sys.exit("no compiled sample in docs/*.md (the marker was lost?)")
failed = 0
with tempfile.TemporaryDirectory() as tmp:
    for doc, line, code in samples:
        path = os.path.join(tmp, "sample.cpp")
        with open(path, "w", encoding="utf-8") as f:
            f.write(code)
        r = subprocess.run([CXX, "-std=c++20", "-fsyntax-only", "-Wall", "-Wextra", "-Werror", "-I", SRC, "-I",
                            BUILD_INCLUDE, "-isystem", EIGEN, path], capture_output=True, text=True)
        name = f"{os.path.relpath(doc, SRC)}:{line}"
        print(f"{name}: {'compiles' if r.returncode == 0 else 'does not compile'}")
        if r.returncode != 0:
            failed += 1
            print(r.stderr)
sys.exit(1 if failed else 0)
