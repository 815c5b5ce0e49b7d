#!/usr/bin/env python3
"""The browser edition in a real browser (GUIDE section 9): headless Chromium (SwiftShader's
WebGL 2) driven by Selenium opens build-web/site/index.html from the disk, steps through every
core stage with the page's keys, and compares each picture with the native `shadowlab render`
of the same stage and camera. A pixel differs when a channel differs by more than
--channel-tolerance; a stage passes when at most --pixel-tolerance of its pixels differ.
Saves the browser's picture of each stage (web_<id>.png, docs/images/web/ holds a copy) and the
whole page at 1920x1080; prints one line per stage.
Exit 77 (ctest: skipped) with the reason when emscripten's build, Chromium or Selenium is absent,
unless SHADOWLAB_WEB_REQUIRED=1 (CI's web step, which built the site first)."""
import argparse
import base64
import concurrent.futures
import functools
import http.server
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import threading
import time

SKIP = 77


def skip(reason):
    if os.environ.get("SHADOWLAB_WEB_REQUIRED") == "1":
        print(f"web: FAILED: {reason}")
        sys.exit(1)
    print(f"web: skipped: {reason}")
    sys.exit(SKIP)


def browser():
    try:
        from selenium import webdriver
    except ImportError:
        skip("python3-selenium is not installed (scripts/deps.sh --test installs it)")
    driver_path = shutil.which("chromedriver")
    if not shutil.which("chromium") or not driver_path:
        skip("chromium or chromium-driver is not installed")
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    for flag in ("--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                 "--no-sandbox", "--window-size=1920,1080"):
        options.add_argument(flag)
    return webdriver.Chrome(service=Service(driver_path), options=options)


# Draws an image (the canvas, or a PNG's data URL) on a 2D canvas and counts the pixels whose
# largest channel difference exceeds the tolerance.
COMPARE = """
const [nativeUrl, tolerance, done] = arguments;
const web = document.getElementById('canvas');
const pixels = source => { const c = document.createElement('canvas');
  c.width = web.width; c.height = web.height; const g = c.getContext('2d');
  g.drawImage(source, 0, 0); return g.getImageData(0, 0, c.width, c.height).data; };
const a = pixels(web);
const img = new Image();
img.onload = () => { const b = pixels(img); let differ = 0, worst = 0;
  for (let i = 0; i < a.length; i += 4) { let d = 0;
    for (let k = 0; k < 3; ++k) d = Math.max(d, Math.abs(a[i + k] - b[i + k]));
    worst = Math.max(worst, d); if (d > tolerance) ++differ; }
  done({differ, total: a.length / 4, worst, png: web.toDataURL('image/png')}); };
img.onerror = () => done({error: 'the native PNG did not load'});
img.src = nativeUrl;
"""


def lessons_and_views(driver, body, stage):
    """Steps through the stage's lessons ('n', as the window steps: the one after the lesson on
    screen) and views ('v'): each must draw without a message, and as many presses as the stage
    has lessons must show each of them once. Returns the failures; prints what it reached."""
    failures = []
    lesson = lambda: driver.execute_script("return document.getElementById('lesson').textContent")
    counted = re.search(r"lesson \d+/(\d+) \(n\)|none of the (\d+) lessons", lesson())
    count = int(next(filter(None, counted.groups()))) if counted else 0
    seen = set()
    for _ in range(count):
        body.send_keys("n")
        text, message = driver.execute_script(
            "return [document.getElementById('lesson').textContent, shadowlab.lastMessage]")
        shown = re.match(rf"lesson (\d+)/{count} \(n\): ", text)
        if not shown:
            failures.append(f"{stage} lesson of {count}: the page shows {text!r}")
        elif message:
            failures.append(f"{stage} {text}: {message!r}")
        else:
            seen.add(int(shown.group(1)))
    if count and seen != set(range(1, count + 1)):
        failures.append(f"{stage}: {count} presses of n showed lessons {sorted(seen)}")
    views = []
    for _ in range(6):
        body.send_keys("v")
        view, message = driver.execute_script("return [shadowlab.view, shadowlab.lastMessage]")
        if message:
            failures.append(f"{stage} view {view}: {message!r}")
        if view in views:
            break
        views.append(view)
    print(f"web: {stage:9} {count} lesson(s) and views {', '.join(views)} drawn")
    return failures


def parameters(driver, stage):
    """The page's parameter table must list the stage's declared parameters (the names and
    defaults `stages --json` prints), and a value outside the declaration must be refused in one
    line naming the parameter. Returns the failures."""
    rows = driver.execute_script(
        "return [...document.querySelectorAll('#params input')].map(i => [i.name, i.value])")
    declared = [p["name"] for p in stage["parameters"]]
    if [name for name, _ in rows] != declared:
        return [f"{stage['id']}: the page's parameters {rows} are not the declared {declared}"]
    if not rows:
        return []
    failures = []
    # The window's keys on the table: Tab selects the next parameter, '+' steps it (ParamSet's
    # step, the page redraws) and '-' steps it again; no other value moves, no message.
    body = driver.find_element("tag name", "body")
    values = lambda: driver.execute_script(
        "return [...document.querySelectorAll('#params input')].map(i => i.value)")
    index = 1 % len(rows)
    body.send_keys(*(["\t"] * index))
    before = values()
    body.send_keys("+")
    up = values()
    body.send_keys("-")
    down = values()
    moved = [k for k in range(len(rows)) if up[k] != before[k]] + \
        [k for k in range(len(rows)) if down[k] != up[k]]
    message = driver.execute_script("return shadowlab.lastMessage")
    if set(moved) != {index} or message:
        failures.append(f"{stage['id']}: Tab x{index}, '+' then '-' gave {before} -> {up} -> "
                        f"{down} ({message!r})")
    body.send_keys(*(["\t"] * (len(rows) - index)))  # back to the first, as the stage opens
    body.send_keys("x")
    name = rows[0][0]
    message = driver.execute_script(
        "const i = document.querySelector('#params input'); i.value = 'not-a-value';"
        "i.dispatchEvent(new Event('change')); return shadowlab.lastMessage")
    if name not in message or "\n" in message.strip():
        failures.append(f"{stage['id']}: {name}=not-a-value gave {message!r}")
    return failures


# A student's folder through the page's folder picker (Selenium hands the input a folder): the
# picked folder's name, the state line and the message over the picture.
TAKE = """
const [done] = arguments;
const wait = () => shadowlab.student.taken > shadowlab.takenBefore
  ? done([shadowlab.lastMessage, document.getElementById('studentState').textContent,
          shadowlab.stages[shadowlab.current].id, shadowlab.student.read])
  : setTimeout(wait, 50);
wait();
"""


def pick_folder(driver, folder):
    """Hands `folder` to the page's folder input; returns [message, state line, stage shown,
    the folder the intake read inside it]."""
    field = driver.find_element("id", "folder")
    driver.execute_script("arguments[0].value = ''; shadowlab.takenBefore = shadowlab.student.taken",
                          field)
    field.send_keys(str(folder.resolve()))
    return driver.execute_async_script(TAKE)


def native_render(shadowlab, stage, folder, png, sets=()):
    """Native `render --shaders`: None when it drew `png`, else its first `FILE:LINE: error:`
    line with the folder cut (or its whole stderr when it printed none)."""
    run = subprocess.run([shadowlab, "render", "--stage", stage, "--shaders", str(folder),
                          "--out", str(png)] + [a for s in sets for a in ("--set", s)],
                         capture_output=True, text=True)
    if run.returncode == 0:
        return None
    for line in run.stderr.splitlines():
        if ": error: " in line and line.split(":")[1].isdigit():
            return line.replace(str(folder) + "/", "")
    return run.stderr.strip().replace("shadowlab: shader error: ", "").replace(str(folder) + "/", "")


def canvas_url(driver):
    return driver.execute_script("return document.getElementById('canvas').toDataURL()")


def differing_share(driver, native_png, args):
    url = "data:image/png;base64," + base64.b64encode(native_png.read_bytes()).decode()
    r = driver.execute_async_script(COMPARE, url, args.channel_tolerance)
    return r.get("differ", 1) / r.get("total", 1), r


def student_folder(driver, args, out, case_dir):
    """One corpus hand-in (tests/students/CASE, its case.json) picked in the page over its stage:
    the intake's notes the case expects are shown; where native `render --shaders` (on the
    folder the intake read) draws, the page draws the same picture; where native refuses it
    with a `FILE:LINE: error:` line, the page shows that line over the picture and the last good
    picture stays. Returns the failures."""
    case = json.loads((case_dir / "case.json").read_text())
    folder = case_dir / case.get("submission", "")
    stage = case["stage"]
    driver.execute_script("shadowlab.takeFolder('', ''); shadowlab.selectId(arguments[0])", stage)
    before = canvas_url(driver)
    started = time.monotonic()
    message, state, shown, read = pick_folder(driver, folder)
    took = time.monotonic() - started
    failures = [f"{case_dir.name}: the page's notes {state!r} lack {note!r}"
                for note in case.get("notes", []) if note not in state]
    native = out / f"native_student_{case_dir.name}.png"
    rendered = args.prerendered.get(case_dir.name)
    error = rendered.result() if rendered and not read else \
        native_render(args.shadowlab, stage, folder / read, native)
    if error is None:
        share, r = differing_share(driver, native, args)
        print(f"web: student {case_dir.name:34} drawn in {took:.2f} s: {share:7.3%} of pixels "
              f"differ from native --shaders")
        if message or share > args.pixel_tolerance:
            pathlib.Path(out, f"web_student_{case_dir.name}.png").write_bytes(
                base64.b64decode(r["png"].split(",", 1)[1]))
            failures.append(f"{case_dir.name}: the page says {message!r}; {share:.3%} of pixels "
                            f"differ")
        return failures
    if not (out / "page_student_error.png").exists():  # what a student sees (docs/web.md)
        driver.save_screenshot(str(out / "page_student_error.png"))
    kept = canvas_url(driver) == before and shown == stage
    named = "/".join(filter(None, [folder.name, read, error]))  # as the student picked it
    ok = named in message.splitlines() and kept
    print(f"web: student {case_dir.name:34} refused in {took:.2f} s as native: {error!r}: "
          f"{'ok' if ok else 'NO'}")
    if not ok:
        failures.append(f"{case_dir.name}: the page says {message!r} (stage {shown}), native "
                        f"{named!r}; last good picture kept: {kept}")
    return failures


def frame_time(driver, native_printed):
    """The page's median ms a frame of the stage on screen (20 frames, each waited for) beside
    the one native `render --repeat 20` printed; printed and returned (a table, not a test:
    docs/web.md)."""
    page_ms = driver.execute_script("return Module.ccall('sl_web_frame_ms', 'number', "
                                    "['number'], [20])")
    native_ms = float(re.search(r"median ([0-9.]+) ms/frame", native_printed).group(1))
    stage = driver.execute_script("return shadowlab.stages[shadowlab.current].id")
    print(f"web: {stage:9} median ms a frame: page {page_ms:.2f} (SwiftShader), native "
          f"{native_ms:.2f} (llvmpipe): {page_ms / native_ms:.1f}x")
    return {"page_ms": page_ms, "native_ms": native_ms}


def student_cases(driver, args, corpus):
    """The corpus's core-tree hand-ins of stages the page runs (their case.json says which)."""
    runs = set(driver.execute_script("return shadowlab.stages.filter(s => !s.nativeOnly)"
                                     ".map(s => s.id)"))
    for folder in sorted(p for p in corpus.iterdir() if (p / "case.json").is_file()):
        case = json.loads((folder / "case.json").read_text())
        if case.get("tree") == "core" and case.get("verdict") != "MISSING" and \
                case.get("stage") in runs and re.search(args.students, folder.name):
            yield folder


def prerender(driver, args, out, corpus, pool):
    """Native renders of every case's folder, started while the browser works (two at a time:
    the page waits on them, not the other way round)."""
    args.prerendered = {}
    for folder in student_cases(driver, args, corpus):
        case = json.loads((folder / "case.json").read_text())
        args.prerendered[folder.name] = pool.submit(
            native_render, args.shadowlab, case["stage"], folder / case.get("submission", ""),
            out / f"native_student_{folder.name}.png")


def student_folders(driver, args, out, corpus):
    """Every core-tree hand-in of the student corpus whose stage the page runs (its case.json
    says which), through the page's folder picker. Returns the failures."""
    failures = []
    for folder in student_cases(driver, args, corpus):
        failures += student_folder(driver, args, out, folder)
    driver.execute_script("shadowlab.takeFolder('', '')")
    return failures


def site_arguments():
    """The options every browser script takes: the built site, the native program, an output
    folder."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--site", required=True)
    ap.add_argument("--shadowlab", required=True)
    ap.add_argument("--out", required=True)
    return ap


def site_output(args):
    """The built site must exist (else skipped, as skip says); returns the output folder, made."""
    if not pathlib.Path(args.site, "shadowlab.js").exists():
        skip(f"no browser build in {args.site} (bash scripts/web.sh builds it)")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    return out


def exit_code(failures):
    """Prints each failure on its line; the exit code (1 when any)."""
    for f in failures:
        print(f"web: FAILED: {f}")
    return 1 if failures else 0


def serve(site):
    """Serves the site over HTTP on a free port of 127.0.0.1 (as a course's static host does), in
    a thread of this process; returns the page's address."""
    handler = functools.partial(QuietHandler, directory=str(site))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return f"http://127.0.0.1:{server.server_address[1]}/index.html"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def open_page(driver, site, address=None):
    """Opens the site's page (from the disk, or at `address`) and waits until it is ready (30 s
    at most); returns whether it became ready."""
    driver.get(address or pathlib.Path(site, "index.html").resolve().as_uri())
    for _ in range(300):
        if driver.execute_script("return window.shadowlab && window.shadowlab.ready"):
            return True
        time.sleep(0.1)
    return False


def main():
    ap = site_arguments()
    ap.add_argument("--channel-tolerance", type=int, default=8)
    ap.add_argument("--pixel-tolerance", type=float, default=0.01)
    ap.add_argument("--students", default="", help="only the corpus cases this regex finds")
    ap.add_argument("--students-only", action="store_true", help="skip the stages' own tour")
    args = ap.parse_args()
    out = site_output(args)
    stages = json.loads(subprocess.run([args.shadowlab, "stages", "--json"], check=True,
                                       capture_output=True, text=True).stdout)
    stages = stages["stages"] if isinstance(stages, dict) else stages
    failures = []
    driver = browser()
    pool = concurrent.futures.ThreadPoolExecutor(2)
    try:
        started = time.monotonic()
        if not open_page(driver, args.site):
            skip_or_fail = driver.execute_script("return window.shadowlab && shadowlab.lastMessage")
            print(f"web: FAILED: the page never became ready ({skip_or_fail})")
            return 1
        print(f"web: first picture {time.monotonic() - started:.2f} s after opening the page")
        ids = driver.execute_script("return shadowlab.stages.map(s => s.id)")
        if ids != [s["id"] for s in stages]:
            failures.append(f"the page lists {ids}, the native program {[s['id'] for s in stages]}")
        corpus = pathlib.Path(__file__).resolve().parents[1] / "students"
        prerender(driver, args, out, corpus, pool)
        body = driver.find_element("tag name", "body")
        frame_times = {}
        for index, stage in enumerate([] if args.students_only else stages):
            body.send_keys(str(index))  # the window's key for the stage
            current, message = driver.execute_script(
                "return [shadowlab.current, shadowlab.lastMessage]")
            if current != index:
                failures.append(f"key {index}: the page shows stage {current}")
                continue
            if "core" not in stage.get("trees", ["core"]):  # the legacy-only stage
                ok = "native program" in message
                print(f"web: {stage['id']:9} native only: {'told' if ok else 'NOT told'}")
                if not ok:
                    failures.append(f"{stage['id']}: no 'native program' note ({message!r})")
                continue
            if message:
                failures.append(f"{stage['id']}: the page says {message!r}")
                continue
            failures += lessons_and_views(driver, body, stage["id"])
            failures += parameters(driver, stage)
            body.send_keys("x")  # the defaults again, for the comparison
            native = out / f"native_{stage['id']}.png"
            printed = subprocess.run([args.shadowlab, "render", "--stage", stage["id"], "--out",
                                      str(native), "--repeat", "20"],
                                     check=True, capture_output=True, text=True).stdout
            url = "data:image/png;base64," + base64.b64encode(native.read_bytes()).decode()
            r = driver.execute_async_script(COMPARE, url, args.channel_tolerance)
            if "error" in r:
                failures.append(f"{stage['id']}: {r['error']}")
                continue
            pathlib.Path(out, f"web_{stage['id']}.png").write_bytes(
                base64.b64decode(r["png"].split(",", 1)[1]))
            share = r["differ"] / r["total"]
            verdict = "ok" if share <= args.pixel_tolerance else "DIFFERS"
            print(f"web: {stage['id']:9} {share:7.3%} of pixels differ by more than "
                  f"{args.channel_tolerance}/255 (worst {r['worst']}): {verdict}")
            frame_times[stage["id"]] = frame_time(driver, printed)
            if verdict != "ok":
                failures.append(f"{stage['id']}: {share:.3%} of pixels differ")
        (out / "frame_times.json").write_text(json.dumps(frame_times, indent=1) + "\n")
        failures += student_folders(driver, args, out, corpus)
        body.send_keys("2")  # the whole page as a student sees it at 1920x1080 (the README's)
        driver.save_screenshot(str(out / "page_1920x1080.png"))
    finally:
        pool.shutdown(cancel_futures=True)
        driver.quit()
    return exit_code(failures)


if __name__ == "__main__":
    sys.exit(main())
