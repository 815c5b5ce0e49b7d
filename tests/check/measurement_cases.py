#!/usr/bin/env python3
"""Two measurements a shader used to pass without the method (issue 25, item 6), asserted.

  known-eyes EXE WORK SEED...   tests/students/margin_game_known_eyes uses the margin only when
                                eyePosition is one of the grader's fixed cameras. Every fixed row
                                passes; the displaced row, whose camera the seed moves, must FAIL
                                with acne (false shadow over 20 %), for every seed given.
  constant-slope EXE WORK       tests/students/margin_constant_only never writes the slope branch.
                                Every lesson but the slope one passes (the rows the seed draws
                                aside: its drawn slope rows must FAIL); the slope lesson must FAIL
                                with false shadow over 0.4 %, above its bound of 0.25 % (measured
                                0.62 %), while our shipped shaders pass it under 0.05 %.
Each `check` writes a fresh report (deleted first) and its exit code is asserted too."""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from report_rows import report_rows  # noqa: E402

STUDENTS = os.path.join(os.path.dirname(HERE), "students")
SLOPE_LESSON = "margin scene=slope margin=0.004 margin-kind=slope slope-min=0.004"


def check(exe, work, name, args, exit_code):
    """Runs `shadowlab check ARGS --report`, asserts its exit code, returns the report's rows."""
    report = os.path.join(work, name + ".json")
    if os.path.exists(report):
        os.remove(report)
    run = subprocess.run([exe, "check", *args, "--report", report], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, check=False)
    if run.returncode != exit_code or not os.path.isfile(report):
        sys.stdout.write(run.stdout.decode("utf-8", errors="replace"))
        sys.exit(f"FAIL: check {' '.join(args)}: exit {run.returncode}, expected {exit_code}"
                 f"{'' if os.path.isfile(report) else '; no report written'}")
    with open(report) as f:
        return report_rows(json.load(f))


def row_line(r):
    fs = r["figures"]["false_shadow_pct"]
    return f"  {r['name']:70} {r['verdict']:5} false shadow {fs:.3f} %"


def known_eyes(exe, work, seeds):
    problems = []
    shaders = os.path.join(STUDENTS, "margin_game_known_eyes")
    for seed in seeds:
        rows = check(exe, work, f"known-eyes-{seed}",
                     ["--stage", "margin", "--shaders", shaders, "--seed", seed], 1)
        print(f"seed {seed}:")
        for r in rows:
            print(row_line(r))
            fs = r["figures"]["false_shadow_pct"]
            if r["view"] == "displaced":
                if r["verdict"] != "FAIL" or fs is None or fs <= 20:
                    problems.append(f"seed {seed}: displaced row {r['verdict']}, false shadow {fs}"
                                    " (expected FAIL with acne over 20 %)")
            elif r["view"] != "drawn" and r["verdict"] != "PASS":  # drawn: the displaced view too
                problems.append(f"seed {seed}: {r['name']} {r['verdict']} (a fixed view: PASS)")
        if not any(r["view"] == "displaced" for r in rows):
            problems.append(f"seed {seed}: no displaced row")
    return problems


def constant_slope(exe, work):
    problems = []
    ours = check(exe, work, "slope-ours", ["--stage", "margin"], 0)
    theirs = check(exe, work, "slope-constant-only",
                   ["--stage", "margin", "--shaders", os.path.join(STUDENTS, "margin_constant_only")],
                   1)
    for label, rows in (("ours", ours), ("constant only", theirs)):
        print(label + ":")
        for r in rows:
            print(row_line(r))
    for who, rows, verdict, check_fs in (
            ("ours", ours, "PASS", lambda fs: fs < 0.05),
            ("constant only", theirs, "FAIL", lambda fs: fs > 0.4)):
        slope = [r for r in rows if r.get("lesson") == SLOPE_LESSON]
        if len(slope) != 1:
            problems.append(f"{who}: {len(slope)} rows of the slope lesson '{SLOPE_LESSON}'")
            continue
        fs = slope[0]["figures"]["false_shadow_pct"]
        if slope[0]["verdict"] != verdict or fs is None or not check_fs(fs):
            problems.append(f"{who}: slope lesson {slope[0]['verdict']}, false shadow {fs}")
        # The rows the seed draws (docs/check.md) are held to ours: the constant fails them too.
        others = [r for r in rows
                  if r is not slope[0] and r["verdict"] != "PASS" and r["view"] != "drawn"]
        if others:
            problems.append(f"{who}: another lesson fails: {others[0]['name']}")
    drawn_slope = [r for r in theirs if r["view"] == "drawn" and "margin-kind=slope" in r["name"]]
    if not drawn_slope or any(r["verdict"] != "FAIL" for r in drawn_slope):
        problems.append("constant only: the drawn slope rows must FAIL: "
                        + ", ".join(f"{r['name']} {r['verdict']}" for r in drawn_slope))
    return problems


def main():
    if len(sys.argv) < 4 or sys.argv[1] not in ("known-eyes", "constant-slope"):
        sys.exit(__doc__)
    mode, exe, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    if mode == "known-eyes":
        if len(sys.argv) < 5:
            sys.exit("known-eyes needs at least one seed")
        problems = known_eyes(exe, work, sys.argv[4:])
    else:
        problems = constant_slope(exe, work)
    if problems:
        sys.exit("FAIL: " + "; ".join(problems))
    print("OK")


if __name__ == "__main__":
    main()
