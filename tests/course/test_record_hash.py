#!/usr/bin/env python3
"""ctest course_record_hash: a record in OUT/students/ edited by hand is not kept (issue 38).
A class of two (ann correct, bob whose shader does not build) is graded; bob's record is edited
(score and stage points raised to full), and the rerun must grade bob again with a line naming
him and the reason, and grades.csv must give bob his real score; ann's untouched record is kept.
A third run keeps both (the rewritten record carries a matching hash). A record in the shape an
older shadowlab kept (issue 34) is graded again with the reason "kept by an older shadowlab".
usage: test_record_hash.py SHADOWLAB REPO WORKDIR"""
import csv, json, os, shutil, subprocess, sys

exe, repo, work = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
cls, out = work + "/class", work + "/out"
shipped = open(os.path.join(repo, "shaders_core/margin/lit.frag")).read()
for name, text in (("ann", shipped), ("bob", shipped.replace("void main", "void main oops"))):
    os.makedirs(cls + "/" + name + "/margin")
    open(cls + "/" + name + "/margin/lit.frag", "w").write(text)
lab = work + "/lab.json"
json.dump({"name": "margin only",
           "stages": [{"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
                       "lessons": {"margin margin-kind=slope": 0},
                       "views": {"cube-on-cube": {"weight": 0}}}]}, open(lab, "w"))
import expect  # noqa: E402
from expect import check  # noqa: E402


def grade():
    r = subprocess.run([exe, "grade", cls, "--assignment", lab, "--out", out, "--jobs", "1"],
                       capture_output=True, text=True, timeout=900)
    return r


def scores():
    return {row["student"]: float(row["total"]) for row in csv.DictReader(open(out + "/grades.csv"))}


r = grade()
check("first run exits 0", r.returncode == 0, r.stdout[-800:] + r.stderr[-800:])
real = scores()
check("bob's real score is below full", real["bob"] < 10 and real["ann"] == 10, real)
path = out + "/students/bob.json"
record = json.load(open(path))
check("the record carries its content hash", len(record.get("record_hash", "")) == 16, record.keys())
record["score"] = 10
for st in record["stages"]:
    st["points"] = st["max_points"]
    st["status"] = "PASS"
json.dump(record, open(path, "w"), indent=1)
r = grade()
check("the rerun exits 0", r.returncode == 0, r.stdout[-800:] + r.stderr[-800:])
check("one line names bob and why he is graded again",
      "grading bob again: its record does not match its content hash" in r.stdout, r.stdout[-800:])
check("ann's record is kept", "grading ann again" not in r.stdout, r.stdout[-800:])
check("grades.csv gives bob his real score, not the edited one", scores() == real, scores())
r = grade()
check("a third run keeps both records", r.returncode == 0 and "again:" not in r.stdout and
      "2 already graded, 0 to grade" in r.stdout, r.stdout[-800:])
# A record kept by an older shadowlab (its shape before issue 34: the report's fields alone, no
# name or version of its own, rows naming their lesson by its label) is not an error: the student
# is graded again with the reason, and the record is written in today's format.
path = out + "/students/ann.json"
record = json.load(open(path))
for key in ("record_format", "record_version", "report_format"):
    record.pop(key)
for st in record["stages"]:
    for row in st["rows"]:
        if row["expectation"]:
            row["expectation"].pop("id")
json.dump(record, open(path, "w"), indent=1)
r = grade()
check("an older shadowlab's record: the rerun exits 0", r.returncode == 0, r.stdout[-800:] + r.stderr[-800:])
check("one line names ann and the older record",
      "grading ann again: kept by an older shadowlab" in r.stdout, r.stdout[-800:])
check("the header counts it", "1 already graded, 1 to grade (1 kept by an older shadowlab)" in r.stdout,
      r.stdout[-800:])
check("bob's record is kept", "grading bob again" not in r.stdout, r.stdout[-800:])
check("the same scores", scores() == real, scores())
check("ann's record is rewritten in today's format",
      json.load(open(path)).get("record_format") == "shadowlab-kept-record", json.load(open(path)).keys())
print("%d checks" % expect.checks)
