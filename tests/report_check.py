#!/usr/bin/env python3
"""Opens the grader's report.html in headless Chromium (stdlib only; the DevTools client
of book/browsercheck.py) and checks that it works offline:
  - every <img> loaded (expected / yours / difference of each scene), at least three;
  - no request went anywhere but file:// (or data:);
  - clicking a pixel of a scene's image shows the command that prints its ray tree, for a final
    picture (drawn smaller than its scene) at the picture's size (`--size WxH`);
  - the ray tree of the first differing pixel of a failed scene is in the page;
  - a failed scene's 3D view (at stages that trace a ray tree) opens by itself, its WebGL canvas
    draws (pixels not all background), and a click on the scene's "yours" image far from the
    pixel shown picks another grid pixel: the trees drawn, their text and the canvas change.
Usage: python3 tests/report_check.py REPORT.html [--chromium PATH] [--expect-view]
(--expect-view: the report must hold a 3D view.)
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
  // A final picture's click: its command draws the scene at the picture's size.
  const final = document.querySelector('td[data-final] img');
  let pickedFinal = null;
  if (final) {
    const rect = final.getBoundingClientRect();
    final.dispatchEvent(new MouseEvent('click', {clientX: rect.left + 1, clientY: rect.top + 1, bubbles: true}));
    pickedFinal = {text: document.getElementById('picked').textContent,
                   size: final.naturalWidth + 'x' + final.naturalHeight};
  }
  // The first 3D view: open by itself; its data is a script loaded from beside the images.
  const frame = () => new Promise(r => requestAnimationFrame(() => r()));
  const box = document.querySelector('details[data-view]');
  let view = null;
  if (box) {
    const root = () => box.querySelector('.view3d');
    for (let i = 0; i < 200 && !(root() && root().dataset.pixel); i++) await new Promise(r => setTimeout(r, 50));
    view = {open: box.open, loaded: !!(root() && root().dataset.pixel)};
    if (view.loaded) {
      const canvas = root().querySelector('canvas');
      const pixels = () => {
        const copy = document.createElement('canvas');
        copy.width = canvas.width; copy.height = canvas.height;
        const c = copy.getContext('2d');
        c.drawImage(canvas, 0, 0);
        return c.getImageData(0, 0, copy.width, copy.height).data;
      };
      const background = [32, 36, 40];
      const off = (a, i, rgb) => Math.abs(a[i] - rgb[0]) + Math.abs(a[i + 1] - rgb[1]) + Math.abs(a[i + 2] - rgb[2]) >= 12;
      await frame();
      const before = pixels();
      view.drawn = 0;
      for (let i = 0; i < before.length; i += 4) if (off(before, i, background)) view.drawn++;
      view.pixelBefore = root().dataset.pixel;
      view.textBefore = root().querySelector('pre').textContent;
      // A click on "yours" in the opposite quarter of the image from the pixel shown.
      const yours = box.closest('td').querySelector('img[alt=yours]');
      const [px, py] = view.pixelBefore.split(',').map(Number);
      const fx = px < yours.naturalWidth / 2 ? 0.85 : 0.15, fy = py < yours.naturalHeight / 2 ? 0.85 : 0.15;
      const rect = yours.getBoundingClientRect();
      yours.dispatchEvent(new MouseEvent('click', {clientX: rect.left + fx * rect.width,
                                                   clientY: rect.top + fy * rect.height, bubbles: true}));
      await frame();
      await frame();
      const after = pixels();
      view.pixelAfter = root().dataset.pixel;
      view.textChanged = root().querySelector('pre').textContent !== view.textBefore;
      view.changed = 0;
      for (let i = 0; i < after.length; i += 4) if (off(after, i, [before[i], before[i + 1], before[i + 2]])) view.changed++;
      view.caption = box.querySelector('.picked3d').textContent;
    }
  }
  return JSON.stringify({
    view,
    views: document.querySelectorAll('details[data-view]').length,
    images: images.length,
    broken: images.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src')),
    picked: picked,
    pickedFinal,
    trees: document.querySelectorAll('pre.tree').length,
    failed: document.querySelectorAll('tr.failed').length,
  });
})()
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("report")
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    parser.add_argument("--expect-view", action="store_true", help="fail when the report holds no 3D view")
    args = parser.parse_args()
    if not shutil.which(args.chromium):
        print(f"SKIPPED the report's browser check: {args.chromium} is missing (apt-get install chromium)")
        return 2
    url = pathlib.Path(args.report).resolve().as_uri()
    with tempfile.TemporaryDirectory() as profile:
        browser = Chromium(args.chromium, profile)
        try:
            deadline = time.monotonic() + TIMEOUT
            session = browser.open(url, deadline)
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
            f = r["pickedFinal"]
            if f is not None and f" --size {f['size']} --tree " not in f["text"]:
                failures.append(f"clicking a final picture shows {f['text']!r}, not drawn at its size {f['size']}")
            if r["failed"] and not r["trees"]:
                failures.append("a failed scene without the ray tree of its first differing pixel")
            v = r["view"]
            if v is None and args.expect_view:
                failures.append("no 3D view in the report (a failed scene of stage 08 or 10 has one)")
            if v is not None:
                if not (v["open"] and v["loaded"]):
                    failures.append(f"the first 3D view did not open and load its data: {v}")
                elif v["drawn"] < 1000:
                    failures.append(f"the 3D view's canvas drew {v['drawn']} pixels not background")
                elif v["pixelAfter"] == v["pixelBefore"] or not v["textChanged"] or v["changed"] < 50:
                    failures.append(f"a click on 'yours' did not change the trees drawn: {v}")
            failures += [f"the page requested {url}" for url in browser.requests_elsewhere()]
            print(f"report: {r['images']} images, {r['failed']} failed rows, {r['trees']} ray trees, "
                  f"{r['views']} 3D views; click: {r['picked']}"
                  + (f"; a final picture's click: {f['text']}" if f else ""))
            if v is not None and v.get("loaded"):
                print(f"3D view: {v['drawn']} pixels drawn; pixel {v['pixelBefore']} -> {v['pixelAfter']} "
                      f"({v['changed']} canvas pixels changed): {v['caption']}")
            for f in failures:
                print(f"FAILED: {f}")
            return 1 if failures else 0
        finally:
            browser.close()


if __name__ == "__main__":
    sys.exit(main())
