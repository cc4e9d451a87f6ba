#!/usr/bin/env python3
"""report.html of a real `cordgrasp run` or `bench` in headless Chromium (ctest label `browser`).

--report run: runs `cordgrasp run` on a cheap shipped input; --report bench: runs a small
`cordgrasp bench` (two shipped objects, one repeat, lift only). Opens the folder's report.html
in headless Chromium through the DevTools protocol (--remote-debugging-pipe; Python standard
library only) and checks that the page loads with no console error and no request outside its
folder, that every image decodes and that every 3D view draws the grasp (the page's
cordgraspSelftest()); for run, that a mouse drag turns the first 3D view; for bench, that the
page has a contact sheet per object and a plot. Saves a screenshot of the whole page as
<out-dir>/report_screenshot.png beside the report (<out-dir>/report/). Exit 0: passed,
1: failed, 77: skipped (no Chromium; the reason printed).
"""
import argparse
import base64
import fcntl
import json
import os
import queue
import shutil
import subprocess
import sys
import threading
import time

SKIP = 77
GRASPS = 2                           # run: grasps planned, each with a 3D view
BENCH_OBJECTS = ["box", "sphere"]    # bench: shipped objects, one contact sheet each
ASSETS = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                      "assets"))
MIN_DRAWN_SHARE = 0.01  # a 3D view draws the grasp: this share of its pixels not background
TIMEOUT_S = 90.0        # the whole browser part
WIDTH_PX = 1280

CHROMIUM_FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--disable-default-apps", "--host-resolver-rules=MAP * ~NOTFOUND",
    "--remote-debugging-pipe",
]


class Browser:
    """Chromium with the DevTools protocol on fds 3 (commands) and 4 (replies, events)."""

    def __init__(self, chromium, profile, log):
        to_r, to_w = os.pipe()
        from_r, from_w = os.pipe()
        # Above 4, so that the child's dup2 to 3 and 4 cannot clobber one with the other.
        to_r_high = fcntl.fcntl(to_r, fcntl.F_DUPFD_CLOEXEC, 10)
        from_w_high = fcntl.fcntl(from_w, fcntl.F_DUPFD_CLOEXEC, 10)
        os.close(to_r)
        os.close(from_w)

        def child_fds():
            os.dup2(to_r_high, 3)
            os.dup2(from_w_high, 4)

        self.proc = subprocess.Popen(
            [chromium, *CHROMIUM_FLAGS, "--user-data-dir=" + profile, "about:blank"],
            stdin=subprocess.DEVNULL, stdout=log, stderr=log, close_fds=False,
            preexec_fn=child_fds)
        os.close(to_r_high)
        os.close(from_w_high)
        self.out = os.fdopen(to_w, "wb", buffering=0)
        self.messages = queue.Queue()
        self.events = []
        self.next_id = 0
        threading.Thread(target=self._read, args=(from_r,), daemon=True).start()

    def _read(self, fd):
        pending = b""
        while True:
            chunk = os.read(fd, 1 << 16)
            if not chunk:
                self.messages.put(None)
                return
            pending += chunk
            *whole, pending = pending.split(b"\0")
            for message in whole:
                self.messages.put(json.loads(message))

    def _next(self, deadline):
        message = self.messages.get(timeout=max(0.1, deadline - time.monotonic()))
        if message is None:
            raise RuntimeError("Chromium closed the DevTools pipe")
        if "id" not in message:
            self.events.append(message)
        return message

    def send(self, method, deadline, session=None, **params):
        """The result of one command; events that arrive meanwhile go to self.events."""
        self.next_id += 1
        command = {"id": self.next_id, "method": method, "params": params}
        if session:
            command["sessionId"] = session
        self.out.write(json.dumps(command).encode() + b"\0")
        while True:
            message = self._next(deadline)
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message["result"]

    def wait_for(self, method, deadline):
        while not any(e["method"] == method for e in self.events):
            self._next(deadline)

    def close(self):
        try:
            self.out.write(json.dumps({"id": 0, "method": "Browser.close"}).encode() + b"\0")
            self.proc.wait(timeout=10)
        except (OSError, subprocess.TimeoutExpired):
            self.proc.kill()
            self.proc.wait()


def drag_turns_the_first_view(browser, session, deadline):
    """Whether a mouse drag across the first 3D view changes its picture."""
    rect = browser.send("Runtime.evaluate", deadline, session, returnByValue=True, expression=(
        "(function () { var r = document.querySelector('.viewer canvas')"
        ".getBoundingClientRect(); return {x: r.x, y: r.y, width: r.width,"
        " height: r.height}; })()"))["result"]["value"]
    clip = dict(rect, scale=1)

    def picture():
        return browser.send("Page.captureScreenshot", deadline, session, format="png",
                            clip=clip)["data"]

    before = picture()
    x, y = rect["x"] + rect["width"] / 2, rect["y"] + rect["height"] / 2
    mouse = dict(button="left", clickCount=1)
    browser.send("Input.dispatchMouseEvent", deadline, session, type="mousePressed", x=x, y=y,
                 buttons=1, **mouse)
    for step in range(1, 6):
        browser.send("Input.dispatchMouseEvent", deadline, session, type="mouseMoved",
                     x=x + 20 * step, y=y + 5 * step, buttons=1, button="left")
    browser.send("Input.dispatchMouseEvent", deadline, session, type="mouseReleased",
                 x=x + 100, y=y + 25, buttons=0, **mouse)
    return picture() != before


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cordgrasp", required=True, help="the cordgrasp executable")
    ap.add_argument("--chromium", default="", help="the Chromium executable ('' if none)")
    ap.add_argument("--out-dir", required=True, help="folder for the report and the screenshot")
    ap.add_argument("--report", choices=["run", "bench"], default="run",
                    help="the command whose report.html is opened")
    args = ap.parse_args()
    if not args.chromium or not os.access(args.chromium, os.X_OK):
        print(f"SKIP: Chromium not found ('{args.chromium}', CMake's CORDGRASP_CHROMIUM); "
              "install Debian's chromium (tools/install-deps.sh) to run this test")
        return SKIP
    start = time.monotonic()
    out = os.path.abspath(args.out_dir)
    folder = os.path.join(out, "report")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    if args.report == "run":
        command = [args.cordgrasp, "run", "--hand", "parallel_gripper", "--object", "box",
                   "--grasps", str(GRASPS), "--quiet", "--out-dir", folder]
    else:
        command = [args.cordgrasp, "bench", "--objects",
                   *[os.path.join(ASSETS, "objects", o + ".obj") for o in BENCH_OBJECTS],
                   "--hands", "cordgrasp_sah", "--planners", "cord", "--repeats", "1",
                   "--tests", "lift", "--time-limit", "20", "--sheet-size", "320x240",
                   "--quiet", "--out-dir", folder]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        print(f"FAIL: cordgrasp {args.report} exited with {run.returncode}:\n"
              f"{run.stdout}{run.stderr}")
        return 1
    page = os.path.realpath(os.path.join(folder, "report.html"))
    folder_url = "file://" + os.path.dirname(page) + "/"
    failures = []
    with open(page, encoding="utf-8") as f:
        html = f.read()
    for scheme in ("http://", "https://"):
        if scheme in html:
            failures.append(f"report.html names an external URL ({scheme})")

    log_path = os.path.join(out, "chromium.log")
    with open(log_path, "wb") as log:
        browser = Browser(args.chromium, os.path.join(out, "profile"), log)
        deadline = time.monotonic() + TIMEOUT_S
        try:
            target = browser.send("Target.createTarget", deadline, url="about:blank")
            session = browser.send("Target.attachToTarget", deadline, flatten=True,
                                   targetId=target["targetId"])["sessionId"]
            for domain in ("Page", "Runtime", "Log", "Network"):
                browser.send(domain + ".enable", deadline, session)
            browser.send("Emulation.setDeviceMetricsOverride", deadline, session,
                         width=WIDTH_PX, height=900, deviceScaleFactor=1, mobile=False)
            browser.send("Page.navigate", deadline, session, url="file://" + page)
            browser.wait_for("Page.loadEventFired", deadline)
            result = browser.send("Runtime.evaluate", deadline, session,
                                  expression="window.cordgraspSelftest()", awaitPromise=True,
                                  returnByValue=True)
            if "exceptionDetails" in result:
                raise RuntimeError(f"cordgraspSelftest(): {result['exceptionDetails']}")
            selftest = result["result"]["value"]
            # The whole page, for a look: the viewport as tall as the content.
            height = browser.send("Page.getLayoutMetrics", deadline, session)["cssContentSize"]
            browser.send("Emulation.setDeviceMetricsOverride", deadline, session,
                         width=WIDTH_PX, height=int(height["height"]) + 1, deviceScaleFactor=1,
                         mobile=False)
            shot = browser.send("Page.captureScreenshot", deadline, session, format="png")
            shot_path = os.path.join(out, "report_screenshot.png")
            with open(shot_path, "wb") as f:
                f.write(base64.b64decode(shot["data"]))
            plots = browser.send("Runtime.evaluate", deadline, session, returnByValue=True,
                                 expression="document.querySelectorAll('svg').length")
            plots = plots["result"]["value"]
            turned = (drag_turns_the_first_view(browser, session, deadline)
                      if args.report == "run" else None)
        except (RuntimeError, queue.Empty) as e:
            print(f"FAIL: the browser did not finish ({e or 'timed out'}); log {log_path}")
            return 1
        finally:
            browser.close()
    print(json.dumps(selftest, indent=1))

    images = selftest["images"]
    # run: per grasp its picture and physics strip, and the sheet; bench: a sheet per object.
    want_images = 2 * GRASPS + 1 if args.report == "run" else len(BENCH_OBJECTS)
    want_views = GRASPS if args.report == "run" else 0
    if len(images) < want_images:
        failures.append(f"{len(images)} images, expected at least {want_images}")
    failures += [f"image {i['src']} did not decode" for i in images if not i["ok"]]
    if len(selftest["views"]) != want_views:
        failures.append(f"{len(selftest['views'])} 3D views drew, expected {want_views}")
    failures += [f"3D view {v['model']}: {v['drawn']} of {v['pixels']} pixels drawn"
                 for v in selftest["views"] if v["drawn"] < MIN_DRAWN_SHARE * v["pixels"]]
    failures += ["page: " + e for e in selftest["errors"]]
    if plots < 1:
        failures.append("no SVG plot on the page")
    if turned is False:
        failures.append("dragging the mouse across the first 3D view did not turn it")
    loaded = 0
    for e in browser.events:
        p = e.get("params", {})
        if e["method"] == "Network.requestWillBeSent":
            url = p["request"]["url"]
            loaded += 1
            if not url.startswith((folder_url, "data:", "blob:")):
                failures.append(f"request outside the folder: {url}")
        elif e["method"] == "Runtime.exceptionThrown":
            failures.append("exception: " + p["exceptionDetails"].get("text", "?") + " " +
                            str(p["exceptionDetails"].get("exception", {}).get("description")))
        elif e["method"] == "Runtime.consoleAPICalled" and p["type"] in ("error", "assert"):
            failures.append("console." + p["type"] + ": " +
                            " ".join(str(a.get("value", a.get("description"))) for a in p["args"]))
        elif e["method"] == "Log.entryAdded" and p["entry"]["level"] == "error":
            failures.append(f"log: {p['entry']['text']} ({p['entry'].get('url', '')})")
    # run: images, viewer scripts, models; bench: the page and its sheets.
    want_loaded = 2 * GRASPS + 4 if args.report == "run" else 1 + len(BENCH_OBJECTS)
    if loaded < want_loaded:
        failures.append(f"only {loaded} requests seen: the network record is incomplete")
    drag = ("" if turned is None else
            f"; a mouse drag {'turned' if turned else 'did not turn'} the first 3D view")
    print(f"report {page}\nscreenshot {shot_path}\n{loaded} files loaded, {plots} plots"
          f"{drag}; {time.monotonic() - start:.1f} s")
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
