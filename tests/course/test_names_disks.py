#!/usr/bin/env python3
"""ctest course_names_disks: names as the file system gives them, and a full disk (issue 39).
  1. A hand-in folder whose name is not UTF-8 (Latin-1 "café" from an old zip tool) is a student:
     graded, its record found again on a rerun (never "no record (its job failed)", never NOT
     GRADED), its row in grades.csv and on the class page with the name escaped (caf\\xE9).
  2. A full disk under --out (a tmpfs, as root) ends with one line on stderr saying the disk is
     full, and what an earlier run wrote (records, grades.csv) is still whole.
Hand-ins without the due file (MISSING): nothing of theirs is rendered, only the solution check.
usage: test_names_disks.py SHADOWLAB REPO WORKDIR"""
import csv, json, os, shutil, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from expect import check

exe, repo, work = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
cls, out = work + "/class", work + "/out"
lab = work + "/lab.json"
os.makedirs(cls)
json.dump({"name": "margin only",
           "stages": [{"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
                       "lessons": {"margin margin-kind=slope": 0},
                       "views": {"cube-on-cube": {"weight": 0}, "sphere-on-cube": {"weight": 0},
                                 "cube-on-sphere": {"weight": 0}, "grazing": {"weight": 0}}}]},
          open(lab, "w"))
latin1 = os.fsencode(cls) + b"/caf\xe9"
os.makedirs(latin1)
open(latin1 + b"/README.txt", "wb").write(b"not yet\n")
os.makedirs(cls + "/ann")
open(cls + "/ann/README.txt", "w").write("not yet\n")


def grade(dest, *extra):
    r = subprocess.run([exe, "grade", cls, "--assignment", lab, "--out", dest, "--seed", "4242"] +
                       list(extra), capture_output=True, timeout=900)
    text = (r.stdout + r.stderr).decode("utf-8", "replace")
    print(text[-3000:])
    return r.returncode, r.stdout.decode("utf-8", "replace"), r.stderr.decode("utf-8", "replace")


# ---- 1. a name that is not UTF-8
code, stdout, stderr = grade(out)
check("a class with a Latin-1 name: exit 0", code == 0, (code, stderr))
check("no 'no record' line", "no record" not in stderr, stderr)
rows = {row["student"]: row for row in csv.DictReader(open(out + "/grades.csv", encoding="utf-8"))}
check("grades.csv: the Latin-1 name's row, escaped", "caf\\xE9" in rows and rows["caf\\xE9"]["status"] == "MISSING",
      sorted(rows))
records = [json.load(open(os.path.join(out, "students", f))) for f in os.listdir(out + "/students")]
rec = [r for r in records if r["student_bytes"]]
check("its record keeps the name's bytes", len(rec) == 1 and rec[0]["student_bytes"] == "636166e9" and
      rec[0]["student"] == "caf\\xE9", [(r["student"], r["student_bytes"]) for r in records])
page = open(out + "/class.html", encoding="utf-8").read()
check("the class page shows it escaped", "caf\\xE9" in page, page[:500])
code, stdout, stderr = grade(out)
check("a rerun finds its record again: nobody graded", code == 0 and "2 already graded, 0 to grade" in stdout,
      (code, stdout, stderr))

# The name as every output shows it (caf\xE9, what a UTF-8 file or a command line can hold) names
# that hand-in in --regrade, --adjust, --times and a roster's hand-in column.
code, stdout, stderr = grade(out, "--regrade", "caf\\xE9")
check("--regrade caf\\xE9 grades that hand-in again", code == 0 and "1 to grade" in stdout and
      "grading caf\\xE9 again: asked for" in stdout, (code, stdout, stderr))
open(work + "/adjust.csv", "w").write("hand-in,stage,points,reason\ncaf\\xE9,margin,+2,the write-up\n")
open(work + "/roster.csv", "w", encoding="utf-8").write("id,name,email,hand-in\n7,Zo\u00e9 Caf\u00e9,z@example.edu,caf\\xE9\n"
                                      "8,Ann,ann@example.edu,ann\n")
code, stdout, stderr = grade(out, "--adjust", work + "/adjust.csv", "--roster", work + "/roster.csv")
rows = {row["student"]: row for row in csv.DictReader(open(out + "/grades.csv", encoding="utf-8"))}
check("--adjust and --roster name it escaped: its row has the adjustment and the roster's id, no "
      "row 'no hand-in', no hand-in off the roster",
      code == 0 and len(rows) == 2 and rows["caf\\xE9"]["adjustments"] == "2.000" and
      rows["caf\\xE9"]["id"] == "7" and "not on the roster" not in stdout, (code, stdout, stderr, rows))
late = dict(json.load(open(lab)), late={"deadline": "2030-01-01T00:00:00Z", "grace_minutes": 0,
                                      "penalty_per_day": 10, "cap": 30})
json.dump(late, open(work + "/late.json", "w"))
open(work + "/times.csv", "w").write("hand-in,time\ncaf\\xE9,2030-01-02T12:00:00Z\n")
r = subprocess.run([exe, "grade", cls, "--assignment", work + "/late.json", "--out", work + "/out-late",
                    "--seed", "4242", "--times", work + "/times.csv"], capture_output=True, timeout=900)
rec = [json.load(open(os.path.join(work, "out-late/students", f)))
       for f in os.listdir(work + "/out-late/students")]
late_of = {x["student"]: x.get("late") or {} for x in rec}
check("--times names it escaped: its time from --times, no unused entry",
      r.returncode == 0 and late_of["caf\\xE9"].get("source") == "--times" and
      b"names no hand-in" not in r.stdout, (r.returncode, r.stdout[-800:], late_of))

# ---- 2. a full disk (a tmpfs; root only)
if os.geteuid() != 0:
    print("skipped: the full-disk case needs root (mount -t tmpfs); CI runs as root")
    sys.exit(0)


def fill(mnt):
    fd = os.open(mnt + "/filler", os.O_WRONLY | os.O_CREAT | os.O_APPEND)
    for size in (65536, 4096, 512, 1):  # to the last byte
        try:
            while os.write(fd, b"\0" * size) == size:
                pass
        except OSError:  # ENOSPC
            pass
    os.close(fd)


def one_full_line(stderr):
    lines = stderr.strip().split("\n")
    return len(lines) == 1 and "shadowlab: grade: the disk" in lines[0] and "full" in lines[0]


mnt = work + "/full"
os.makedirs(mnt)
subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", mnt], check=True)
try:
    # Full before anything is written: the solution check's mark does not fit.
    os.makedirs(mnt + "/fresh")
    fill(mnt)
    code, stdout, stderr = grade(mnt + "/fresh")
    check("full from the start: exit 3, one line saying so", code == 3 and one_full_line(stderr),
          (code, stderr))
    os.remove(mnt + "/filler")
    # A class graded, then the disk fills and a hand-in changes: its record does not fit.
    code, stdout, stderr = grade(mnt + "/out")
    check("graded on the tmpfs", code == 0, (code, stderr))
    kept = {}
    for d in ("students", "feedback", "."):
        for f in os.listdir(mnt + "/out/" + d):
            if os.path.isfile(mnt + "/out/" + d + "/" + f) and not f.startswith("."):
                kept[d + "/" + f] = open(mnt + "/out/" + d + "/" + f, "rb").read()
    open(cls + "/ann/README.txt", "w").write("changed\n")
    fill(mnt)
    code, stdout, stderr = grade(mnt + "/out")
    check("full mid-run: exit 3, one line saying so", code == 3 and one_full_line(stderr),
          (code, stderr))
    lost = [f for f, data in kept.items() if open(mnt + "/out/" + f, "rb").read() != data]
    check("nothing written before is lost (records, pages, grades.csv)", lost == [], lost)
finally:
    subprocess.run(["umount", mnt])
print("course_names_disks: ok")
