#!/usr/bin/env python3
"""ctest course_release, in TREE (core or legacy): the release of lab4 (moved to TREE) holds no
line of any marked solution region; graded by the assignment, every starter stage gets 0 points
with FAIL rows (or is MISSING), while the shipped solution gets every point; the window runs on
the release and draws (a screenshot that is not blank).  usage: test_release.py SHADOWLAB REPO WORKDIR TREE"""
import json, os, re, shutil, subprocess, sys

exe, repo, work, tree = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
lab = json.load(open(os.path.join(repo, "assignments/lab4.json")))
for s in lab["stages"]:
    s["tree"] = tree
assignment = work + "/lab4-%s.json" % tree
json.dump(lab, open(assignment, "w"), indent=1)
rel = work + "/release"
subprocess.run([exe, "release", "--assignment", assignment, "--out", rel], check=True)

# 1. No solution text anywhere in the release.
released = ""
for root, _, files in os.walk(rel):
    for f in files:
        released += open(os.path.join(root, f), errors="replace").read() + "\n"
due = [s for s in lab["stages"] if s.get("due", True)]
regions = 0
for s in due:
    for f in s["files"]:
        shipped = open(os.path.join(repo, "shaders_" + tree, f)).read()
        for region in re.findall(r"// BEGIN SOLUTION\n(.*?)// END SOLUTION", shipped, re.S):
            regions += 1
            for line in region.splitlines():
                code = line.strip()
                if len(code) < 4 or code.startswith("//"):
                    continue
                assert code not in released, "%s: solution line in the release: %s" % (f, code)
        assert "BEGIN SOLUTION" not in open(os.path.join(rel, "shaders", f)).read()
        assert "TODO" in open(os.path.join(rel, "shaders", f)).read(), f + ": no TODO for the student"
assert regions >= len(due), regions
print("no solution line of %d regions in the release" % regions)

# 2. The starter fails every due stage; the solution passes every one.
def grade(shaders, report):
    r = subprocess.run([exe, "check", "--assignment", assignment, "--shaders", shaders,
                        "--report", report, "--time-limit", "300"], capture_output=True, text=True, timeout=900)
    print(r.stdout[-1500:], r.stderr[-1500:])
    return r.returncode, json.load(open(report))

code, starter = grade(rel + "/shaders", work + "/starter.json")
assert code == 1, code
for st in starter["stages"]:
    assert st["points"] == 0, (st["stage"], st["points"])
    assert st["status"] in ("FAIL", "MISSING"), st["status"]
    assert all(r["verdict"] in ("FAIL", "MISSING") for r in st["rows"]), st["stage"]
solution = work + "/solution"
for s in due:
    for f in s["files"]:
        os.makedirs(os.path.dirname(os.path.join(solution, f)), exist_ok=True)
        shutil.copy(os.path.join(repo, "shaders_" + tree, f), os.path.join(solution, f))
code, full = grade(solution, work + "/solution.json")
assert code == 0, code
assert abs(full["score"] - full["max_score"]) < 0.01 and full["max_score"] > 0, full["score"]

# 3. The window runs on the release: every due stage draws two frames and saves a picture.
for s in due:
    shot = work + "/window-%s.png" % s["stage"]
    cmd = ["timeout", "120", "xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", exe, "window",
           "--shaders", rel + "/shaders", "--stage", s["stage"], "--frames", "2", "--screenshot", shot]
    if tree == "legacy":
        cmd[cmd.index("--frames"):cmd.index("--frames")] = ["--glsl", "legacy"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, (s["stage"], r.returncode, r.stderr[-800:])
    assert os.path.getsize(shot) > 1000, shot
print("course_release %s: ok" % tree)
