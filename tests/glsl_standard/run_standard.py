#!/usr/bin/env python3
"""GLSL that NVIDIA's compiler takes and the standard forbids (tests/glsl_standard/*/): each case
must be ERROR with glslang's message at the student's file and line, exit 2, both in
`check --stage S --shaders DIR` and in `check --assignment A.json --shaders DIR` (an assignment
with that one stage due). Mesa refuses some of these itself, with its own words: the message
asserted here is glslang's, the same on every driver.

usage: run_standard.py SHADOWLAB WORKDIR"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_rows import rows  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))

# case folder, stage, tree, the student's file, its line, glslang's words
CASES = [
    ("legacy_in_qualifier", "phong", "legacy", "phong/lit.vert", 3,
     "'in for stage inputs' : not supported for this version or the enabled extensions"),
    ("texture_call_120", "rgb", "legacy", "rgb/lit.frag", 16,
     "'texture' : no matching overloaded function found"),
    ("cg_saturate", "depth", "core", "depth/lit.frag", 20,
     "'saturate' : no matching overloaded function found"),
    ("varying_unfed", "margin", "core", "margin/lit.frag", 29,
     "'normalWorld' : the fragment shader reads this input, but the vertex shader"),
    ("varying_type", "margin", "core", "margin/lit.frag", 8,
     "Linking vertex and fragment stages: Types must match"),
    # Where compilers disagree, one rule of ours (issue 38): Mesa stops at a NUL, glslang reads on;
    # glslang passes invariant(all) in a fragment shader, Mesa refuses it; a lone CR made glslang
    # blame an #include; a huge uniform array made Mesa run out of memory (a CRASH row).
    ("cr_line_ends", "margin", "core", "margin/lit.frag", 1,
     "a line ends in a carriage return alone (CR, an old Mac editor's line end)"),
    ("nul_in_comment", "margin", "core", "margin/lit.frag", 2,
     "a NUL byte (0x00): GLSL source is text, and drivers differ on it"),
    ("invariant_all_fragment", "margin", "core", "margin/lit.frag", 2,
     "'#pragma STDGL invariant(all)' : not allowed in a fragment shader"),
    ("uniform_array_huge", "margin", "core", "margin/lit.frag", 2,
     "'huge' : the fragment shader's uniforms take 400000019 components"),
]

BY_GLSLANG = "by the GLSL standard (glslang, Khronos' reference compiler)"



def run(exe, args, report):
    p = subprocess.run([exe] + args + ["--report", report], capture_output=True, text=True,
                       timeout=600)
    with open(report) as f:
        return p, json.load(f)


def check_case(exe, work, case):
    name, stage, tree, file, line, words = case
    shaders = os.path.join(HERE, name)
    # `check --stage` names the folder given; `check --assignment` reads a private snapshot of
    # the submission and names files relative to it (as it does for a driver's error).
    full = f"{shaders}/{file}:{line}: error: {words}"
    relative = f"{file}:{line}: error: {words}"
    problems = []
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    assignment = os.path.join(folder, "assignment.json")
    with open(assignment, "w") as f:
        json.dump({"name": f"glsl standard: {name}",
                   "stages": [{"stage": stage, "tree": tree, "files": [file], "points": 10}]}, f)
    runs = {
        "check --stage": ["check", "--stage", stage, "--glsl", tree, "--shaders", shaders],
        "check --assignment": ["check", "--assignment", assignment, "--shaders", shaders],
    }
    for how, args in runs.items():
        expected = full if how == "check --stage" else relative
        p, report = run(exe, args, os.path.join(folder, how.split()[-1][2:] + ".json"))
        if p.returncode != 2:
            problems.append(f"{how}: exit {p.returncode}, not 2")
        if expected not in p.stderr or BY_GLSLANG not in p.stderr:
            problems.append(f"{how}: stderr lacks '{expected}' after '{BY_GLSLANG}':\n"
                            + p.stderr[-2000:])
        mine = [r for r in rows(report) if r["stage"] == stage]
        if not mine:
            problems.append(f"{how}: no row of stage {stage} in the report")
        for r in mine:
            if r["verdict"] != "ERROR" or expected not in r["message"]:
                problems.append(f"{how}: row {r.get('name', stage)} is {r['verdict']}: "
                                f"{r['message']!r}, expected ERROR with '{expected}'")
                break
    return problems


def main():
    exe, work = sys.argv[1], sys.argv[2]
    failed = 0
    for case in CASES:
        problems = check_case(exe, work, case)
        print(("FAIL " if problems else "ok   ") + case[0])
        for p in problems:
            print("    " + p)
        failed += bool(problems)
    print(f"{len(CASES) - failed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
