#!/usr/bin/env python3
"""`check` in the browser against native `check` (docs/web.md, "Check in the page"): headless
Chromium (SwiftShader's WebGL 2) runs the page's check over our shaders (every stage the page
runs) and over hand-ins of the student corpus (tests/students, the core tree), each with the
same seed as a native `check --report` of the same files (llvmpipe). Every row must have the
native verdict; figures are printed beside native's (the largest difference per case), and the
times of both. Writes page_report_CASE.json and native_report_CASE.json to --out and a
summary (check_parity.json). With --student-edition the site is the student edition's
(site-student): no line of a solution region may be in it, our stubbed shaders score 0, and at a
seed whose drawn figures it ships its verdicts are still native's (the instructor's).
Exit 77 (ctest: skipped) as web_browser.py does."""
import base64
import json
import pathlib
import re
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import web_browser  # noqa: E402  (the browser, the folder picker, the skip rule)

# The check as a student starts it; while it runs, a 20 ms timer measures the page's longest
# pause (what a student's clicks wait for).
RUN = """
const [what, seed, done] = arguments;
document.getElementById('seed').value = seed;
let last = performance.now(), pause = 0;
const beat = setInterval(() => { const now = performance.now();
                                 pause = Math.max(pause, now - last); last = now; }, 20);
shadowlab.startCheck(what);
const wait = () => shadowlab.check.running ? setTimeout(wait, 100)
  : (clearInterval(beat), done({report: shadowlab.check.report, error: shadowlab.check.error,
          seconds: shadowlab.check.seconds, state: document.getElementById('checkState').textContent,
          traced_here: shadowlab.check.tracedHere || 0,
          traced_by_workers: shadowlab.check.tracedByWorkers || 0, longest_pause_ms: pause,
          view_errors: shadowlab.tracers.viewErrors.slice(0, 3)}));
wait();
"""


def rows_of(report):
    """(stage/tree, view, lesson) -> row, in the report's order."""
    out = []
    for stage in report["stages"]:
        for row in stage["rows"]:
            out.append(((stage["stage"] + "/" + stage["tree"], row.get("view", ""),
                         row.get("lesson", "")), row))
    return out


def figure_gap(a, b):
    """The largest |a - b| over the figures both rows measured, with its name ((0, "") when none
    is); speckle shares left out (a share of the false shadow's few pixels: 100 against 0 for
    one speck)."""
    gaps = [(abs(a[k] - b[k]), k) for k in a if isinstance(a.get(k), (int, float))
            and isinstance(b.get(k), (int, float)) and "speckle" not in k]
    return max(gaps) if gaps else (0.0, "")


def compare(name, page, native, folder):
    """The rows whose verdicts differ (or that one side lacks), or whose ERROR line differs once
    native's path to the folder is cut (the page names it as picked), and the largest figure
    gap."""
    failures, worst = [], (0.0, "")
    p_rows, n_rows = rows_of(page), rows_of(native)
    if [k for k, _ in p_rows] != [k for k, _ in n_rows]:
        failures.append(f"{name}: the page's rows {[k for k, _ in p_rows]} are not native's "
                        f"{[k for k, _ in n_rows]}")
        return failures, worst
    for (key, p), (_, n) in zip(p_rows, n_rows):
        said = n["message"].replace(f"{folder.parent}/", "") if folder else n["message"]
        if p["verdict"] != n["verdict"] or (p["verdict"] == "ERROR" and p["message"] != said):
            failures.append(f"{name}: {'/'.join(filter(None, key))}: the page {p['verdict']} "
                            f"({p['message']}), native {n['verdict']} ({said})")
        gap, figure = figure_gap(p.get("figures", {}), n.get("figures", {}))
        worst = max(worst, (gap, f"{figure} in {'/'.join(filter(None, key))}"))
    return failures, worst


def same_fields(name, page, native):
    """The downloaded report has the native report's fields: its own, each stage's and each
    row's (rows paired in order, as compare pairs them), and its version."""
    pairs = [("report", page, native)]
    for ps, ns in zip(page.get("stages", []), native.get("stages", [])):
        pairs.append((f"stage {ns.get('stage')}", ps, ns))
        pairs += [(f"row {nr.get('lesson')!r} of {ns.get('stage')}", pr, nr)
                  for pr, nr in zip(ps.get("rows", []), ns.get("rows", []))]
    failures = [f"{name}: the page's {level} fields differ from native's: only the page's "
                f"{sorted(set(p) - set(n))}, only native's {sorted(set(n) - set(p))}"
                for level, p, n in pairs if set(p) != set(n)]
    if page.get("report_version") != native.get("report_version"):
        failures.append(f"{name}: report_version {page.get('report_version')} against "
                        f"native's {native.get('report_version')}")
    return failures[:5]


def native_check(shadowlab, what, folder, seed, report, assignment=None):
    """Native `check --report` (`--assignment` where `what` is "assignment"): (its report,
    seconds, its last stderr line); the report is None where it refused the run (exit 2: a folder
    the intake refuses)."""
    command = [shadowlab, "check", "--seed", str(seed), "--report", str(report)]
    if what == "assignment":
        command += ["--assignment", str(assignment)]
    else:
        command += ["--glsl", "core"] + (["--all"] if what == "all" else ["--stage", what])
    if folder:
        command += ["--shaders", str(folder)]
    report.unlink(missing_ok=True)
    started = time.monotonic()
    run = subprocess.run(command, capture_output=True, text=True)  # exit code: the verdict's
    seconds = time.monotonic() - started
    said = (run.stderr.strip().splitlines() or [""])[-1]
    return (json.loads(report.read_text()) if report.exists() else None), seconds, said


def check_case(driver, args, out, name, what, folder):
    if folder:
        web_browser.pick_folder(driver, folder)
    else:
        driver.execute_script("shadowlab.takeFolder('', '')")
    got = driver.execute_async_script(RUN, what, str(args.seed))
    native, native_s, said = native_check(args.shadowlab, what, folder, args.seed,
                                          out / f"native_report_{name}.json", args.assignment)
    if native is None:  # refused: the page must refuse with native's reason
        reason = said.split(f"{folder}: ", 1)[-1]
        same = bool(got.get("error")) and got["error"].endswith(reason)
        print(f"web: check {name:34} refused as native: {reason!r}: {'ok' if same else 'NO'}")
        return ([] if same else [f"{name}: the page says {got.get('error')!r}, native "
                                 f"{said!r}"]), {"refused": True, "same": same}
    if got.get("error"):
        return [f"{name}: the page's check says {got['error']!r}, native ran it"], None
    page = json.loads(got["report"])
    (out / f"page_report_{name}.json").write_text(got["report"])
    failures, worst = compare(name, page, native, folder)
    if abs(page["score"] - native["score"]) > 1e-6:
        failures.append(f"{name}: the page scores {page['score']}, native {native['score']}")
    failures += same_fields(name, page, native)
    shot = out / "page_check.png"  # the page after a check with a failing row (docs/web.md)
    if not shot.exists() and '"verdict": "FAIL"' in got["report"] and driver.execute_script(
            "const p = document.querySelector('#checkRows .picture');"
            "if (p) p.click(); return !!p"):
        time.sleep(0.5)
        driver.save_screenshot(str(shot))
    if args.serve and got["traced_here"]:
        # Served, the workers trace every view: a row that traced on the page's thread looked up a
        # key its view did not predict (eval/trace_view.h).
        failures.append(f"{name}: {got['traced_here']} references traced on the page's thread, "
                        f"{got['traced_by_workers']} by its workers; views the workers could not "
                        f"trace or the check refused: {got['view_errors'] or 'none'}")
    rows = sum(len(s["rows"]) for s in page["stages"])
    verdicts = " ".join(sorted({r["verdict"] for _, r in rows_of(page)}))
    print(f"web: check {name:34} {rows:3} rows ({verdicts}): "
          f"{'same verdicts' if not failures else 'DIFFER'}, largest figure gap {worst[0]:.3g} "
          f"({worst[1]}); page {got['seconds']:.1f} s, native {native_s:.1f} s; traced by "
          f"workers {got['traced_by_workers']}, on the page's thread {got['traced_here']}; "
          f"longest pause {got['longest_pause_ms'] / 1000:.2f} s")
    return failures, {"rows": rows, "page_s": got["seconds"], "native_s": native_s,
                      "figure_gap": worst[0], "gap_figure": worst[1], "same": not failures,
                      "traced_by_workers": got["traced_by_workers"],
                      "traced_here": got["traced_here"],
                      "longest_pause_s": got["longest_pause_ms"] / 1000}


def wait_for_tracers(driver):
    """Served, the page starts a tracer a core (at most 4): waits until they are up (60 s)."""
    want = driver.execute_script("return Math.max(1, Math.min(4, navigator.hardwareConcurrency || 1))")
    for _ in range(600):
        if driver.execute_script("return shadowlab.tracers.ready.length") == want:
            return True
        if driver.execute_script("return shadowlab.tracers.failed"):
            return False
        time.sleep(0.1)
    return False


# The first view the page sends a tracer is replaced by one the worker cannot trace: it answers
# with an error for that view alone.
POISON_ONE_VIEW = """
const worker = shadowlab.tracers.ready[0], post = worker.postMessage.bind(worker);
let first = true;
worker.postMessage = message => {
  post(first ? { key: message.key, view: { scene: 7 } } : message);
  first = false;
};
"""


def one_view_refused(driver, args, out):
    """Served: a view one worker cannot trace is traced by its row on the page's thread, and the
    workers trace every other view of the check (a single view's error must not turn them off
    for the session). Our `check --all` again, its first view refused by the worker: exactly one
    reference traced on the page's thread, the verdicts those of the first run."""
    first = json.loads((out / "page_report_ours_all.json").read_text())
    driver.execute_script("shadowlab.takeFolder('', '')")
    driver.execute_script(POISON_ONE_VIEW)
    got = driver.execute_async_script(RUN, "all", str(args.seed))
    failed = driver.execute_script("return shadowlab.tracers.failed")
    failures = []
    if got.get("error"):
        return [f"one view refused: the page's check says {got['error']!r}"]
    if got["traced_here"] != 1 or len(got["view_errors"]) != 1 or failed:
        failures.append(f"one view refused: {got['traced_here']} references traced on the page's "
                        f"thread (1 wanted), {got['traced_by_workers']} by the workers, view "
                        f"errors {got['view_errors']}, the workers {failed or 'still on'}")
    verdicts = [(k, r["verdict"]) for k, r in rows_of(json.loads(got["report"]))]
    if verdicts != [(k, r["verdict"]) for k, r in rows_of(first)]:
        failures.append("one view refused: the rows' verdicts differ from the first run's")
    print(f"web: one view refused by its worker: {got['traced_here']} traced on the page's "
          f"thread, {got['traced_by_workers']} by the workers, {len(verdicts)} rows: "
          f"{'ok' if not failures else 'NO'}")
    return failures


def solution_lines(repo):
    """The lines of every marked solution region of our core tree (the code a student edition
    must not ship), those long enough to mean something."""
    lines = set()
    for path in pathlib.Path(repo, "shaders_core").rglob("*"):
        inside = False
        for line in path.read_text(errors="replace").splitlines() if path.is_file() else []:
            if "END SOLUTION" in line:
                inside = False
            elif inside and len(line.strip()) >= 16 and not line.strip().startswith("//"):
                lines.add(line.strip())
            elif "BEGIN SOLUTION" in line:
                inside = True
    return lines


def leaked_solutions(site, repo):
    """The solution lines found in the site's shadowlab.js (its embedded files are in the
    WebAssembly, base64 inside the .js): none for a student edition."""
    text = pathlib.Path(site, "shadowlab.js").read_text(errors="replace")
    blobs = [text.encode()]
    for b64 in re.findall(r"base64,([A-Za-z0-9+/=]{1000,})", text):
        blobs.append(base64.b64decode(b64))
    lines = solution_lines(repo)
    return lines, sorted(line for line in lines if any(line.encode() in b for b in blobs))


def student_edition(driver, args, out):
    """The student edition's site: no solution line anywhere in it, and our (stubbed) shaders
    checked in it score 0, as the native student edition's starter does."""
    repo = pathlib.Path(__file__).resolve().parents[2]
    lines, leaked = leaked_solutions(args.site, repo)
    print(f"web: student edition: {len(leaked)} of {len(lines)} solution lines in shadowlab.js")
    failures = [f"the student edition ships a solution line: {line!r}" for line in leaked[:5]]
    driver.execute_script("shadowlab.takeFolder('', '')")
    got = driver.execute_async_script(RUN, "margin", str(args.seed))
    score = json.loads(got["report"])["score"] if got.get("report") else None
    (out / "page_report_starter.json").write_text(got.get("report") or "")
    print(f"web: student edition: the starter's margin check scores {score}")
    if score != 0:
        failures.append(f"the starter's margin check scores {score} ({got.get('error')})")
    return failures


def main():
    ap = web_browser.site_arguments()
    ap.add_argument("--seed", type=int,
                    help="the displaced views' seed (default 4242; a student edition's: the "
                         "last seed whose drawn figures it ships)")
    ap.add_argument("--students", default="", help="only the corpus cases this regex finds")
    ap.add_argument("--no-ours", action="store_true", help="skip the check of our shaders")
    ap.add_argument("--assignment", help="check everything due by this assignment file (as "
                    "`check --assignment`): the hand-ins of its due stages, against native's")
    ap.add_argument("--student-edition", action="store_true",
                    help="the site is the student edition's: no solution in it, the starter 0")
    ap.add_argument("--per-verdict", type=int, default=0,
                    help="only the first N cases of each stage and expected verdict (0: all)")
    ap.add_argument("--serve", action="store_true",
                    help="serve the site over HTTP, as a course does: the page's Web Workers "
                         "trace every reference (a page opened from the disk traces on its thread)")
    args = ap.parse_args()
    if args.seed is None:
        shipped = pathlib.Path(__file__).resolve().parents[2] / "src/stages/drawn_figures.json"
        args.seed = json.loads(shipped.read_text())["seeds"][-1] if args.student_edition else 4242
    out = web_browser.site_output(args)
    driver = web_browser.browser()
    driver.set_script_timeout(1800)
    failures, summary = [], {}
    try:
        address = web_browser.serve(args.site) if args.serve else None
        if not web_browser.open_page(driver, args.site, address):
            print("web: FAILED: the page never became ready")
            return 1
        if args.serve and not wait_for_tracers(driver):
            print("web: FAILED: the page's reference tracers never started "
                  f"({driver.execute_script('return shadowlab.tracers.failed')!r})")
            return 1
        runs = set(driver.execute_script(
            "return shadowlab.stages.filter(s => !s.nativeOnly).map(s => s.id)"))
        if args.student_edition:
            failures += student_edition(driver, args, out)
        what = "all"
        if args.assignment:  # as the page takes the file the course publishes beside it
            text = pathlib.Path(args.assignment).read_text()
            driver.execute_script("shadowlab.takeAssignment(new TextEncoder().encode("
                                  "arguments[0]), arguments[1])", text, pathlib.Path(args.assignment).name)
            due = {st["stage"] for st in json.loads(text)["stages"] if st.get("due", True)}
            runs &= due
            what = "assignment"
        ours = pathlib.Path(__file__).resolve().parents[2] / "shaders_core" if args.assignment else None
        cases = [] if args.no_ours else [("ours_" + what, what, ours)]
        corpus = pathlib.Path(__file__).resolve().parents[1] / "students"
        taken = []  # (stage, verdict) of the cases taken
        for folder in sorted(p for p in corpus.iterdir() if (p / "case.json").is_file()):
            case = json.loads((folder / "case.json").read_text())
            kind = (case.get("stage"), case.get("verdict"))
            if case.get("tree") == "core" and case.get("stage") in runs and \
                    args.students and re.search(args.students, folder.name) and \
                    (not args.per_verdict or taken.count(kind) < args.per_verdict):
                taken.append(kind)
                cases.append((folder.name, what if args.assignment else case["stage"],
                              folder / case.get("submission", "")))
        for name, what, folder in cases:
            f, result = check_case(driver, args, out, name, what, folder)
            failures += f
            if result:
                summary[name] = result
        if args.serve and "ours_all" in summary:
            failures += one_view_refused(driver, args, out)
    finally:
        driver.quit()
    (out / "check_parity.json").write_text(json.dumps(summary, indent=1) + "\n")
    return web_browser.exit_code(failures)


if __name__ == "__main__":
    sys.exit(main())
