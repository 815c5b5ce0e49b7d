#!/usr/bin/env python3
"""ctest course_out_links: grade's own names under --out never lead outside it (issue 38).
A symbolic link is planted, one at a time, at each name grade creates or opens under --out (the
lock, solution_check.txt, the exports, the folders students/ feedback/ work/ logs/, a job's log and
progress file, a student's record, page and work folder), pointing once to a file and once to a
folder outside --out. Each run must be refused with one line naming the link (exit 2), and
nothing outside --out may change (every file's bytes and mode compared before and after).
usage: test_out_links.py SHADOWLAB REPO WORKDIR [NAME...]  (NAME: only these names)"""
import json, os, shutil, subprocess, sys

exe, repo, work = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
cls, out, outside = work + "/class", work + "/out", work + "/outside"
os.makedirs(cls + "/ann/margin")
shutil.copy(os.path.join(repo, "shaders_core/margin/lit.frag"), cls + "/ann/margin/lit.frag")
lab = work + "/lab.json"
json.dump({"name": "margin only",
           "stages": [{"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
                       "lessons": {"margin margin-kind=slope": 0},
                       "views": {"cube-on-cube": {"weight": 0}}}]}, open(lab, "w"))
os.makedirs(outside + "/folder/inner")
for rel in ("victim.txt", "folder/inner/keep.txt", "folder/ann.json"):
    open(os.path.join(outside, rel), "w").write("precious " + rel + "\n")
import expect  # noqa: E402
from expect import check  # noqa: E402


def snapshot(root):
    state = {}
    for base, dirs, files in os.walk(root):
        for name in dirs + files:
            p = os.path.join(base, name)
            st = os.lstat(p)
            data = open(p, "rb").read() if os.path.isfile(p) and not os.path.islink(p) else b""
            state[os.path.relpath(p, root)] = (st.st_mode, data)
    return state


before = snapshot(outside)
# Each name grade writes, and whether its parent folder must exist for the link to be planted.
names = [".grade.lock", "solution_check.txt", "grades.csv", "gradebook-canvas.csv",
         "gradebook-moodle.csv", "class.html", "adjustments.csv", "students", "feedback", "work", "logs",
         "logs/job-0.log", "logs/job-0.progress", "students/ann.json", "feedback/ann.html",
         "work/ann"]
for name in sys.argv[4:] or names:
    for target in (outside + "/victim.txt", outside + "/folder"):
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(os.path.dirname(os.path.join(out, name)), exist_ok=True)
        os.symlink(target, os.path.join(out, name))
        r = subprocess.run([exe, "grade", cls, "--assignment", lab, "--out", out, "--jobs", "1"],
                           capture_output=True, text=True, timeout=600)
        lines = r.stderr.strip().splitlines()
        label = "a link at OUT/%s to %s" % (name, os.path.basename(target))
        check(label + ": refused with one line naming it (exit 2)",
              r.returncode == 2 and len(lines) == 1 and (out + "/" + name) in lines[0] and
              "symbolic link" in lines[0], (r.returncode, r.stderr[-800:]))
        check(label + ": nothing outside --out changed", snapshot(outside) == before)
print("%d checks" % expect.checks)
