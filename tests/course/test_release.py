#!/usr/bin/env python3
"""ctest course_release, in TREE (core or legacy): the release of lab4 (moved to TREE), made from
an instructor's own copy of the trees (`--solutions`), holds that copy's stubs and no line of any
marked solution region; graded by the assignment, every starter stage gets 0 points with FAIL rows
(or is MISSING), while the shipped solution gets every point; the window runs on the release and
draws (a screenshot that is not blank). In the core tree also: a marker look-alike refuses the
release naming its file and line and writes nothing; a solution that loses a row (an extra view
whose light our own method cannot handle) refuses the release naming the row; the student edition
holds every shipped file and no line of any region.
usage: test_release.py SHADOWLAB REPO WORKDIR TREE"""
import json, os, re, shutil, subprocess, sys

exe, repo, work, tree = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
LIMITS = ["--time-limit", "300"]
lab = json.load(open(os.path.join(repo, "assignments/lab4.json")))
for s in lab["stages"]:
    s["tree"] = tree
assignment = work + "/lab4-%s.json" % tree
json.dump(lab, open(assignment, "w"), indent=1)

# The instructor's own trees: the shipped ones with one stub reworded.
mine = work + "/instructor"
shutil.copytree(os.path.join(repo, "shaders_" + tree), mine + "/shaders_" + tree)
own = mine + "/shaders_%s/margin/lit.frag" % tree
text = open(own).read()
assert "// STUB: // TODO: `margin` when" in text
open(own, "w").write(text.replace("// STUB: // TODO: `margin` when", "// STUB: // TODO (instructor's own): `margin` when"))
rel = work + "/release"
r = subprocess.run([exe, "release", "--assignment", assignment, "--out", rel, "--solutions", mine] + LIMITS,
                   capture_output=True, text=True)
print(r.stdout[-1500:], r.stderr[-1500:])
assert r.returncode == 0, r.returncode
assert "the solution earns every point" in r.stdout
assert "TODO (instructor's own)" in open(rel + "/shaders/margin/lit.frag").read()

def regions_of(text):
    return re.findall(r"// BEGIN SOLUTION\n(.*?)// END SOLUTION", text, re.S)

def solution_lines(region):
    for line in region.splitlines():
        code = line.strip()
        if len(code) >= 4 and not code.startswith("//"):
            yield code

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
        for region in regions_of(shipped):
            regions += 1
            for code in solution_lines(region):
                assert code not in released, "%s: solution line in the release: %s" % (f, code)
        assert "BEGIN SOLUTION" not in open(os.path.join(rel, "shaders", f)).read()
        assert "TODO" in open(os.path.join(rel, "shaders", f)).read(), f + ": no TODO for the student"
assert regions >= len(due), regions
print("no solution line of %d regions in the release" % regions)

# 2. The starter fails every due stage; the solution passes every one.
def grade(shaders, report):
    r = subprocess.run([exe, "check", "--assignment", assignment, "--shaders", shaders,
                        "--report", report] + LIMITS, capture_output=True, text=True, timeout=900)
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
    cmd = ["timeout", "120", "sh", os.path.join(repo, "tests", "with_xvfb.sh"), "1280x1024x24", exe, "window",
           "--shaders", rel + "/shaders", "--stage", s["stage"], "--frames", "2", "--screenshot", shot]
    if tree == "legacy":
        cmd[cmd.index("--frames"):cmd.index("--frames")] = ["--glsl", "legacy"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, (s["stage"], r.returncode, r.stderr[-800:])
    assert os.path.getsize(shot) > 1000, shot

if tree == "core":
    # 4. A marker look-alike in the instructor's trees refuses the release, naming the file and
    #    the line, and nothing is written (each case checks before any grading).
    shipped_rgb = open(os.path.join(repo, "shaders_core/rgb/lit.frag")).read()
    line = shipped_rgb.splitlines().index("    // BEGIN SOLUTION") + 1
    mine_rgb = mine + "/shaders_core/rgb/lit.frag"
    looks = ["//BEGIN SOLUTION", "/* BEGIN SOLUTION */", "// begin solution", "// BEGIN  SOLUTION",
             "// BEGIN_SOLUTION", "if (true) // BEGIN SOLUTION"]
    for look in looks:
        open(mine_rgb, "w").write(shipped_rgb.replace("    // BEGIN SOLUTION", "    " + look, 1))
        r = subprocess.run([exe, "release", "--assignment", assignment, "--out", work + "/refused",
                            "--solutions", mine], capture_output=True, text=True, timeout=300)
        want = "shaders_core/rgb/lit.frag: line %d: '%s' looks like a solution marker" % (line, look)
        assert r.returncode == 2 and want in r.stderr and r.stderr.count("\n") == 1, (look, r.returncode, r.stderr)
        assert not os.path.exists(work + "/refused"), look
    # END misspelled: the BEGIN is never closed (and the END look-alike refuses first).
    for broken, want in [(shipped_rgb.replace("    // END SOLUTION", "    // END-SOLUTION", 1), "'// END-SOLUTION' looks like"),
                         (re.sub(r"    // END SOLUTION\n(    // STUB:.*\n)*", "", shipped_rgb, count=1), "line %d: BEGIN SOLUTION is never closed" % line),
                         (shipped_rgb.replace("    // END SOLUTION\n", "", 1), "line %d: a STUB line inside the region opened on line %d" % (line + 3, line)),
                         (shipped_rgb.replace("    // BEGIN SOLUTION", "    // BEGIN SOLUTION\n    // BEGIN SOLUTION", 1), "BEGIN SOLUTION inside the region")]:
        open(mine_rgb, "w").write(broken)
        r = subprocess.run([exe, "release", "--assignment", assignment, "--out", work + "/refused",
                            "--solutions", mine], capture_output=True, text=True, timeout=300)
        assert r.returncode == 2 and want in r.stderr, (want, r.returncode, r.stderr)
        assert not os.path.exists(work + "/refused")
    open(mine_rgb, "w").write(shipped_rgb)
    print("look-alike markers refused: %d" % (len(looks) + 4))

    # 5. The solution is graded first: an extra view whose light our own method cannot handle
    #    costs the solution points, so the release is refused naming that view.
    bad = {"name": "margin with a bad extra view",
           "stages": [{"stage": "margin", "files": ["margin/lit.frag"], "points": 30}],
           "extra_views": [{"name": "low-light", "light": [1.5, 0.6, 1.0]}]}
    json.dump(bad, open(work + "/bad.json", "w"), indent=1)
    r = subprocess.run([exe, "release", "--assignment", work + "/bad.json", "--out", work + "/refused"] + LIMITS,
                       capture_output=True, text=True, timeout=1800)
    print(r.stdout[-800:], r.stderr[-800:])
    assert r.returncode == 2 and r.stderr.count("\n") == 1, (r.returncode, r.stderr)
    assert "/extra_views/0 (line" in r.stderr and "view low-light" in r.stderr and "the solution (the shipped shaders) loses" in r.stderr, r.stderr
    assert not os.path.exists(work + "/refused")
    # A graded row that draws with a marked file its stage does not list (students have only its
    # stub) refuses too: the mirror without its vertex shader.
    json.dump({"name": "mirror", "stages": [{"stage": "mirror", "files": ["mirror/surface.frag"], "points": 5}]},
              open(work + "/mirror.json", "w"))
    r = subprocess.run([exe, "release", "--assignment", work + "/mirror.json", "--out", work + "/refused"] + LIMITS,
                       capture_output=True, text=True, timeout=1800)
    assert r.returncode == 2 and "/stages/0/files (line 1): mirror/surface.vert (the shipped shaders) holds a solution region" in r.stderr, r.stderr
    assert not os.path.exists(work + "/refused")

    # 6. The student edition: every shipped file, no line of any region.
    edition = work + "/edition"
    subprocess.run([exe, "release", "--student-edition", "--out", edition], check=True)
    stubbed = marked = 0
    for t in ("core", "legacy"):
        src = os.path.join(repo, "shaders_" + t)
        for d, _, files in os.walk(src):
            for f in files:
                rel_path = os.path.relpath(os.path.join(d, f), src)
                shipped = open(os.path.join(d, f)).read()
                got = open(os.path.join(edition, "shaders_" + t, rel_path)).read()
                stubbed += got != shipped
                marked += "// BEGIN SOLUTION" in shipped
                assert "BEGIN SOLUTION" not in got and "STUB:" not in got, rel_path
                for region in regions_of(shipped):
                    for code in solution_lines(region):
                        assert code not in got, (rel_path, code)
    assert stubbed == marked >= 20, (stubbed, marked)
    print("student edition: %d files stubbed" % stubbed)
print("course_release %s: ok" % tree)
