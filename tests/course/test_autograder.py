#!/usr/bin/env python3
"""ctest course_autograder: `release --gradescope` writes autograder.zip with setup.sh and
run_autograder at its root; run_autograder is run in a simulated /autograder tree (its root in
AUTOGRADER_ROOT, the program built here in SHADOWLAB: setup.sh's build from the zip, in a fresh
chroot and a 768 MB cgroup, is CI's scripts/gradescope_suite.sh; the zip's content is
tests/install/autograder_zip.sh's) for a nested zip, a missing stage, a broken shader and correct work;
each results.json has Gradescope's documented fields (score, max_score, output, visibility,
stdout_visibility, tests with name, score, max_score, status, visibility, output) and the points
make_class.py derived from the assignment.  usage: test_autograder.py SHADOWLAB REPO WORKDIR"""
import json, os, shutil, stat, subprocess, sys, zipfile

exe, repo, work = sys.argv[1:4]
exe = os.path.abspath(exe)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
lab = os.path.join(repo, "assignments/lab4.json")
subprocess.run([exe, "release", "--assignment", lab, "--out", work + "/release", "--gradescope"],
               check=True, stdout=subprocess.DEVNULL)
z = zipfile.ZipFile(work + "/release/autograder.zip")
names = z.namelist()
for required in ("setup.sh", "run_autograder", "assignment.json", "shadowlab/CMakeLists.txt",
                 "shadowlab/cmake/glad.cmake", "shadowlab/scripts/deps.sh",
                 "shadowlab/src/course/assignment.cpp"):
    assert required in names, required
for script in ("setup.sh", "run_autograder"):
    mode = z.getinfo(script).external_attr >> 16
    assert mode & stat.S_IXUSR, script + " is not executable"
    assert z.read(script).startswith(b"#!/usr/bin/env bash"), script
assert b"scripts/deps.sh" in z.read("setup.sh")
expected = json.loads(subprocess.run(
    [sys.executable, os.path.join(os.path.dirname(__file__), "make_class.py"), repo,
     work + "/release/shaders", work + "/class"], check=True, capture_output=True, text=True).stdout)

# Gradescope's documented top-level keys (its specification has no top-level max_score: the
# maximum is the tests' max_score added up, docs/assignment.md).
TOP = {"score": (int, float), "output": str, "visibility": str, "stdout_visibility": str,
       "tests": list}
TEST = {"name": str, "score": (int, float), "max_score": (int, float), "status": str,
        "visibility": str, "output": str}
VIS = {"visible", "hidden", "after_due_date", "after_published"}
for student in ("alice", "bob", "carol", "dave"):  # correct, missing stages, broken, nested zip
    root = work + "/ag-" + student
    os.makedirs(root + "/source")
    z.extractall(root + "/source")
    os.chmod(root + "/source/run_autograder", 0o755)
    entry = work + "/class/" + student + (".zip" if os.path.exists(work + "/class/" + student + ".zip") else "")
    # Gradescope unpacks an uploaded zip's content into submission/; a zip inside stays a zip.
    if entry.endswith(".zip"):
        zipfile.ZipFile(entry).extractall(root + "/submission")
    else:
        shutil.copytree(entry, root + "/submission")
    env = dict(os.environ, AUTOGRADER_ROOT=root, SHADOWLAB=exe)
    r = subprocess.run([root + "/source/run_autograder"], env=env, capture_output=True, text=True,
                       timeout=900, cwd=root)
    assert r.returncode == 0, (student, r.returncode, r.stderr[-1000:])
    res = json.load(open(root + "/results/results.json"))
    for k, t in TOP.items():
        assert isinstance(res[k], t), (student, k)
    assert res["visibility"] in VIS and res["stdout_visibility"] in VIS
    total = maximum = 0
    for test in res["tests"]:
        for k, t in TEST.items():
            assert isinstance(test[k], t), (student, k, test)
        assert test["status"] in ("passed", "failed") and test["visibility"] in VIS
        assert 0 <= test["score"] <= test["max_score"] + 1e-9
        total += test["score"]
        maximum += test["max_score"]
    assert abs(total - res["score"]) < 0.05, (student, total, res["score"])
    want = sum(expected["points"][student].values())
    assert abs(res["score"] - want) < 0.05, (student, res["score"], want)
    assert abs(maximum - 100) < 0.05 and "max_score" not in res, (student, maximum)
    assert any(t["visibility"] == "hidden" for t in res["tests"]), "the instructor's view is not hidden"
    assert any(t["visibility"] == "after_due_date" for t in res["tests"])
    print(student, res["score"], "of", maximum, len(res["tests"]), "tests")
# Gradescope's submission_metadata.json: created_at under the assignment's late policy (10 % of
# the points a day, or part of one, after the grace; at most 30 %). 1.5 days late is 2 days: 20
# of 100 points off; a malformed file is the platform's, not the student's: no penalty.
late_lab = dict(json.load(open(lab)), late={"deadline": "2026-12-04T23:59:00+01:00", "grace_minutes": 15,
                                            "penalty_per_day": 10, "cap": 30})
json.dump(late_lab, open(work + "/lab4-late.json", "w"))
subprocess.run([exe, "release", "--assignment", work + "/lab4-late.json", "--out", work + "/release-late",
                "--gradescope"], check=True, stdout=subprocess.DEVNULL)
late_zip = zipfile.ZipFile(work + "/release-late/autograder.zip")
for case, metadata, off in (("late", '{"created_at": "2026-12-06T10:59:00.542003+00:00", "id": 1}', 20),
                            ("malformed", '{"created_at": "yesterday"}', 0)):
    root = work + "/ag-" + case
    os.makedirs(root + "/source")
    late_zip.extractall(root + "/source")
    shutil.copytree(work + "/class/alice", root + "/submission")
    open(root + "/submission_metadata.json", "w").write(metadata)
    env = dict(os.environ, AUTOGRADER_ROOT=root, SHADOWLAB=exe)
    r = subprocess.run(["bash", root + "/source/run_autograder"], env=env, capture_output=True, text=True,
                       timeout=900, cwd=root)
    res = json.load(open(root + "/results/results.json"))
    earned = sum(t["score"] for t in res["tests"])
    assert abs(earned - 100) < 0.05, (case, earned)
    assert abs(res["score"] - (100 - off)) < 0.05, (case, res["score"], off)
    if off:
        assert "2 days late: the late policy takes 20 points off, 80 of 100 points" in res["output"], res["output"]
    else:
        assert "no late policy applied" in r.stderr, r.stderr[-1000:]
    print(case, res["score"])
# A grader that cannot run still leaves a results.json (0 points, says why).
root = work + "/ag-broken"
os.makedirs(root + "/source")
z.extractall(root + "/source")
os.makedirs(root + "/submission")
env = dict(os.environ, AUTOGRADER_ROOT=root, SHADOWLAB="/nonexistent/shadowlab")
r = subprocess.run(["bash", root + "/source/run_autograder"], env=env, capture_output=True, text=True)
res = json.load(open(root + "/results/results.json"))
assert res["score"] == 0 and "could not grade" in res["output"], res
# NOT GRADED rows (check exits 3, its results.json has no score): the run fails with 3, as
# docs/check.md promises, never exit 0 with a results.json Gradescope would read as a grade. A
# stand-in program plays check's part (a real NOT GRADED needs a failing machine).
root = work + "/ag-not-graded"
os.makedirs(root + "/source")
z.extractall(root + "/source")
os.makedirs(root + "/submission")
fake = work + "/not-graded-check"
open(fake, "w").write('#!/bin/sh\nwhile [ "$1" != --report ]; do shift; done\n'
                      'printf \'{"output": "not graded: rerun", "tests": []}\\n\' > "$2"\nexit 3\n')
os.chmod(fake, 0o755)
env = dict(os.environ, AUTOGRADER_ROOT=root, SHADOWLAB=fake)
r = subprocess.run(["bash", root + "/source/run_autograder"], env=env, capture_output=True, text=True)
assert r.returncode == 3 and "not graded" in r.stderr, (r.returncode, r.stderr[-500:])
assert "score" not in json.load(open(root + "/results/results.json"))
print("course_autograder: ok")
