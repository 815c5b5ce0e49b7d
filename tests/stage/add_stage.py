#!/usr/bin/env python3
"""The adding-a-stage test (docs/adding-a-stage.md): the program built with one more stage lists,
renders and checks it, with nothing of src/ edited but the one line of stage_list.h.

usage: add_stage.py EXE WORKDIR

EXE is shadowlab_extra_stage (tests/stage.cmake): the program's own sources, stage_list.h with
the one line `SL_STAGE(throwaway)` added, and tests/stage/throwaway.cpp. Its data folder is the
source tree's, plus what a stage adds there: its shaders in both trees (a copy of phong's) and
its defaults entry in expectations.json (throwaway_expectation.json). Exit 0 when it lists,
renders and checks the stage (PASS, as many rows as tests/check/planned_rows.py counts), 1 with
the step that failed.
"""
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", ".."))
STAGE = "throwaway"


def data_folder(work):
    """The source tree's data folder plus the throwaway stage's shaders and expectation."""
    data = os.path.join(work, "data")
    shutil.rmtree(data, ignore_errors=True)
    for tree in ("shaders_core", "shaders_legacy"):
        shutil.copytree(os.path.join(REPO, tree), os.path.join(data, tree))
        shutil.copytree(os.path.join(REPO, tree, "phong"), os.path.join(data, tree, STAGE))
    for folder in ("scenes", "slides_examples"):
        shutil.copytree(os.path.join(REPO, folder), os.path.join(data, folder))
    with open(os.path.join(REPO, "src", "stages", "expectations.json"), encoding="utf-8") as f:
        book = json.load(f)
    with open(os.path.join(HERE, "throwaway_expectation.json"), encoding="utf-8") as f:
        book["expectations"].append(json.load(f))
    os.makedirs(os.path.join(data, "src", "stages"))
    for name in os.listdir(os.path.join(REPO, "src", "stages")):  # the other data files as shipped
        if name.endswith(".json") and name != "expectations.json":
            shutil.copy(os.path.join(REPO, "src", "stages", name), os.path.join(data, "src", "stages"))
    with open(os.path.join(data, "src", "stages", "expectations.json"), "w", encoding="utf-8") as f:
        json.dump(book, f, indent=1)
    return data


def run(exe, args, env, expect=0):
    p = subprocess.run([exe] + args, env=env, capture_output=True, text=True, timeout=300)
    if p.returncode != expect:
        sys.exit(f"add_stage: `{' '.join(args)}` exited {p.returncode}, not {expect}\n"
                 f"{p.stdout[-2000:]}{p.stderr[-2000:]}")
    return p.stdout


def main():
    exe, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, SHADOWLAB_DATA_DIR=data_folder(work))
    stages = json.loads(run(exe, ["stages", "--json"], env))
    ids = [s["id"] for s in stages]
    with open(os.path.join(REPO, "src", "stages", "stage_list.h"), encoding="utf-8") as f:
        listed = [l[len("SL_STAGE("):-1] for l in f.read().split() if l.startswith("SL_STAGE(")]
    if ids != listed + [STAGE]:
        sys.exit(f"add_stage: `stages --json` lists {ids}, not stage_list.h's and {STAGE}")
    print(f"add_stage: lists {len(ids)} stages, the last {STAGE}")
    picture = os.path.join(work, STAGE + ".png")
    if os.path.exists(picture):
        os.remove(picture)
    run(exe, ["render", "--stage", STAGE, "--out", picture], env)
    if not os.path.getsize(picture):
        sys.exit(f"add_stage: `render --stage {STAGE}` wrote no picture")
    print(f"add_stage: renders it ({os.path.getsize(picture)} bytes)")
    report = os.path.join(work, "check.json")
    run(exe, ["check", "--stage", STAGE, "--glsl", "core", "--seed", "1", "--report", report],
        env)
    with open(report, encoding="utf-8") as f:
        rows = [row for stage in json.load(f)["stages"] for row in stage["rows"]]
    sys.path.insert(0, os.path.join(REPO, "tests", "check"))
    from planned_rows import planned_rows
    want = planned_rows(stages, book_of(env), "core", STAGE)
    verdicts = sorted({r["verdict"] for r in rows})
    if len(rows) != want or verdicts != ["PASS"]:
        sys.exit(f"add_stage: `check --stage {STAGE}`: {len(rows)} rows {verdicts}, "
                 f"expected {want} rows PASS")
    print(f"add_stage: checks it: {len(rows)} rows PASS")
    return 0


def book_of(env):
    path = os.path.join(env["SHADOWLAB_DATA_DIR"], "src", "stages", "expectations.json")
    with open(path, encoding="utf-8") as f:
        return json.load(f)


if __name__ == "__main__":
    sys.exit(main())
