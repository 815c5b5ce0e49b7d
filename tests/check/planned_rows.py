#!/usr/bin/env python3
"""How many rows `check` plans, counted from the data: src/stages/expectations.json (each stage's
lessons and the grading views of each scene) and `shadowlab stages --json` (each stage's trees,
its own scene), so adding a stage or a lesson edits no test.

usage: planned_rows.py STAGES_JSON [--expectations PATH] [--tree core|legacy] [--stage ID]
                       [--no-displaced] [--submission]

The count follows GUIDE section 4 and docs/check.md, written here a second time on purpose (a
check of grade/check_run.cpp's checkCases, not a copy of its answer): each lesson of a stage and
tree (the entries of its id whose "trees" cover it) is seen from every view of its scene ("views"
in the data; a scene without views has one, its own camera); with a seed (`check --all` draws
one), each lesson in the stage's own scene gains a "displaced" view (the mirror stage's too:
its camera and mirror moved). A submission (`--shaders`) gains one row for each of the stage's "drawn" entries in the
tree (parameters the seed draws, judged against our shaders at the same values: our own shaders
get none), two for an entry with a "response" (its second row, one parameter moved by a drawn
ratio). Prints one number.
"""
import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def planned_rows(stages, book, tree=None, only=None, displaced=True, submission=False):
    views = book.get("views", {})
    rows = 0
    for stage in stages:
        if only and stage["id"] != only:
            continue
        for t in stage["trees"]:
            if tree and t != tree:
                continue
            lessons = [e for e in book["expectations"]
                       if e["stage"] == stage["id"] and t in e.get("trees", [t])]
            for e in lessons:
                scene = e.get("scene", stage["scene"])
                rows += len(views.get(scene, [])) or 1
                if displaced and scene == stage["scene"]:
                    rows += 1
            if submission:
                rows += sum(2 if "response" in d else 1 for d in book.get("drawn", [])
                            if d["stage"] == stage["id"] and t in d.get("trees", [t]))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("stages", help="the output of `shadowlab stages --json`")
    parser.add_argument("--expectations",
                        default=os.path.join(HERE, "..", "..", "src", "stages", "expectations.json"))
    parser.add_argument("--tree", choices=["core", "legacy"])
    parser.add_argument("--stage")
    parser.add_argument("--no-displaced", action="store_true")
    parser.add_argument("--submission", action="store_true",
                        help="count a submission's rows: the drawn ones too")
    args = parser.parse_args()
    with open(args.stages, encoding="utf-8") as f:
        stages = json.load(f)
    with open(args.expectations, encoding="utf-8") as f:
        book = json.load(f)
    known = {s["id"] for s in stages}
    if args.stage and args.stage not in known:
        sys.exit(f"planned_rows: no stage '{args.stage}' in {args.stages}")
    print(planned_rows(stages, book, args.tree, args.stage, not args.no_displaced,
                       args.submission))
    return 0


if __name__ == "__main__":
    sys.exit(main())
