#!/usr/bin/env python3
"""The example module (examples/module) built out of the tree against an installed SDK, and used from every
front end: the CLI (its problem, tool and integrator), Python, a sweep, mpirun, a chart; the loader's refusals
(a broken file, a wrong stamp, an id taken twice). Known answers: the Roessler spectrum (Sprott 2003) and its
sum against the time average of the divergence, dopri5's order and its agreement with verner9, return times of
a linear centre equal to its period 2 pi.
Usage: module_test.py ROLLVIZ BUILD_DIR SRC"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

RV, BUILD, SRC = sys.argv[1], sys.argv[2], sys.argv[3]
ROSSLER = os.path.join(SRC, "examples", "module", "rossler.json")
HH = os.path.join(SRC, "scenes", "henon_heiles.json")
TMP = tempfile.mkdtemp(prefix="rollviz-module-test-")
MODULE = None  # the built example module


def sh(*args, **kw):
    r = subprocess.run(list(args), capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed ({r.returncode}):\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}")
    return r


def env(**extra):
    e = dict(os.environ)
    e.pop("DISPLAY", None)
    e["HOME"] = os.path.join(TMP, "home")  # no modules of the user's
    e["ROLLVIZ_MODULE_PATH"] = os.path.dirname(MODULE)
    e.update(extra)
    return e


def run(*args, timeout=600, **extra):
    return subprocess.run([RV, *args], capture_output=True, text=True, env=env(**extra), timeout=timeout)


def build_module(source, name):
    """cmake configure + build of a module source folder against the installed SDK; the path of its .so."""
    out = os.path.join(TMP, name)
    sh("cmake", "-S", source, "-B", out, f"-DCMAKE_PREFIX_PATH={TMP}/prefix")  # as a user would: the defaults
    sh("cmake", "--build", out, "-j2")
    found = [os.path.join(out, f) for f in os.listdir(out) if f.endswith(".so")]
    assert len(found) == 1, found
    return found[0]


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0] if k != "status"}


class Module(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        global MODULE
        os.makedirs(os.path.join(TMP, "home"))
        sh("cmake", "--install", BUILD, "--prefix", os.path.join(TMP, "prefix"))
        MODULE = build_module(os.path.join(SRC, "examples", "module"), "example")

    def ok(self, *args, **extra):
        r = run(*args, **extra)
        self.assertEqual(r.returncode, 0, f"{args}: {r.stderr}")
        return r

    def test_the_sdk_is_installed_without_debug_info(self):
        # a dev build's librollviz_dynamics.so carries ~350 MB of it (cmake/Sdk.cmake strips it on install)
        for name in ("librollviz_dynamics.so", "librollviz_render.so", "librollviz_scenes.so"):
            found = [os.path.join(d, name) for d, _, files in os.walk(os.path.join(TMP, "prefix")) if name in files]
            self.assertEqual(len(found), 1, name)
            with open(found[0], "rb") as f:
                self.assertNotIn(b".debug_info", f.read(), f"{found[0]} keeps its debug info")

    def test_every_list_and_info_names_what_it_added(self):
        self.assertIn("rossler", self.ok("list", "problems").stdout.split())
        self.assertIn("return_times", self.ok("list", "tools").stdout)
        self.assertIn("dopri5", self.ok("list", "integrators").stdout)
        self.assertIn("return_times.mean", self.ok("list", "quantities").stdout)
        info = self.ok("info", "--json")
        modules = json.loads(info.stdout)["modules"]
        self.assertEqual(len(modules), 1, modules)
        self.assertIn(os.path.basename(MODULE), modules[0])
        self.assertIn("problems: rossler", modules[0])
        self.assertIn("tools: return_times", modules[0])
        self.assertIn("integrators: dopri5", modules[0])
        d = self.ok("describe-tool", "return_times").stdout
        for word in ("mean", "std", "points", "bins", "return-times"):
            self.assertIn(word, d)

    def test_rossler_spectrum_and_its_sum(self):
        # Sprott (2003): (0.0714, 0, -5.39); the sum is the time average of the trace a + x - c on the same orbit
        r = json.loads(self.ok("lyapunov", ROSSLER, "--time", "5000", "--json").stdout)
        e = sorted(r["exponents"], reverse=True)
        self.assertAlmostEqual(e[0], 0.0714, delta=0.01)
        self.assertAlmostEqual(e[1], 0.0, delta=0.01)
        self.assertAlmostEqual(e[2], -5.39, delta=0.05)
        # the same orbit: at a fixed RK4 step the tangent vectors do not change the steps (an adaptive method's
        # error control sees them, and on a chaotic orbit another step sequence is another orbit after t ~ 300)
        rk4 = ("--set", "integrator.method=rk4", "--set", "integrator.step=0.005")
        r = json.loads(self.ok("lyapunov", ROSSLER, *rk4, "--time", "5000", "--json").stdout)
        out = os.path.join(TMP, "div.csv")
        self.ok("integrate", ROSSLER, *rk4, "--time", "5000", "--every", "0.005", "--columns", "t,divergence",
                "-o", out)
        c = read_csv(out)
        t, d = c["t"], c["divergence"]
        mean = sum(0.5 * (d[i] + d[i + 1]) * (t[i + 1] - t[i]) for i in range(len(t) - 1)) / t[-1]
        self.assertAlmostEqual(r["sum"], mean, delta=1e-5 * abs(mean))  # the trapezoidal rule's error: ~1e-7

    def test_dopri5_agrees_with_verner9_and_has_order_5(self):
        def final(method, **settings):
            out = os.path.join(TMP, f"{method}-{len(os.listdir(TMP))}.csv")
            sets = [a for k, v in settings.items() for a in ("--set", f"integrator.{k}={v}")]
            self.ok("integrate", ROSSLER, "--set", f"integrator.method={method}", *sets, "--time", "10", "--every",
                    "1", "--columns", "t,x,y,z", "-o", out)
            c = read_csv(out)
            self.assertEqual(len(c["t"]), 11)
            return c
        ref = final("verner9", tolerance=1e-14)
        adaptive = final("dopri5", tolerance=1e-10)
        gap = max(abs(a - b) for k in "xyz" for a, b in zip(adaptive[k], ref[k]))
        self.assertLess(gap, 5e-8)
        # at fixed steps h, h/2, h/4 the error at t = 10 falls like h^5
        errors = []
        for h in (0.08, 0.04, 0.02):
            c = final("dopri5", adaptive="no", step=h)
            errors.append(max(abs(c[k][-1] - ref[k][-1]) for k in "xyz"))
        orders = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
        for p in orders:
            self.assertGreater(p, 4.6, (errors, orders))
            self.assertLess(p, 5.6, (errors, orders))

    def test_return_times_of_a_linear_centre_are_its_period(self):
        # Henon-Heiles near its minimum: x oscillates with omega = 1, so the section x = 0 returns after 2 pi
        r = self.ok("return-times", HH, "--set", "energy=1e-6", "--set", "initial.map=[0.0005,0.0005]",
                    "--points", "40", "--json")
        j = json.loads(r.stdout)
        self.assertEqual(j["count"], 40)
        self.assertAlmostEqual(j["mean"], 2 * math.pi, delta=1e-5)
        self.assertLess(j["max"] - j["min"], 1e-4)
        self.assertLessEqual(j["min"], j["mean"])
        # the table as CSV: the histogram holds every return time
        out = os.path.join(TMP, "hist.csv")
        self.ok("return-times", ROSSLER, "--points", "300", "--bins", "12", "-o", out)
        h = read_csv(out)
        self.assertEqual(len(h["time"]), 12)
        self.assertEqual(sum(h["frequency"]), 300)
        # a setting out of its range names the flag's key
        bad = run("return-times", ROSSLER, "--points", "0")
        self.assertEqual(bad.returncode, 2, bad.stderr)
        self.assertIn("points", bad.stderr)

    def test_python(self):
        pyenv = {"PYTHONPATH": os.path.join(BUILD, "python")}
        code = ("import rollviz, json\n"
                f"s = rollviz.Scene.load({ROSSLER!r})\n"
                "r = s.return_times(points=100)\n"
                "assert int(r['count']) == 100 and 5 < r.mean < 7, r\n"
                "assert len(r['frequency']) == 30 and sum(r['frequency']) == 100, r\n"
                "assert 'rossler' in [p['id'] for p in rollviz.problems()]\n"
                "assert any(t['id'] == 'return_times' and 'return_times.mean' in t['sweep_quantities']\n"
                "           for t in rollviz.tools())\n"
                "assert rollviz.modules()[0]['tools'] == ['return_times']\n"
                "assert 'points' in rollviz.Scene.return_times.__doc__\n"
                "print(json.dumps({'mean': r.mean}))\n")
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env(**pyenv))
        self.assertEqual(r.returncode, 0, r.stderr)
        # the CLI computes the same number
        cli = json.loads(self.ok("return-times", ROSSLER, "--points", "100", "--json").stdout)
        self.assertEqual(json.loads(r.stdout)["mean"], cli["mean"])

    def test_sweep_on_threads_and_ranks(self):
        spec = os.path.join(TMP, "s.json")
        with open(spec, "w") as f:
            json.dump({"scene": ROSSLER, "axes": [{"id": "c", "min": 4, "max": 6, "count": 3}],
                       "quantity": "return_times.mean", "set": {"return_times.points": 50}}, f)
        a, b = os.path.join(TMP, "s1.csv"), os.path.join(TMP, "s2.csv")
        self.ok("sweep", spec, "-o", a, "--threads", "2")
        with open(a) as f:
            self.assertEqual([r["status"] for r in csv.DictReader(f)], ["ok"] * 3)
        c = read_csv(a)
        self.assertEqual(len(c["c"]), 3)
        for m in c["return_times.mean"]:
            self.assertTrue(5 < m < 7, c)
        if shutil.which("mpirun"):
            r = subprocess.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", "2", "-x",
                                "ROLLVIZ_MODULE_PATH", "-x", "HOME", RV, "sweep", spec, "-o", b],
                               capture_output=True, text=True, env=env(), timeout=600)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(a) as fa, open(b) as fb:
                self.assertEqual(fa.read(), fb.read())

    def test_every_tool_with_a_runner_in_every_front_end(self):
        # the registry's tools that run through scenes/ToolRunner.h: each declared output comes out of the CLI
        # (--json fields or -o columns), out of Python, and the chart view draws
        pyenv = {"PYTHONPATH": os.path.join(BUILD, "python")}
        listing = subprocess.run([sys.executable, "-c", "import rollviz, json; print(json.dumps([t.as_dict() for t in rollviz.tools()]))"],
                                 capture_output=True, text=True, env=env(**pyenv))
        self.assertEqual(listing.returncode, 0, listing.stderr)
        tools = [t for t in json.loads(listing.stdout) if t["runner"]]
        self.assertIn("return_times", [t["id"] for t in tools])
        for t in tools:
            with self.subTest(tool=t["id"]):
                # on its example scene when it ships one (scenes/tools/ID.json), else on the Rossler scene
                example = os.path.join(SRC, "scenes", "tools", t["id"] + ".json")
                scene = example if os.path.exists(example) else ROSSLER
                names = [o[0] for o in t["outputs"] if not o[0].startswith("<")]  # <...>: named by the scene
                fields = json.loads(self.ok(t["command"], scene, "--json").stdout)
                table = os.path.join(TMP, t["id"] + ".csv")
                self.ok(t["command"], scene, "-o", table)
                with open(table) as f:
                    columns = f.readline().strip().split(",")
                for n in names:
                    self.assertTrue(n in fields or n in columns, (t["id"], n, fields, columns))
                # a field is a key of the result; a column too, or one of the Table the runner names (history)
                code = (f"import rollviz\nr = rollviz.Scene.load({scene!r}).{t['id']}()\n"
                        f"table = r.get({t['table']!r}, ()) if {t['table']!r} else ()\n"
                        f"missing = [n for n in {names!r} if n not in r and n not in table]\n"
                        f"assert not missing, missing\n")
                r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env(**pyenv))
                self.assertEqual(r.returncode, 0, r.stderr)
                if t["chart"]:  # the fixed point, separatrices and the tree are drawn on the map (GUI)
                    png = os.path.join(TMP, t["id"] + ".png")
                    self.ok("chart", scene, "--view", t["chart"], "-o", png)
                    self.assertGreater(os.path.getsize(png), 1000)
                for output, q in t["output_quantities"].items():  # each output a sweep can chart is one
                    self.assertIn(output, names)
                    self.assertIn(q, t["sweep_quantities"])

    def test_chart_view_of_the_tool(self):
        out = os.path.join(TMP, "rt.png")
        self.ok("chart", ROSSLER, "--view", "return_times", "-o", out, "--set", "return_times.points=200")
        from PIL import Image
        img = Image.open(out).convert("RGB")
        colours = img.getcolors(1 << 20)
        self.assertGreater(len(colours), 20)  # not blank: axes, text and the curve

    def test_refusals(self):
        broken = os.path.join(TMP, "broken")
        os.makedirs(broken, exist_ok=True)
        with open(os.path.join(broken, "libbroken.so"), "w") as f:
            f.write("not a library\n")
        # in the search path: skipped with a warning naming it, the rest works (the example still loads)
        r = run("list", "problems", ROLLVIZ_MODULE_PATH=broken + ":" + os.path.dirname(MODULE))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("libbroken.so", r.stderr)
        self.assertIn("rossler", r.stdout.split())
        self.assertIn("chaplygin_ball", r.stdout.split())
        # named with --module: bad input
        r = run("--module", os.path.join(broken, "libbroken.so"), "list", "problems")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("libbroken.so", r.stderr)
        r = run("--module", os.path.join(broken, "missing.so"), "list", "problems")
        self.assertEqual(r.returncode, 2, r.stderr)
        # another stamp: refused with both stamps, its entry point never runs
        wrong = build_module(os.path.join(SRC, "tests", "modules", "wrong_stamp"), "wrong")
        r = run("--module", wrong, "list", "problems")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("another rollviz or compiler ABI", r.stderr)
        self.assertIn("rollviz 0.0.0", r.stderr)
        self.assertNotIn("entry point", r.stderr.replace("no ROLLVIZ_MODULE entry point", ""))
        # the same ids twice: the second file is refused, naming both files
        twin = os.path.join(TMP, "twin")
        os.makedirs(twin, exist_ok=True)
        shutil.copy(MODULE, os.path.join(twin, "libtwin.so"))
        r = run("--module", os.path.join(twin, "libtwin.so"), "list", "problems")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("libtwin.so", r.stderr)
        self.assertIn(os.path.basename(MODULE), r.stderr)
        r = run("list", "tools", ROLLVIZ_MODULE_PATH=os.path.dirname(MODULE) + ":" + twin)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("libtwin.so", r.stderr)
        self.assertIn("already registered by", r.stderr)
        self.assertEqual(r.stdout.count("return_times"), 1)


if __name__ == "__main__":
    try:
        unittest.main(argv=[sys.argv[0]], verbosity=2)
    finally:
        shutil.rmtree(TMP, ignore_errors=True)
