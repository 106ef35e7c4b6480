#!/usr/bin/env python3
"""The gallery's pictures (and, with --videos, its 10-second videos), made by rollviz itself from the scenes of
scenes/gallery: each picture is the 3D view at the end of the scene's video (video.duration x view.speed).
Usage: make_gallery.py ROLLVIZ OUT_DIR [--videos] [--size WxH]. The guide's gallery page is built from it
(docs/generate.py)."""
import argparse
import os
import subprocess
import sys


def gallery(rollviz):
    """The gallery scenes as `rollviz list gallery` gives them: dicts of path, id, title, description, time."""
    out = subprocess.run([rollviz, "list", "gallery"], capture_output=True, text=True, check=True).stdout
    scenes, lines = [], out.splitlines()
    for k in range(0, len(lines), 4):
        path, title, description, time = (line.strip() for line in lines[k:k + 4])
        if not time.startswith("picture at t = "):
            sys.exit(f"make_gallery.py: unexpected `rollviz list gallery` output near {path!r}")
        scenes.append({"path": path, "id": os.path.splitext(os.path.basename(path))[0], "title": title,
                       "description": description, "time": float(time.split("= ")[1])})
    return scenes


def make(rollviz, out, videos=False, size="640x400", pages=None):
    """Renders every gallery scene into OUT/ID.png (and OUT/ID.mp4; with PAGES a folder, PAGES/ID.html, its web
    page, whose size in bytes each scene's "page_bytes" holds); returns the scenes."""
    os.makedirs(out, exist_ok=True)
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    scenes = gallery(rollviz)
    for s in scenes:
        subprocess.run([rollviz, "render", s["path"], "-o", os.path.join(out, s["id"] + ".png"), "--size", size,
                        "--time", repr(s["time"])], check=True, env=env, capture_output=True)
        if videos:
            subprocess.run([rollviz, "video", s["path"], "-o", os.path.join(out, s["id"] + ".mp4"), "--size",
                            size], check=True, env=env, capture_output=True)
        if pages:
            os.makedirs(pages, exist_ok=True)
            page = os.path.join(pages, s["id"] + ".html")
            subprocess.run([rollviz, "page", s["path"], "-o", page], check=True, env=env, capture_output=True)
            s["page_bytes"] = os.path.getsize(page)
    return scenes


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("rollviz")
    p.add_argument("out")
    p.add_argument("--videos", action="store_true", help="also the 10-second videos (MP4)")
    p.add_argument("--size", default="640x400")
    p.add_argument("--pages", action="store_true", help="also the web pages (OUT/ID.html)")
    a = p.parse_args()
    for s in make(a.rollviz, a.out, a.videos, a.size, a.out if a.pages else None):
        print(os.path.join(a.out, s["id"] + ".png"), "-", s["title"])
