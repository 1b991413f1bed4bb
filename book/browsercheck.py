#!/usr/bin/env python3
"""Opens built chapters in headless Chromium and checks that they render (stdlib only).

Usage: python3 book/browsercheck.py [--chromium PATH] [PAGE.html ...]
       (pages relative to book/book; default: 02-ray-casting.html 10-textures-sampling.html)

Talks to Chromium over the DevTools protocol on a pipe (--remote-debugging-pipe:
commands go in on fd 3, replies and events come out on fd 4, JSON messages ended
by a NUL byte), so no websocket, driver or package is needed. For each page,
loaded through a file:// URL in a fresh profile:
  (a) KaTeX math rendered: elements of class `katex` exist, none of class
      `katex-error`, and the shipped stylesheet applies (a `.katex` element's
      computed font-family is KaTeX_Main, its `.base` boxes are inline-blocks);
  (b) every <img> loaded (complete, naturalWidth > 0), and there is at least one;
  (c) the KaTeX fonts loaded: after document.fonts.ready, some KaTeX face has
      status "loaded";
  (d) no request failed, and none went anywhere but file:// (or data:).
Exit status 0 when every page passes, 1 naming each failure otherwise.
"""

import argparse
import json
import os
import pathlib
import select
import shutil
import subprocess
import sys
import tempfile
import time

FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-dev-shm-usage",  # containers often have a tiny /dev/shm
    "--remote-debugging-pipe",
]
TIMEOUT = 60.0  # seconds for the whole check of one page; a page loads in well under 2 s here

# Evaluated in the page after its load event: waits for the fonts, then reports.
PROBE = r"""
(async () => {
  await document.fonts.ready;
  const images = [...document.images];
  const first = document.querySelector('.katex');
  const base = document.querySelector('.katex .base');
  const faces = [...document.fonts].filter(f => f.family.replace(/["']/g, '').startsWith('KaTeX'));
  return JSON.stringify({
    katex: document.querySelectorAll('.katex').length,
    katexErrors: document.querySelectorAll('.katex-error').length,
    fontFamily: first ? getComputedStyle(first).fontFamily : '',
    baseDisplay: base ? getComputedStyle(base).display : '',
    images: images.length,
    brokenImages: images.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src')),
    katexFaces: faces.length,
    loadedKatexFaces: faces.filter(f => f.status === 'loaded').map(f => f.family.replace(/["']/g, '')),
  });
})()
"""


class Chromium:
    """A headless Chromium driven over --remote-debugging-pipe."""

    def __init__(self, executable, profile):
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()

        def fds():  # in the child: the protocol's fds 3 (commands) and 4 (replies)
            os.dup2(to_browser_r, 3)
            os.dup2(from_browser_w, 4)

        self.process = subprocess.Popen(
            [executable, *FLAGS, f"--user-data-dir={profile}", "about:blank"],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            preexec_fn=fds,
            pass_fds=(3, 4),  # kept open after preexec_fn has put the pipes there
        )
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.targets = {}  # a tab's target, by its session (`open`)

    def send(self, method, params=None, session=None, deadline=None):
        """Sends a command and returns its result; events that arrive meanwhile are kept."""
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        while True:
            reply = self.receive(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})
            self.events.append(reply)

    def receive(self, deadline):
        while b"\0" not in self.buffer:
            left = (deadline or time.monotonic() + TIMEOUT) - time.monotonic()
            ready, _, _ = select.select([self.from_browser], [], [], max(left, 0))
            if not ready:
                raise TimeoutError("no answer from Chromium in time")
            chunk = os.read(self.from_browser, 1 << 16)
            if not chunk:
                err = self.process.stderr.read().decode(errors="replace")[-2000:]
                raise RuntimeError(f"Chromium closed the pipe (exit {self.process.poll()}):\n{err}")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def wait_for(self, method, session, deadline):
        """Waits for an event of this session (or finds it among those already kept)."""
        while True:
            for event in self.events:
                if event.get("method") == method and event.get("sessionId") == session:
                    return event
            self.events.append(self.receive(deadline))

    def open(self, url, deadline, viewport=None):
        """A new tab with the Page, Network and Runtime events on (and a `viewport` of
        (width, height), if given), `url` loaded in it; its session. Events kept from here on."""
        target = self.send("Target.createTarget", {"url": "about:blank"}, deadline=deadline)["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True},
                            deadline=deadline)["sessionId"]
        for domain in ("Page", "Network", "Runtime"):
            self.send(f"{domain}.enable", session=session, deadline=deadline)
        if viewport:
            self.send("Emulation.setDeviceMetricsOverride", {"width": viewport[0], "height": viewport[1],
                      "deviceScaleFactor": 1, "mobile": False}, session=session, deadline=deadline)
        self.targets[session] = target
        self.events.clear()
        self.send("Page.navigate", {"url": url}, session=session, deadline=deadline)
        self.wait_for("Page.loadEventFired", session, deadline)
        return session

    def requests_elsewhere(self):
        """Every request the pages made to anything but file:// or data: (offline pages make none)."""
        return [e["params"]["request"]["url"] for e in self.events
                if e.get("method") == "Network.requestWillBeSent"
                and not e["params"]["request"]["url"].startswith(("file:", "data:"))]

    def close(self):
        try:
            self.send("Browser.close", deadline=time.monotonic() + 5)
        except Exception:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self.to_browser)
        os.close(self.from_browser)


def check_page(browser, url):
    """The failures of one page (an empty list when it passes)."""
    deadline = time.monotonic() + TIMEOUT
    session = browser.open(url, deadline)
    result = browser.send(
        "Runtime.evaluate",
        {"expression": PROBE, "awaitPromise": True, "returnByValue": True},
        session=session,
        deadline=deadline,
    )
    if "exceptionDetails" in result:
        return [f"the probe failed: {result['exceptionDetails'].get('text')}"]
    r = json.loads(result["result"]["value"])

    failures = []
    if r["katex"] == 0:
        failures.append("(a) no KaTeX math on the page (no element of class katex)")
    if r["katexErrors"]:
        failures.append(f"(a) {r['katexErrors']} formula(s) failed to render (class katex-error)")
    if r["katex"] and "KaTeX_Main" not in r["fontFamily"]:
        failures.append(f"(a) the KaTeX stylesheet does not apply (.katex font-family: {r['fontFamily']!r})")
    if r["katex"] and r["baseDisplay"] != "inline-block":
        failures.append(f"(a) the KaTeX stylesheet does not apply (.katex .base display: {r['baseDisplay']!r})")
    if r["images"] == 0:
        failures.append("(b) no <img> on the page")
    for src in r["brokenImages"]:
        failures.append(f"(b) image not loaded: {src}")
    if r["katex"] and not r["loadedKatexFaces"]:
        failures.append(f"(c) no KaTeX font loaded ({r['katexFaces']} KaTeX faces declared)")

    # (d) Failed requests, and requests that left the book.
    requests = {}
    for event in browser.events:
        if event.get("sessionId") != session:
            continue
        params = event.get("params", {})
        if event.get("method") == "Network.requestWillBeSent":
            requests[params["requestId"]] = params["request"]["url"]
            scheme = params["request"]["url"].split(":", 1)[0]
            if scheme not in ("file", "data"):
                failures.append(f"(d) the page requested {params['request']['url']}")
        elif event.get("method") == "Network.loadingFailed":
            failed = requests.get(params["requestId"], params["requestId"])
            failures.append(f"(d) failed to load {failed}: {params.get('errorText')}")
    print(
        f"  {r['katex']} formulas, {r['images']} images, KaTeX fonts loaded: "
        f"{', '.join(sorted(set(r['loadedKatexFaces']))) or 'none'}"
    )
    browser.send("Target.closeTarget", {"targetId": browser.targets[session]}, deadline=deadline)
    return failures


def main():
    here = pathlib.Path(__file__).resolve().parent
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    parser.add_argument("--book", default=str(here / "book"), help="the built book (default: book/book)")
    parser.add_argument("pages", nargs="*", default=["02-ray-casting.html", "10-textures-sampling.html"])
    args = parser.parse_args()
    if not os.access(args.chromium, os.X_OK):
        print(f"browsercheck: no Chromium at {args.chromium}")
        return 1

    failed = False
    with tempfile.TemporaryDirectory(prefix="browsercheck-") as profile:
        browser = Chromium(args.chromium, profile)
        try:
            for page in args.pages:
                path = pathlib.Path(args.book, page).resolve()
                print(f"browsercheck: {page}")
                if not path.is_file():
                    print(f"  FAILED: no such page {path}")
                    failed = True
                    continue
                failures = check_page(browser, path.as_uri())
                for failure in failures:
                    print(f"  FAILED: {failure}")
                failed |= bool(failures)
        except (RuntimeError, TimeoutError) as error:
            print(f"browsercheck: {error}")
            failed = True
        finally:
            browser.close()
    print("browsercheck: " + ("FAILED" if failed else "ok"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
