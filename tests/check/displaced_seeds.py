#!/usr/bin/env python3
"""Correct shaders pass the displaced view whatever the seed (issue 25: the displaced view moves
the casters, the light and now the camera; a correct method cannot tell it from a fixed view).

    displaced_seeds.py EXE WORK --seeds FIRST-LAST [--case NAME]... [--all-correct] [--jobs N]
                       [--time-limit S]

Grades each case (a folder of tests/students/ whose case.json says PASS) with `check --stage ID
--glsl TREE --shaders CASE --seed S` for every seed in the range, and our shipped shaders (case
`ours:STAGE:TREE`) the same way: every run must exit 0 with every row PASS, the displaced rows
included. Prints one line per run with the displaced rows' worst false shadow, false lit and edge
p95. --all-correct takes every PASS case of a shadow stage (not the layouts). Exits 1 on any
run that does not pass."""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from report_rows import report_rows  # noqa: E402

STUDENTS = os.path.join(os.path.dirname(HERE), "students")
SHADOW_STAGES = ("rgb", "depth", "bias", "margin", "hardware", "fixed", "peers")


def correct_cases():
    names = []
    for name in sorted(os.listdir(STUDENTS)):
        path = os.path.join(STUDENTS, name, "case.json")
        if not os.path.isfile(path) or name.startswith("layout_"):
            continue
        with open(path) as f:
            case = json.load(f)
        if case["verdict"] == "PASS" and case["stage"] in SHADOW_STAGES:
            names.append(name)
    return names


def describe(name):
    """(stage, tree, overlay folder or None) of a case name."""
    if name.startswith("ours:"):
        _, stage, tree = name.split(":")
        return stage, tree, None
    with open(os.path.join(STUDENTS, name, "case.json")) as f:
        case = json.load(f)
    if case["verdict"] != "PASS":
        sys.exit(f"{name}: its verdict is {case['verdict']}; only correct cases belong here")
    return case["stage"], case["tree"], os.path.join(STUDENTS, name, case.get("submission", ""))


def run(exe, work, name, seed, extra):
    stage, tree, overlay = describe(name)
    report = os.path.join(work, f"{name.replace(':', '-')}-{seed}.json")
    if os.path.exists(report):
        os.remove(report)
    args = [exe, "check", "--stage", stage, "--glsl", tree, "--seed", str(seed), "--report", report]
    if overlay:
        args += ["--shaders", overlay]
    args += extra
    done = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, check=False)
    if not os.path.isfile(report):
        return False, f"{name} seed {seed}: exit {done.returncode}, no report"
    with open(report) as f:
        rows = report_rows(json.load(f))
    displaced = [r for r in rows if r["view"] == "displaced"]
    failing = [r for r in rows if r["verdict"] != "PASS"]
    worst = lambda key: max((r["figures"][key] or 0) for r in displaced) if displaced else float("nan")
    line = (f"{name:32} seed {seed:>6}: exit {done.returncode}, {len(rows)} rows, displaced "
            f"false shadow {worst('false_shadow_pct'):.3f} %, false lit {worst('false_lit_pct'):.3f} %, "
            f"edge p95 {worst('edge_p95_px'):.2f} px")
    ok = done.returncode == 0 and not failing and displaced
    if not displaced:
        line += "  NO DISPLACED ROW"
    for r in failing:
        line += f"\n    {r['name']} {r['verdict']}: {r['message'][:200]}"
    return ok, line


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("exe")
    parser.add_argument("work")
    parser.add_argument("--seeds", required=True, help="FIRST-LAST, inclusive")
    parser.add_argument("--case", action="append", default=[])
    parser.add_argument("--all-correct", action="store_true")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--time-limit", help="passed to check (a busy machine's measurement run)")
    args = parser.parse_args()
    first, last = (int(x) for x in args.seeds.split("-"))
    cases = args.case + (correct_cases() if args.all_correct else [])
    if not cases:
        sys.exit("no case given (--case NAME, ours:STAGE:TREE, or --all-correct)")
    os.makedirs(args.work, exist_ok=True)
    jobs = [(c, s) for c in cases for s in range(first, last + 1)]
    extra = ["--time-limit", args.time_limit] if args.time_limit else []
    failed = 0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for ok, line in pool.map(lambda j: run(args.exe, args.work, *j, extra), jobs):
            print(("   " if ok else "BAD") + " " + line, flush=True)
            failed += not ok
    print(f"{len(jobs) - failed} of {len(jobs)} runs pass every row, the displaced view included")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
