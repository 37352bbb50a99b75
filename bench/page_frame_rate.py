#!/usr/bin/env python3
"""The preview page's frame rate in headless Chromium: how many pictures per second its 3D view
draws while the page plays (software WebGL: no GPU), and how long the page takes to be ready.

usage: page_frame_rate.py FAPC INPUT [SIZE] [SECONDS]
  e.g. bench/page_frame_rate.py build/bin/fapc corpus/examples/mimic/figure3.mimic 640x480 5

Writes the page with --view 3d and with --view both into a temporary folder, plays each (muted)
for SECONDS and prints one line per page: the file's size, the time to ready, the 3D view's draws
per second and the browser's animation frames per second over the same time. The 3D view draws
once per animation frame while playing, so the two agree unless drawing falls behind.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "face"))
from browser_screenshot import Chromium  # noqa: E402  (the tests' driver of headless Chromium)

# Counts the browser's animation frames from now on, in window.benchFrames.
COUNT_FRAMES = ("window.benchFrames = 0; (function count() { window.benchFrames++; "
                "requestAnimationFrame(count); })(); true")


def measure(page, width, height, seconds):
    browser = Chromium("chromium", width * 2, height, ["--autoplay-policy=no-user-gesture-required"])
    try:
        begun = time.time()
        deadline = begun + 120
        browser.open("file://" + page, deadline)
        browser.wait_ready(deadline)
        ready = time.time() - begun
        browser.evaluate("document.getElementById('face').muted = true; "
                         "document.getElementById('face').play().then(() => true)", deadline, gesture=True)
        browser.evaluate(COUNT_FRAMES, deadline)
        draws0 = browser.evaluate("window.fapcHead3d.draws()", deadline)
        start = time.time()
        time.sleep(seconds)
        draws1, frames = browser.evaluate("[window.fapcHead3d.draws(), window.benchFrames]", deadline)
        elapsed = time.time() - start
        return ready, (draws1 - draws0) / elapsed, frames / elapsed
    finally:
        browser.close()


def main():
    fapc, source = sys.argv[1], sys.argv[2]
    size = sys.argv[3] if len(sys.argv) > 3 else "640x480"
    seconds = float(sys.argv[4]) if len(sys.argv) > 4 else 5.0
    width, height = (int(v) for v in size.split("x"))
    folder = tempfile.mkdtemp(prefix="fapc-page-bench-")
    try:
        print("page frame rate: %s at %s, played %.0f s in headless Chromium (software WebGL)"
              % (os.path.basename(source), size, seconds))
        for view in ("3d", "both"):
            page = os.path.join(folder, "page-%s.html" % view)
            subprocess.run([fapc, "render", source, "-o", page, "--view", view, "--size", size], check=True)
            ready, draws, frames = measure(page, width, height, seconds)
            print("  --view %-4s  %6.2f MB  ready in %5.2f s  3D view %5.1f draws/s  browser %5.1f frames/s"
                  % (view, os.path.getsize(page) / 1e6, ready, draws, frames))
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
