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
