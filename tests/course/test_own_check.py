#!/usr/bin/env python3
"""ctest course_own_check: a student's own check report handed in beside the shaders (issue 36,
docs/assignment.md "own_check_report"). A small assignment (rgb and depth, one view each and the
displaced view) and three students handing in the same files (rgb correct, depth drawing no
shadow: rows that pass and rows that fail):
  honest      the report `check --assignment --report` wrote on these files: every row agrees
  doctored    a zip, in a wrapper folder, with that report edited: a FAIL row said PASS and the
              score set to the maximum: the grade unchanged, the row listed as a disagreement
  garbage     a report that is not JSON: a note naming the file, the grade unchanged
  padded.zip  the honest report padded to 2 MiB (over a zip's 1 MB per shader): compared, agrees
  huge.zip    a report of 5 MiB (over its 4 MiB): left out with a note, the hand-in still graded
Every count comes from the report `check` wrote, none is pinned here.
usage: test_own_check.py SHADOWLAB REPO WORKDIR"""
import json, os, shutil, subprocess, sys, zipfile

sys.path.insert(0, os.path.dirname(__file__))
from expect import expect, finish, grade

exe, repo, work = sys.argv[1:4]
work = os.path.abspath(work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
REPORT = "check-report.json"
SEED = "7"
others = {v: 0 for v in ["sphere-on-cube", "cube-on-sphere", "grazing"]}
lab = os.path.join(work, "lab.json")
json.dump({"name": "own check lab", "own_check_report": REPORT,
           "stages": [{"stage": "rgb", "tree": "core", "files": ["rgb/lit.frag"], "points": 10,
                       "lessons": {"rgb margin=0.01": 0,
                                   "rgb encoding=packed map-size=2048 margin=0.002": 0},
                       "views": others},
                      {"stage": "depth", "tree": "core", "files": ["depth/lit.frag"], "points": 10,
                       "views": others}]}, open(lab, "w"))

# The hand-in: rgb as shipped, depth lit everywhere (its shadow test's result ignored).
hand = os.path.join(work, "hand")
core = os.path.join(repo, "shaders_core")
for rel in ["rgb/lit.frag", "depth/lit.frag"]:
    os.makedirs(os.path.join(hand, os.path.dirname(rel)), exist_ok=True)
    text = open(os.path.join(core, rel)).read()
    if rel.startswith("depth"):
        lit = text.replace("shade(worldPosition, worldNormal, visibility,",
                           "shade(worldPosition, worldNormal, 1.0,")
        expect(lit != text, "depth/lit.frag no longer calls shade() as this test edits it")
        text = lit
    open(os.path.join(hand, rel), "w").write(text)

# The student's own check, as they would run it on the assignment they were given.
report_path = os.path.join(work, "report.json")
r = subprocess.run([exe, "check", "--assignment", lab, "--shaders", hand, "--seed", SEED,
                    "--report", report_path], capture_output=True, text=True, timeout=300)
expect(r.returncode == 1, "check --assignment: exit %d (some rows fail): %s" % (r.returncode, r.stderr))
report = json.load(open(report_path))
rows = [row for st in report["stages"] for row in st["rows"]]
verdicts = [row["verdict"] for row in rows]
expect("PASS" in verdicts and "FAIL" in verdicts, "the hand-in should pass some rows, fail others: %s" % verdicts)
expect(any(row["seed"] is not None for row in rows), "no displaced row in the report")

klass = os.path.join(work, "class")
for name in ["honest", "garbage"]:
    shutil.copytree(hand, os.path.join(klass, name))
shutil.copy(report_path, os.path.join(klass, "honest", REPORT))
open(os.path.join(klass, "garbage", REPORT), "w").write("{not json")
doctored = json.loads(json.dumps(report))
edited = next(row for st in doctored["stages"] for row in st["rows"] if row["verdict"] == "FAIL")
edited["verdict"] = "PASS"
doctored["score"] = doctored["max_score"]
with zipfile.ZipFile(os.path.join(klass, "doctored.zip"), "w") as z:
    for rel in ["rgb/lit.frag", "depth/lit.frag"]:
        z.write(os.path.join(hand, rel), "doctored_lab/" + rel)
    z.writestr("doctored_lab/" + REPORT, json.dumps(doctored))

for name, size in [("padded", 2 << 20), ("huge", 5 << 20)]:
    text = json.dumps(report)
    with zipfile.ZipFile(os.path.join(klass, name + ".zip"), "w", zipfile.ZIP_DEFLATED) as z:
        for rel in ["rgb/lit.frag", "depth/lit.frag"]:
            z.write(os.path.join(hand, rel), rel)
        z.writestr(REPORT, text + " " * (size - len(text)))

out = os.path.join(work, "out")
r = grade(exe, klass, lab, out, "--seed", SEED, "--time-limit", "300")
expect(r.returncode == 0, "grade: exit %d" % r.returncode)
names = ["honest", "doctored", "garbage", "padded", "huge"]
rec = {n: json.load(open(os.path.join(out, "students", n + ".json"))) for n in names}
for name, rc in rec.items():
    # The report is never a score, never a shader, never a missing stage.
    expect(rc["score"] == report["score"], "%s: score %s, check said %s" % (name, rc["score"], report["score"]))
    expect([s["status"] for s in rc["stages"]] == [s["status"] for s in report["stages"]],
           "%s: stages %s" % (name, [s["status"] for s in rc["stages"]]))
    expect(REPORT not in rc["files"], "%s: the report is listed as a hand-in file" % name)
    expect(not os.path.exists(os.path.join(out, "work", name, "snapshot", REPORT)),
           "%s: the report was copied into the snapshot" % name)
    if name != "huge":
        expect(rc["own_check"] is not None and rc["own_check"]["file"] == REPORT, "%s: own_check %s" % (name, rc["own_check"]))

for name in ["honest", "padded"]:
    honest = rec[name]["own_check"] or {}
    want = {"problem": None, "compared": len(rows), "agreed": len(rows), "disagreed": 0,
            "unmatched": 0, "not_comparable": 0, "machine": report["machine"]}
    expect(all(honest.get(k) == v for k, v in want.items()), "%s: %s" % (name, honest))
    expect(not any(REPORT in n for n in rec[name]["notes"]), "%s: notes %s" % (name, rec[name]["notes"]))
h = rec["huge"]
expect(h["own_check"] is None and h["notes"] == ["'%s' unpacks to more than 4096 KB: left out" % REPORT],
       "huge: %s, notes %s" % (h["own_check"], h["notes"]))
d = rec["doctored"]["own_check"] or {}
expect(d.get("problem", "") is None and d.get("compared") == len(rows) and d.get("agreed") == len(rows) - 1
       and d.get("disagreed") == 1, "doctored: %s" % d)
expect(d.get("disagreements") == [{"stage": edited["stage"], "tree": edited["tree"], "row": edited["name"],
                               "home": "PASS", "grade": "FAIL", "seen": True}],
       "doctored: disagreements %s" % d["disagreements"])
g = rec["garbage"]
expect((g["own_check"] or {}).get("problem") == "not JSON" and g["own_check"]["compared"] == 0,
       "garbage: %s" % g["own_check"])
expect(g["notes"] == ["`%s` (your own check report) was not compared with the grade: not JSON" % REPORT],
       "garbage: notes %s" % g["notes"])

page = lambda name: open(os.path.join(out, name), encoding="utf-8").read()
klass_page = page("class.html")
expect("4 students handed in their own check report; 2 agreed with the grade on every row compared"
       in klass_page, "class page: no own check summary")
section = klass_page[klass_page.find("Own check reports"):]
expect("%s: PASS at home, FAIL graded" % edited["name"] in section and "<td>1 of %d</td>" % len(rows) in section,
       "class page: the doctored row is not listed")
expect("not compared: not JSON" in section, "class page: the garbage report is not listed")
expect("honest.html" not in section.split("</table>")[0], "class page: honest listed as disagreeing")
expect("agreed with the grade on %d of %d rows: it said PASS where the grade says FAIL on %s."
       % (len(rows) - 1, len(rows), edited["name"]) in page("feedback/doctored.html"),
       "doctored's page: no line for the disagreement")
expect("agreed with the grade on %d of %d rows." % (len(rows), len(rows)) in page("feedback/honest.html"),
       "honest's page: no line")
expect("not compared with the grade: not JSON" in page("feedback/garbage.html"), "garbage's page: no note")
finish("own check: honest (folder and 2 MiB zip) agrees on %d rows, the doctored row found, garbage and "
       "a 5 MiB report notes; grades unchanged" % len(rows))
