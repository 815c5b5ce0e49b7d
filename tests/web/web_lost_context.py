#!/usr/bin/env python3
"""A WebGL context lost during the page's check is the browser's, never the student's (docs/web.md,
"Check in the page"): headless Chromium runs the page's `check --all` over our shaders and, once
--after rows are in, loses the page's WebGL context (WEBGL_lose_context, as a GPU reset or a
driver's watchdog does). The check must end within --bound seconds with every row in the report:
the rows before the loss as they were (PASS), every row after it NOT GRADED saying the context
was lost (none FAIL or ERROR: a lost context fails every compile and reads zeros), the report's
exit code the machine's (3). Then the context comes back and, after a reload, the page's check of
one stage passes again. Exit 77 (ctest: skipped) as web_browser.py does."""
import json
import pathlib
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import web_browser  # noqa: E402  (the browser, the page, the skip rule)
import web_check  # noqa: E402  (the page's check as a student starts it)

# Starts `check --all`; loses the context once `after` rows are in; answers when the check ends.
LOSE = """
const [after, seed, done] = arguments;
document.getElementById('seed').value = seed;
shadowlab.takeFolder('', '');
shadowlab.startCheck('all');
const started = performance.now();
let lostAt = -1;
const ext = document.getElementById('canvas').getContext('webgl2').getExtension('WEBGL_lose_context');
const wait = () => {
  if (lostAt < 0 && shadowlab.check.rows.length >= after) {
    lostAt = shadowlab.check.rows.length;
    ext.loseContext();
  }
  if (shadowlab.check.running) { setTimeout(wait, 20); return; }
  done({lostAt, report: shadowlab.check.report, exit: shadowlab.check.exit,
        seconds: (performance.now() - started) / 1000, hasExt: !!ext});
};
wait();
"""


def main():
    ap = web_browser.site_arguments()
    ap.add_argument("--after", type=int, default=20, help="rows in before the context is lost")
    ap.add_argument("--bound", type=float, default=120,
                    help="seconds the check may take to end after the loss")
    ap.add_argument("--seed", type=int, default=4242)
    args = ap.parse_args()
    out = web_browser.site_output(args)
    driver = web_browser.browser()
    driver.set_script_timeout(args.bound + 300)
    failures = []
    try:
        if not web_browser.open_page(driver, args.site):
            return web_browser.exit_code(["the page never became ready"])
        got = driver.execute_async_script(LOSE, args.after, str(args.seed))
        if not got["hasExt"]:
            web_browser.skip("this browser has no WEBGL_lose_context")
        report = json.loads(got["report"]) if got["report"] else None
        if report is None:
            return web_browser.exit_code([f"no report after the loss ({got})"])
        (out / "page_report_lost.json").write_text(got["report"])
        # A stage done before the loss keeps its verdicts (ours: PASS); the stage under way and
        # every one after it is NOT GRADED naming the loss (a stage's rows share one failure, as
        # natively when its worker fails).
        done, lost, other = [], [], []
        for st in report["stages"]:
            verdicts = {r["verdict"] for r in st["rows"]}
            if verdicts == {"PASS"}:
                done.append(st["stage"])
            elif verdicts == {"NOT GRADED"} and all("context was lost" in r["message"]
                                                    for r in st["rows"]):
                lost.append(st["stage"])
            else:
                other.append((st["stage"], sorted(verdicts), st["rows"][0]["message"][:100]))
        print(f"web: lost context: lost after {got['lostAt']} rows; the check ended "
              f"{got['seconds']:.1f} s after it began; stages done before: {done}; NOT GRADED "
              f"naming the loss: {lost}; otherwise: {other}; exit {report['exit_code']}")
        if other or not done or not lost:
            failures.append(f"stages neither done before the loss nor NOT GRADED for it: {other}")
        if report["exit_code"] != 3:
            failures.append(f"the report's exit code is {report['exit_code']}, not the machine's 3")
        if got["seconds"] > args.bound:
            failures.append(f"the check took {got['seconds']:.0f} s (bound {args.bound} s)")
        # A reload recovers: the page's check of one stage passes again.
        driver.refresh()
        if not web_browser.open_page(driver, args.site):
            return web_browser.exit_code(failures + ["the page never became ready after a reload"])
        again = driver.execute_async_script(web_check.RUN, "phong", str(args.seed))
        verdicts = sorted({r["verdict"] for s in json.loads(again["report"])["stages"]
                           for r in s["rows"]}) if again.get("report") else again
        print(f"web: lost context: after a reload the page's check of phong: {verdicts}")
        if verdicts != ["PASS"]:
            failures.append(f"after a reload: {verdicts}")
    finally:
        driver.quit()
    return web_browser.exit_code(failures)


if __name__ == "__main__":
    sys.exit(main())
