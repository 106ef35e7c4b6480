# Sphinx configuration of rollviz's guide (built by the CMake target `docs`, warnings as errors, into
# build/<preset>/docs/html). The pages are Markdown (MyST); docs/generate.py adds the reference pages generated
# from the program itself (the command line's own help) before Sphinx reads them.
project = "rollviz"
author = "the rollviz developers"
extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
myst_heading_anchors = 3
html_theme = "alabaster"
html_title = "rollviz"
exclude_patterns = ["_build", "pages"]
# the gallery's web pages (docs/generate.py writes them into pages/gallery/): copied beside the guide as they are
html_extra_path = ["pages"]
