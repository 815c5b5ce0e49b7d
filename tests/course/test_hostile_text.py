#!/usr/bin/env python3
"""ctest course_hostile_text: text we did not write, bounded (issue 38). Through the real binary:
  --times with a 500,000-digit fraction (a field past the CSV bound), a 4,000-digit one, a day the month does not have (2026-11-31) and a +99:99
  zone: each refused with one short line naming the file and line (exit 2), never a crash;
  a --times entry naming no hand-in of the class: a warning line naming it;
  a roster of 100,001 students: "more than 100000 students (the limit)" on the first row past it;
  Gradescope's submission_metadata.json with a 500,000-digit fraction in created_at: a note, no
  penalty, full points (the platform's file never costs the student), never a crash;
  a student's page and record name the student's files and our tree, never the grader's folders.
usage: test_hostile_text.py SHADOWLAB REPO WORKDIR"""
import csv, json, os, shutil, subprocess, sys

exe, repo, work = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
cls, out = work + "/class", work + "/out"
os.makedirs(cls + "/ann/margin")
shutil.copy(os.path.join(repo, "shaders_core/margin/lit.frag"), cls + "/ann/margin/lit.frag")
# eve's shader includes a file outside her folder: her page must name her files and our tree,
# never the grader's folders (the snapshot under --out, where our shaders are installed).
os.makedirs(cls + "/eve/margin")
eve = open(os.path.join(repo, "shaders_core/margin/lit.frag")).read()
open(cls + "/eve/margin/lit.frag", "w").write(
    eve.replace("void main", '#include "../../secret.glsl"\nvoid main', 1))
lab = work + "/lab.json"
json.dump({"name": "margin only",
           "late": {"deadline": "2026-12-04T23:59:00+01:00", "grace_minutes": 15,
                    "penalty_per_day": 10, "cap": 30},
           "stages": [{"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
                       "lessons": {"margin margin-kind=slope": 0},
                       "views": {"cube-on-cube": {"weight": 0}}}]}, open(lab, "w"))
import expect  # noqa: E402
from expect import check  # noqa: E402


def run(*args):
    return subprocess.run([exe] + list(args), capture_output=True, text=True, timeout=900)


def grade(*extra):
    return run("grade", cls, "--assignment", lab, "--out", out, "--jobs", "1", *extra)


def write(name, text):
    path = os.path.join(work, name)
    open(path, "w").write(text)
    return path


r = grade()  # the solution check and ann, once: the runs below reuse both
check("the class is graded (exit 0)", r.returncode == 0, r.stderr[-800:])
page = open(out + "/feedback/eve.html").read()
record = json.load(open(out + "/students/eve.json"))
text = page + json.dumps([st["message"] for st in record["stages"]])
check("eve's include is refused, naming what is allowed without grader paths",
      "allowed: files under your hand-in and shaders_core" in text and "/snapshot" not in text and
      os.path.abspath(repo) not in text and out not in text, text[-1500:])
for label, value, want in (
        ("a 500,000-digit fraction", "2026-12-05T10:00:00." + "5" * 500000 + "+01:00",
         "a field of 500026 bytes; at most 4096 are allowed"),
        ("a 4,000-digit fraction", "2026-12-05T10:00:00." + "5" * 4000 + "+01:00", "is not ISO 8601"),
        ("2026-11-31 (no such day)", "2026-11-31T10:00:00Z", "is not ISO 8601"),
        ("a +99:99 zone", "2026-12-05T10:00:00+99:99", "is not ISO 8601")):
    times = write("times.csv", "hand-in,time\nann," + value + "\n")
    r = grade("--times", times)
    lines = r.stderr.strip().splitlines()
    check("--times with %s: refused in one short line naming file and line (exit 2)" % label,
          r.returncode == 2 and len(lines) == 1 and "times.csv: line 2: " in lines[0] and
          want in lines[0] and len(lines[0]) < 400, (r.returncode, r.stderr[-600:]))
times = write("times.csv", "hand-in,time\nann,2026-12-05T10:00:00+01:00\nghost,2026-12-05T10:00:00Z\n")
r = grade("--times", times)
check("--times naming a hand-in not in the class: a warning line naming it",
      r.returncode == 0 and
      "warning: --times: 1 entry names no hand-in in the class (unused): ghost" in r.stdout,
      (r.returncode, r.stdout[-800:], r.stderr[-400:]))
rows = ["id,name,email,hand-in"] + ["%d,S%d,s%d@x.org,h%d" % (k, k, k, k) for k in range(100001)]
roster = write("roster.csv", "\n".join(rows) + "\n")
r = grade("--roster", roster)
check("a roster of 100,001 students: the limit stated exactly",
      r.returncode == 2 and "roster.csv: line 100002: more than 100000 students (the limit)" in r.stderr,
      (r.returncode, r.stderr[-600:]))
meta = write("submission_metadata.json",
             json.dumps({"created_at": "2026-12-06T10:59:00." + "5" * 500000 + "+00:00"}))
report = work + "/report.json"
r = run("check", "--assignment", lab, "--shaders", cls + "/ann", "--submission-metadata", meta,
        "--report", report)
res = json.load(open(report)) if os.path.exists(report) else {}
check("Gradescope's created_at with a 500,000-digit fraction: a note, no penalty, full points",
      r.returncode == 0 and "no late policy applied" in r.stderr and
      res.get("score") == res.get("max_score") == 10, (r.returncode, r.stderr[-600:]))
print("%d checks" % expect.checks)
