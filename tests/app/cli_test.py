#!/usr/bin/env python3
"""End-to-end tests of the `rollviz` command line (design.md "Command line"): outputs, exit statuses,
messages that name the culprit, and no file left behind on failure. Usage: cli_test.py ROLLVIZ ROLLVIZ_OSMESA SRC"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

RV, RVO, SRC = sys.argv[1], sys.argv[2], sys.argv[3]
SCENE = os.path.join(SRC, "scenes", "chaplygin_ball.json")


def run(*args, exe=None, env=None):
    e = dict(os.environ)
    e.pop("DISPLAY", None)
    if env:
        e.update(env)
    return subprocess.run([exe or RV, *args], capture_output=True, text=True, env=e, timeout=300)


def pixels(path):
    from PIL import Image
    img = Image.open(path).convert("RGB")
    return img.size, list(img.getdata())


def varied(px):
    n = len(px)
    mean = sum(sum(p) for p in px) / (3 * n)
    var = sum((c - mean) ** 2 for p in px for c in p) / (3 * n)
    return var ** 0.5 > 5 and len(set(px)) > 50


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

    def test_poincare_chart(self):
        out = self.path("c.png")
        r = run("chart", SCENE, "--view", "poincare", "-o", out, "--points", "300", "--size", "400x400")
        self.assertEqual(r.returncode, 0, r.stderr)
        size, px = pixels(out)
        self.assertEqual(size, (400, 400))
        # white background, axes, blue points: mostly white but with a real number of blue-ish pixels
        blue = sum(1 for p in px if p[2] > 150 and p[0] < 100)
        self.assertGreater(blue, 300)
        self.assertBadInput(run("chart", SCENE, "--view", "nope", "-o", self.path("n.png")), "--view nope")
        self.assertFalse(os.path.exists(self.path("n.png")))

    def test_gui_without_a_display_says_so(self):
        r = run("gui", SCENE, env={"WAYLAND_DISPLAY": ""})
        if "WAYLAND_DISPLAY" in os.environ:
            return
        self.assertEqual(r.returncode, 1)
        self.assertIn("no display", r.stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
