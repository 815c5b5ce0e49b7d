#!/usr/bin/env python3
"""ctest course_roster: `grade --roster` and the LMS exports (issue 29, docs/assignment.md
"Roster", "Gradebook exports"). A roster with a
byte order mark, a quoted name holding a comma and a non-ASCII name; hand-ins that need no
rendering (a README only, an empty zip) so the test is quick:
  ann       on the roster, a README only        -> her row: id, name, email, MISSING, 0
  bea.zip   on the roster, an empty zip          -> her row
  carl      on the roster, no hand-in            -> a row "no hand-in": MISSING, 0 points
  zed       a hand-in not on the roster          -> named in the summary, empty id/name/email
Checks grades.csv's columns and cells, every record's `roster`, the pages; then malformed
rosters: exit 2, one line naming the file and the line, nothing graded.
usage: test_roster.py SHADOWLAB REPO WORKDIR"""
import csv, json, os, shutil, subprocess, sys, zipfile

sys.path.insert(0, os.path.dirname(__file__))
from expect import expect, finish, grade

exe, repo, work = sys.argv[1:4]
work = os.path.abspath(work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
# A small assignment (quick; once the release work is merged, grade checks its solution first):
# rgb in one view, one lesson.
lab = os.path.join(work, "lab.json")
json.dump({"name": "Lab 4: shadow maps",
           "stages": [{"stage": "rgb", "tree": "core", "files": ["rgb/lit.frag"], "points": 20,
                       "lessons": {"rgb margin=0.01": 0},
                       "views": {v: 0 for v in ["cube-on-cube", "sphere-on-cube", "cube-on-sphere",
                                                "grazing"]}}]},
          open(lab, "w"))
klass = os.path.join(work, "class")
for name in ["ann", "zed"]:
    os.makedirs(os.path.join(klass, name))
    open(os.path.join(klass, name, "README.md"), "w").write("nothing here\n")
zipfile.ZipFile(os.path.join(klass, "bea.zip"), "w").close()
roster = os.path.join(work, "roster.csv")
open(roster, "wb").write(
    "\ufeffid,name,email,hand-in\r\n"
    "1001,\"Ng, Ann\",ann@example.edu,ann\r\n"
    "1002,Béa Šimić,bea@example.edu,bea\r\n"
    "1003,\"Carl \"\"C\"\" Org\",carl@example.edu,carl\r\n".encode("utf-8"))


out = os.path.join(work, "out")
r = grade(exe, klass, lab, out, "--roster", roster, "--time-limit", "300")
expect(r.returncode == 0, "exit %d" % r.returncode)
expect("1 hand-in not on the roster: zed" in r.stdout, "zed not named in the summary")

rows = list(csv.reader(open(os.path.join(out, "grades.csv"), encoding="utf-8", newline="")))
header = rows[0]
expect(header[:5] == ["student", "id", "name", "email", "status"], "header %s" % header)
due = [s["stage"] + "/" + s["tree"] for s in json.load(open(lab))["stages"] if s.get("due", True)]
expect(header[5:] == due + ["adjustments", "late_penalty", "total", "max", "not_graded"], "header %s" % header)
by = {row[0]: dict(zip(header, row)) for row in rows[1:]}
expect(sorted(by) == ["ann", "bea", "carl", "zed"], "rows %s" % sorted(by))
want = {"ann": ("1001", "Ng, Ann", "ann@example.edu"),
        "bea": ("1002", "Béa Šimić", "bea@example.edu"),
        "carl": ("1003", 'Carl "C" Org', "carl@example.edu"),
        "zed": ("", "", "")}
for who, (i, name, email) in want.items():
    row = by.get(who, {})
    expect((row.get("id"), row.get("name"), row.get("email")) == (i, name, email),
           "%s: %s" % (who, row))
carl = by.get("carl", {})
expect(carl.get("status") == "MISSING" and carl.get("total") == "0.000", "carl: %s" % carl)
expect(all(carl.get(s) == "0.000" for s in due), "carl's stages: %s" % carl)

# Every record carries its roster entry (zed's is null); carl has a page saying "no hand-in".
for who, (i, name, email) in want.items():
    if who == "carl":
        continue
    rec = json.load(open(os.path.join(out, "students", who + ".json")))
    expect(rec["roster"] == ({"id": i, "name": name, "email": email} if i else None),
           "%s's record: %s" % (who, rec["roster"]))
page = open(os.path.join(out, "feedback", "carl.html"), encoding="utf-8").read()
expect("no hand-in" in page and "1003" in page, "carl's page")
page = open(os.path.join(out, "feedback", "bea.html"), encoding="utf-8").read()
expect("Béa Šimić" in page, "bea's page does not name her")
expect("Ng, Ann" in open(os.path.join(out, "class.html"), encoding="utf-8").read(),
       "the class page does not name Ann")

# The LMS exports: Canvas's Gradebook import columns and Moodle's CSV grade import, exactly.
title = json.load(open(lab))["name"]
canvas = list(csv.reader(open(os.path.join(out, "gradebook-canvas.csv"), encoding="utf-8", newline="")))
expect(canvas[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", title],
       "canvas header %s" % canvas[0])
expect(sorted(canvas[1:]) == sorted([["Ng, Ann", "", "1001", "", "", "0.00"],
                                     ["Béa Šimić", "", "1002", "", "", "0.00"],
                                     ['Carl "C" Org', "", "1003", "", "", "0.00"],
                                     ["zed", "", "", "", "", "0.00"]]), "canvas rows %s" % canvas[1:])
moodle = list(csv.reader(open(os.path.join(out, "gradebook-moodle.csv"), encoding="utf-8", newline="")))
expect(moodle[0] == ["ID number", "Email address", title], "moodle header %s" % moodle[0])
expect(sorted(moodle[1:]) == sorted([["1001", "ann@example.edu", "0.00"], ["1002", "bea@example.edu", "0.00"],
                                     ["1003", "carl@example.edu", "0.00"], ["", "", "0.00"]]),
       "moodle rows %s" % moodle[1:])

# Malformed rosters: exit 2, one line naming the file and the line.
bad = {
    "header.csv": ("name,id,email,hand-in\n1,a,b,c\n", "line 1: the header must be"),
    "fields.csv": ("id,name,email,hand-in\n1,Ann,a@x,ann\n2,Bo,b@x\n", "line 3: 3 fields"),
    "quote.csv": ("id,name,email,hand-in\n1,\"Ann,a@x,ann\n", "line 2: a quoted field is never closed"),
    "stray.csv": ("id,name,email,hand-in\n1,A\"nn,a@x,ann\n", "line 2: a quote inside an unquoted field"),
    "twice.csv": ("id,name,email,hand-in\n1,Ann,a@x,ann\n2,Ann B,b@x,ann\n", "line 3: hand-in 'ann' is already on line 2"),
    "latin1.csv": (b"id,name,email,hand-in\n1,B\xe9a,b@x,bea\n", "line 2: not UTF-8"),
}
for name, (text, message) in bad.items():
    path = os.path.join(work, name)
    open(path, "wb").write(text if isinstance(text, bytes) else text.encode())
    r = subprocess.run([exe, "grade", klass, "--assignment", lab, "--out", work + "/bad",
                        "--roster", path], capture_output=True, text=True, timeout=120)
    lines = r.stderr.strip().splitlines()
    expect(r.returncode == 2 and len(lines) == 1 and name in lines[0] and message in lines[0],
           "%s: exit %d, %s" % (name, r.returncode, r.stderr))
    expect(not os.path.exists(work + "/bad/students") or not os.listdir(work + "/bad/students"),
           name + ": graded although the roster is malformed")

finish("roster: columns, records, the student with no hand-in, malformed rosters refused")
