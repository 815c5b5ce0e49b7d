#!/usr/bin/env python3
"""Grade every student submission in tests/students/ and compare with the instructor's verdict.

Each case is a folder holding a shader overlay and case.json:
    {"stage": ID, "tree": "core"|"legacy", "verdict": "PASS"|"FAIL"|"ERROR"|"MISSING", "why": "...",
     "submission": SUBFOLDER (optional), "notes": [TEXT, ...] (optional: check must print each)}
The verdict was decided from the shaders and their pictures, never from the grader. For each case
this runs `shadowlab check --stage ID --glsl TREE --shaders CASE --report R.json` and takes the
stage's verdict as the worst of the report's rows for that stage (every lesson and view the check
grades): ERROR/TIMEOUT/CRASH > FAIL > PASS > SKIP. Prints one line per case and a closing line
`N passed, M failed`; exits 1 on any disagreement, 2 on a bad corpus.

    run_students.py [--exe build/shadowlab] [--only NAME]... [--prefix P] [--seed S] [--jobs 2]
                    [--work DIR]
    run_students.py --table      (the README's table of cases, from the case.json files)
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
VERDICTS = ("PASS", "FAIL", "ERROR", "MISSING")
# How bad a verdict is; a stage is as bad as its worst row.
SEVERITY = {"SKIP": 0, "PASS": 1, "FAIL": 2, "ERROR": 3, "TIMEOUT": 3, "CRASH": 3, "MISSING": 3,
            "NOT GRADED": 4}
# check's one line for a submission that replaces no shipped file at all (exit 2, no report):
# for the stage graded, nothing was handed in.
NOTHING_REPLACED = "no file replaces a shipped shader"
CASE_TIMEOUT_S = 600


def load_case(name):
    folder = os.path.join(HERE, name)
    with open(os.path.join(folder, "case.json")) as f:
        case = json.load(f)
    missing = [k for k in ("stage", "tree", "verdict", "why") if k not in case]
    if missing:
        raise ValueError(f"{name}/case.json: missing {', '.join(missing)}")
    if case["verdict"] not in VERDICTS:
        raise ValueError(f"{name}/case.json: verdict must be one of {', '.join(VERDICTS)}")
    if case["tree"] not in ("core", "legacy"):
        raise ValueError(f"{name}/case.json: tree must be core or legacy")
    notes = case.get("notes", [])
    if not isinstance(notes, list) or not all(isinstance(n, str) for n in notes):
        raise ValueError(f"{name}/case.json: notes must be a list of strings")
    case["name"] = name
    # A layout case keeps its submission in a subfolder ("submission"), so that case.json is not
    # part of what is handed in (a wrapper folder must be the submission's only entry).
    case["folder"] = os.path.join(folder, case.get("submission", ""))
    if not os.path.isdir(case["folder"]):
        raise ValueError(f"{name}/case.json: submission '{case.get('submission')}' is no folder")
    return case


def all_cases():
    return sorted(d for d in os.listdir(HERE)
                  if os.path.isfile(os.path.join(HERE, d, "case.json")))


def rows_of(node, stage):
    """Every graded row for `stage`: the report's results and any nested rows (per view, per
    lesson) that carry a verdict of their own."""
    found = []
    if isinstance(node, dict):
        if "verdict" in node and node.get("stage", stage) == stage:
            found.append(node)
        for value in node.values():
            if isinstance(value, (list, dict)):
                found.extend(rows_of(value, stage))
    elif isinstance(node, list):
        for item in node:
            found.extend(rows_of(item, stage))
    return found


def describe(row):
    """The worst row's label and figures, short."""
    parts = []
    for key in ("view", "lesson", "entry", "label"):
        if isinstance(row.get(key), (str, int, float)):
            parts.append(f"{key}={row[key]}")
    exp = row.get("expectation")
    if isinstance(exp, dict) and exp.get("entry") and "entry" not in row:
        parts.append(f"entry={exp['entry']}")
    # The figures the verdict held to a bound, from the row's reasons (the report names them: no
    # list here), each with the bounds it missed; a row without reasons, every figure measured.
    judged = {}
    for f in row.get("reasons") or []:
        value = f.get("value")
        entry = judged.setdefault(f["figure"], f"{f['figure']}=" + (
            f"{value:.4g}" if isinstance(value, (int, float)) else "not measured"))
        if not f.get("passed"):
            judged[f["figure"]] = entry + f" (not {f['side']} {f['bound']:.4g})"
    shown = list(judged.values())
    if not judged:
        figures = row.get("figures") or {}
        shown = [f"{k}={v:.4g}" for k, v in figures.items() if isinstance(v, (int, float))]
    parts.extend(shown)
    if row.get("verdict") in ("ERROR", "TIMEOUT", "CRASH") and row.get("message"):
        parts.append(str(row["message"]).splitlines()[0][:160])
    return " ".join(parts)


def grade(case, exe, work, seed=None):
    report = os.path.join(work, case["name"] + ".json")
    if os.path.exists(report):
        os.remove(report)
    cmd = [exe, "check", "--stage", case["stage"], "--glsl", case["tree"], "--shaders",
           case["folder"], "--report", report]
    if seed is not None:  # else check draws one: the verdict must not depend on it
        cmd += ["--seed", str(seed)]
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=CASE_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return "TIMEOUT", f"no answer in {CASE_TIMEOUT_S} s"
    output = proc.stdout.strip().splitlines()
    last = output[-1][:160] if output else ""
    # Every note the instructor expects check to print (a wrapper descended, a near miss named).
    unsaid = [n for n in case.get("notes", []) if n not in proc.stdout]
    if unsaid:
        return "NO-NOTE", "not said: " + "; ".join(unsaid)
    rows = []
    if os.path.exists(report):
        with open(report) as f:
            rows = rows_of(json.load(f).get("stages", []), case["stage"])  # report v2
    if not rows:  # no report: the exit code is all there is (docs/check.md)
        if proc.returncode == 2:
            if any(NOTHING_REPLACED in line for line in output):
                return "MISSING", last
            return "ERROR", last
        if proc.returncode == 0:
            return "PASS", "(no report row)"
        if proc.returncode == 1:
            return "FAIL", "(no report row)"
        return "CRASH", f"exit {proc.returncode}: {last}"
    worst = max(rows, key=lambda r: SEVERITY.get(r.get("verdict"), 3))
    verdict = worst.get("verdict")
    if proc.returncode not in (0, 1, 2):
        return "CRASH", f"exit {proc.returncode}: {last}"
    figures = describe(worst)
    if len(rows) > 1:
        figures = f"[{len(rows)} rows] " + figures
    return verdict, figures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default=os.path.join(REPO, "build", "shadowlab"))
    parser.add_argument("--only", action="append", default=[], metavar="NAME")
    parser.add_argument("--prefix", help="only the cases whose name starts so (e.g. mirror_)")
    parser.add_argument("--seed", type=int,
                        help="the displaced views' seed (check --seed); default: check draws one")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--work", default=None, help="folder for the reports (default: a temp one)")
    parser.add_argument("--table", action="store_true", help="print the cases as a markdown table")
    args = parser.parse_args()

    names = all_cases()
    for name in args.only:
        if name not in names:
            print(f"--only: no case '{name}' in {HERE}", file=sys.stderr)
            return 2
    if args.only:
        names = [n for n in names if n in args.only]
    if args.prefix:
        names = [n for n in names if n.startswith(args.prefix)]
    try:
        cases = [load_case(n) for n in names]
    except (ValueError, json.JSONDecodeError) as e:
        print(e, file=sys.stderr)
        return 2
    if args.table:
        print("| case | stage | tree | verdict | why |")
        print("|---|---|---|---|---|")
        for c in cases:
            print(f"| `{c['name']}` | {c['stage']} | {c['tree']} | {c['verdict']} | {c['why']} |")
        return 0
    if not os.access(args.exe, os.X_OK):
        print(f"--exe: '{args.exe}' is not an executable (build the shadowlab target)",
              file=sys.stderr)
        return 2
    work = args.work or tempfile.mkdtemp(prefix="students-")
    os.makedirs(work, exist_ok=True)

    passed, failed = 0, []
    width = max(len(c["name"]) for c in cases) if cases else 10
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(grade, c, args.exe, work, args.seed): c for c in cases}
        for future in concurrent.futures.as_completed(futures):
            case = futures[future]
            got, figures = future.result()
            ok = got == case["verdict"]
            mark = "ok  " if ok else "DIFF"
            print(f"{mark} {case['name']:<{width}} {case['stage']:<8} {case['tree']:<6} "
                  f"expected {case['verdict']:<5} got {got:<7} {figures}", flush=True)
            if ok:
                passed += 1
            else:
                failed.append(case["name"])
    print(f"{passed} passed, {len(failed)} failed")
    if failed:
        print("disagree: " + ", ".join(sorted(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
