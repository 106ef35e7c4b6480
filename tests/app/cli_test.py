#!/usr/bin/env python3
"""End-to-end tests of the `rollviz` command line (design.md "Command line"): outputs, exit statuses,
messages that name the culprit, and no file left behind on failure. Usage: cli_test.py ROLLVIZ ROLLVIZ_OSMESA SRC"""
import csv
import json
import math
import os
import signal
import time
import subprocess
import sys
import tempfile
import unittest

RV, RVO, SRC = sys.argv[1], sys.argv[2], sys.argv[3]
SCENE = os.path.join(SRC, "scenes", "chaplygin_ball.json")


def run(*args, exe=None, env=None, timeout=300):
    e = dict(os.environ)
    e.pop("DISPLAY", None)
    if env:
        e.update(env)
    return subprocess.run([exe or RV, *args], capture_output=True, text=True, env=e, timeout=timeout)


def pixels(path):
    from PIL import Image
    img = Image.open(path).convert("RGB")
    return img.size, list(img.getdata())


def varied(px):
    n = len(px)
    mean = sum(sum(p) for p in px) / (3 * n)
    var = sum((c - mean) ** 2 for p in px for c in p) / (3 * n)
    return var ** 0.5 > 5 and len(set(px)) > 50


def interrupt(p):
    """Ctrl-C to a run started with stderr=PIPE (killed if it is still there after a minute): its status and
    what it said."""
    try:
        if p.poll() is None:
            p.send_signal(signal.SIGINT)
            p.wait(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    err = p.stderr.read().decode()
    p.stderr.close()
    return p.returncode, err

class Cli(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def assertBadInput(self, r, *words):
        self.assertEqual(r.returncode, 2, r.stderr)
        for w in words:
            self.assertIn(w, r.stderr)

    def test_list_and_describe(self):
        r = run("list", "problems")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("chaplygin_ball", r.stdout.split())
        self.assertIn("lorenz", r.stdout.split())
        self.assertIn("rk4", run("list", "integrators").stdout)
        d = run("describe", "chaplygin_ball")
        self.assertEqual(d.returncode, 0, d.stderr)
        for word in ("I1", "K3", "gamma3", "L/G", "Lplane", "Lbody", "invariant measure: yes"):
            self.assertIn(word, d.stdout)
        self.assertBadInput(run("describe", "no_such_problem"), "no_such_problem")

    def test_integrate_writes_header_and_rows_on_exact_times(self):
        out = self.path("i.csv")
        r = run("integrate", SCENE, "--time", "1", "--every", "0.1", "--columns", "t,E,H,n", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.reader(open(out)))
        self.assertEqual(rows[0], ["t", "E", "H", "n"])
        self.assertEqual(len(rows), 12)
        self.assertEqual([float(x[0]) for x in rows[1:]], [k * 0.1 for k in range(11)])
        e = [float(x[1]) for x in rows[1:]]
        self.assertAlmostEqual(e[0], 0.5, delta=1e-12)  # the scene's energy, reached by completion
        self.assertLess(max(abs(v - e[0]) for v in e), 1e-10)
        h = [float(x[2]) for x in rows[1:]]
        self.assertAlmostEqual(h[0], 0.3, delta=1e-12)

    def test_integrate_to_stdout_and_set_overrides(self):
        r = run("integrate", SCENE, "--time", "0.2", "--every", "0.1", "--columns", "E",
                "--set", "energy=0.4", "--set", "integrator.step=0.002")
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.split()
        self.assertEqual(lines[0], "E")
        self.assertAlmostEqual(float(lines[1]), 0.4, delta=1e-12)

    def test_lorenz_integrates(self):
        r = run("integrate", os.path.join(SRC, "scenes", "lorenz.json"), "--time", "1", "--every", "0.5",
                "--columns", "t,x,y,z")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(len(r.stdout.split()), 4)
        # without --columns: every observable of the problem (Lorenz has no energy: the old default t,E failed)
        r = run("integrate", os.path.join(SRC, "scenes", "lorenz.json"), "--time", "1", "--every", "0.5")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.split()[0], "t,x,y,z")
        self.assertEqual(len(r.stdout.split()), 4)

    def test_bad_input_exits_2_naming_the_culprit_and_leaves_no_file(self):
        keep = self.path("keep.csv")
        with open(keep, "w") as f:
            f.write("keep\n")
        bad = self.path("bad.json")
        with open(bad, "w") as f:
            f.write('{ "problem": ')
        self.assertBadInput(run("render", bad, "-o", self.path("bad.png")), "bad.json", "malformed JSON")
        self.assertFalse(os.path.exists(self.path("bad.png")))
        self.assertBadInput(run("integrate", bad, "--time", "1", "--every", "0.1", "-o", keep), "bad.json")
        self.assertEqual(open(keep).read(), "keep\n", "an existing output is not overwritten on bad input")

        doc = json.load(open(SCENE))
        doc["problem"] = "no_such_problem"
        np = self.path("np.json")
        json.dump(doc, open(np, "w"))
        self.assertBadInput(run("integrate", np, "--time", "1", "--every", "0.1", "-o", self.path("np.csv")),
                            "no_such_problem", "np.json:problem")
        self.assertFalse(os.path.exists(self.path("np.csv")))

        self.assertBadInput(run("integrate", SCENE, "--set", "no_such_param=1", "--time", "1", "--every", "0.1",
                                "-o", self.path("u.csv")), "no_such_param")
        self.assertFalse(os.path.exists(self.path("u.csv")))
        self.assertBadInput(run("integrate", SCENE, "--set", "I1=1", "--set", "I2=1", "--set", "I3=5",
                                "--time", "1", "--every", "1", "-o", self.path("y.csv")), "I3", "triangle")
        self.assertBadInput(run("integrate", SCENE, "--time", "1", "--every", "0.1", "--columns", "t,bogus"),
                            "bogus")
        self.assertBadInput(run("integrate", SCENE, "--time", "1", "--every", "0.1", "-o", "/no/such/dir/x.csv"),
                            "/no/such/dir/x.csv")
        self.assertBadInput(run("render", SCENE, "-o", "/no/such/dir/x.png"), "/no/such/dir/x.png")
        self.assertBadInput(run("render", SCENE, "-o", self.path("s.png"), "--size", "wide"), "--size")
        self.assertBadInput(run("integrate", SCENE, "--time", "1"), "--every")  # usage
        self.assertBadInput(run("integrate", os.path.join(self.dir, "missing.json"), "--time", "1", "--every", "1"),
                            "missing.json")
        self.assertEqual(sorted(os.listdir(self.dir)), ["bad.json", "keep.csv", "np.json"])

    def test_a_scene_keeps_the_guis_results(self):
        # the GUI saves its Results dock as "results": lines of text, read back by every command
        doc = json.load(open(SCENE))
        doc["results"] = ["12:00:00  fixed point (0.1, 0.2): elliptic; multipliers 0.5+0.8i 0.5-0.8i"]
        good = self.path("good.json")
        json.dump(doc, open(good, "w"))
        r = run("integrate", good, "--time", "0.1", "--every", "0.1", "--columns", "E")
        self.assertEqual(r.returncode, 0, r.stderr)
        doc["results"] = ["fine", 3]
        bad = self.path("bad-results.json")
        json.dump(doc, open(bad, "w"))
        self.assertBadInput(run("integrate", bad, "--time", "0.1", "--every", "0.1"), "bad-results.json",
                            "results")

    def test_a_blow_up_exits_1_with_the_reason_and_no_file(self):
        out = self.path("blow.csv")
        r = run("integrate", SCENE, "--set", "integrator.step=50", "--time", "100000", "--every", "1000", "-o", out)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("finite", r.stderr)
        self.assertFalse(os.path.exists(out))

    def test_render_png_on_egl_and_osmesa_agree(self):
        a, b = self.path("egl.png"), self.path("osmesa.png")
        r = run("render", SCENE, "-o", a, "--size", "640x360", "--time", "2")
        self.assertEqual(r.returncode, 0, r.stderr)
        r = run("render", SCENE, "-o", b, "--size", "640x360", "--time", "2", exe=RVO)
        self.assertEqual(r.returncode, 0, r.stderr)
        (sa, pa), (sb, pb) = pixels(a), pixels(b)
        self.assertEqual(sa, (640, 360))
        self.assertEqual(sb, (640, 360))
        self.assertTrue(varied(pa))
        self.assertTrue(varied(pb), "OSMesa picture is flat (link order?)")
        mean = sum(abs(x - y) for p, q in zip(pa, pb) for x, y in zip(p, q)) / (3 * len(pa))
        self.assertLess(mean, 2.0)

    def test_every_apex_scene_renders_and_snapshots_scale_and_go_transparent(self):
        apex = os.path.join(SRC, "scenes", "apex")
        for name in sorted(os.listdir(apex)):
            out = self.path(name + ".png")
            r = run("render", os.path.join(apex, name), "-o", out, "--size", "320x240", "--time", "2")
            self.assertEqual(r.returncode, 0, name + ": " + r.stderr)
            size, px = pixels(out)
            self.assertEqual(size, (320, 240))
            self.assertTrue(varied(px), name)
        big = self.path("big.png")
        r = run("render", SCENE, "-o", big, "--size", "160x90", "--time", "1", "--scale", "4")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(pixels(big)[0], (640, 360))
        self.assertBadInput(run("render", SCENE, "-o", big, "--scale", "2", "--transparent"), "--transparent")
        self.assertBadInput(run("render", SCENE, "-o", big, "--set", "view.axes.style=cube"), "view.axes.style")

    def test_every_example_model_scene_renders(self):
        # the model files of examples/models with their scenes: each draws a real picture (interpreted here;
        # the compiled path is tests/scenes/ModelFileTest.cpp's)
        models = os.path.join(SRC, "examples", "models")
        scenes = sorted(n for n in os.listdir(models) if n.endswith(".scene.json"))
        self.assertGreaterEqual(len(scenes), 7)
        for name in scenes:
            out = self.path(name + ".png")
            r = run("render", os.path.join(models, name), "-o", out, "--size", "320x240", "--time", "1",
                    env={"ROLLVIZ_COMPILE_MODELS": "0"})
            self.assertEqual(r.returncode, 0, name + ": " + r.stderr)
            self.assertTrue(varied(pixels(out)[1]), name)

    def test_chart_scale_and_paper_style(self):
        from PIL import Image, ImageChops, ImageFilter, ImageStat
        import xml.etree.ElementTree as ET
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        args = ["chart", hh, "--view", "lyapunov", "--set", "lyapunov.time=50"]
        one, two = self.path("one.png"), self.path("two.png")
        for out, extra in ((one, []), (two, ["--scale", "2"])):
            r = run(*args, "--size", "400x300", "-o", out, *extra)
            self.assertEqual(r.returncode, 0, r.stderr)
        a, b = Image.open(one).convert("L"), Image.open(two).convert("L")
        self.assertEqual(b.size, (800, 600))
        # the same figure, finer: halved, it is the 1x picture (the same ticks, labels and layout) within what
        # anti-aliasing moves -- blurred, a mean difference under 6 (the chart at another time differs by 8.3)
        blur = ImageFilter.GaussianBlur(2)
        diff = ImageStat.Stat(ImageChops.difference(a.filter(blur), b.resize(a.size, Image.BOX).filter(blur))).mean[0]
        self.assertLess(diff, 6, diff)
        self.assertGreater(ImageStat.Stat(a).stddev[0], 10)  # and not a blank picture
        # the paper style: a 3.5-inch column at 300 dpi unless --size; its type sized for print
        paper, paper_svg = self.path("paper.png"), self.path("paper.svg")
        for out in (paper, paper_svg):
            r = run(*args, "--style", "paper", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(Image.open(paper).size, (1050, 788))
        sizes = {}
        for e in ET.parse(paper_svg).getroot().iter():
            text = "".join(e.itertext()).strip()
            if e.tag.endswith("text") and text and e.get("font-size"):
                sizes[text] = float(e.get("font-size"))
        self.assertGreaterEqual(sizes.get("Lyapunov exponents", 0), 33, sizes)  # 8 pt or more at 300 dpi
        self.assertBadInput(run(*args, "--style", "print", "-o", self.path("x.png")), "--style")
        self.assertBadInput(run(*args, "--scale", "9", "-o", self.path("x.png")), "--scale")

    def test_charts_as_vector_figures_and_every_format_by_its_extension(self):
        import xml.etree.ElementTree as ET
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        png, svg, pdf = self.path("l.png"), self.path("l.svg"), self.path("l.pdf")
        for out in (png, svg, pdf):
            r = run("chart", hh, "--view", "lyapunov", "--set", "lyapunov.time=50", "-o", out, "--size", "640x480")
            self.assertEqual(r.returncode, 0, out + ": " + r.stderr)
        # the SVG is XML whose text is text: the title and the axes' titles
        root = ET.parse(svg).getroot()
        texts = [t.strip() for e in root.iter() if e.tag.endswith("text") for t in e.itertext() if t.strip()]
        self.assertIn("Lyapunov exponents", texts)
        self.assertIn("t", texts)
        # the SVG (librsvg) and the PDF (poppler) draw the PNG's picture: not blank, the same dark strokes (axes,
        # text, curves) where the PNG has them, within a tolerance
        subprocess.run(["pdftoppm", "-png", "-r", "72", "-singlefile", pdf, self.path("from_pdf")], check=True)
        subprocess.run(["rsvg-convert", "-b", "white", "-w", "640", "-h", "480", svg, "-o", self.path("from_svg.png")], check=True)
        size, a = pixels(png)
        for name in ("from_pdf.png", "from_svg.png"):
            size2, b = pixels(self.path(name))
            self.assertEqual(size, size2, name)
            self.assertTrue(varied(b), name)
            w, h = size
            dark = lambda px: [sum(px[y * w + x][0] < 128 for y in range(h)) for x in range(w)]
            da, db = dark(a), dark(b)
            self.assertGreater(sum(db), 0.5 * sum(da), name)
            self.assertLess(sum(abs(p - q) for p, q in zip(da, db)), 0.6 * sum(da), name + ": strokes elsewhere")
        # a Poincare map of many points stays a usable vector figure
        map_svg = self.path("map.svg")
        r = run("chart", hh, "--view", "poincare", "--points", "20000", "-o", map_svg)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertLess(os.path.getsize(map_svg), 10e6)
        ET.parse(map_svg)
        # an output's format follows its extension: any other is bad input, and nothing is written
        for cmd, name, supported in (
                (["chart", hh, "--view", "lyapunov"], "fig.jpg", ".png, .svg, .pdf"),
                (["chart", hh], "fig", ".png, .svg, .pdf"),
                (["render", hh], "view.svg", ".png, .vtm"),
                (["video", hh], "film.avi", ".mp4"),
                (["integrate", hh, "--time", "1", "--every", "1"], "x.txt", ".csv, .vtp"),
                (["poincare", hh, "--points", "3"], "p.dat", ".csv, .vtp")):
            self.assertBadInput(run(*cmd, "-o", self.path(name)), name, supported)
            self.assertFalse(os.path.exists(self.path(name)), name)
        # a chart of cells (a sweep over two axes): its cells and colour bar go into SVG and PDF as rectangles
        # (one per run of a colour along a row), and the figures draw the PNG's picture
        sweep = self.path("two.json")
        with open(sweep, "w") as f:
            json.dump({"scene": os.path.join(SRC, "scenes", "henon_map.json"), "quantity": "lyapunov.max",
                       "axes": [{"id": "a", "min": 1.0, "max": 1.4, "count": 20},
                                {"id": "b", "min": 0.2, "max": 0.3, "count": 15}]}, f)
        two = {e: self.path("two." + e) for e in ("png", "svg", "pdf")}
        r = run("sweep", sweep, "-o", self.path("two.csv"), "--png", two["svg"], "--size", "640x480")
        self.assertEqual(r.returncode, 0, r.stderr)
        for e in ("png", "pdf"):
            r = run("chart", sweep, "--view", "sweep", "--csv", self.path("two.csv"), "--size", "640x480", "-o", two[e])
            self.assertEqual(r.returncode, 0, r.stderr)
        rects = [e for e in ET.parse(two["svg"]).getroot().iter() if e.tag.endswith(("path", "polygon", "rect"))]
        self.assertGreater(len(rects), 300 // 4, "the cells are shapes in the SVG")
        subprocess.run(["pdftoppm", "-png", "-r", "72", "-singlefile", two["pdf"], self.path("two_pdf")], check=True)
        subprocess.run(["rsvg-convert", "-b", "white", "-w", "640", "-h", "480", two["svg"], "-o",
                        self.path("two_svg.png")], check=True)
        _, a = pixels(two["png"])
        for name in ("two_pdf.png", "two_svg.png"):
            size2, b = pixels(self.path(name))
            self.assertEqual(size2, (640, 480), name)
            # the plot's cells: coloured (not grey, not white) pixels where the PNG has them
            coloured = lambda px: [abs(p[0] - p[2]) > 40 or abs(p[1] - p[2]) > 40 for p in px]
            ca, cb = coloured(a), coloured(b)
            self.assertGreater(sum(ca), 0.3 * len(ca))
            same = sum(x == y for x, y in zip(ca, cb))
            self.assertGreater(same, 0.95 * len(ca), name + ": the cells are not where the PNG has them")

    def test_a_video_frame_shows_the_state_at_its_time(self):
        # frame k of a video is the state at t = k * speed / fps: frame 15 at 10 fps matches a still at t = 1.5
        # (H.264 noise aside) and not one at t = 1.2
        out = self.path("t.mp4")
        r = run("video", SCENE, "-o", out, "--duration", "2", "--fps", "10", "--size", "320x240")
        self.assertEqual(r.returncode, 0, r.stderr)
        frame = self.path("frame15.png")
        subprocess.run(["ffmpeg", "-v", "error", "-i", out, "-vf", "select=eq(n\\,15)", "-vframes", "1", frame],
                       check=True)
        stills = {}
        for t in ("1.5", "1.2"):
            stills[t] = self.path("still" + t + ".png")
            r = run("render", SCENE, "-o", stills[t], "--size", "320x240", "--time", t)
            self.assertEqual(r.returncode, 0, r.stderr)
        (_, f), (_, a), (_, b) = pixels(frame), pixels(stills["1.5"]), pixels(stills["1.2"])
        diff = lambda p, q: sum(abs(x - y) for u, v in zip(p, q) for x, y in zip(u, v)) / (3 * len(p))
        self.assertLess(diff(f, a), 4.0)
        self.assertGreater(diff(f, b), 2 * diff(f, a))

    def test_video_has_codec_size_and_exact_frame_count(self):
        out = self.path("v.mp4")
        r = run("video", SCENE, "-o", out, "--duration", "2", "--fps", "10", "--size", "320x240")
        self.assertEqual(r.returncode, 0, r.stderr)
        info = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                               "stream=codec_name,width,height,nb_read_frames,avg_frame_rate", "-of", "json", out],
                              capture_output=True, text=True, check=True)
        s = json.loads(info.stdout)["streams"][0]
        self.assertIn(s["codec_name"], ("h264", "mpeg4"))
        self.assertEqual((s["width"], s["height"]), (320, 240))
        self.assertEqual(int(s["nb_read_frames"]), 20)
        self.assertEqual(s["avg_frame_rate"], "10/1")
        self.assertEqual([f for f in os.listdir(self.dir)], ["v.mp4"], "no temporary left behind")

    def test_the_scenes_video_section_sets_rate_size_length_and_encoder(self):
        def probe(path):
            info = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                   "stream=width,height,nb_read_frames,avg_frame_rate", "-of", "json", path],
                                  capture_output=True, text=True, check=True)
            s = json.loads(info.stdout)["streams"][0]
            return s["width"], s["height"], int(s["nb_read_frames"]), s["avg_frame_rate"]
        section = ["--set", "video.fps=8", "--set", "video.width=240", "--set", "video.height=160",
                   "--set", "video.duration=1.5"]
        sizes = {}
        for crf in (12, 40):
            out = self.path("c%d.mp4" % crf)
            r = run("video", SCENE, "-o", out, *section, "--set", "video.crf=%d" % crf, "--set", "video.preset=ultrafast")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(probe(out), (240, 160, 12, "8/1"))
            sizes[crf] = os.path.getsize(out)
        # a higher constant rate factor is a coarser quantiser: the same frames in fewer bytes
        self.assertLess(sizes[40], sizes[12] / 2, sizes)
        # the command line's flags win over the section
        out = self.path("f.mp4")
        r = run("video", SCENE, "-o", out, *section, "--fps", "4", "--size", "160x120")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(probe(out), (160, 120, 6, "4/1"))
        # bad settings name their key
        self.assertBadInput(run("video", SCENE, "-o", out, "--set", "video.preset=quickest"), "video.preset", "ultrafast")
        self.assertBadInput(run("video", SCENE, "-o", out, "--set", "video.crf=60"), "crf")
        self.assertBadInput(run("video", SCENE, "-o", self.path("odd.mp4"), "--set", "video.width=321"),
                            "video.width", "even")
        self.assertFalse(os.path.exists(self.path("odd.mp4")))

    def test_poincare_lyapunov_spectrum(self):
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        out = self.path("p.csv")
        r = run("poincare", hh, "--points", "4", "--set", "initial.map=[0,0.25]", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.reader(open(out)))
        self.assertEqual(rows[0], ["y", "py", "t", "sheet"])
        self.assertEqual(len(rows), 5)
        for row in rows[1:]:  # the straight-line orbit crosses at (0, sqrt(E/2)) every time
            self.assertAlmostEqual(float(row[0]), 0.0, delta=1e-9)
            self.assertAlmostEqual(float(row[1]), 0.25, delta=1e-9)
        r = run("lyapunov", os.path.join(SRC, "scenes", "lorenz.json"), "--time", "500", "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        self.assertEqual(len(j["exponents"]), 3)
        self.assertAlmostEqual(j["sum"], -41 / 3, delta=1e-3)
        self.assertEqual(j["time"], 500)
        r = run("spectrum", hh, "--function", "x", "--samples", "4096", "--set", "integrator.method=rk4", "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        self.assertEqual(j["samples"], 4096)
        self.assertGreater(len(j["peaks"]), 0)
        self.assertBadInput(run("spectrum", hh, "--function", "x", "--set", "integrator.method=merson"), "fixed-step")
        self.assertBadInput(run("spectrum", hh, "--function", "nope"), "nope")
        self.assertBadInput(run("poincare", hh, "--set", "poincare.section=nope"), "poincare.section")

    def test_high_order_integrators(self):
        # the Taylor method, Verner's pair and Adams PECE through the scene's integrator section: the same map
        # points as Everhart's small steps
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        points = {}
        # (the scene's integrator.order, 15, is Everhart's: beyond Adams' 14, so its order is set too)
        adams = ["--set", "integrator.step=0.02", "--set", "integrator.order=12"]
        steps = {"everhart": ["--set", "integrator.step=0.01"], "adams": adams}
        for method in ("taylor", "everhart", "verner9", "adams"):
            out = self.path(method + ".csv")
            extra = steps.get(method, [])
            r = run("poincare", hh, "--points", "10", "--set", "initial.map=[0.1,0.2]", "--set",
                    "integrator.method=" + method, *extra, "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(out) as f:
                points[method] = [[float(v) for v in row[:3]] for row in list(csv.reader(f))[1:]]
        self.assertEqual(len(points["taylor"]), 10)
        self.assertEqual(len(points["verner9"]), 10)
        self.assertEqual(len(points["adams"]), 10)
        # crossings located on the series / on Verner's interpolant / on the integrated Adams polynomial
        for method in ("taylor", "verner9", "adams"):
            for a, b in zip(points[method], points["everhart"]):
                for u, v in zip(a, b):
                    self.assertAlmostEqual(u, v, delta=1e-9, msg=method)
        listed = run("list", "integrators").stdout
        self.assertIn("taylor", listed)
        self.assertIn("verner9", listed)
        self.assertIn("adams", listed)
        # Adams integrates the tangent vectors too (its starting values come from Verner's pair)
        r = run("lyapunov", hh, "--time", "50", "--set", "integrator.method=adams", *adams, "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(len(json.loads(r.stdout)["exponents"]), 4)
        self.assertBadInput(run("poincare", hh, "--set", "integrator.method=adams", "--set",
                                "integrator.order=15"), "integrator.order")
        # the tangent vectors of the Lyapunov exponents are not the model's field: a clear refusal
        self.assertBadInput(run("lyapunov", hh, "--time", "10", "--set", "integrator.method=taylor"), "taylor")
        self.assertBadInput(run("poincare", hh, "--set", "integrator.method=taylor", "--set",
                                "integrator.order=61"), "integrator.order")

    def test_poincare_chart(self):
        out = self.path("c.png")
        r = run("chart", SCENE, "--view", "poincare", "-o", out, "--points", "300", "--size", "400x400")
        self.assertEqual(r.returncode, 0, r.stderr)
        size, px = pixels(out)
        self.assertEqual(size, (400, 400))
        # white background, axes, blue points: mostly white but with a real number of blue-ish pixels
        blue = sum(1 for p in px if p[2] > 150 and p[0] < 100)
        self.assertGreater(blue, 300)
        self.assertBadInput(run("chart", SCENE, "--view", "nope", "-o", self.path("n.png")), "--view")
        self.assertFalse(os.path.exists(self.path("n.png")))

    def test_a_gui_session_is_a_scene_and_its_saved_map_draws_headless(self):
        # a session as File > Save session writes it (scenes/Session.h): the scene and the map's trajectories
        import json as js
        import math
        with open(os.path.join(SRC, "scenes", "henon_heiles.json")) as f:
            hh = js.load(f)
        red = [(-0.2 + 0.05 * math.cos(k / 10), 0.05 * math.sin(k / 10)) for k in range(63)]
        green = [(0.2 + 0.05 * math.cos(k / 10), 0.05 * math.sin(k / 10)) for k in range(63)]
        def trajectory(points, colour):
            return {"start": [0, 0.1, 0.1, 0.3], "parameters": {"energy": 0.125}, "integrator": {},
                    "colour": colour, "x": [p[0] for p in points], "y": [p[1] for p in points], "z": [],
                    "state": [], "running": False, "first": 1, "last": 0, "origin": ""}
        # and what the map's fixed-point tools drew: a family (blue, a vertical line between the circles) and
        # a search's path with the point it found
        family = {"name": "Fixed point continuation", "summary": "", "colour": [0, 0, 1],
                  "x": [0.0] * 41, "y": [-0.1 + 0.005 * k for k in range(41)],
                  "fixed_points": [{"parameter": 1.5, "multipliers": [[0.25, 0.97], [0.25, -0.97]]}]}
        search = {"name": "Fixed point", "summary": "fixed point (0, 0.12): elliptic", "colour": [0.9, 0.1, 0.1],
                  "x": [0.01, 0.0], "y": [0.13, 0.12], "found": [0.0, 0.12]}
        session = {"rollviz_session": 1, "scene": hh, "scene_path": "", "results": "",
                   "trajectories": [trajectory(red, [1, 0, 0]), trajectory(green, [0, 0.8, 0])],
                   "tools": [family, search]}
        path = self.path("s.json")
        with open(path, "w") as f:
            js.dump(session, f)
        out = self.path("s.png")
        r = run("chart", path, "--view", "poincare", "-o", out, "--size", "400x400")
        self.assertEqual(r.returncode, 0, r.stderr)
        (w, h), px = pixels(out)
        def columns(test):
            return [i % w for i, p in enumerate(px) if test(p)]
        reds = columns(lambda p: p[0] > 180 and p[1] < 90 and p[2] < 90)
        greens = columns(lambda p: p[1] > 150 and p[0] < 90 and p[2] < 90)
        self.assertGreater(len(reds), 100)
        self.assertGreater(len(greens), 100)
        # drawn as saved, not computed: the red circle left of the green one
        self.assertLess(max([c for c in reds if c < w // 2 - 20]), min(greens))
        blues = columns(lambda p: p[2] > 180 and p[0] < 90 and p[1] < 90)
        self.assertGreater(len(blues), 40)
        self.assertTrue(all(abs(c - sum(blues) / len(blues)) < 6 for c in blues), "the family is one line")
        self.assertLess(max([c for c in reds if c < w // 2 - 20]), min(blues))
        self.assertLess(max(blues), min(greens))
        # the search's point is drawn in the middle too (its red cross over the family's line)
        self.assertTrue(any(abs(c - sum(blues) / len(blues)) < 10 for c in reds))
        # the session is a scene for every command (its scene)
        r = run("integrate", path, "--time", "1", "--every", "0.5", "--columns", "t,E")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertAlmostEqual(float(r.stdout.splitlines()[1].split(",")[1]), 0.125, delta=1e-12)
        self.assertBadInput(run("chart", path, "--view", "poincare", "--points", "10", "-o", out), "--points")
        session["rollviz_session"] = 2
        session["trajectories"][1]["colour"] = [2, 0, 0]
        with open(path, "w") as f:
            js.dump(session, f)
        self.assertBadInput(run("chart", path, "--view", "poincare", "-o", self.path("t.png")), "s.json", "format")
        self.assertFalse(os.path.exists(self.path("t.png")))
        session["rollviz_session"] = 1
        with open(path, "w") as f:
            js.dump(session, f)
        self.assertBadInput(run("chart", path, "--view", "poincare", "-o", self.path("t.png")),
                            "trajectories[1].colour")
        session["trajectories"][1]["colour"] = [0, 0.8, 0]
        session["tools"][1]["found"] = [0.0]
        with open(path, "w") as f:
            js.dump(session, f)
        self.assertBadInput(run("chart", path, "--view", "poincare", "-o", self.path("t.png")), "tools[1].found")

    def test_multipliers_and_bifurcation_charts(self):
        for view in ("multipliers", "bifurcation"):
            out = self.path(view + ".png")
            r = run("chart", SCENE, "--view", view, "-o", out, "--size", "400x400")
            self.assertEqual(r.returncode, 0, r.stderr)
            size, px = pixels(out)
            self.assertEqual(size, (400, 400))
            self.assertTrue(varied(px) or len(set(px)) > 50, view)
            # coloured marks (the unit circle is grey; multipliers and branches are coloured)
            coloured = sum(1 for p in px if max(p) - min(p) > 80)
            self.assertGreater(coloured, 40, view)
        self.assertBadInput(run("chart", os.path.join(SRC, "scenes", "lorenz.json"), "--view", "bifurcation",
                                "-o", self.path("l.png")), "no bifurcation diagrams")

    def test_fixedpoint_json_and_text(self):
        r = run("fixedpoint", os.path.join(SRC, "scenes", "henon_map.json"), "--guess", "0.6,0.2", "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        x = (-0.7 + (0.49 + 5.6) ** 0.5) / 2.8
        self.assertAlmostEqual(j["point"][0], x, delta=1e-12)
        self.assertIn("hyperbolic", j["type"])
        self.assertEqual(len(j["multipliers"]), 2)
        # the product of the multipliers is det DP = -b
        (a, b), (c, d) = j["multipliers"]
        self.assertAlmostEqual(a * c - b * d, -0.3, delta=1e-9)
        # Henon-Heiles' straight-line orbit, gradient method and the whole path, as text
        t = run("fixedpoint", os.path.join(SRC, "scenes", "henon_heiles.json"), "--guess", "0.02,0.23",
                "--path")
        self.assertEqual(t.returncode, 0, t.stderr)
        self.assertIn("type: elliptic", t.stdout)
        self.assertIn("search:", t.stdout)

    def test_fixedpoint_on_a_family_of_steady_motions(self):
        # the rolling disk's steady motion (a two-parameter family of fixed points of its map; the relation
        # between tilt, spin and turning rate is checked in tests/scenes/RollingModelTest.cpp): the search
        # ends near the guess and says it lies on a family
        scene = os.path.join(SRC, "examples", "rolling", "disk_steady.scene.json")
        r = run("fixedpoint", scene, "--json", env={"ROLLVIZ_COMPILE_MODELS": "0"})
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        self.assertEqual(j["family"], 2)
        self.assertEqual(j["type"], "elliptic")
        self.assertLess(j["residual"], 1e-9)
        guess = [0.02, -0.03, 2.03, 0.88]
        self.assertLess(sum((a - b) ** 2 for a, b in zip(j["point"], guess)) ** 0.5, 0.06)
        t = run("fixedpoint", scene, env={"ROLLVIZ_COMPILE_MODELS": "0"})
        self.assertIn("family: the point lies on a 2-dimensional family", t.stdout)

    def test_fixedpoint_failures(self):
        hm = os.path.join(SRC, "scenes", "henon_map.json")
        r = run("fixedpoint", hm, "--guess", "0.2,0", "--set", "fixedpoint.max_iterations=1",
                "--set", "fixedpoint.max_distance=0.001")
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("no convergence", r.stderr)
        self.assertBadInput(run("fixedpoint", hm, "--guess", "0.2"), "--guess", "2 coordinates")
        self.assertBadInput(run("fixedpoint", hm, "--guess", "0.2,x"), "--guess")
        self.assertBadInput(run("fixedpoint", hm, "--guess", "0.2,0", "--method", "bisection"), "--method",
                            "newton")
        self.assertBadInput(run("fixedpoint", hm, "--guess", "0.2,0", "--set", "fixedpoint.accuracy=-1"),
                            "fixedpoint.accuracy")
        z = run("fixedpoint", hm, "--guess", "0.6,0.2", "--set", "fixedpoint.derivatives=differences",
                "--set", "fixedpoint.derivative_accuracy=1e-30", "--set", "fixedpoint.zero=1e-6")
        self.assertEqual(z.returncode, 1, z.stderr)
        self.assertIn("value of zero", z.stderr)

    def test_continue_locates_the_period_doubling(self):
        out = self.path("c.csv")
        r = run("continue", os.path.join(SRC, "scenes", "standard_map.json"), "--guess", "3.14159,0",
                "--param", "K", "--to", "4.5", "--step", "0.05", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("hyperbolic with reflection (multiplier -1)", r.stdout)
        k = float(r.stdout.split("K = ")[1].split(":")[0])
        self.assertAlmostEqual(k, 4.0, delta=1e-8)
        rows = list(csv.DictReader(open(out)))
        self.assertEqual(rows[0]["K"], "0.90000000000000002")
        self.assertAlmostEqual(float(rows[-1]["K"]), 4.5, delta=1e-12)
        for row in rows:
            self.assertAlmostEqual(float(row["re1"]) + float(row["re2"]), 2 - float(row["K"]), delta=1e-9)
        self.assertBadInput(run("continue", os.path.join(SRC, "scenes", "standard_map.json"), "--guess", "3,0",
                                "--param", "Q", "--to", "1"), "--param", "Q")
        self.assertFalse(os.path.exists(self.path("bad.csv")))

    def test_continue_by_arclength_passes_the_henon_fold(self):
        # x' = 1 - a x^2 + y, y' = b x: the family of x = 1 / (1 - b) at a = 0 turns back at the fold
        # a = -(1 - b)^2 / 4 (b = 0.3: -0.1225), where natural continuation stops
        henon = os.path.join(SRC, "scenes", "henon_map.json")
        args = [henon, "--set", "a=0", "--guess", "1.4285714285714286,0.42857142857142855", "--param", "a",
                "--to", "-0.5", "--step", "-0.01"]
        natural = run("continue", *args, "-o", self.path("n.csv"))
        self.assertEqual(natural.returncode, 1, natural.stderr)
        self.assertIn("continuation.method = arclength", natural.stderr)
        out = self.path("a.csv")
        r = run("continue", *args, "--arclength", "--set", "continuation.points=200", "--json", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        self.assertEqual(j["method"], "arclength")
        self.assertEqual(len(j["changes"]), 1)
        fold = j["changes"][0]
        self.assertEqual(fold["kind"], "fold")
        self.assertAlmostEqual(fold["parameter"], -0.1225, delta=1e-9)
        self.assertAlmostEqual(fold["point"][0], 2 / 0.7, delta=1e-6)
        self.assertIn("200 points", j["end"])
        rows = list(csv.DictReader(open(out)))
        self.assertEqual(len(rows), 200)
        for row in rows:  # every point a fixed point of its a, on both sides of the fold
            a, x = float(row["a"]), float(row["x"])
            self.assertAlmostEqual(a * x * x + 0.7 * x - 1, 0, delta=1e-9 * max(1, x * x))
        self.assertGreater(max(float(row["x"]) for row in rows), 2 / 0.7 + 0.3)  # the other root
        text = run("continue", *args, "--arclength", "--set", "continuation.points=200")
        self.assertIn("fold at a = -0.1225", text.stderr)
        self.assertIn("the family ends: 200 points", text.stderr)

    def test_continue_switches_to_the_doubled_family(self):
        # Henon, b = 0.3: the point doubles at a = 0.3675 going down from 1.4; its 2-cycle (x1 + x2 = (1 - b) / a,
        # x1 x2 = ((1 - b)^2 - a) / a^2) lives above and doubles in turn at a = (1 - b)^2 + (1 + b)^2 / 4
        henon = os.path.join(SRC, "scenes", "henon_map.json")
        out = self.path("d.csv")
        r = run("continue", henon, "--guess", "0.63,0.19", "--param", "a", "--to", "0", "--step", "-0.05",
                "--doubled", "--json", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        self.assertAlmostEqual(j["changes"][0]["parameter"], 0.3675, delta=1e-9)
        d = j["doubled"]
        self.assertEqual(d["order"], 2)
        self.assertLess(d["first"], 0.3675 + 0.01)
        self.assertAlmostEqual(d["last"], 1.4, delta=1e-12)
        self.assertIn(0.9125, [round(c["parameter"], 9) for c in d["changes"] if c["kind"] == "multiplier -1"])
        rows = list(csv.DictReader(open(out)))
        self.assertEqual(len(rows), d["points"])
        for row in rows:
            a, x = float(row["a"]), float(row["x"])
            self.assertAlmostEqual(x * x - 0.7 / a * x + (0.49 - a) / a ** 2, 0, delta=1e-9)
        text = run("continue", henon, "--guess", "0.63,0.19", "--param", "a", "--to", "0", "--step", "-0.05",
                   "--doubled")
        self.assertIn("(multiplier -1)", text.stderr)
        self.assertIn("the family of order 2 born at the period doubling starts at a = 0.3", text.stderr)
        none = run("continue", henon, "--guess", "0.63,0.19", "--param", "a", "--to", "1", "--step", "-0.05",
                   "--doubled")
        self.assertEqual(none.returncode, 1, none.stderr)
        self.assertIn("continuation.switch = 1: the family in a has 0 period doublings", none.stderr)

    def test_bifurcation_curve_of_the_henon_period_doubling(self):
        # the doubling of the point born at the fold: a = 3 (1 - b)^2 / 4, x = 2 / (3 (1 - b)); along it the other
        # multiplier is b, -1 at b = -1 (a 1:2 resonance)
        henon = os.path.join(SRC, "scenes", "henon_map.json")
        out = self.path("curve.csv")
        args = [henon, "--set", "fixedpoint.guess=[0.63,0.19]", "--set", "continuation.parameter=a",
                "--set", "continuation.to=0",
                "--set", "continuation.step=-0.05", "--second_parameter", "b", "--kind", "period_doubling",
                "--second_min", "-1.05", "--second_max", "0.5"]
        r = run("bifurcation-curve", *args, "--json", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        self.assertEqual(j["kind"], "period doubling")
        self.assertEqual(j["parameters"], ["a", "b"])
        self.assertAlmostEqual(j["start"]["a"], 0.3675, delta=1e-9)
        rows = list(csv.DictReader(open(out)))
        self.assertEqual(len(rows), j["points"])
        self.assertEqual(list(rows[0].keys()), ["a", "b", "x", "y"])
        for row in rows:
            a, b = float(row["a"]), float(row["b"])
            self.assertAlmostEqual(a, 0.75 * (1 - b) ** 2, delta=1e-8)
            self.assertAlmostEqual(float(row["x"]), 2 / (3 * (1 - b)), delta=1e-8)
        self.assertEqual(sorted([float(rows[0]["b"]), float(rows[-1]["b"])]), [-1.05, 0.5])
        self.assertEqual(len(j["events"]), 1)
        self.assertIn("1:2 resonance", j["events"][0]["what"])
        self.assertAlmostEqual(j["events"][0]["b"], -1, delta=1e-8)
        # the chart of the curve (the same settings as scene keys), and the inputs it refuses
        sets = ["fixedpoint.guess=[0.63,0.19]", "continuation.parameter=a", "continuation.to=0",
                "continuation.step=-0.05", "bifurcation_curve.second_parameter=b",
                "bifurcation_curve.kind=period_doubling", "bifurcation_curve.second_min=-1.05",
                "bifurcation_curve.second_max=0.5"]
        png = self.path("curve.png")
        c = run("chart", henon, "--view", "bifurcation_curve", *sum([["--set", x] for x in sets], []), "-o", png)
        self.assertEqual(c.returncode, 0, c.stderr)
        self.assertGreater(os.path.getsize(png), 1000)
        base = [henon, "--set", "fixedpoint.guess=[0.63,0.19]", "--set", "continuation.parameter=a",
                "--set", "continuation.to=0",
                "--set", "continuation.step=-0.05"]
        self.assertBadInput(run("bifurcation-curve", *base), "bifurcation_curve.second_parameter")
        self.assertBadInput(run("bifurcation-curve", *base, "--second_parameter", "c"), "not a parameter")
        none = run("bifurcation-curve", *base, "--second_parameter", "b", "--kind", "neimark_sacker")
        self.assertEqual(none.returncode, 1, none.stderr)
        self.assertIn("finds no Neimark-Sacker point", none.stderr)

    def test_bifurcation_tree_of_the_area_preserving_henon_map(self):
        r = run("bifurcation-tree", os.path.join(SRC, "scenes", "henon_map.json"), "--set", "b=-1",
                "--set", "a=2", "--guess", "0.4,-0.4", "--param", "a", "--to", "4.2", "--step", "0.05",
                "--set", "bifurcation_tree.levels=1", "--json", "-o", self.path("t.csv"))
        self.assertEqual(r.returncode, 0, r.stderr)
        j = json.loads(r.stdout)
        self.assertAlmostEqual(j["doublings"][0]["parameter"], 3.0, delta=1e-8)
        self.assertAlmostEqual(j["doublings"][1]["parameter"], 4.0, delta=1e-8)
        self.assertIn("levels", j["end"])
        # the cascade from a = 2.5 down to order 32 (values: tests/dynamics/reference/henon_cascade.py)
        r = run("bifurcation-tree", os.path.join(SRC, "scenes", "henon_map.json"), "--set", "b=-1",
                "--set", "a=2.5", "--guess", "0.35,-0.35", "--param", "a", "--to", "5", "--step", "0.05",
                "--set", "bifurcation_tree.levels=5", "-o", self.path("t5.csv"))
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.splitlines()  # with -o the report goes to standard output
        values = [float(line.split("=")[1]) for line in lines if line.startswith("period doubling")]
        self.assertEqual(len(values), 6, r.stdout)
        self.assertAlmostEqual(values[5], 4.1361430974114378, delta=1e-9)
        ratios = [float(line.split(":")[1]) for line in lines if line.startswith("ratio:")]
        self.assertAlmostEqual(ratios[2], 8.72, delta=0.05)
        self.assertIn("the tree ends: 6 doublings followed", r.stdout)
        h = run("bifurcation-tree", os.path.join(SRC, "scenes", "standard_map.json"), "--guess", "0.01,0.01",
                "--param", "K", "--to", "2", "--step", "0.1")
        self.assertEqual(h.returncode, 1, h.stderr)
        self.assertIn("not elliptic", h.stderr)

    def test_the_fixed_point_family_runs_through_the_registry(self):
        # continue without -o: the family's CSV on standard output, what it says on the way on standard error
        sm = os.path.join(SRC, "scenes", "tools", "continuation.json")
        r = run("continue", sm)
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(r.stdout.splitlines()))
        self.assertEqual(list(rows[0].keys()), ["K", "theta", "p", "re1", "im1", "re2", "im2", "residual", "type"])
        self.assertEqual(rows[0]["type"], "elliptic")
        self.assertAlmostEqual(float(rows[-1]["K"]), 4.5, delta=1e-12)
        self.assertIn("(multiplier -1)", r.stderr)
        # --json alone: one JSON object and nothing else (the table is not mixed in)
        j = json.loads(run("continue", sm, "--json").stdout)
        self.assertEqual((j["parameter"], j["points"]), ("K", len(rows)))
        self.assertAlmostEqual(j["changes"][0]["parameter"], 4, delta=1e-8)
        # a flag that takes no value (--doubled is continuation.switch = 1), the same family as the setting
        a = run("continue", sm, "--to", "4.2", "--doubled", "--json")
        b = run("continue", sm, "--to", "4.2", "--set", "continuation.switch=1", "--json")
        self.assertEqual(a.returncode, 0, a.stderr)
        self.assertEqual(json.loads(a.stdout), json.loads(b.stdout))
        self.assertEqual(json.loads(a.stdout)["doubled"]["order"], 2)
        # --path (fixedpoint.path = yes): the search's points, each nearer the fixed point
        hm = os.path.join(SRC, "scenes", "tools", "fixedpoint.json")
        f = json.loads(run("fixedpoint", hm, "--path", "--json").stdout)
        x = (-0.7 + (0.49 + 5.6) ** 0.5) / 2.8
        self.assertEqual(f["type"], "hyperbolic with reflection")
        self.assertAlmostEqual(f["path"][-1]["point"][0], x, delta=1e-12)
        self.assertLess(f["path"][-1]["residual"], 1e-10)
        self.assertNotIn("path", json.loads(run("fixedpoint", hm, "--json").stdout))
        # describe-tool lists the runner's arguments, as the command's --help does
        d = run("describe-tool", "continuation").stdout
        self.assertIn("--doubled", d)
        self.assertIn("--guess X,Y[,Z]", d)
        # the flags' values are checked where they become settings, and the message names the flag
        sep = os.path.join(SRC, "scenes", "tools", "separatrix.json")
        self.assertBadInput(run("separatrix", sep, "--branch", "5"), "--branch 5", "1, 2, 3, 4")
        self.assertBadInput(run("continue", sm, "--to", "x"), "--to x")
        self.assertBadInput(run("bifurcation-tree", sm, "--param", "Q"), "--param Q", "not a parameter")
        # the separatrix's branches: the rows by branch, the notes with -o on standard output
        out = self.path("sep.csv")
        r = run("separatrix", sep, "--branch", "1,2", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual({row["branch"] for row in csv.DictReader(open(out))}, {"1", "2"})
        self.assertIn("branch 2:", r.stdout)

    def test_map3d_plot_and_multipliers_are_commands_too(self):
        # Henon-Heiles' crossings of x = 0 in (x, y, px): on the plane, and with py >= 0 on the level E = 1/8
        rows = list(csv.DictReader(run("map3d", os.path.join(SRC, "scenes", "tools", "map3d.json"), "--points", "50")
                                   .stdout.splitlines()))
        self.assertEqual(len(rows), 50)
        for row in rows:
            x, y, px = float(row["x"]), float(row["y"]), float(row["px"])
            self.assertLess(abs(x), 1e-9)
            self.assertLessEqual(px * px / 2 + y * y / 2 - y ** 3 / 3, 0.125 + 1e-9)  # py^2 / 2 is the rest
        # the orbit stays inside the potential's triangle (V < 1/6 below the saddles)
        out = self.path("plot.csv")
        r = run("plot", os.path.join(SRC, "scenes", "tools", "plot.json"), "--x", "x", "--y", "y", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(out) as f:
            points = [(float(row["x"]), float(row["y"])) for row in csv.DictReader(f)]
        self.assertGreater(len(points), 1000)
        self.assertTrue(all((x * x + y * y) / 2 + x * x * y - y ** 3 / 3 <= 0.125 + 1e-9 for x, y in points))
        # the product of the Henon map's multipliers is det DF = -b at every step
        j = json.loads(run("multipliers", os.path.join(SRC, "scenes", "tools", "multipliers.json"), "--json").stdout)
        self.assertGreater(len(j["multipliers"]), 5)
        for (a, b), (c, d) in j["multipliers"]:
            self.assertAlmostEqual(a * c - b * d, -0.3, delta=1e-9)

    def test_separatrix_surface_ram(self):
        sm = os.path.join(SRC, "scenes", "standard_map.json")
        out = self.path("s.csv")
        r = run("separatrix", sm, "--guess", "0.01,0.01", "--branch", "all", "-o", out,
                "--set", "separatrix.iterations=5")
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(open(out)))
        self.assertEqual(sorted({row["branch"] for row in rows}), ["1", "2", "3", "4"])
        e = run("separatrix", sm, "--guess", "3.1,0")
        self.assertEqual(e.returncode, 1, e.stderr)
        self.assertIn("not hyperbolic", e.stderr)
        surf = self.path("z.csv")
        r = run("surface", os.path.join(SRC, "scenes", "henon_map.json"), "--x", "0,1", "--y", "0,0.4",
                "--step", "0.05", "--threads", "2", "-o", surf)
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(open(surf)))
        self.assertEqual(len(rows), 21 * 9)
        self.assertEqual(list(rows[0].keys()), ["x", "y", "distance"])
        ram = self.path("ram.csv")
        r = run("ram", os.path.join(SRC, "scenes", "henon_heiles.json"), "--x", "-0.6,0.8", "--y", "-0.6,0.6",
                "--step", "0.05", "-o", ram)
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(open(ram)))
        for row in rows:
            y, py = float(row["y"]), float(row["py"])
            rest = 0.125 - py * py / 2 - (y * y / 2 - y ** 3 / 3)
            if abs(rest) > 1e-9:
                self.assertEqual(float(row["allowed"]), 1.0 if rest > 0 else 0.0, row)
        self.assertBadInput(run("surface", sm, "--x", "1,0", "--y", "0,1"), "--x")
        self.assertBadInput(run("surface", sm, "--z", "1,2,3"), "--z")
        self.assertBadInput(run("ram", sm, "--level", "nope"), "grid.level", "not an observable")
        # the known answer (scenes/tools/surface.json): the Henon map's fixed point x = (-0.7 + sqrt(0.49 + 5.6))
        # / 2.8, y = 0.3 x is where the search from fixedpoint.guess ends, and the node of least distance lies
        # in its valley (within two cells: the valley is long and narrow, so not always the nearest node)
        j = json.loads(run("surface", os.path.join(SRC, "scenes", "tools", "surface.json"), "--json").stdout)
        x = (-0.7 + math.sqrt(0.49 + 5.6)) / 2.8
        self.assertLessEqual(abs(j["least"]["at"][0] - x), 2 * 0.05)
        self.assertLessEqual(abs(j["least"]["at"][1] - 0.3 * x), 2 * 0.02)
        self.assertLess(j["least"]["distance"], 0.05)
        self.assertEqual(j["nodes"], 21 * 21)
        self.assertEqual(j["search"], "converged")
        self.assertAlmostEqual(j["search_path"][-1][0], x, delta=1e-9)
        self.assertAlmostEqual(j["search_path"][-1][1], 0.3 * x, delta=1e-9)
        # the region of allowed motion's share of the rectangle: the area inside p^2/2 + y^2/2 - y^3/3 = 1/8
        j = json.loads(run("ram", os.path.join(SRC, "scenes", "henon_heiles.json"), "--x", "-0.6,0.8", "--y",
                           "-0.6,0.6", "--step", "0.01", "--json").stdout)
        ys = [-0.6 + 0.0001 * k for k in range(14001)]
        area = sum(2 * math.sqrt(max(0.0, 2 * (0.125 - y * y / 2 + y ** 3 / 3))) for y in ys) * 0.0001
        self.assertAlmostEqual(j["allowed_fraction"], area / (1.4 * 1.2), delta=0.01)
        self.assertEqual(j["level_name"], "px")

    def test_diagram(self):
        out = self.path("d.csv")
        r = run("diagram", SCENE, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(open(out)))
        self.assertIn("tau", {row["branch"] for row in rows})
        state = [row for row in rows if row["branch"] == "state"][0]
        self.assertAlmostEqual(float(state["h"]), 0.5, delta=1e-9)  # the scene's energy
        j = json.loads(run("diagram", SCENE, "--json").stdout)
        self.assertEqual(j["axes"], ["n", "h"])
        self.assertBadInput(run("diagram", os.path.join(SRC, "scenes", "lorenz.json")), "no bifurcation diagrams")
        self.assertBadInput(run("diagram", SCENE, "--diagram", "xy"), "diagram.diagram", "nh")
        self.assertBadInput(run("diagram", SCENE, "--branch", "xy"), "diagram.branch", "tau")
        self.assertBadInput(run("diagram", SCENE, "--min", "1", "--max", "0"), "diagram.min")
        # one branch over a range of its own: the rows are that branch's, at its parameter's steps
        r = run("diagram", SCENE, "--branch", "tau", "--min", "0.5", "--max", "0.6", "--step", "0.05", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(open(out)))
        self.assertEqual({row["branch"] for row in rows}, {"tau", "state"})
        self.assertTrue(all(float(row["parameter"]) in (0.5, 0.55, 0.6) for row in rows if row["branch"] == "tau"))
        # the chart of another of the problem's diagrams; an unknown one names the flag and the known ones
        png = self.path("ch.png")
        r = run("chart", SCENE, "--view", "bifurcation", "--diagram", "ch", "-o", png, "--size", "300x300")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.getsize(png) > 1000)
        self.assertBadInput(run("chart", SCENE, "--view", "bifurcation", "--diagram", "xy", "-o", png),
                            "diagram.diagram", "ch")

    def test_every_scene_has_a_poincare_map(self):
        # a section the motion never crosses would make `poincare` run forever: every shipped scene must return
        for name in sorted(os.listdir(os.path.join(SRC, "scenes"))):
            if not name.endswith(".json"):
                continue
            r = run("poincare", os.path.join(SRC, "scenes", name), "--points", "3", timeout=60)
            self.assertEqual(r.returncode, 0, name + ": " + r.stderr)
            self.assertEqual(len(r.stdout.strip().splitlines()), 4, name)

    def test_every_registered_tool_is_described_runs_somewhere_and_takes_its_settings(self):
        r = run("list", "tools")
        self.assertEqual(r.returncode, 0, r.stderr)
        ids = [line.split()[0] for line in r.stdout.splitlines() if line.strip() and ":" in line
               and not line.startswith("rollviz")]
        for tool in ("poincare", "lyapunov", "spectrum", "megno", "fixedpoint", "continuation", "separatrix",
                     "bifurcation_tree", "surface", "ram", "diagram"):
            self.assertIn(tool, ids)
        views = run("chart", "--help").stdout
        lorenz = os.path.join(SRC, "scenes", "lorenz.json")
        for tool in ids:
            d = run("describe-tool", tool)
            self.assertEqual(d.returncode, 0, d.stderr)
            self.assertIn("outputs:", d.stdout, tool)
            lines = d.stdout.splitlines()
            command = [l.split("rollviz ", 1)[1] for l in lines if l.strip().startswith("command: rollviz")]
            view = [l.split("--view ", 1)[1] for l in lines if l.strip().startswith("chart: rollviz chart")]
            self.assertTrue(command or view, tool + " runs nowhere")
            where = [l.split(": ", 1)[1] for l in lines if l.strip().startswith("computation:")]
            self.assertEqual(len(where), 1, tool)
            self.assertTrue(os.path.exists(os.path.join(SRC, where[0].split()[0])), where[0])
            for c in command:
                self.assertEqual(run(c, "--help").returncode, 0, c)
            for v in view:
                self.assertIn(v, views, tool)
            # every setting is a --set key of its section, at its default value
            head = [l for l in lines if l.startswith("settings (scene section")]
            if head:
                section = head[0].split('"')[1]
                start = lines.index(head[0]) + 1
                sets = []
                for l in lines[start:]:
                    if not l.strip():
                        break
                    key, default = l.split()[:2]
                    sets += ["--set", "%s.%s=%s" % (section, key, default if default[0].isdigit() or
                                                     default[0] == "-" else json.dumps(default))]
                i = run("integrate", lorenz, "--time", "0.01", "--every", "0.01", "--columns", "t", *sets)
                self.assertEqual(i.returncode, 0, i.stderr)
        self.assertBadInput(run("describe-tool", "no_such_tool"), "no_such_tool", "megno")

    def test_the_tools_reference_is_up_to_date(self):
        sys.path.insert(0, os.path.join(SRC, "scripts"))
        import make_tools_reference
        with open(os.path.join(SRC, "docs", "tools.md")) as f:
            self.assertEqual(f.read(), make_tools_reference.reference(RV),
                             "docs/tools.md is stale: run scripts/make_tools_reference.py build/dev/app/rollviz")

    def test_megno_known_answers_and_chart(self):
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        r = run("megno", hh, "--set", "energy=0.08333333333333333", "--time", "3000", "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        regular = json.loads(r.stdout)
        self.assertAlmostEqual(regular["megno"], 2, delta=0.2)
        self.assertEqual(regular["time"], 3000)
        # in the chaotic sea MEGNO's rate tends to the largest Lyapunov exponent; over a finite time one orbit may
        # stick near islands for a while (either estimate then lags), so the medians of three orbits are compared
        rates, exponents = [], []
        for start in ("[0.1,0.1]", "[0.12,0.1]", "[0.05,0.05]"):
            chaotic = json.loads(run("megno", hh, "--set", "energy=0.16666666666666666", "--set",
                                     "initial.map=" + start, "--time", "20000", "--json").stdout)
            lyap = json.loads(run("lyapunov", hh, "--set", "energy=0.16666666666666666", "--set",
                                  "initial.map=" + start, "--time", "20000", "--json").stdout)
            self.assertGreater(chaotic["megno"], 20, start)
            rates.append(chaotic["megno_rate"])
            exponents.append(lyap["exponents"][0])
        rate, exponent = sorted(rates)[1], sorted(exponents)[1]
        self.assertAlmostEqual(rate, exponent, delta=0.15 * exponent, msg=f"{rates} {exponents}")
        # the scene section and the text output
        t = run("megno", hh, "--set", "megno.time=100")
        self.assertEqual(t.returncode, 0, t.stderr)
        self.assertIn("time = 100", t.stdout)
        self.assertBadInput(run("megno", hh, "--set", "megno.interval=0"), "megno.interval")
        png = self.path("megno.png")
        c = run("chart", hh, "--view", "megno", "-o", png, "--size", "480x320", "--set", "megno.time=500")
        self.assertEqual(c.returncode, 0, c.stderr)
        size, px = pixels(png)
        self.assertEqual(size, (480, 320))
        self.assertTrue(varied(px))

    def start_until_checkpoint(self, args, checkpoint, saved=os.path.exists):
        """starts a long command, waits until it has saved its checkpoint once (saved(checkpoint)), then kills
        it with SIGKILL"""
        e = dict(os.environ)
        e.pop("DISPLAY", None)
        p = subprocess.Popen([RV, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=e)
        deadline = time.time() + 60
        while not saved(checkpoint) and p.poll() is None and time.time() < deadline:
            time.sleep(0.02)
        p.kill()
        p.wait()
        self.assertTrue(saved(checkpoint), "the run ended before it saved a checkpoint")

    @staticmethod
    def sweep_checkpoint_has_points(path):
        """whether a sweep's store holds a point's record: its header (dynamics/jobs/SweepStore.cpp) is a magic
        word, the identity's length (int64) and JSON, the points (int64) and columns (int32), padded to 64
        bytes; the records after it are zeros until written"""
        try:
            data = open(path, "rb").read()
            start = data.index(b"{")
            end = start + int.from_bytes(data[start - 8:start], "little") + 12
            return any(data[(end + 63) // 64 * 64:])
        except (OSError, ValueError):
            return False

    def test_killed_runs_resume_to_the_same_result(self):
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        full, resumed, ck = self.path("full.csv"), self.path("res.csv"), self.path("map.ck")
        args = ["poincare", hh, "--points", "40000"]
        r = run(*args, "-o", full)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.start_until_checkpoint([*args, "-o", resumed, "--checkpoint", ck], ck)
        self.assertFalse(os.path.exists(resumed))
        r = run(*args, "-o", resumed, "--checkpoint", ck)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(open(full).read(), open(resumed).read())
        self.assertFalse(os.path.exists(ck), "a completed run removes its checkpoint")

        lorenz = os.path.join(SRC, "scenes", "lorenz.json")

        def killed_and_resumed(args, checkpoint):
            """the JSON of a whole run and of one killed after its first save and resumed"""
            whole = run(*args)
            self.assertEqual(whole.returncode, 0, whole.stderr)
            self.start_until_checkpoint([*args, "--checkpoint", checkpoint], checkpoint)
            again = run(*args, "--checkpoint", checkpoint)
            self.assertEqual(again.returncode, 0, again.stderr)
            return json.loads(whole.stdout), json.loads(again.stdout)

        # each run takes ~5 s in the dev build, five times the first save's period (app/cli/Checkpoint.cpp): a
        # shorter one (Lorenz's fused RK4 made 20000 take 1.2 s) may end before it saves on a busy machine
        whole, again = killed_and_resumed(["megno", lorenz, "--time", "40000", "--json"], self.path("megno.ck"))
        self.assertEqual(whole, again)
        ck2 = self.path("lyap.ck")
        args = ["lyapunov", lorenz, "--time", "100000", "--json"]
        whole, again = killed_and_resumed(args, ck2)
        self.assertEqual(whole["exponents"], again["exponents"])

        # another run's checkpoint is refused, naming the flag
        self.start_until_checkpoint([*args, "--checkpoint", ck2], ck2)
        self.assertBadInput(run("lyapunov", lorenz, "--time", "30000", "--checkpoint", ck2), "--checkpoint",
                            "another run")

    def test_interrupted_map_saves_and_resumes(self):
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        full, resumed, ck = self.path("full.csv"), self.path("res.csv"), self.path("map.ck")
        args = ["poincare", hh, "--points", "20000"]
        self.assertEqual(run(*args, "-o", full).returncode, 0)
        e = dict(os.environ)
        e.pop("DISPLAY", None)
        p = subprocess.Popen([RV, *args, "-o", resumed, "--checkpoint", ck], stderr=subprocess.PIPE, env=e)
        # Ctrl-C once it computes (the temporary output exists): earlier, no handler is installed yet; from
        # then on a Ctrl-C at any moment saves the checkpoint (app/cli/Checkpoint.cpp), so no further delay
        deadline = time.time() + 60
        while not any(n.startswith(".res.partial-") for n in os.listdir(self.dir)) and time.time() < deadline:
            time.sleep(0.01)
        p.send_signal(signal.SIGINT)
        self.assertEqual(p.wait(timeout=60), 130)
        self.assertTrue(os.path.exists(ck))
        r = run(*args, "-o", resumed, "--checkpoint", ck)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(open(full).read(), open(resumed).read())

    @staticmethod
    def on_a_terminal(*args):
        """runs rollviz with stdout and stderr on one pseudo-terminal: its exit status and all it printed"""
        import pty
        e = dict(os.environ)
        e.pop("DISPLAY", None)
        master, slave = pty.openpty()
        p = subprocess.Popen([RV, *args], stdin=subprocess.DEVNULL, stdout=slave, stderr=slave, env=e)
        os.close(slave)
        out = b""
        while True:
            try:
                chunk = os.read(master, 65536)
            except OSError:  # EIO: the last writer closed the terminal
                break
            if not chunk:
                break
            out += chunk
        os.close(master)
        return p.wait(timeout=300), out.decode()

    def test_progress_on_a_terminal_is_one_line_erased_before_anything_else_is_printed(self):
        lorenz = os.path.join(SRC, "scenes", "lorenz.json")
        status, out = self.on_a_terminal("lyapunov", lorenz, "--time", "2000")
        self.assertEqual(status, 0, out)
        self.assertIn("\r\x1b[Klyapunov:", out)  # the line, rewritten in place
        # erased before the result: nothing of it after the result, no result glued to a percentage
        self.assertIn("exponents =", out.split("\x1b[K")[-1], out)
        self.assertNotRegex(out, r"%\s*exponents")
        # rows printed on the terminal are the progress: no line beside them
        status, out = self.on_a_terminal("integrate", lorenz, "--time", "3", "--every", "1")
        self.assertEqual(status, 0, out)
        self.assertNotIn("integrate:", out)
        self.assertEqual(len([line for line in out.splitlines() if line]), 5, out)
        # to a file: the line, erased at the end
        csv_out = self.path("t.csv")
        status, out = self.on_a_terminal("integrate", lorenz, "--time", "300", "--every", "300", "-o", csv_out)
        self.assertEqual(status, 0, out)
        self.assertIn("integrate:", out)
        self.assertTrue(out.endswith("\r\x1b[K"), repr(out[-80:]))
        # not a terminal: no progress at all
        r = run("lyapunov", lorenz, "--time", "2000")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("lyapunov:", r.stderr)
        self.assertNotIn("\r", r.stderr)

    def test_ctrl_c_stops_a_run_between_rows_far_apart_keeping_the_rows_written(self):
        lorenz = os.path.join(SRC, "scenes", "lorenz.json")
        out = self.path("far.csv")
        e = dict(os.environ)
        e.pop("DISPLAY", None)
        # rows at t = 0 and t = 1e9 only: hours of steps between them, during which Ctrl-C must be heard
        p = subprocess.Popen([RV, "integrate", lorenz, "--time", "1e9", "--every", "1e9", "-o", out],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=e)
        deadline = time.time() + 60  # computing once the temporary output exists (the handler is in)
        while not any(n.startswith(".far.partial-") for n in os.listdir(self.dir)) and time.time() < deadline:
            self.assertIsNone(p.poll(), "it ended before it computed")
            time.sleep(0.01)
        p.send_signal(signal.SIGINT)
        try:
            status = p.wait(timeout=60)
        finally:
            if p.poll() is None:
                p.kill()
        err = p.stderr.read().decode()
        p.stderr.close()
        self.assertEqual(status, 130, err)
        # what was finished is kept (design.md: the rows written, whole), nothing half-written is left
        self.assertEqual(open(out).read().splitlines(), ["t,x,y,z", "0,1,1,1"])
        self.assertEqual(sorted(os.listdir(self.dir)), ["far.csv"])

    def compiler_stand_in(self, body):
        """a model compiler (ROLLVIZ_MODEL_COMPILER) that writes its pid, then runs `body` (sh)"""
        path = self.path("cc.sh")
        with open(path, "w") as f:
            f.write("#!/bin/sh\necho $$ > %s.pid\n%s\n" % (path, body))
        os.chmod(path, 0o755)
        return path

    @staticmethod
    def pid_in(path):
        """the pid a compiler stand-in wrote, or None before it did"""
        try:
            with open(path) as f:
                return int(f.read())
        except (OSError, ValueError):
            return None

    @staticmethod
    def dead(pid):
        """whether a process ended (a zombie nobody reaps has ended too)"""
        try:
            with open("/proc/%d/stat" % pid) as f:
                return f.read().rsplit(")", 1)[1].split()[0] == "Z"
        except OSError:
            return True

    def wait_for(self, condition, what, seconds=120):
        deadline = time.time() + seconds
        while not condition():
            self.assertLess(time.time(), deadline, what)
            time.sleep(0.02)

    def test_a_model_compilation_never_blocks_a_run_and_fills_the_cache_for_the_next(self):
        scene = os.path.join(SRC, "examples", "models", "lorenz.scene.json")
        cache = self.path("cache")
        args = ["integrate", scene, "--time", "1", "--every", "0.5"]
        env = {"ROLLVIZ_MODEL_CACHE": cache, "ROLLVIZ_COMPILE_WAIT": "0.2"}
        # a compiler that would take ten minutes: the run goes on interpreted, says so once, and is right
        slow = self.compiler_stand_in("exec sleep 600")
        r = run(*args, env={**env, "ROLLVIZ_MODEL_COMPILER": slow}, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr.count("runs interpreted for now"), 1, r.stderr)
        self.assertIn("ROLLVIZ_COMPILE_WAIT", r.stderr)
        self.assertEqual(r.stdout, run(*args, env={"ROLLVIZ_COMPILE_MODELS": "0"}).stdout)
        # its compilation goes on after the run, in a process of its own: stopped here
        helper = int(r.stderr.split("(process ")[1].split(")")[0])
        self.wait_for(lambda: self.pid_in(slow + ".pid"), "the compiler did not start")
        compiler = self.pid_in(slow + ".pid")
        self.assertFalse(self.dead(compiler), "the compiler ended with the run")
        os.killpg(helper, signal.SIGTERM)
        self.wait_for(lambda: self.dead(compiler), "the compiler was not stopped")

        # a real compiler that starts only once the run has ended: the next run finds its library cached
        real = run("info").stdout.split("compiled to native code")[1].split("(")[1].split(",")[0]
        go = self.path("go")
        delayed = self.compiler_stand_in('while [ ! -e %s ]; do sleep 0.05; done\nexec %s "$@"' % (go, real))
        delayed_env = {**env, "ROLLVIZ_MODEL_COMPILER": delayed}
        r = run(*args, env=delayed_env, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("runs interpreted for now", r.stderr)
        open(go, "w").close()
        self.wait_for(lambda: any(n.endswith(".sum") for n in os.listdir(cache)), "nothing was cached", 600)
        again = run(*args, env=delayed_env, timeout=120)
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertNotIn("compiling", again.stderr)  # loaded from the cache
        self.assertNotIn("interpreted", again.stderr)
        rows = [[float(v) for v in line.split(",")] for line in again.stdout.splitlines()[1:]]
        for a, b in zip(rows, [[float(v) for v in line.split(",")] for line in r.stdout.splitlines()[1:]]):
            for x, y in zip(a, b):
                self.assertAlmostEqual(x, y, delta=1e-9 * max(1, abs(y)))

    def test_ctrl_c_stops_a_model_compilation_a_run_waits_for(self):
        scene = os.path.join(SRC, "examples", "models", "lorenz.scene.json")
        slow = self.compiler_stand_in("exec sleep 600")
        e = dict(os.environ, ROLLVIZ_MODEL_CACHE=self.path("cache"), ROLLVIZ_COMPILE_WAIT="inf",
                 ROLLVIZ_MODEL_COMPILER=slow)
        e.pop("DISPLAY", None)
        p = subprocess.Popen([RV, "integrate", scene, "--time", "1", "--every", "0.5"], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, env=e)
        try:
            self.wait_for(lambda: self.pid_in(slow + ".pid"), "the compiler did not start")
            compiler = self.pid_in(slow + ".pid")
        finally:
            status, err = interrupt(p)
        self.assertEqual(status, 130, err)
        self.assertIn("compilation was stopped", err)
        self.wait_for(lambda: self.dead(compiler), "the compiler outlived Ctrl-C")

        # past the wait, the run goes on interpreted while the compiler goes on in its own process: Ctrl-C
        # stops both (and a run that ends by itself leaves it running, as the test above shows)
        os.remove(slow + ".pid")
        e["ROLLVIZ_COMPILE_WAIT"] = "0"
        out = self.path("long.csv")
        p = subprocess.Popen([RV, "integrate", scene, "--time", "1e9", "--every", "1e9", "-o", out],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=e)
        try:
            self.wait_for(lambda: self.pid_in(slow + ".pid") and
                          any(n.startswith(".long.partial-") for n in os.listdir(self.dir)), "it did not start")
            compiler = self.pid_in(slow + ".pid")
        finally:
            status, err = interrupt(p)
        self.assertEqual(status, 130, err)
        self.assertIn("runs interpreted for now", err)
        self.wait_for(lambda: self.dead(compiler), "the detached compiler outlived Ctrl-C")

    def test_json_help_promises_no_output_the_object_lacks(self):
        import re
        for tool, scene, args in [("lyapunov", "lorenz.json", ["--time", "50"]), ("megno", "lorenz.json", ["--time", "50"]),
                                  ("poincare", "henon_heiles.json", ["--points", "5"])]:
            path = os.path.join(SRC, "scenes", scene)
            r = run(tool, path, *args, "--json")
            self.assertEqual(r.returncode, 0, r.stderr)
            keys = set(json.loads(r.stdout))
            described = run("describe-tool", tool).stdout.split("outputs:")[1].split("\n\n")[0]
            outputs = [line.split()[0] for line in described.splitlines() if line.strip()]
            usage = run(tool, "--help").stdout
            said = usage[usage.index("--json"):].split("\n  -")[0]
            for name in outputs:
                if name not in keys:
                    self.assertIsNone(re.search(r"(?<![\w<])%s(?![\w>])" % re.escape(name), said),
                                      "%s --json help names '%s', which its object lacks: %s" % (tool, name, said))

    def test_scene_path_problems_and_duplicate_keys_are_bad_input(self):
        out = self.path("a.csv")
        args = ["--time", "1", "--every", "1", "--columns", "t", "-o", out]
        self.assertBadInput(run("integrate", os.path.join(SRC, "scenes"), *args), "is a folder")
        empty = self.path("empty.json")
        open(empty, "w").close()
        self.assertBadInput(run("integrate", empty, *args), empty, "empty")
        dup = self.path("dup.json")
        with open(dup, "w") as f:
            f.write('{"problem": "lorenz", "parameters": {"rho": 28, "rho": 20}, "initial": {}}')
        self.assertBadInput(run("integrate", dup, *args), dup + ":parameters.rho", "twice")
        self.assertFalse(os.path.exists(out))

    def test_grids_are_the_same_with_one_and_two_threads_and_when_resumed(self):
        hh = os.path.join(SRC, "scenes", "henon_heiles.json")
        for tool in ("surface", "ram"):
            outs = []
            for threads in ("1", "2"):
                outs.append(self.path("%s%s.csv" % (tool, threads)))
                r = run(tool, hh, "--x", "-0.3,0.3", "--y", "-0.3,0.3", "--step", "0.05", "--threads", threads,
                        "-o", outs[-1])
                self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(open(outs[0]).read(), open(outs[1]).read(), tool)
        # a surface killed after its first save and resumed with another number of threads: the same file
        ck, resumed = self.path("grid.ck"), self.path("resumed.csv")
        args = ["surface", hh, "--x", "-0.4,0.4", "--y", "-0.4,0.4", "--step", "0.005"]  # ~5 s: saves after 1 s
        self.start_until_checkpoint([*args, "--threads", "1", "-o", resumed, "--checkpoint", ck], ck)
        r = run(*args, "--threads", "2", "-o", resumed, "--checkpoint", ck)
        self.assertEqual(r.returncode, 0, r.stderr)
        whole = self.path("whole.csv")
        self.assertEqual(run(*args, "--threads", "2", "-o", whole).returncode, 0)
        self.assertEqual(open(whole).read(), open(resumed).read())

    def sweep_file(self, name, doc):
        path = self.path(name)
        with open(path, "w") as f:
            json.dump(doc, f)
        return path

    def sweep_values(self, path):
        """the rows of a sweep's CSV without the cost column (--timing: it differs from run to run)"""
        rows = list(csv.reader(open(path)))
        if "seconds" not in rows[0]:
            return rows
        cost = rows[0].index("seconds")
        return [r[:cost] + r[cost + 1:] for r in rows]

    def sweep_counts(self, stderr):
        """(points, computed now, from the checkpoint) from the summary line on stderr"""
        import re
        m = re.search(r"sweep: (\d+) points: (\d+) computed now, (\d+) from the checkpoint", stderr)
        self.assertIsNotNone(m, stderr)
        return tuple(int(g) for g in m.groups())

    def test_sweeps_are_the_same_on_threads_ranks_and_when_resumed(self):
        hh = self.sweep_file("hh.json", {
            "scene": os.path.join(SRC, "scenes", "henon_heiles.json"),
            "axes": [{"id": "map.0", "min": -0.3, "max": 0.3, "count": 12},
                     {"id": "map.1", "min": -0.3, "max": 0.3, "count": 10}],
            "quantity": "megno", "set": {"megno.time": 800}})
        one, two, png = self.path("one.csv"), self.path("two.csv"), self.path("hh.png")
        r = run("sweep", hh, "-o", one, "--threads", "1")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.sweep_counts(r.stderr), (120, 120, 0))
        rows = self.sweep_values(one)
        self.assertEqual(rows[0], ["map.0", "map.1", "megno", "status"])
        self.assertEqual(len(rows), 121)
        statuses = [row[-1] for row in rows[1:]]
        self.assertGreater(statuses.count("ok"), 60)
        self.assertTrue(all(s == "ok" or s.startswith("failed: ") for s in statuses))
        r = run("sweep", hh, "-o", two, "--threads", "2", "--png", png)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(rows, self.sweep_values(two), "1 and 2 threads differ")
        size, px = pixels(png)
        self.assertEqual(size, (900, 700))
        self.assertTrue(varied(px))
        # `rollviz chart --view sweep` draws the same picture from the CSV; another sweep's CSV is refused
        again = self.path("again.png")
        r = run("chart", hh, "--view", "sweep", "--csv", two, "--size", "900x700", "-o", again)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(pixels(again)[1], px)
        self.assertBadInput(run("chart", hh, "--view", "sweep", "--csv", SCENE, "-o", again), "--csv")
        self.assertBadInput(run("chart", hh, "--view", "sweep", "-o", again), "--csv")
        # MPI: rank 0 writes, the others compute; -n 1 and -n 2 give the threaded chart bit for bit
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
        env.pop("DISPLAY", None)
        for ranks in ("1", "2"):
            out = self.path("mpi%s.csv" % ranks)
            r = subprocess.run(["mpirun", "-n", ranks, RV, "sweep", hh, "-o", out], capture_output=True, text=True,
                               env=env, timeout=300)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertEqual(rows, self.sweep_values(out), "mpirun -n %s differs" % ranks)
            self.assertEqual(self.sweep_counts(r.stderr)[1], 120)
        # killed (SIGKILL) once it has saved some points and started again: the same chart, and every point
        # computed exactly once (one point at a time, --lanes 1, which a checkpoint records: the chart above ran
        # on lanes, the same numbers)
        ck, resumed = self.path("sweep.ck"), self.path("resumed.csv")
        self.start_until_checkpoint(["sweep", hh, "-o", resumed, "--threads", "1", "--lanes", "1",
                                     "--checkpoint", ck], ck, self.sweep_checkpoint_has_points)
        self.assertFalse(os.path.exists(resumed))
        r = run("sweep", hh, "-o", resumed, "--threads", "2", "--lanes", "1", "--checkpoint", ck)
        self.assertEqual(r.returncode, 0, r.stderr)
        total, now, before = self.sweep_counts(r.stderr)
        self.assertGreater(before, 0)
        self.assertEqual(now + before, total)
        self.assertEqual(rows, self.sweep_values(resumed))
        self.assertFalse(os.path.exists(ck), "a completed sweep removes its checkpoint")
        # another sweep's checkpoint is refused
        open(ck, "w").write("not a sweep store")
        self.assertBadInput(run("sweep", hh, "-o", resumed, "--checkpoint", ck), "--checkpoint", ck)

    def test_sweep_known_answers_bad_files_and_examples(self):
        lorenz = os.path.join(SRC, "scenes", "lorenz.json")
        sw = self.sweep_file("lor.json", {"scene": lorenz, "quantity": "lyapunov.max",
                                          "axes": [{"id": "rho", "min": 4, "max": 28, "count": 2}],
                                          "set": {"lyapunov.time": 200}})
        out = self.path("lor.csv")
        r = run("sweep", sw, "-o", out, "--png", self.path("lor.png"))
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = list(csv.DictReader(open(out)))
        self.assertLess(float(rows[0]["lyapunov.max"]), 0)  # stable equilibria
        r = run("lyapunov", lorenz, "--set", "rho=28", "--set", "lyapunov.time=200", "--json")
        # the sweep follows the largest exponent's vector alone (its intervals need not shorten for the third
        # exponent's contraction, as the whole spectrum's do): the same value to rounding
        self.assertAlmostEqual(float(rows[1]["lyapunov.max"]), json.loads(r.stdout)["exponents"][0], delta=1e-9)
        good = {"scene": lorenz, "quantity": "lyapunov.max", "axes": [{"id": "rho", "min": 0, "max": 1, "count": 3}]}
        for field, change in [("axes.0.id", lambda d: d["axes"][0].update(id="no_such")),
                              ("quantity", lambda d: d.update(quantity="no_such")),
                              ("axes.0.count", lambda d: d["axes"][0].update(count=0)),
                              ("axes.0.min", lambda d: d["axes"][0].update(min=2)),
                              ("scene", lambda d: d.update(scene="no_such.json"))]:
            doc = json.loads(json.dumps(good))
            change(doc)
            bad = self.sweep_file("bad.json", doc)
            self.assertBadInput(run("sweep", bad, "-o", self.path("bad.csv")), bad + ":" + field)
            self.assertFalse(os.path.exists(self.path("bad.csv")))
        self.assertBadInput(run("sweep", self.path("none.json"), "-o", out), "none.json")
        self.assertEqual(os.listdir(self.dir).count("bad.csv"), 0)
        # the shipped example sweeps, on a coarse grid
        folder = os.path.join(SRC, "scenes", "sweeps")
        examples = sorted(f for f in os.listdir(folder) if f.endswith(".json"))
        self.assertGreaterEqual(len(examples), 5)
        for name in examples:
            doc = json.load(open(os.path.join(folder, name)))
            doc["scene"] = os.path.normpath(os.path.join(folder, doc["scene"]))
            for a in doc["axes"]:
                a["count"] = 2
            if "options" in doc and "orbit_points" in doc["options"]:
                doc["options"]["orbit_points"] = 5
            doc.get("options", {}).pop("refine", None)  # a row per grid point (refinement: its own test)
            out = self.path(name + ".csv")
            r = run("sweep", self.sweep_file(name, doc), "-o", out, "--png", self.path(name + ".png"))
            self.assertEqual(r.returncode, 0, name + ": " + r.stderr)
            self.assertEqual(len(list(csv.reader(open(out)))), 1 + 2 ** len(doc["axes"]), name)
            self.assertTrue(varied(pixels(self.path(name + ".png"))[1]), name)
            # one point at a time: the same numbers as the batches on SIMD lanes (every example's method is
            # rk4 or one the sweep does not batch, so equal means bit for bit)
            single = self.path(name + ".single.csv")
            r = run("sweep", self.sweep_file(name, doc), "-o", single, "--lanes", "1")
            self.assertEqual(r.returncode, 0, name + ": " + r.stderr)
            self.assertEqual(self.sweep_values(single), self.sweep_values(out), name)
        self.assertEqual([f for f in os.listdir(self.dir) if "sweep-part" in f], [], "a temporary store was left")

    def test_sweep_window_and_refinement(self):
        henon = os.path.join(SRC, "scenes", "henon_map.json")
        base = {"scene": henon, "quantity": "observable.x", "options": {"time": 40},
                "axes": [{"id": "map.0", "min": -2.5, "max": 2.5, "count": 9},
                         {"id": "map.1", "min": -2.5, "max": 2.5, "count": 9}]}
        # --window: the same counts over another window, equal to a sweep file with those axes
        zoom = json.loads(json.dumps(base))
        zoom["axes"][0].update(min=-1, max=0.5)
        zoom["axes"][1].update(min=0, max=1)
        a, b = self.path("window.csv"), self.path("file.csv")
        r = run("sweep", self.sweep_file("base.json", base), "-o", a, "--window", "-1,0.5,0,1")
        self.assertEqual(r.returncode, 0, r.stderr)
        r = run("sweep", self.sweep_file("zoom.json", zoom), "-o", b)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.sweep_values(a), self.sweep_values(b))
        self.assertEqual(len(self.sweep_values(a)), 82)
        for bad in ("-1,0.5", "1,0,0,1", "a,b,c,d"):
            self.assertBadInput(run("sweep", self.sweep_file("base.json", base), "-o", a, "--window", bad),
                                "--window")
        # refine: the grid, then the cells where the regimes meet (escape / bounded), to 4x the resolution; the
        # CSV has the points computed, each a plain sweep's value there
        refined = json.loads(json.dumps(base))
        refined["options"]["refine"] = 2
        fine = json.loads(json.dumps(base))
        for axis in fine["axes"]:
            axis["count"] = 33
        rf, ff = self.sweep_file("refined.json", refined), self.sweep_file("fine.json", fine)
        rc, fc, png, vti = self.path("refined.csv"), self.path("fine.csv"), self.path("refined.png"), \
            self.path("refined.vti")
        r = run("sweep", rf, "-o", rc, "--png", png)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("levels of refinement", r.stderr)
        self.assertEqual(run("sweep", ff, "-o", fc).returncode, 0)
        rows, every = self.sweep_values(rc), {tuple(row[:2]): row for row in self.sweep_values(fc)[1:]}
        self.assertEqual(rows[0], ["map.0", "map.1", "observable.x", "status"])
        self.assertGreater(len(rows) - 1, 81)
        self.assertLess(len(rows) - 1, 33 * 33 * 3 // 4)
        for row in rows[1:]:
            self.assertEqual(row, every[tuple(row[:2])])
        self.assertTrue(varied(pixels(png)[1]))
        # the chart from the refined CSV is the sweep's own picture; .vti holds the finest grid
        again = self.path("again.png")
        r = run("chart", rf, "--view", "sweep", "--csv", rc, "--size", "900x700", "-o", again)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(pixels(again)[1], pixels(png)[1])
        r = run("sweep", rf, "-o", vti)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn('WholeExtent="0 32 0 32 0 0"', open(vti, errors="replace").read())
        # on MPI ranks, level after level (the others wait for each level's last records): the same file
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
        env.pop("DISPLAY", None)
        for ranks in ("2", "3"):
            out = self.path("refined_mpi%s.csv" % ranks)
            r = subprocess.run(["mpirun", "-n", ranks, RV, "sweep", rf, "-o", out], capture_output=True,
                               text=True, env=env, timeout=300)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertIn("more rank", r.stderr)
            self.assertEqual(self.sweep_values(out), rows, "mpirun -n %s differs" % ranks)

    def test_sweep_points_on_lanes_equal_one_at_a_time(self):
        # MEGNO over Henon-Heiles initial points with rk4: several points at once (the default) and --lanes 1
        # (one at a time) write the same CSV; `rollviz info` names the lanes
        hh = self.sweep_file("hh_lanes.json", {
            "scene": os.path.join(SRC, "scenes", "henon_heiles.json"), "quantity": "megno",
            "axes": [{"id": "map.0", "min": -0.45, "max": 0.6, "count": 6},
                     {"id": "map.1", "min": -0.5, "max": 0.5, "count": 5}],
            "set": {"megno.time": 50, "integrator.method": "rk4", "integrator.step": 0.02}})
        a, b = self.path("lanes.csv"), self.path("single.csv")
        self.assertEqual(run("sweep", hh, "-o", a).returncode, 0)
        r = run("sweep", hh, "-o", b, "--lanes", "1")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.sweep_values(a), self.sweep_values(b))
        self.assertBadInput(run("sweep", hh, "-o", b, "--lanes", "3"), "--lanes")
        self.assertIn("SIMD lanes", run("info").stdout)

    def test_gui_without_a_display_says_so(self):
        r = run("gui", SCENE, env={"WAYLAND_DISPLAY": ""})
        if "WAYLAND_DISPLAY" in os.environ:
            return
        self.assertEqual(r.returncode, 1)
        self.assertIn("no display", r.stderr)

    def test_info_names_the_renderer_and_warns_on_software(self):
        r = run("info")
        self.assertEqual(r.returncode, 0, r.stderr)
        for word in ("rollviz", "VTK", "Eigen", "libavcodec", "GL_RENDERER", "GL_VERSION", "EGL devices"):
            self.assertIn(word, r.stdout)
        j = json.loads(run("info", "--json").stdout)
        renderer = j["renderer"]
        self.assertEqual(renderer["backend"], "egl")
        self.assertTrue(renderer["renderer"] and renderer["version"][0].isdigit(), renderer)
        software = any(w in renderer["renderer"] for w in ("llvmpipe", "softpipe", "swrast"))
        self.assertEqual(renderer["software"], software)
        # a CPU rasteriser is worth a warning, on stderr (stdout stays the report)
        self.assertEqual("rendering on the CPU" in r.stderr, software, r.stderr)
        o = json.loads(run("info", "--json", exe=RVO).stdout)["renderer"]
        self.assertEqual((o["backend"], o["software"]), ("osmesa", True))

    def test_an_egl_device_is_chosen_by_number_and_a_wrong_one_is_bad_input(self):
        devices = json.loads(run("info", "--json").stdout)["renderer"]["devices"]
        if not devices:
            self.skipTest("this EGL does not enumerate devices")
        last = str(len(devices) - 1)
        j = json.loads(run("info", "--json", env={"ROLLVIZ_EGL_DEVICE": last}).stdout)["renderer"]
        self.assertEqual(j["context"], "EGL device " + devices[-1])
        out = self.path("d.png")
        r = run("render", SCENE, "-o", out, "--size", "160x120", env={"ROLLVIZ_EGL_DEVICE": last})
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(varied(pixels(out)[1]))
        for wrong in (str(len(devices)), "gpu"):
            r = run("render", SCENE, "-o", self.path("w.png"), env={"ROLLVIZ_EGL_DEVICE": wrong})
            self.assertBadInput(r, "ROLLVIZ_EGL_DEVICE=" + wrong)
            self.assertFalse(os.path.exists(self.path("w.png")))

    def test_without_egl_the_command_goes_to_rollviz_osmesa(self):
        # no EGL vendor library (GLVND finds none): what a machine without Mesa's EGL or a GPU driver looks like
        noegl = {"__EGL_VENDOR_LIBRARY_FILENAMES": os.path.join(self.dir, "none.json")}
        out = self.path("o.png")
        r = run("render", SCENE, "-o", out, "--size", "160x120", env=noegl)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("rollviz-osmesa instead", r.stderr)
        self.assertTrue(varied(pixels(out)[1]))
        j = json.loads(run("info", "--json", env=noegl).stdout)["renderer"]
        self.assertEqual(j["backend"], "osmesa")
        self.assertIn("no EGL context", j["egl_unavailable"])


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v", *sys.argv[4:]])
