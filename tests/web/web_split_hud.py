#!/usr/bin/env python3
"""The page does what the window does (docs/web.md): the split view (`s`) and the HUD's text.

In headless Chromium (SwiftShader's WebGL 2) the page is driven with the window's keys, and
- the HUD lines over the picture must be the native window's for the same stage and keys: the
  window runs them under Xvfb (`shadowlab window --keys ... --state`) and its state's `hudText`
  (every line its panels drew, wrapped to its width) must hold the page's lines, in words, and
  nothing else;
- after `s` each half of the canvas must be the native `shadowlab render` of that half's
  settings at the half's size (the field of view widened as the window widens it), as the
  window's own test holds its halves (tests/render/test_window_projector.cpp), and the two halves
  must differ from each other as the two native renders do;
- `l` circles the light (the shadows move) until `l` again, and `c` brings back the first picture.
Saves the page with each split (page_split_STAGE.png: docs/images/web/ holds bias's).
Exit 77 (ctest: skipped) as web_browser.py does."""
import base64
import concurrent.futures
import json
import math
import pathlib
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import web_browser  # noqa: E402  (the browser, the page, the skip rule)

ROOT = pathlib.Path(__file__).resolve().parents[2]

# (stage, keys): the window's keys, pressed in the window and on the page after the stage opens.
HUD_CASES = [
    ("bias", "s"),       # the title, the first lesson, split: each half's label
    ("bias", "ns"),      # the next lesson and its split
    ("margin", "\t=v"),  # the second parameter stepped, a debug view's legend, no lesson
    ("mirror", "s"),     # the mirror's split: its two methods
]
# Stages whose split (`s` as the stage opens: the labels are held to the window's above) is
# compared pixel by pixel with native renders of its halves' settings, and whether its halves
# must differ: a lesson's failure beside its fix does; the mirror's texture and stencil methods
# draw the same reflection (0.2 % of pixels apart natively).
SPLIT_STAGES = [("bias", True), ("mirror", False)]

# The canvas's pixels in columns [x, x + w) against a PNG of that size (a data URL), or against
# the canvas's own columns [other, other + w) when the URL is null: how many pixels differ by more
# than the tolerance in a channel.
COMPARE_COLUMNS = """
const [url, x, w, other, tolerance, done] = arguments;
const web = document.getElementById('canvas');
const pixels = (source, sx) => { const c = document.createElement('canvas');
  c.width = w; c.height = web.height; const g = c.getContext('2d');
  g.drawImage(source, sx, 0, w, web.height, 0, 0, w, web.height);
  return g.getImageData(0, 0, w, web.height).data; };
const a = pixels(web, x);
const count = b => { let differ = 0, worst = 0;
  for (let i = 0; i < a.length; i += 4) { let d = 0;
    for (let k = 0; k < 3; ++k) d = Math.max(d, Math.abs(a[i + k] - b[i + k]));
    worst = Math.max(worst, d); if (d > tolerance) ++differ; }
  return {differ, total: a.length / 4, worst}; };
if (url === null) { done(count(pixels(web, other))); }
else { const img = new Image();
  img.onload = () => done(count(pixels(img, 0)));
  img.onerror = () => done({error: 'the native PNG did not load'});
  img.src = url; }
"""


def words(lines):
    return " ".join(lines).split()


def native_hud(args, stage, keys, out):
    """The native window's HUD lines for `stage` after `keys` (its --state's hudText)."""
    state = out / f"window_{stage}_{len(keys)}.json"
    run = subprocess.run(
        ["sh", str(ROOT / "tests" / "with_xvfb.sh"), "1920x1080x24", args.shadowlab, "window",
         "--stage", stage, "--size", "1280x720", "--frames", str(len(keys) + 3), "--keys", keys,
         "--state", str(state)], capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        return None, f"native window exit {run.returncode}: {run.stderr.strip()[-300:]}"
    return json.loads(state.read_text())["hudText"], ""


SPLIT_ON = "return Module.ccall('sl_web_split_sets', 'string', [], []) !== ''"


def open_stage(driver, body, stage):
    """The stage as a fresh window opens it: selected, the split off (it stays on across
    stages, as in the window)."""
    driver.execute_script("shadowlab.selectId(arguments[0])", stage)
    if driver.execute_script(SPLIT_ON):
        body.send_keys("s")


def page_hud(driver, body, stage, keys):
    """The page's HUD lines for `stage` after `keys`, pressed as the window's."""
    open_stage(driver, body, stage)
    if keys:
        body.send_keys(*keys)
    return driver.execute_script("return [shadowlab.hud, shadowlab.lastMessage]")


def hud_cases(driver, body, args, out, pool):
    """Each case's page lines against the window's: every page line is in the window's text
    (wrapped there: compared in words) and the words are as many. Returns the failures."""
    natives = {case: pool.submit(native_hud, args, *case, out) for case in HUD_CASES}
    failures = []
    for stage, keys in HUD_CASES:
        page, message = page_hud(driver, body, stage, keys)
        native, error = natives[(stage, keys)].result()
        name = f"{stage} after {keys!r}"
        if error:
            failures.append(f"HUD {name}: {error}")
            continue
        text = " ".join(words(native))
        missing = [line for line in page if " ".join(line.split()) not in text]
        same = not missing and len(words(page)) == len(words(native)) and not message
        print(f"web: HUD {name:22} {len(page)} line(s) on the page, {len(native)} in the window: "
              f"{'the same words' if same else 'DIFFER'}")
        if not same:
            failures.append(f"HUD {name}: the page shows {page} ({message!r}), the window "
                            f"{native}")
    return failures


def native_half(args, stage, sets, width, height, fovy, png):
    subprocess.run([args.shadowlab, "render", "--stage", stage, "--size", f"{width}x{height}",
                    "--fovy", f"{fovy:.6f}", "--out", str(png)] +
                   [a for name, value in sets for a in ("--set", f"{name}={value}")],
                   check=True, capture_output=True)
    return "data:image/png;base64," + base64.b64encode(png.read_bytes()).decode()


def scene_fovy(stage_info):
    """The field of view a half draws with: its scene's, widened to the half's aspect as the
    window widens it (math/orbit.h: fovyFittingWidth)."""
    scene = stage_info.get("defaultScene") or "slides"
    return json.loads((ROOT / "scenes" / f"{scene}.json").read_text())["camera"].get("fovy", 45)


def widened(fovy, aspect):
    framed = 4 / 3
    if aspect >= framed:
        return fovy
    half = math.radians(fovy) / 2
    return min(150.0, math.degrees(2 * math.atan(math.tan(half) * framed / aspect)))


def split_case(driver, body, args, out, stage_info, must_differ):
    """`s` on the page: each half the native render of its settings (the page's halves, whose
    labels hud_cases held to the window's); the halves differ from each other as the native ones
    do (within the pixel tolerance), by more than it where they `must_differ`. Returns the
    failures."""
    stage = stage_info["id"]
    open_stage(driver, body, stage)
    body.send_keys("s")
    hud, message, width, height, pairs = driver.execute_script(
        "const c = document.getElementById('canvas');"
        "return [shadowlab.hud, shadowlab.lastMessage, c.width, c.height,"
        "        Module.ccall('sl_web_split_sets', 'string', [], [])]")
    # "NAME\tN=V,N=V" a half a line (sl_web_split_sets)
    halves = [(line.split("\t")[0], [tuple(s.split("=", 1)) for s in line.split("\t")[1].split(",")
                                     if s]) for line in pairs.splitlines()]
    labels = [line for line in hud if line.startswith(("left: ", "right: "))]
    if message or len(labels) != 2 or len(halves) != 2:
        return [f"split {stage}: the page says {message!r}, labels {labels}"]
    failures, shares = [], []
    half = width // 2
    for k, (label, sets) in enumerate(halves):
        w = half if k == 0 else width - half
        fovy = widened(scene_fovy(stage_info), w / height)
        url = native_half(args, stage, sets, w, height, fovy, out / f"native_{stage}_half{k}.png")
        r = driver.execute_async_script(COMPARE_COLUMNS, url, k * half, w, 0,
                                        args.channel_tolerance)
        if "error" in r:
            failures.append(f"split {stage} half {k}: {r['error']}")
            continue
        share = r["differ"] / r["total"]
        ok = share <= args.pixel_tolerance and labels[k].endswith(label)
        print(f"web: split {stage:7} {labels[k]:40} {share:7.3%} of pixels differ from native "
              f"render ({' '.join(f'{n}={v}' for n, v in sets) or 'defaults'}, fovy {fovy:.1f}): "
              f"{'ok' if ok else 'DIFFERS'}")
        if not ok:
            failures.append(f"split {stage} half {k} ({labels[k]}, expected {label}): {share:.3%}")
    # The two halves against each other, on the page and natively (the PNGs written above).
    r = driver.execute_async_script(COMPARE_COLUMNS, None, 0, half, half, args.channel_tolerance)
    page_share = r["differ"] / r["total"]
    a = (out / f"native_{stage}_half0.png").read_bytes()
    b = (out / f"native_{stage}_half1.png").read_bytes()
    native_share = halves_differ(driver, a, b, args) if len(a) and len(b) else 0
    ok = abs(page_share - native_share) <= args.pixel_tolerance and \
        (native_share > args.pixel_tolerance or not must_differ)
    print(f"web: split {stage:7} the halves differ in {page_share:.2%} of pixels on the page, "
          f"{native_share:.2%} natively: {'ok' if ok else 'NOT as native'}")
    if not ok:
        failures.append(f"split {stage}: halves differ by {page_share:.2%}, natively "
                        f"{native_share:.2%}")
    pathlib.Path(out, f"web_split_{stage}.png").write_bytes(base64.b64decode(
        web_browser.canvas_url(driver).split(",", 1)[1]))
    driver.save_screenshot(str(out / f"page_split_{stage}.png"))  # with its HUD (docs/web.md)
    body.send_keys("s")  # split off again
    return failures


NATIVE_PAIR = """
const [urlA, urlB, tolerance, done] = arguments;
const load = url => new Promise((ok, no) => { const i = new Image(); i.onload = () => ok(i);
  i.onerror = no; i.src = url; });
Promise.all([load(urlA), load(urlB)]).then(([a, b]) => {
  const px = img => { const c = document.createElement('canvas'); c.width = a.width;
    c.height = a.height; const g = c.getContext('2d'); g.drawImage(img, 0, 0);
    return g.getImageData(0, 0, a.width, a.height).data; };
  const p = px(a), q = px(b); let differ = 0;
  for (let i = 0; i < p.length; i += 4) { let d = 0;
    for (let k = 0; k < 3; ++k) d = Math.max(d, Math.abs(p[i + k] - q[i + k]));
    if (d > tolerance) ++differ; }
  done(differ / (p.length / 4)); });
"""


def halves_differ(driver, a, b, args):
    url = lambda data: "data:image/png;base64," + base64.b64encode(data).decode()
    return driver.execute_async_script(NATIVE_PAIR, url(a), url(b), args.channel_tolerance)


def light_case(driver, body, args, stage="depth"):
    """The window's `l` and `c` on the page: the light circling for about a second moves the
    shadows (more than --pixel-tolerance of the canvas differs), `l` again stops it (two pictures
    a moment apart are the same), and `c` brings back the stage's first picture."""
    open_stage(driver, body, stage)
    width = driver.execute_script("return document.getElementById('canvas').width")
    share = lambda url: (lambda r: r.get("differ", 1) / max(r.get("total", 1), 1))(
        driver.execute_async_script(COMPARE_COLUMNS, url, 0, width, 0, args.channel_tolerance))
    first = web_browser.canvas_url(driver)
    body.send_keys("l")
    time.sleep(1.0)
    body.send_keys("l")
    stopped = web_browser.canvas_url(driver)
    moved = share(first)
    time.sleep(0.3)
    still = share(stopped)
    body.send_keys("c")
    back = share(first)
    message = driver.execute_script("return shadowlab.lastMessage")
    ok = moved > args.pixel_tolerance and still == 0 and back <= args.pixel_tolerance and not message
    print(f"web: light {stage}: `l` for 1 s moved {100 * moved:.2f} % of the pixels, stopped "
          f"{100 * still:.2f} %, `c` back to the first picture {100 * back:.3f} %: "
          f"{'as the window' if ok else 'WRONG'}")
    return [] if ok else [f"light {stage}: moved {moved:.4f}, after stopping {still:.4f}, after "
                          f"`c` {back:.4f} ({message!r})"]


def main():
    ap = web_browser.site_arguments()
    ap.add_argument("--channel-tolerance", type=int, default=8)
    ap.add_argument("--pixel-tolerance", type=float, default=0.01)
    args = ap.parse_args()
    if subprocess.run(["sh", "-c", "command -v Xvfb"], capture_output=True).returncode != 0:
        web_browser.skip("Xvfb is not installed (the native window's text is read under it)")
    out = web_browser.site_output(args)
    stages = json.loads(subprocess.run([args.shadowlab, "stages", "--json"], check=True,
                                       capture_output=True, text=True).stdout)
    stages = {s["id"]: s for s in (stages["stages"] if isinstance(stages, dict) else stages)}
    driver = web_browser.browser()
    pool = concurrent.futures.ThreadPoolExecutor(2)
    failures = []
    try:
        if not web_browser.open_page(driver, args.site):
            print("web: FAILED: the page never became ready")
            return 1
        body = driver.find_element("tag name", "body")
        failures += hud_cases(driver, body, args, out, pool)
        failures += light_case(driver, body, args)
        for stage, must_differ in SPLIT_STAGES:
            failures += split_case(driver, body, args, out, stages[stage], must_differ)
    finally:
        pool.shutdown(cancel_futures=True)
        driver.quit()
    return web_browser.exit_code(failures)


if __name__ == "__main__":
    sys.exit(main())
