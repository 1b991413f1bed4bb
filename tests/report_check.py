#!/usr/bin/env python3
"""Opens the grader's report.html in headless Chromium (stdlib only; the DevTools client
of book/browsercheck.py) and checks that it works offline:
  - every <img> loaded (expected / yours / difference of each scene), at least three;
  - no request went anywhere but file:// (or data:);
  - clicking a pixel of a scene's image shows the command that prints its ray tree;
  - the ray tree of the first differing pixel of a failed scene is in the page.
Usage: python3 tests/report_check.py REPORT.html [--chromium PATH]
Exit status 0 when it passes, 1 naming each failure, 2 when Chromium is missing.
"""
import argparse
import json
import pathlib
import shutil
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "book"))
from browsercheck import TIMEOUT, Chromium  # noqa: E402

PROBE = r"""
(async () => {
  const images = [...document.images];
  const scene = document.querySelector('td[data-scene] img');
  let picked = '';
  if (scene) {
    const rect = scene.getBoundingClientRect();
    scene.dispatchEvent(new MouseEvent('click', {clientX: rect.left + rect.width / 2,
                                                 clientY: rect.top + rect.height / 2, bubbles: true}));
    picked = document.getElementById('picked').textContent;
  }
  return JSON.stringify({
    images: images.length,
    broken: images.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src')),
    picked: picked,
    trees: document.querySelectorAll('pre.tree').length,
    failed: document.querySelectorAll('tr.failed').length,
  });
})()
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("report")
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    args = parser.parse_args()
    if not shutil.which(args.chromium):
        print(f"SKIPPED the report's browser check: {args.chromium} is missing (apt-get install chromium)")
        return 2
    url = pathlib.Path(args.report).resolve().as_uri()
    with tempfile.TemporaryDirectory() as profile:
        browser = Chromium(args.chromium, profile)
        try:
            deadline = time.monotonic() + TIMEOUT
            target = browser.send("Target.createTarget", {"url": "about:blank"}, deadline=deadline)["targetId"]
            session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True},
                                   deadline=deadline)["sessionId"]
            for domain in ("Page", "Network", "Runtime"):
                browser.send(f"{domain}.enable", session=session, deadline=deadline)
            browser.events.clear()
            browser.send("Page.navigate", {"url": url}, session=session, deadline=deadline)
            browser.wait_for("Page.loadEventFired", session, deadline)
            result = browser.send("Runtime.evaluate", {"expression": PROBE, "awaitPromise": True,
                                                       "returnByValue": True}, session=session, deadline=deadline)
            if "exceptionDetails" in result:
                print(f"the probe failed: {result['exceptionDetails'].get('text')}")
                return 1
            r = json.loads(result["result"]["value"])
            failures = []
            if r["images"] < 3:
                failures.append(f"only {r['images']} images (expected, yours, difference at least)")
            failures += [f"image not loaded: {src}" for src in r["broken"]]
            if "--tree" not in r["picked"]:
                failures.append(f"clicking a pixel shows {r['picked']!r}, not the ray-tree command")
            if r["failed"] and not r["trees"]:
                failures.append("a failed scene without the ray tree of its first differing pixel")
            for event in browser.events:
                if event.get("method") == "Network.requestWillBeSent":
                    scheme = event["params"]["request"]["url"].split(":", 1)[0]
                    if scheme not in ("file", "data"):
                        failures.append(f"the page requested {event['params']['request']['url']}")
            print(f"report: {r['images']} images, {r['failed']} failed rows, {r['trees']} ray trees; "
                  f"click: {r['picked']}")
            for f in failures:
                print(f"FAILED: {f}")
            return 1 if failures else 0
        finally:
            browser.close()


if __name__ == "__main__":
    sys.exit(main())
