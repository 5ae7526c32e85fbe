#!/usr/bin/python3
"""Open a flight page in a real Firefox and read what it shows.

Why: Firefox has no --dump-dom and no --screenshot with WebGL, and headless Firefox offers no
WebGL at all. So this script starts a private X server (Xvfb, Mesa's software OpenGL) and
Firefox ESR on it, and drives Firefox through its remote protocol, WebDriver BiDi, over a
websocket (Debian's python3-websocket). tests/cli/export_html_test.cpp runs it
(ExportHtmlFirefox.*).

    firefox_page.py PAGE [--selftest WxH ...] [--shot WxH:FILE.png ...] [--at SECONDS]

--selftest opens file://PAGE#selftest in a viewport of W x H CSS pixels and waits for the
page's own self-test to write its findings into <pre id="selftest-result">. --shot opens
file://PAGE#t=SECONDS (or the page as it starts, without --at) in a viewport of W x H and saves
a PNG of it. Printed on stdout, as one JSON object on one line: "selftest" (the findings,
parsed, by viewport: {"1280x720": {...}}) and "browser_errors" (the JavaScript errors Firefox
itself logged while the pages ran).

Exit status 0 when every step worked; 1 with a message on stderr when Firefox, Xvfb, the
protocol, WebGL or the self-test's result is missing (the JSON is printed all the same when
the findings were read). Every step has a time limit, and Xvfb and Firefox (with all their
processes) are killed at the end whatever happened.
"""

import argparse
import base64
import json
import os
import queue
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

try:
    import websocket  # Debian: python3-websocket
except ImportError:
    sys.exit("firefox_page.py: python3-websocket is missing (tools/bootstrap.sh test installs it)")

STEP_SECONDS = 30  # the longest any single step may take

# A quiet profile: no first-run pages, no updates, no network chatter, no session restore.
PREFS = {
    "browser.shell.checkDefaultBrowser": False,
    "browser.startup.homepage_override.mstone": "ignore",
    "browser.startup.page": 0,
    "browser.aboutwelcome.enabled": False,
    "browser.sessionstore.resume_from_crash": False,
    "datareporting.policy.dataSubmissionEnabled": False,
    "datareporting.healthreport.uploadEnabled": False,
    "toolkit.telemetry.reportingpolicy.firstRun": False,
    "app.update.disabledForTesting": True,
    "app.normandy.enabled": False,
    "extensions.update.enabled": False,
    "network.captive-portal-service.enabled": False,
    "network.connectivity-service.enabled": False,
}


class Failure(Exception):
    pass


# Every process started here (each the leader of a process group of its own), so that the end
# of run() kills them whatever step failed or was interrupted.
started = []


def fail_on_term(signum, frame):
    # Once: `timeout` sends its signal twice (to the script and to its process group), and a
    # second one must not interrupt the cleanup the first one started.
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    raise Failure("stopped by signal %d" % signum)


def start_xvfb():
    """A private X display; returns (process, ':N'). -displayfd picks a free display number."""
    if not shutil.which("Xvfb"):
        raise Failure("Xvfb is missing (tools/bootstrap.sh test installs xvfb)")
    read_end, write_end = os.pipe()
    xvfb = subprocess.Popen(
        ["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1400x1000x24", "-nolisten", "tcp"],
        pass_fds=[write_end], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        start_new_session=True)
    started.append(xvfb)
    os.close(write_end)
    number = b""
    deadline = time.monotonic() + STEP_SECONDS
    os.set_blocking(read_end, False)
    while not number.endswith(b"\n"):
        if time.monotonic() > deadline or xvfb.poll() is not None:
            os.close(read_end)
            raise Failure("Xvfb did not start")
        try:
            chunk = os.read(read_end, 16)
        except BlockingIOError:
            time.sleep(0.05)
            continue
        if not chunk:
            time.sleep(0.05)
        number += chunk
    os.close(read_end)
    return xvfb, ":" + number.decode().strip()


def start_firefox(display, home):
    """Firefox on `display` with its remote protocol on a free port; returns (process, ws URL)."""
    if not shutil.which("firefox-esr"):
        raise Failure("firefox-esr is missing (tools/bootstrap.sh test installs it)")
    profile = os.path.join(home, "profile")
    os.makedirs(profile)
    with open(os.path.join(profile, "user.js"), "w") as f:
        for name, value in PREFS.items():
            f.write("user_pref(%s, %s);\n" % (json.dumps(name), json.dumps(value)))
    env = dict(os.environ, DISPLAY=display, HOME=home, MOZ_CRASHREPORTER_DISABLE="1")
    env.pop("MOZ_HEADLESS", None)
    firefox = subprocess.Popen(
        ["firefox-esr", "--no-remote", "--profile", profile, "--remote-debugging-port=0",
         "about:blank"],
        env=env, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
        start_new_session=True)
    started.append(firefox)
    lines = queue.Queue()
    threading.Thread(target=lambda: [lines.put(l) for l in iter(firefox.stderr.readline, b"")],
                     daemon=True).start()
    seen = []
    deadline = time.monotonic() + STEP_SECONDS
    while time.monotonic() < deadline:
        try:
            line = lines.get(timeout=0.2).decode(errors="replace")
        except queue.Empty:
            if firefox.poll() is not None:
                break
            continue
        seen.append(line)
        found = re.search(r"WebDriver BiDi listening on (ws://\S+)", line)
        if found:
            return firefox, found.group(1).rstrip("/") + "/session"
    raise Failure("Firefox did not open its remote protocol:\n" + "".join(seen[-20:]))


def stop(process):
    """Ends a process and every process of its group (it was started in a session of its own)."""
    if process is None or (process.poll() is not None and not group_alive(process.pid)):
        return
    for sig, wait in ((signal.SIGTERM, 5), (signal.SIGKILL, 5)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            return
        try:
            process.wait(timeout=wait)
        except subprocess.TimeoutExpired:
            continue
        if not group_alive(process.pid):
            return


def group_alive(pgid):
    try:
        os.killpg(pgid, 0)
        return True
    except ProcessLookupError:
        return False


class Bidi:
    """Commands and events of WebDriver BiDi over one websocket, each answer awaited in time."""

    def __init__(self, url):
        self.ws = websocket.create_connection(url, timeout=STEP_SECONDS, suppress_origin=True)
        self.next_id = 0
        self.events = []

    def command(self, method, params, seconds=STEP_SECONDS):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        deadline = time.monotonic() + seconds
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                raise Failure("%s: no answer within %d s" % (method, seconds))
            self.ws.settimeout(left)
            try:
                message = json.loads(self.ws.recv())
            except websocket.WebSocketTimeoutException:
                raise Failure("%s: no answer within %d s" % (method, seconds))
            if message.get("type") == "event":
                self.events.append(message)
            elif message.get("id") == self.next_id:
                if message.get("type") == "error":
                    raise Failure("%s: %s: %s" % (method, message.get("error"),
                                                  message.get("message")))
                return message["result"]

    def evaluate(self, context, expression, await_promise=False):
        result = self.command("script.evaluate", {
            "expression": expression, "target": {"context": context},
            "awaitPromise": await_promise})
        if result.get("type") == "exception":
            raise Failure("script.evaluate(%s): %s" % (
                expression, result["exceptionDetails"].get("text")))
        return result["result"].get("value")


def open_page(bidi, context, url, size):
    """Shows `url` (from a blank page, so that a change of fragment loads the page anew) in a
    viewport of `size`; fails when the page fell back to its no-WebGL view."""
    bidi.command("browsingContext.navigate", {"context": context, "url": "about:blank",
                                              "wait": "complete"})
    bidi.command("browsingContext.setViewport", {
        "context": context, "viewport": {"width": size[0], "height": size[1]}})
    bidi.command("browsingContext.navigate", {"context": context, "url": url,
                                              "wait": "complete"})
    if bidi.evaluate(context, "document.querySelector('.no-webgl') !== null"):
        raise Failure("no WebGL in Firefox: the page shows its fallback (%s)" % url)


def run(args, home, out):
    """Fills `out` with what was read, as far as it got."""
    page = "file://" + os.path.abspath(args.page)
    try:
        display = start_xvfb()[1]
        url = start_firefox(display, home)[1]
        bidi = Bidi(url)
        bidi.command("session.new", {"capabilities": {}})
        bidi.command("session.subscribe", {"events": ["log.entryAdded"]})
        context = bidi.command("browsingContext.getTree", {})["contexts"][0]["context"]
        try:
            out["selftest"] = {}
            for width, height in args.selftest:
                open_page(bidi, context, page + "#selftest", (width, height))
                deadline = time.monotonic() + STEP_SECONDS
                text = None
                while not text and time.monotonic() < deadline:
                    text = bidi.evaluate(
                        context, "document.getElementById('selftest-result')?.textContent")
                    if not text:
                        time.sleep(0.2)
                if not text:
                    raise Failure("the page wrote no self-test result within %d s" % STEP_SECONDS)
                out["selftest"]["%dx%d" % (width, height)] = json.loads(text)
            for width, height, png in args.shot:
                fragment = "" if args.at is None else "#t=%g" % args.at
                open_page(bidi, context, page + fragment, (width, height))
                # Two animation frames: what the page drew at load is on the screen.
                bidi.evaluate(context, "new Promise(r => requestAnimationFrame(() => "
                              "requestAnimationFrame(() => r(true))))", await_promise=True)
                shot = bidi.command("browsingContext.captureScreenshot", {"context": context})
                with open(png, "wb") as f:
                    f.write(base64.b64decode(shot["data"]))
        finally:
            out["browser_errors"] = [
                "%s: %s" % (e["params"].get("type"), e["params"].get("text"))
                for e in bidi.events
                if e.get("method") == "log.entryAdded" and e["params"].get("level") == "error"]
            try:
                bidi.command("browser.close", {}, seconds=10)
            except Exception:
                pass  # Firefox is killed below in any case
    finally:
        for process in reversed(started):
            stop(process)


def size_spec(text):
    found = re.fullmatch(r"(\d+)x(\d+)", text)
    if not found:
        raise argparse.ArgumentTypeError("expected WxH, got " + text)
    return int(found.group(1)), int(found.group(2))


def shot_spec(text):
    found = re.fullmatch(r"(\d+)x(\d+):(.+\.png)", text)
    if not found:
        raise argparse.ArgumentTypeError("expected WxH:FILE.png, got " + text)
    return int(found.group(1)), int(found.group(2)), found.group(3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("page")
    parser.add_argument("--selftest", type=size_spec, action="append", default=[])
    parser.add_argument("--shot", type=shot_spec, action="append", default=[])
    parser.add_argument("--at", type=float)
    args = parser.parse_args()
    if not os.path.isfile(args.page):
        sys.exit("firefox_page.py: no page at " + args.page)
    signal.signal(signal.SIGTERM, fail_on_term)
    signal.signal(signal.SIGINT, fail_on_term)
    home = tempfile.mkdtemp(prefix="firefox-page-")
    out = {}
    status = 0
    try:
        run(args, home, out)
    except (Failure, OSError, websocket.WebSocketException) as e:
        sys.stderr.write("firefox_page.py: %s\n" % e)
        status = 1
    finally:
        shutil.rmtree(home, ignore_errors=True)
    if out.get("selftest") or status == 0:
        print(json.dumps(out))
    for size, found in out.get("selftest", {}).items():
        if "webgl" not in found:
            sys.stderr.write("firefox_page.py: the self-test at %s stopped early: %s\n"
                             % (size, found.get("problems")))
            status = 1
        elif found["webgl"] is not True:
            sys.stderr.write("firefox_page.py: the self-test at %s found no WebGL\n" % size)
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
