"""`rollviz page` in a real browser (issue 63): headless Chromium through Selenium (Debian's chromium,
chromium-driver and python3-selenium, installed by scripts/deps.sh test), on its WebGL path (SwiftShader) and on
the 2D-canvas fallback a browser without WebGL gets. Every wait is for a condition, with a generous deadline.

Run: ROLLVIZ_EXE=build/dev/app/rollviz ROLLVIZ_SOURCE_DIR=. python3 -m pytest -q tests/app/test_page.py
"""
import io
import json
import math
import os
import re
import subprocess
import tempfile
import time

import numpy as np
import pytest
from PIL import Image

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.common.action_chains import ActionChains

EXE = os.environ.get("ROLLVIZ_EXE", "build/dev/app/rollviz")
SRC = os.environ.get("ROLLVIZ_SOURCE_DIR", ".")
RATTLEBACK = os.path.join(SRC, "scenes", "gallery", "rattleback_reversal.json")
DEADLINE = 60  # seconds: a condition not met by then fails


def rollviz(*args):
    return subprocess.run([EXE, *args], capture_output=True, text=True, timeout=600)


@pytest.fixture(scope="module")
def tmp():
    with tempfile.TemporaryDirectory() as d:
        yield d


@pytest.fixture(scope="module")
def rattleback_page(tmp):
    path = os.path.join(tmp, "rattleback.html")
    r = rollviz("page", RATTLEBACK, "-o", path, "--duration", "4")
    assert r.returncode == 0, r.stderr
    return path


def browser(webgl):
    o = Options()
    flags = ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1024,768",
             "--host-resolver-rules=MAP * ~NOTFOUND"]
    # SwiftShader's WebGL must be asked for by name; without it the browser has no WebGL at all
    flags += ["--use-angle=swiftshader", "--enable-unsafe-swiftshader"] if webgl else ["--disable-webgl"]
    for f in flags:
        o.add_argument(f)
    o.set_capability("goog:loggingPrefs", {"performance": "ALL", "browser": "ALL"})
    return webdriver.Chrome(options=o)


@pytest.fixture(scope="module", params=["webgl", "canvas2d"])
def driver(request):
    d = browser(request.param == "webgl")
    d.mode = request.param
    yield d
    d.quit()


def wait_for(condition, what):
    end = time.time() + DEADLINE
    while time.time() < end:
        value = condition()
        if value is not None and value is not False:
            return value
        time.sleep(0.1)
    raise AssertionError(f"not within {DEADLINE} s: {what}")


def shot(d):
    return np.asarray(Image.open(io.BytesIO(d.get_screenshot_as_png())).convert("RGB")).astype(float)


def view_pixels(d):
    """The 3D view's part of the screenshot."""
    r = d.execute_script("const b = document.getElementById('view').getBoundingClientRect();"
                         "return [b.left, b.top, b.width, b.height].map(Math.round);")
    x, y, w, h = r
    return shot(d)[y:y + h, x:x + w]


def open_page(d, path):
    d.get("file://" + path)
    wait_for(lambda: d.execute_script("return !!window.rollviz"), "the page's viewer starts")
    assert d.execute_script("return window.rollviz.webgl") == (d.mode == "webgl")


def animation_frames(d, n):
    """Waits until the browser has run n animation frames (the page's loop has had n chances to draw)."""
    d.execute_async_script("const done = arguments[0]; let k = %d;"
                           "const f = () => (--k > 0 ? requestAnimationFrame(f) : done());"
                           "requestAnimationFrame(f);" % n)


def severe_errors(d):
    return [e for e in d.get_log("browser") if e.get("level") == "SEVERE"]


def test_it_plays_pauses_and_turns(driver, rattleback_page):
    d = driver
    open_page(d, rattleback_page)
    first = wait_for(lambda: (lambda a: a if a.std() > 5 and len(np.unique(a.reshape(-1, 3), axis=0)) > 50 else None)(
        view_pixels(d)), "the view is not blank")
    # playing: the frame advances and the picture changes
    f0 = d.execute_script("return rollviz.frame()")
    wait_for(lambda: d.execute_script("return rollviz.frame()") != f0, "the motion plays")
    wait_for(lambda: np.abs(view_pixels(d) - first).mean() > 0.05, "the picture changes while playing")
    # paused: nothing changes however long the page runs
    d.find_element("id", "play").click()
    assert not d.execute_script("return rollviz.playing()")
    frame = d.execute_script("return rollviz.frame()")
    animation_frames(d, 3)
    still = view_pixels(d)
    animation_frames(d, 30)
    assert d.execute_script("return rollviz.frame()") == frame
    assert np.abs(view_pixels(d) - still).mean() == 0, "the picture changed while paused"
    # a drag turns the camera (the motion stays paused)
    canvas = d.find_element("css selector", "#view canvas")
    ActionChains(d).move_to_element(canvas).click_and_hold().move_by_offset(150, 40).release().perform()
    wait_for(lambda: np.abs(view_pixels(d) - still).mean() > 0.05, "a drag turns the view")
    assert d.execute_script("return rollviz.frame()") == frame
    # Reset view brings the scene's camera back: the paused picture again
    d.find_element("id", "reset").click()
    wait_for(lambda: np.abs(view_pixels(d) - still).mean() < 0.01, "Reset view restores the scene's camera")
    # and it plays on when asked
    d.find_element("id", "play").click()
    wait_for(lambda: d.execute_script("return rollviz.frame()") != frame, "it plays again")
    assert not severe_errors(d)


def test_the_slider_shows_the_state_at_its_time(driver, rattleback_page):
    d = driver
    open_page(d, rattleback_page)
    d.find_element("id", "play").click()  # paused: the slider alone moves it
    data = d.execute_script("const D = rollviz.data; return [D.fps, D.speed, rollviz.frames];")
    fps, speed, frames = data
    assert frames == 4 * fps + 1
    k = 3 * frames // 4
    # the slider's own event, as a user's drag of it ends
    d.execute_script("const s = document.getElementById('slider'); s.value = arguments[0];"
                     "s.dispatchEvent(new Event('input'));", k)
    wait_for(lambda: d.execute_script("return rollviz.frame()") == k, "the slider sets the frame")
    t = d.execute_script("return rollviz.time()")
    assert t == pytest.approx(k * speed / fps, abs=1e-12)
    assert d.find_element("id", "time").text == f"t = {t:.3f}"
    state = d.execute_script("return rollviz.state()")
    names = d.execute_script("return rollviz.data.variables")
    # the CLI's state at the same time (rows at multiples of speed / fps)
    r = rollviz("integrate", RATTLEBACK, "--time", repr(t + 1e-9), "--every", repr(speed / fps))
    assert r.returncode == 0, r.stderr
    rows = [line.split(",") for line in r.stdout.splitlines()]
    header, row = rows[0], [float(v) for v in rows[k + 1]]
    assert row[0] == pytest.approx(t, abs=1e-12)
    for name, value in zip(names, state):
        assert value == pytest.approx(row[header.index(name)], abs=1e-9), name
    # the body is drawn in that pose: its matrix takes the body's frame to the world's, and the world's vertical
    # in the body's frame is gamma (the matrix's third row), in float precision
    m = d.execute_script("return rollviz.matrix('body#1')")  # the body's surface (body: its shadow)
    gamma = [state[names.index(g)] for g in ("gamma1", "gamma2", "gamma3")]
    third_row = [m[2], m[6], m[10]]
    assert third_row == pytest.approx(gamma, abs=2e-6)
    # the support's trace shown ends at the contact point at that time: (x, y) is the centre of mass, and the
    # contact seen from it is the ellipsoid's Gauss map r = -B^2 gamma / sqrt(gamma B^2 gamma) - a (semi-axes
    # b, centre of mass a from the geometric centre), turned into the plane by the rows alpha and beta
    with open(RATTLEBACK) as f:
        p = json.load(f)["parameters"]
    b2 = [p["b1"] ** 2, p["b2"] ** 2, p["b3"] ** 2]
    norm = math.sqrt(sum(b2[i] * gamma[i] ** 2 for i in range(3)))
    r = [-b2[i] * gamma[i] / norm - p["a" + str(i + 1)] for i in range(3)]
    alpha = [state[names.index(g)] for g in ("alpha1", "alpha2", "alpha3")]
    beta = [state[names.index(g)] for g in ("beta1", "beta2", "beta3")]
    contact = (state[names.index("x")] + sum(alpha[i] * r[i] for i in range(3)),
               state[names.index("y")] + sum(beta[i] * r[i] for i in range(3)))
    trace = d.execute_script("return rollviz.shown('trace')")
    assert trace and len(trace) >= 6
    assert trace[-3:-1] == pytest.approx(contact, abs=1e-5)
    assert not severe_errors(d)


def test_the_page_makes_no_request(driver, rattleback_page):
    d = driver
    d.get_log("performance")  # drop what came before
    open_page(d, rattleback_page)
    animation_frames(d, 10)
    urls = []
    for entry in d.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            urls.append(message["params"]["request"]["url"])
    assert urls, "the performance log records the page's own load"
    outside = [u for u in urls if not (u.startswith("file://") or u.startswith("data:"))]
    assert not outside, outside
    html = open(rattleback_page, encoding="utf-8").read()
    assert not re.search(r"<(script|link|img|iframe)[^>]+(src|href)=", html, re.I)


def test_a_sessions_page_holds_its_map(driver, tmp):
    with open(os.path.join(SRC, "scenes", "henon_heiles.json")) as f:
        hh = json.load(f)
    ring = [(0.2 + 0.05 * math.cos(k / 10), 0.05 * math.sin(k / 10)) for k in range(63)]
    session = {"rollviz_session": 1, "scene": hh, "scene_path": "", "results": "", "tools": [],
               "trajectories": [{"start": [0, 0.1, 0.1, 0.3], "parameters": {}, "integrator": {},
                                 "colour": [0.9, 0.1, 0.1], "x": [p[0] for p in ring], "y": [p[1] for p in ring],
                                 "z": [], "state": [], "running": False, "first": 1, "last": 0, "origin": ""}]}
    path, page = os.path.join(tmp, "s.json"), os.path.join(tmp, "s.html")
    with open(path, "w") as f:
        json.dump(session, f)
    r = rollviz("page", path, "-o", page, "--duration", "2")
    assert r.returncode == 0, r.stderr
    d = driver
    open_page(d, page)
    m = d.execute_script("return rollviz.data.map")
    assert [m["x"], m["y"]] == ["y", "py"] and len(m["series"]) == 1
    box = d.find_element("id", "map")
    assert box.is_displayed()
    mapcanvas = box.find_element("tag name", "canvas")
    wait_for(lambda: d.execute_script(
        "const c = arguments[0], g = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;"
        "let red = 0; for (let i = 0; i < g.length; i += 4) red += g[i] > 180 && g[i + 1] < 80 && g[i + 2] < 80;"
        "return red > 50;", mapcanvas), "the map draws its trajectory's points in its colour")
    # the wheel zooms the map in about the pointer
    before = d.execute_script("return rollviz.mapRange()")
    assert before[0] <= 0.15 and before[1] >= 0.25 and before[2] <= -0.05 and before[3] >= 0.05
    d.execute_script("arguments[0].dispatchEvent(new WheelEvent('wheel', {deltaY: -400, clientX: "
                     "arguments[0].getBoundingClientRect().left + 200, clientY: "
                     "arguments[0].getBoundingClientRect().top + 200, bubbles: true, cancelable: true}))", mapcanvas)
    after = d.execute_script("return rollviz.mapRange()")
    assert after[1] - after[0] < 0.8 * (before[1] - before[0])
    assert after[3] - after[2] < 0.8 * (before[3] - before[2])
    # with --set the saved map would not be the motion's: refused
    r = rollviz("page", path, "-o", os.path.join(tmp, "t.html"), "--set", "energy=0.1")
    assert r.returncode == 2 and "--set" in r.stderr
    assert not severe_errors(d)


def test_bad_input_is_refused_and_writes_nothing(tmp):
    for args, named in ((["-o", os.path.join(tmp, "m.png")], "-o"),
                        (["-o", os.path.join(tmp, "m.html"), "--fps", "0"], "--fps"),
                        (["-o", os.path.join(tmp, "m.html"), "--duration", "-1"], "--duration"),
                        (["-o", os.path.join(tmp, "m.html"), "--speed", "0"], "--speed")):
        r = rollviz("page", RATTLEBACK, *args)
        assert r.returncode == 2, (args, r.stderr)
        assert named in r.stderr, (args, r.stderr)
    assert not [f for f in os.listdir(tmp) if f.startswith("m.")]
