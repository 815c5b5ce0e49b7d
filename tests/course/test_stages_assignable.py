#!/usr/bin/env python3
"""ctest course_stages_TREE: every stage can be assigned on its own. For each stage with a
solution region in the TREE tree, a one-stage assignment (its files: every marked file of the
stage's folder) is released (the release grades the shipped solution first), the released
starter scores 0 on the stage without being MISSING (it builds, draws, and fails every row),
and the shipped solution scores full marks, both through `check --assignment`. The stages
without regions are refused with their reason: phong (its lit pass is the lighting every stage
is graded against) and fixed (fixed-function GL: no shader to hand in).
usage: test_stages_assignable.py SHADOWLAB REPO WORKDIR TREE"""
import json, os, shutil, subprocess, sys

exe, repo, work, tree = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
root = os.path.join(repo, "shaders_" + tree)
stages = [s["id"] for s in json.loads(subprocess.run([exe, "stages", "--json"], capture_output=True,
                                                      text=True, check=True).stdout)]
LIMITS = ["--time-limit", "300"]

def marked(stage):
    folder = os.path.join(root, stage)
    if not os.path.isdir(folder):
        return []
    return sorted(stage + "/" + f for f in os.listdir(folder)
                  if "// BEGIN SOLUTION" in open(os.path.join(folder, f)).read())

def run(args, timeout=1800):
    r = subprocess.run([exe] + args, capture_output=True, text=True, timeout=timeout)
    return r.returncode, r.stdout, r.stderr

assignable = []
for stage in stages:
    files = marked(stage)
    a = {"name": "only " + stage, "stages": [{"stage": stage, "tree": tree, "points": 10,
                                               "files": files or [stage + "/lit.frag"]}]}
    path = "%s/%s.json" % (work, stage)
    json.dump(a, open(path, "w"))
    if not files:
        code, out, err = run(["release", "--assignment", path, "--out", work + "/" + stage] + LIMITS)
        assert code == 2 and err.count("\n") == 1, (stage, code, err)
        reason = {"phong": "phong/lit.frag: no BEGIN SOLUTION region",
                  "fixed": "runs in the legacy tree only" if tree == "core" else "has no shaders in the legacy tree"}
        assert stage in reason and reason[stage] in err, (stage, err)
        print("%s/%s refused: %s" % (stage, tree, err.strip()))
        continue
    assignable.append(stage)
    rel = work + "/" + stage
    code, out, err = run(["release", "--assignment", path, "--out", rel] + LIMITS)
    assert code == 0, (stage, code, out[-2000:], err[-2000:])
    assert "the solution earns every point: 10 of 10" in out, (stage, out[-1000:])
    for f in files:
        text = open(os.path.join(rel, "shaders", f)).read()
        assert "BEGIN SOLUTION" not in text and "TODO" in text, (stage, f)

    def grade(shaders, report):
        code, out, err = run(["check", "--assignment", path, "--shaders", shaders, "--report", report] + LIMITS)
        return code, json.load(open(report)), out + err

    code, starter, log = grade(rel + "/shaders", work + "/%s-starter.json" % stage)
    st = starter["stages"][0]
    assert code == 1 and st["status"] == "FAIL" and st["points"] == 0, (stage, code, st["status"], st["points"], log[-2000:])
    assert all(r["verdict"] == "FAIL" for r in st["rows"]), (stage, [r["verdict"] for r in st["rows"]])
    solution = work + "/%s-solution" % stage
    for f in files:
        os.makedirs(os.path.dirname(os.path.join(solution, f)), exist_ok=True)
        shutil.copy(os.path.join(root, f), os.path.join(solution, f))
    code, full, log = grade(solution, work + "/%s-solution.json" % stage)
    assert code == 0 and full["score"] == full["max_score"] == 10, (stage, code, full["score"], log[-2000:])
    print("%s/%s: starter 0 of 10 (%d rows FAIL), solution 10 of 10 (%s)"
          % (stage, tree, len(st["rows"]), ", ".join(files)))
assert set(assignable) == set(stages) - {"phong", "fixed"}, assignable
print("course_stages_%s: ok" % tree)
