#!/usr/bin/python3
"""End-to-end test of the live browser view (python3 -m cosserat.view) in headless Chromium
(Debian's chromium, chromium-driver and python3-selenium; scripts/install-deps.sh --test).

  test_live_view.py [--screenshot PNG]     (PYTHONPATH: the built package; web/ npm-installed)

On the default problem (examples/cantilever.json, stepped in real time):
  - the page draws the rod (a WebGL canvas, frames counted by the page) and shows the status and
    the real-time ratio;
  - the server publishes at least 60 frames of simulated state per second (95 % of 60 over 3 s,
    allowing for the scheduler) at a real-time ratio within 10 % of 1;
  - moving the tip-force slider from −0.2 N to +1.5 N moves the tip the server reports across to
    +x (the wire's tip deflection at +1.5 N is P L³/(3EI) ≈ 0.4 m in beam theory: the reported
    x must exceed +0.05 m within 3 s), and the page measures the slider-to-frame latency;
  - dragging the tip with the mouse moves it (over 1 cm for a 150 px drag);
  - a value past a slider's limit gets a message on the page, and the page keeps drawing.
With a malformed problem file the page shows the error naming the field, and Ctrl-C ends it
cleanly; a port in use or a web/ without three.js is refused at start (exit 1, a message).
"""
import argparse
import json
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request

import numpy as np

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(problem):
    port = free_port()
    proc = subprocess.Popen([sys.executable, "-m", "cosserat.view", problem, "--port", str(port)],
                            cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            # Ctrl-C reaches it as at a terminal (a shell's background job
                            # would have it ignored)
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    url = f"http://127.0.0.1:{port}/"
    for _ in range(100):
        try:
            urllib.request.urlopen(url + "config", timeout=1).read()
            return proc, url
        except OSError:
            time.sleep(0.1)
    proc.kill()
    sys.exit(f"the server did not start: {proc.stdout.read()}")


def state(url):
    return json.loads(urllib.request.urlopen(url + "state", timeout=2).read())


def browser():
    opts = Options()
    opts.binary_location = "/usr/bin/chromium"
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader", "--window-size=1200,800"):
        opts.add_argument(arg)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)


def wait_for(what, check, timeout=10.0):
    end = time.time() + timeout
    while time.time() < end:
        value = check()
        if value:
            return value
        time.sleep(0.1)
    raise AssertionError(f"timed out waiting for {what}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--screenshot")
    args = ap.parse_args()
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what, flush=True)
        if not ok:
            failures.append(what)

    driver = browser()
    server, url = start_server("examples/cantilever.json")
    try:
        driver.get(url)
        body = driver.find_element(By.TAG_NAME, "body")
        drawn = lambda: int(body.get_attribute("data-frames-drawn") or 0)  # noqa: E731
        wait_for("the page to draw frames", lambda: drawn() > 20)
        check(len(driver.find_elements(By.CSS_SELECTOR, "#scene canvas")) == 1, "a canvas is drawn")
        check(body.get_attribute("data-status") == "running", "the page shows the status running")
        readout = driver.find_element(By.ID, "readout").text
        check("real time" in readout and "×" in readout, f"the real-time ratio is shown: {readout!r}")

        s0, t0 = state(url), time.time()
        time.sleep(3.0)
        s1, t1 = state(url), time.time()
        rate = (s1["frame"] - s0["frame"]) / (t1 - t0)
        check(rate >= 0.95 * 60, f"the server publishes {rate:.1f} frames of state per second")
        ratio = s1["real_time_ratio"]
        check(ratio is not None and abs(ratio - 1) < 0.1, f"real-time ratio {ratio}")

        x_before = s1["tip"][0]
        driver.execute_script(
            "const s = document.getElementById('control-tip_force_x');"
            "s.value = 1.5; s.dispatchEvent(new Event('input'));")
        wait_for("the tip to cross to +x", lambda: state(url)["tip"][0] > 0.05, timeout=3.0)
        x_after = state(url)["tip"][0]
        check(x_after > 0.05 > x_before, f"the slider moved the tip from x = {x_before:.4f} to {x_after:.4f} m")
        latency = wait_for("the page's latency", lambda: body.get_attribute("data-latency-ms"))
        print(f"slider to drawn frame: {latency} ms", flush=True)
        fps = body.get_attribute("data-fps")
        print(f"page draws {fps} frames per second (headless Chromium, software WebGL)", flush=True)

        # Dragging the tip with the mouse pulls it (a spring toward the pointer): 150 px to the
        # left of where it is drawn must move the tip the server reports by over 1 cm.
        tip_screen = driver.execute_script("return window.cosseratTipOnScreen();")
        before = np.asarray(state(url)["tip"])
        canvas = driver.find_element(By.CSS_SELECTOR, "#scene canvas")
        rect = driver.execute_script("return arguments[0].getBoundingClientRect();", canvas)
        dx = tip_screen["x"] - (rect["left"] + rect["width"] / 2)
        dy = tip_screen["y"] - (rect["top"] + rect["height"] / 2)
        actions = ActionChains(driver)
        actions.move_to_element_with_offset(canvas, int(dx), int(dy)).click_and_hold()
        actions.move_by_offset(-75, 0).move_by_offset(-75, 0).pause(1.5).perform()
        moved = np.linalg.norm(np.asarray(state(url)["tip"]) - before)
        ActionChains(driver).release().perform()
        check(moved > 0.01, f"dragging the tip moved it by {moved:.4f} m")

        drawn_before = drawn()
        ok = driver.execute_script("return await window.cosseratSetControl('tip_force_x', 1e9);")
        message = driver.find_element(By.ID, "message").text
        check(ok is False and "tip_force_x" in message and "outside" in message,
              f"a value past the limit is refused on the page: {message!r}")
        end = time.time() + 5.0
        while drawn() <= drawn_before + 10 and time.time() < end:
            time.sleep(0.1)
        check(drawn() > drawn_before + 10,
              f"the page keeps drawing after the refusal ({drawn() - drawn_before} frames in 5 s)")
        if args.screenshot:
            driver.execute_script("const s = document.getElementById('control-tip_force_y');"
                                  "s.value = 0.8; s.dispatchEvent(new Event('input'));")
            time.sleep(1.5)
            driver.save_screenshot(args.screenshot)
            print(f"screenshot: {args.screenshot}")
    finally:
        server.kill()

    with tempfile.TemporaryDirectory() as d:
        bad = os.path.join(d, "bad.json")
        with open(bad, "w") as f:
            json.dump({"format": "cosserat-problem/1", "rod": {"length": -1}}, f)
        server, url = start_server(bad)
        try:
            driver.get(url)
            error = wait_for("the error on the page",
                             lambda: driver.find_element(By.ID, "error").text)
            check("rod.length" in error, f"a malformed file's error is on the page: {error[:80]!r}")
            # Ctrl-C on it: a clean exit (it has no simulation thread to stop).
            server.send_signal(signal.SIGINT)
            out = server.communicate(timeout=20)[0]
            check(server.returncode == 0 and "Traceback" not in out,
                  f"Ctrl-C on a view of a bad file exits 0 "
                  f"(got {server.returncode}: {out[-80:]!r})")
        finally:
            server.kill()
            driver.quit()
        # Refusals at start, exit status 1 and a message, never an abort: a port in use (with
        # a quasi-static problem, whose solver thread must be stopped first), and a web/
        # without three.js (the page would stay blank).
        with socket.socket() as taken:
            taken.bind(("127.0.0.1", 0))
            taken.listen()
            port = str(taken.getsockname()[1])
            run = subprocess.run([sys.executable, "-m", "cosserat.view", "examples/stay_cable.json",
                                  "--port", port], cwd=ROOT, capture_output=True, text=True)
        check(run.returncode == 1 and "in use" in run.stderr,
              f"a port in use: exit 1 and a message (got {run.returncode}: {run.stderr[-80:]!r})")
        for name in ("index.html", "app.js"):
            with open(os.path.join(ROOT, "web", name), "rb") as src:
                with open(os.path.join(d, name), "wb") as dst:
                    dst.write(src.read())
        run = subprocess.run([sys.executable, "-m", "cosserat.view", "examples/cantilever.json",
                              "--port", "0"], cwd=ROOT, capture_output=True, text=True,
                             env=dict(os.environ, COSSERAT_WEB_DIR=d))
        check(run.returncode == 1 and "npm ci" in run.stderr,
              f"no three.js: exit 1 naming npm ci (got {run.returncode}: {run.stderr[-80:]!r})")
        # A COSSERAT_WEB_DIR without the page is named, not passed over for another copy.
        run = subprocess.run([sys.executable, "-m", "cosserat.view", "examples/cantilever.json",
                              "--port", "0"], cwd=ROOT, capture_output=True, text=True,
                             env=dict(os.environ, COSSERAT_WEB_DIR=os.path.join(d, "nowhere")))
        check(run.returncode == 1 and "COSSERAT_WEB_DIR" in run.stderr,
              f"a missing web dir: exit 1 naming it (got {run.returncode}: {run.stderr[-80:]!r})")
    print("FAILED: " + "; ".join(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
