#!/usr/bin/env python3
"""Open a page in headless Chromium, wait until it says it is ready, and save a screenshot.

usage: browser_screenshot.py CHROMIUM URL OUT.png X Y WIDTH HEIGHT [EXPRESSION]

Talks to Chromium over --remote-debugging-pipe (the DevTools protocol as NUL-separated JSON on
file descriptors 3 and 4), so it needs nothing beyond Python's standard library and Debian's
chromium: no network, no WebSocket client. The page is ready when its title starts with "ready"
(the fapc preview page sets it once the video has seeked). Prints one JSON line: the page's
title and the body's data-* attributes (the preview page's cursor time and position), and the
value of EXPRESSION (JavaScript, evaluated in the page once it is ready) when one is given.
"""
import base64
import fcntl
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time


class Chromium:
    """A headless Chromium with one page, driven over --remote-debugging-pipe."""

    def __init__(self, chromium, width, height, flags=()):
        to_browser_r, to_browser_w = os.pipe()
        from_browser_r, from_browser_w = os.pipe()
        # Chromium reads commands on fd 3 and writes replies on fd 4; park both ends above 20 first
        # so the dup2 calls in the child cannot clobber each other.
        high_r = fcntl.fcntl(to_browser_r, fcntl.F_DUPFD, 20)
        high_w = fcntl.fcntl(from_browser_w, fcntl.F_DUPFD, 20)
        self.profile = tempfile.mkdtemp(prefix="fapc-chromium-")

        def in_child():
            os.dup2(high_r, 3)
            os.dup2(high_w, 4)

        self.browser = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
             "--no-first-run", "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--user-data-dir=" + self.profile, "--remote-debugging-pipe",
             "--window-size=%d,%d" % (max(1280, width), max(900, height))] + list(flags) + ["about:blank"],
            pass_fds=(3, 4), preexec_fn=in_child,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for fd in (to_browser_r, from_browser_w, high_r, high_w):
            os.close(fd)
        self.to_browser, self.from_browser = to_browser_w, from_browser_r
        self.pending = b""
        self.next_id = 0
        self.session = None

    def send(self, method, params=None, session=None):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        return self.next_id

    def reply(self, request, deadline):
        while time.time() < deadline:
            while b"\0" in self.pending:
                raw, self.pending = self.pending.split(b"\0", 1)
                message = json.loads(raw)
                if message.get("id") == request:
                    if "error" in message:
                        raise SystemExit("chromium: %s" % message["error"])
                    return message["result"]
            chunk = os.read(self.from_browser, 1 << 20)
            if not chunk:
                raise SystemExit("chromium closed the pipe")
            self.pending += chunk
        raise SystemExit("chromium did not answer in time")

    def call(self, method, params, deadline):
        """A command to the page."""
        return self.reply(self.send(method, params, self.session), deadline)

    def open(self, url, deadline):
        target = self.reply(self.send("Target.createTarget", {"url": "about:blank"}), deadline)["targetId"]
        self.session = self.reply(self.send("Target.attachToTarget", {"targetId": target, "flatten": True}),
                                  deadline)["sessionId"]
        self.call("Page.navigate", {"url": url}, deadline)

    def evaluate(self, expression, deadline, gesture=False):
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                                "userGesture": gesture, "awaitPromise": True}, deadline)
        return result["result"].get("value")

    def wait_ready(self, deadline):
        """The page's title and body data-* once its title starts with "ready"."""
        state = {}
        while time.time() < deadline:
            expression = "JSON.stringify({title: document.title, data: Object.assign({}, document.body ? document.body.dataset : {})})"
            state = json.loads(self.evaluate(expression, deadline) or "{}")
            if state.get("title", "").startswith("ready"):
                return state
            time.sleep(0.05)
        raise SystemExit("the page never became ready: %s" % state)

    def close(self):
        try:
            self.send("Browser.close")
            self.browser.wait(10)
        except Exception:
            self.browser.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def main():
    chromium, url, out = sys.argv[1], sys.argv[2], sys.argv[3]
    x, y, width, height = (int(v) for v in sys.argv[4:8])
    browser = Chromium(chromium, x + width, y + height)
    deadline = time.time() + 60
    try:
        browser.open(url, deadline)
        state = browser.wait_ready(deadline)
        shot = browser.call("Page.captureScreenshot",
                            {"format": "png", "clip": {"x": x, "y": y, "width": width,
                                                       "height": height, "scale": 1}}, deadline)
        with open(out, "wb") as f:
            f.write(base64.b64decode(shot["data"]))
        if len(sys.argv) > 8:
            state["value"] = browser.evaluate(sys.argv[8], deadline)
        print(json.dumps(state))
    finally:
        browser.close()


if __name__ == "__main__":
    main()
