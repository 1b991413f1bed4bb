#!/usr/bin/env python3
"""Opens a ray-tree view (`grader render SCENE --tree X,Y --view PAGE.html`) in headless
Chromium (stdlib only; the DevTools client of book/browsercheck.py) and checks that it works
offline:
  - the WebGL canvas draws: the scene, and every kind of ray the tree's data holds (eye, shadow
    reaching the light or blocked, reflected, transmitted): hiding the trees, or one kind (a
    click on its legend), changes pixels;
  - a drag turns the view (the picture changes), the wireframe toggle redraws it;
  - the tree's text is on the page, and its segments are the ones the data holds;
  - no request went anywhere but file:// (or data:).
Usage: python3 tests/view3d_check.py PAGE.html [--chromium PATH] [--screenshot PNG]
Prints a JSON summary; exit status 0 when it passes, 1 naming each failure, 2 when Chromium
is missing.
"""
import argparse
import base64
import json
import pathlib
import shutil
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "book"))
from browsercheck import TIMEOUT, Chromium  # noqa: E402

# Counts the canvas's pixels near each ray colour and those not the background, before and after a
# drag, and with the wireframe on.
PROBE = r"""
(async () => {
  const canvas = document.querySelector('.view3d canvas');
  const data = JSON.parse(document.getElementById('view3d-data').textContent);
  const colors = {eye: [240, 240, 240], reflected: [79, 194, 247], transmitted: [199, 125, 255],
                  shadow: [255, 214, 79], blocked: [255, 82, 82]};
  const background = [32, 36, 40];
  const frame = () => new Promise(r => requestAnimationFrame(() => r()));
  function pixels() {
    const copy = document.createElement('canvas');
    copy.width = canvas.width; copy.height = canvas.height;
    const c = copy.getContext('2d');
    c.drawImage(canvas, 0, 0);
    return c.getImageData(0, 0, copy.width, copy.height).data;
  }
  const distance = (px, i, rgb) => Math.abs(px[i] - rgb[0]) + Math.abs(px[i + 1] - rgb[1]) + Math.abs(px[i + 2] - rgb[2]);
  function hash(px) {
    let h = 0;
    for (let i = 0; i < px.length; i += 4) h = (h * 31 + px[i] + 7 * px[i + 1] + 13 * px[i + 2]) >>> 0;
    return h;
  }
  await frame();
  const shown = pixels();
  // The trees hidden: the pixels that change are the rays' (and their hit points').
  const treeBoxes = [...document.querySelectorAll('.view3d-controls input[data-view^=tree-]')];
  treeBoxes.forEach(b => b.click());
  await frame();
  const hidden = pixels();
  treeBoxes.forEach(b => b.click());
  await frame();
  // Each kind of ray hidden in turn (a click on its legend): the pixels that change are its own.
  const changed = (a, b) => {
    let n = 0;
    for (let i = 0; i < a.length; i += 4) if (distance(a, i, [b[i], b[i + 1], b[i + 2]]) >= 12) n++;
    return n;
  };
  const rays = {drawn: 0, trees: changed(shown, hidden)};
  for (let i = 0; i < shown.length; i += 4) if (distance(shown, i, background) >= 12) rays.drawn++;
  for (const key of document.querySelectorAll('.view3d-legend [data-kind]')) {
    key.click();
    await frame();
    rays[key.dataset.kind] = changed(shown, pixels());
    key.click();
    await frame();
  }
  const rect = canvas.getBoundingClientRect();
  const at = (dx) => ({clientX: rect.left + rect.width / 2 + dx, clientY: rect.top + rect.height / 2, bubbles: true});
  canvas.dispatchEvent(new MouseEvent('mousedown', at(0)));
  window.dispatchEvent(new MouseEvent('mousemove', at(60)));
  window.dispatchEvent(new MouseEvent('mouseup', at(60)));
  await frame();
  const turned = pixels();
  document.querySelector('.view3d-controls input[type=checkbox]').click();
  await frame();
  const wired = pixels();
  const kinds = {};
  for (const tree of data.trees) for (const s of tree.segments) {
    const k = s.kind === 'shadow' && s.hit !== null ? 'blocked' : s.kind;
    kinds[k] = (kinds[k] || 0) + 1;
  }
  return JSON.stringify({
    rays, kinds, treeBoxes: treeBoxes.length,
    hashes: {shown: hash(shown), turned: hash(turned), wired: hash(wired)},
    trees: data.trees.length,
    texts: [...document.querySelectorAll('.view3d pre')].map(p => p.textContent),
    treeTexts: data.trees.map(t => t.text),
    objects: data.objects.length,
  });
})()
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("page")
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    parser.add_argument("--screenshot", default=None, help="write what the canvas first shows to this PNG")
    args = parser.parse_args()
    if not shutil.which(args.chromium):
        print(f"SKIPPED the ray-tree view's browser check: {args.chromium} is missing (apt-get install chromium)")
        return 2
    url = pathlib.Path(args.page).resolve().as_uri()
    with tempfile.TemporaryDirectory() as profile:
        browser = Chromium(args.chromium, profile)
        try:
            deadline = time.monotonic() + TIMEOUT
            session = browser.open(url, deadline, viewport=(900, 900))
            if args.screenshot:
                # The canvas alone, as a student first sees it: before the probe's clicks and drag.
                box = browser.send("Runtime.evaluate", {
                    "expression": "new Promise(r => requestAnimationFrame(() => { const b = document.querySelector("
                                  "'.view3d canvas').getBoundingClientRect(); r(JSON.stringify([b.x, b.y, b.width, b.height])); }))",
                    "awaitPromise": True, "returnByValue": True}, session=session, deadline=deadline)
                x, y, width, height = json.loads(box["result"]["value"])
                clip = {"x": x, "y": y, "width": width, "height": height, "scale": 1}
                shot = browser.send("Page.captureScreenshot", {"format": "png", "clip": clip},
                                    session=session, deadline=deadline)
                pathlib.Path(args.screenshot).write_bytes(base64.b64decode(shot["data"]))
            result = browser.send("Runtime.evaluate", {"expression": PROBE, "awaitPromise": True,
                                                       "returnByValue": True}, session=session, deadline=deadline)
            if "exceptionDetails" in result:
                details = result["exceptionDetails"]
                print(f"the probe failed: {details.get('text')} {details.get('exception', {}).get('description')}")
                return 1
            r = json.loads(result["result"]["value"])
            failures = []
            area = 720 * 480
            if r["rays"]["drawn"] < area // 50:
                failures.append(f"the canvas is background but for {r['rays']['drawn']} pixels")
            if r["treeBoxes"] != r["trees"]:
                failures.append(f"{r['treeBoxes']} tree toggles for {r['trees']} trees")
            if r["rays"]["trees"] == 0:
                failures.append("hiding the trees changes nothing: no ray is drawn")
            # A hit's point is 25 pixels; a segment across the view hundreds: 50 asks for lines.
            for kind, segments in r["kinds"].items():
                if r["rays"].get(kind, 0) < 50:
                    failures.append(f"{segments} {kind} ray(s) in the data, and hiding them changes "
                                    f"{r['rays'].get(kind, 0)} pixels, not a line's 50")
            if r["hashes"]["turned"] == r["hashes"]["shown"]:
                failures.append("a drag did not turn the view")
            if r["hashes"]["wired"] == r["hashes"]["turned"]:
                failures.append("the wireframe toggle did not redraw")
            for text in r["treeTexts"]:
                if not any(text in shown for shown in r["texts"]):
                    failures.append("a tree's text is not on the page")
            failures += [f"a request left the page: {request}" for request in browser.requests_elsewhere()]
            print(json.dumps({k: r[k] for k in ("rays", "kinds", "hashes", "trees", "objects")}))
            for failure in failures:
                print(f"FAILED: {failure}")
            return 1 if failures else 0
        finally:
            browser.close()


if __name__ == "__main__":
    sys.exit(main())
