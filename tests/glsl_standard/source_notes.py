#!/usr/bin/env python3
"""Source rules end to end (docs/check.md "Source rules"): `check --report` carries each row's
`source_notes`. A shader that recognises the graded cameras and one with a constant margin each
get their finding on every row of their stage; a correct submission gets none.

usage: source_notes.py SHADOWLAB WORKDIR"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_rows import rows  # noqa: E402

STUDENTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "students")

# student case, stage, text every row's source_notes must hold ("" = none at all), exit code
CASES = [
    ("depth_game_known_eyes", "depth",
     "depth/lit.frag:56 compares the camera position (eyePosition) with a constant", 1),
    ("margin_fixed_005", "margin",
     "the shadow comparison does not depend on the normal or the light direction", 1),
    ("rgb_correct_core", "rgb", "", 0),
]



def main():
    exe, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failed = 0
    for name, stage, text, code in CASES:
        shaders = os.path.realpath(os.path.join(STUDENTS, name))
        report = os.path.join(work, name + ".json")
        p = subprocess.run([exe, "check", "--stage", stage, "--shaders", shaders, "--report",
                            report], capture_output=True, text=True, timeout=600)
        problems = [] if p.returncode == code else [f"exit {p.returncode}, not {code}"]
        with open(report) as f:
            mine = [r for r in rows(json.load(f)) if r["stage"] == stage]
        if not mine:
            problems.append("no row of the stage")
        for r in mine:
            notes = r.get("source_notes")
            if not isinstance(notes, list):
                problems.append(f"{r.get('name')}: source_notes is {notes!r}, not a list")
            elif text and not any(text in n and shaders in n for n in notes):
                problems.append(f"{r.get('name')}: no source note says '{text}': {notes}")
            elif not text and notes:
                problems.append(f"{r.get('name')}: notes for a correct submission: {notes}")
        print(("FAIL " if problems else "ok   ") + name)
        for pr in problems[:5]:
            print("    " + pr)
        failed += bool(problems)
    print(f"{len(CASES) - failed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
