#!/usr/bin/env python3
"""Opens `grader class`'s class.html in headless Chromium (stdlib only; the DevTools client of
book/browsercheck.py) and checks what an instructor reads first:
  - the page lays out: the class's mistakes at a glance first, their first row on the first
    screen; the table of what the class gets wrong, its first row the check named by --first (the
    one most students fail), with a cause and the students' names;
  - the heat map has a row per exercise graded, each row's counts summing to the students graded;
  - every picture of the clusters of wrong pictures loads (expected, a student's, the difference),
    with --pictures, at least one;
  - nothing is requested but file:// (or data:): the page works offline.
Usage: python3 tests/class_check.py CLASS.html --first CHECK --students N [--pictures] [--chromium PATH]
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
(() => {
  const first = document.querySelector('table.causes tr[data-check]');
  const top = document.querySelector('table.mistakes tr[data-students]') || first;
  const rows = [...document.querySelectorAll('table.heat tr[data-exercise]')].map(r =>
    [...r.querySelectorAll('td.n')].map(td => Number(td.textContent)).reduce((a, b) => a + b, 0));
  const box = top ? top.getBoundingClientRect() : null;
  return JSON.stringify({
    first: first ? first.dataset.check : null,
    firstText: first ? first.textContent : '',
    firstShown: !!box && box.width > 0 && box.height > 0 && box.top < window.innerHeight,
    sums: rows,
    pictures: [...document.querySelectorAll('tr.clusters img')].map(i => [i.getAttribute('src'), i.complete && i.naturalWidth > 0]),
  });
})()
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("page")
    parser.add_argument("--first", required=True)
    parser.add_argument("--students", type=int, required=True)
    parser.add_argument("--pictures", action="store_true")
    parser.add_argument("--chromium")
    args = parser.parse_args()
    chromium = args.chromium or shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("SKIPPED: no Chromium on this machine (apt install chromium)")
        return 2
    url = pathlib.Path(args.page).resolve().as_uri()
    with tempfile.TemporaryDirectory() as profile:
        browser = Chromium(chromium, profile)
        try:
            deadline = time.monotonic() + TIMEOUT
            session = browser.open(url, deadline)
            result = browser.send("Runtime.evaluate", {"expression": PROBE, "returnByValue": True},
                                  session=session, deadline=deadline)
            if "exceptionDetails" in result:
                print(f"the probe failed: {result['exceptionDetails'].get('text')}")
                return 1
            r = json.loads(result["result"]["value"])
            failures = []
            if r["first"] != args.first:
                failures.append(f"the first row of what the class gets wrong is {r['first']}, not {args.first}")
            if not r["firstShown"]:
                failures.append("the page's first row (the mistakes at a glance) is not on the first screen")
            if not r["sums"]:
                failures.append("no exercise in the heat map")
            failures += [f"a heat-map row counts {s} students, not {args.students}" for s in r["sums"]
                         if s != args.students]
            failures += [f"the picture {src} does not load" for src, loaded in r["pictures"] if not loaded]
            if args.pictures and not r["pictures"]:
                failures.append("no cluster of wrong pictures")
            failures += [f"the page requested {url}" for url in browser.requests_elsewhere()]
            print(f"class page: first {r['first']} ({r['firstText'][:80]!r}), {len(r['sums'])} exercises, "
                  f"{len(r['pictures'])} pictures")
            for f in failures:
                print(f"FAILED: {f}")
            return 1 if failures else 0
        finally:
            browser.close()


if __name__ == "__main__":
    sys.exit(main())
