#!/usr/bin/python3
"""Checks what `./run` leaves with no display (CI calls this after it): out/chaplygin_ball.png is a real 1280x720
picture and out/chaplygin_ball.mp4 an H.264 video of 125 frames at 1280x720 (5 s at 25 fps), its frames not blank.
Usage: check_run_output.py OUT_DIR. Prints one line per check and a closing 'N passed, N failed' line."""
import subprocess
import sys
from pathlib import Path

import numpy as np
from PIL import Image

out = Path(sys.argv[1] if len(sys.argv) > 1 else "out")
png, mp4 = out / "chaplygin_ball.png", out / "chaplygin_ball.mp4"
results = []


def check(name, ok, detail=""):
    results.append(ok)
    print(f"{'ok  ' if ok else 'FAIL'} {name}{': ' + detail if detail else ''}")


def not_blank(rgb):
    """a picture, not one flat colour: varied intensities and many colours"""
    a = np.asarray(rgb, dtype=float)
    colours = len(np.unique(a.reshape(-1, 3), axis=0))
    return a.std() > 5 and colours > 50, f"std {a.std():.1f}, {colours} colours"


check("png exists", png.is_file(), str(png))
if png.is_file():
    img = Image.open(png).convert("RGB")
    check("png is 1280x720", img.size == (1280, 720), f"{img.size[0]}x{img.size[1]}")
    check("png is not blank", *not_blank(img))

check("mp4 exists", mp4.is_file(), str(mp4))
if mp4.is_file():
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=codec_name,width,height,nb_read_frames", "-of", "csv=p=0", str(mp4)],
                           capture_output=True, text=True)
    fields = probe.stdout.strip().split(",")
    check("mp4 is H.264 at 1280x720 with 125 frames", probe.returncode == 0 and fields == ["h264", "1280", "720", "125"],
          probe.stdout.strip() or probe.stderr.strip())
    # the last frame decoded: the ball is still drawn at the end of the video
    frame = subprocess.run(["ffmpeg", "-v", "error", "-sseof", "-0.5", "-i", str(mp4), "-frames:v", "1", "-f",
                            "rawvideo", "-pix_fmt", "rgb24", "-"], capture_output=True)
    if frame.returncode == 0 and len(frame.stdout) == 1280 * 720 * 3:
        check("mp4's last frame is not blank", *not_blank(np.frombuffer(frame.stdout, np.uint8).reshape(720, 1280, 3)))
    else:
        check("mp4's last frame decodes", False, frame.stderr.decode(errors="replace").strip())

failed = results.count(False)
print(f"run-output: {len(results) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
