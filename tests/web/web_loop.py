#!/usr/bin/env python3
"""A shader that loops never freezes the page (docs/web.md, "A shader that loops"): headless
Chromium opens the built page; a corpus hand-in whose loops end (LOOPS_END) is drawn over the
depth stage, with no note naming the budget's uniform; then a folder `looping/` is picked: the
depth-stage lit.frag of tests/web/looping (a filter loop that never ends) beside the margin
stage's file of a corpus hand-in (tests/students/MARGIN_CASE). The page must say, naming the
file, that a loop ran past the loop budget, within --bound seconds, keep the last good picture,
and still answer (the next view, another stage, our peers stage's loops through the budget). Then the page's `check --all` over the
folder: every depth row TIMEOUT naming the file (native `check` gives the stage TIMEOUT from its
CPU-time budget; --native runs it and compares, about 3 minutes), the margin stage graded after
it with the case's verdict. Prints the times. Exit 77 (ctest: skipped) as web_browser.py does."""
import json
import os
import pathlib
import re
import shutil
import signal
import sys
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import web_browser  # noqa: E402  (the browser, the folder picker, the skip rule)
import web_check  # noqa: E402  (the page's check, native check and the row comparison)

HERE = pathlib.Path(__file__).resolve().parent
MARGIN_CASE = "margin_tan_clamp"  # a margin hand-in the corpus grades PASS
LOOPS_END = "depth_pcf_loop"  # a depth hand-in filtering in two loops that end
FILE = "looping/depth/lit.frag"  # as the student picked it
SAID = re.compile(re.escape(FILE) + r": error: a loop ran past (\d+) iterations")


def hand_in(out):
    """looping/: our looping depth file and the corpus case's margin file. (folder, margin's
    verdict from its case.json)"""
    folder = out / "looping"
    shutil.rmtree(folder, ignore_errors=True)
    case = HERE.parent / "students" / MARGIN_CASE
    shutil.copytree(HERE / "looping" / "depth", folder / "depth")
    shutil.copytree(case / "margin", folder / "margin")
    return folder, json.loads((case / "case.json").read_text())["verdict"]


def lecture(driver, args, folder, out):
    """A hand-in whose loops end, then the looping folder over the depth stage (the last good
    picture is the first's), then the next view, another stage, our peers stage. Failures."""
    failures = []
    # A hand-in whose loops end is drawn, and the probe's uniform is not called the student's.
    driver.execute_script("shadowlab.selectId('depth')")
    message, state, _, _ = web_browser.pick_folder(driver, HERE.parent / "students" / LOOPS_END)
    print(f"web: loop: {LOOPS_END} (loops that end) drawn with message {message!r}")
    if message or not state.startswith("your shaders") or "sl_" in state:
        failures.append(f"{LOOPS_END}: the page says {message!r}, {state!r}")
    before = web_browser.canvas_url(driver)
    started = time.monotonic()
    message, state, shown, _ = web_browser.pick_folder(driver, folder)
    took = time.monotonic() - started
    said = SAID.search(message)
    kept = web_browser.canvas_url(driver) == before and shown == "depth"
    print(f"web: loop: the page answered the looping folder in {took:.2f} s: {message!r}; "
          f"last good picture kept: {kept}")
    driver.save_screenshot(str(out / "page_loop.png"))
    if not said or not state.startswith("not adopted") or not kept:
        failures.append(f"the page says {message!r} ({state.splitlines()[0]!r}), last good "
                        f"picture kept: {kept}")
    if took > args.bound:
        failures.append(f"the page took {took:.1f} s to stop the loop (bound {args.bound} s)")
    body = driver.find_element("tag name", "body")
    for key, what in (("v", "the next view"), ("1", "stage 1")):
        shown_before = web_browser.canvas_url(driver)
        started = time.monotonic()
        body.send_keys(key)
        message = driver.execute_script("return shadowlab.lastMessage")
        drawn = web_browser.canvas_url(driver) != shown_before
        print(f"web: loop: then {what} drew in {time.monotonic() - started:.2f} s "
              f"(message {message!r}, a new picture: {drawn})")
        if message or not drawn:
            failures.append(f"after the loop, {what} says {message!r}, a new picture: {drawn}")
    # Our peers stage filters in loops: drawn through the budget, which "the ESSL WebGL runs"
    # shows (that its picture is native's is web_browser.py's test).
    message, essl = driver.execute_script(
        "shadowlab.selectId('peers'); shadowlab.showTranslation();"
        "return [shadowlab.lastMessage, document.getElementById('essl').textContent]")
    steps = essl.count("if (sl_loopSpent()) break;")
    print(f"web: loop: our peers stage drew (message {message!r}) with {steps} loop(s) "
          f"counted in the ESSL the page shows")
    if message or not steps:
        failures.append(f"our peers stage says {message!r}; budget steps in its ESSL: {steps}")
    return failures


def check_all(driver, args, folder, margin, out):
    """The page's check --all over the looping folder; `margin` the margin rows' verdict.
    Failures."""
    failures = []
    got = driver.execute_async_script(web_check.RUN, "all", str(args.seed))
    if got.get("error"):
        return [f"the page's check says {got['error']!r}"]
    report = json.loads(got["report"])
    (out / "page_report_looping.json").write_text(got["report"])
    rows = web_check.rows_of(report)
    depth = [r for k, r in rows if k[0] == "depth/core"]
    after = [r for k, r in rows if k[0] == "margin/core"]
    stopped = [r for r in depth if r["verdict"] == "TIMEOUT" and FILE in r["message"]
               and r["message"].startswith("stage depth (core): ")]
    graded = [r for r in after if r["verdict"] == margin]
    print(f"web: loop: the page's check --all in {got['seconds']:.1f} s: {len(stopped)} of "
          f"{len(depth)} depth rows TIMEOUT naming {FILE} "
          f"({depth[0]['message'] if depth else 'none'!r}); then {len(graded)} of {len(after)} "
          f"margin rows {margin} ({MARGIN_CASE}'s verdict)")
    if not depth or len(stopped) != len(depth):
        failures.append(f"depth rows: {[(r['verdict'], r['message']) for r in depth]}")
    if not after or len(graded) != len(after):
        failures.append(f"margin rows: {[(r['verdict'], r['message']) for r in after]}")
    if args.native:
        native, seconds, _ = web_check.native_check(args.shadowlab, "depth", folder, args.seed,
                                                    out / "native_report_looping.json")
        page = dict(report, stages=[s for s in report["stages"] if s["stage"] == "depth"])
        differ, _ = web_check.compare("looping", page, native, None)
        print(f"web: loop: native check --stage depth in {seconds:.0f} s: "
              f"{'the same verdicts' if not differ else differ}")
        failures += differ
    return failures


def watchdog(driver, seconds):
    """A frozen tab answers nothing, not even Selenium's timeouts: after `seconds` the test
    fails, the browser closed (or its driver killed)."""
    def frozen():
        print(f"web: FAILED: the page did not finish within {seconds} s: a frozen tab", flush=True)
        served = driver.service.process.pid
        for stat in pathlib.Path("/proc").glob("[0-9]*/stat"):  # the browser chromedriver started
            try:
                if int(stat.read_text().rsplit(")", 1)[1].split()[1]) == served:
                    os.kill(int(stat.parent.name), signal.SIGKILL)
            except (OSError, ValueError, IndexError):
                pass
        driver.service.process.kill()
        os._exit(1)
    timer = threading.Timer(seconds, frozen)
    timer.daemon = True
    timer.start()
    return timer


def main():
    ap = web_browser.site_arguments()
    ap.add_argument("--seed", type=int, default=4242)
    ap.add_argument("--bound", type=float, default=15.0,
                    help="seconds the page may take to stop the loop and answer")
    ap.add_argument("--frozen", type=float, default=120.0,
                    help="seconds after which the page counts as frozen (the test takes ~25)")
    ap.add_argument("--native", action="store_true", help="also native check (minutes)")
    args = ap.parse_args()
    out = web_browser.site_output(args)
    driver = web_browser.browser()
    driver.set_script_timeout(600)
    timer = watchdog(driver, args.frozen + (300 if args.native else 0))
    try:
        if not web_browser.open_page(driver, args.site):
            print("web: FAILED: the page never became ready")
            return 1
        folder, margin = hand_in(out)
        failures = lecture(driver, args, folder, out) + \
            check_all(driver, args, folder, margin, out)
    finally:
        timer.cancel()
        driver.quit()
    return web_browser.exit_code(failures)


if __name__ == "__main__":
    sys.exit(main())
