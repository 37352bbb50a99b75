#!/usr/bin/env python3
"""Open a page in headless Chromium, wait until it says it is ready, and save a screenshot.

usage: browser_screenshot.py CHROMIUM URL OUT.png X Y WIDTH HEIGHT

Talks to Chromium over --remote-debugging-pipe (the DevTools protocol as NUL-separated JSON on
file descriptors 3 and 4), so it needs nothing beyond Python's standard library and Debian's
chromium: no network, no WebSocket client. The page is ready when its title starts with "ready"
(the fapc preview page sets it once the video has seeked). Prints one JSON line: the page's
title and the body's data-* attributes (the preview page's cursor time and position).
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


def main():
    chromium, url, out = sys.argv[1], sys.argv[2], sys.argv[3]
    x, y, width, height = (int(v) for v in sys.argv[4:8])
    to_browser_r, to_browser_w = os.pipe()
    from_browser_r, from_browser_w = os.pipe()
    # Chromium reads commands on fd 3 and writes replies on fd 4; park both ends above 20 first so
    # the dup2 calls in the child cannot clobber each other.
    high_r = fcntl.fcntl(to_browser_r, fcntl.F_DUPFD, 20)
    high_w = fcntl.fcntl(from_browser_w, fcntl.F_DUPFD, 20)
    profile = tempfile.mkdtemp(prefix="fapc-chromium-")

    def in_child():
        os.dup2(high_r, 3)
        os.dup2(high_w, 4)

    browser = subprocess.Popen(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
         "--no-first-run", "--disable-background-networking", "--disable-component-update",
         "--disable-sync", "--user-data-dir=" + profile, "--remote-debugging-pipe",
         "--window-size=%d,%d" % (max(1280, x + width), max(900, y + height)), "about:blank"],
        pass_fds=(3, 4), preexec_fn=in_child,
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for fd in (to_browser_r, from_browser_w, high_r, high_w):
        os.close(fd)
    pending = b""
    next_id = [0]

    def send(method, params=None, session=None):
        next_id[0] += 1
        message = {"id": next_id[0], "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(to_browser_w, json.dumps(message).encode() + b"\0")
        return next_id[0]

    def reply(request, deadline):
        nonlocal pending
        while time.time() < deadline:
            while b"\0" in pending:
                raw, pending = pending.split(b"\0", 1)
                message = json.loads(raw)
                if message.get("id") == request:
                    if "error" in message:
                        raise SystemExit("chromium: %s" % message["error"])
                    return message["result"]
            chunk = os.read(from_browser_r, 1 << 20)
            if not chunk:
                raise SystemExit("chromium closed the pipe")
            pending += chunk
        raise SystemExit("chromium did not answer in time")

    deadline = time.time() + 60
    try:
        target = reply(send("Target.createTarget", {"url": "about:blank"}), deadline)["targetId"]
        session = reply(send("Target.attachToTarget", {"targetId": target, "flatten": True}),
                        deadline)["sessionId"]
        reply(send("Page.navigate", {"url": url}, session), deadline)
        state = {}
        while time.time() < deadline:
            expression = "JSON.stringify({title: document.title, data: Object.assign({}, document.body ? document.body.dataset : {})})"
            result = reply(send("Runtime.evaluate", {"expression": expression, "returnByValue": True},
                                session), deadline)
            state = json.loads(result["result"].get("value", "{}"))
            if state.get("title", "").startswith("ready"):
                break
            time.sleep(0.05)
        else:
            raise SystemExit("the page never became ready: %s" % state)
        shot = reply(send("Page.captureScreenshot",
                          {"format": "png", "clip": {"x": x, "y": y, "width": width,
                                                     "height": height, "scale": 1}}, session),
                     deadline)
        with open(out, "wb") as f:
            f.write(base64.b64decode(shot["data"]))
        print(json.dumps(state))
    finally:
        try:
            send("Browser.close")
            browser.wait(10)
        except Exception:
            browser.kill()
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    main()
