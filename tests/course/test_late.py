#!/usr/bin/env python3
"""ctest course_late: the assignment's late policy and TAs' adjustments in `grade`
(docs/assignment.md "Late policy", "Adjustments").
Deadline 2026-12-04T23:59:00+01:00, grace 15 minutes, 10 % of the points per day or part of a
day, cap 30 %; rgb due (20 points, one lesson in one view, so it renders quickly); every student
hands in the shipped (correct) rgb/lit.frag:
  late      --times: 1.5 days after the deadline   -> 2 days: 4 of 20 points off, total 16
  grace     --times: 10 minutes after               -> on time: total 20
  filetime  not in --times; its file's time 3.5 days late -> 4 days, capped at 30 %: 6 off, total 14
Checks grades.csv's late_penalty and total, each record's `late` (with its source), the page;
then --adjust (totals without a regrade, reasons on the page, kept across a regrade, [0, max]);
then a malformed --times or --adjust and --times without a late policy: exit 2 with the line.
usage: test_late.py SHADOWLAB REPO WORKDIR"""
import calendar, csv, json, os, re, shutil, subprocess, sys, time

sys.path.insert(0, os.path.dirname(__file__))
from expect import expect, finish, grade

exe, repo, work = sys.argv[1:4]
work = os.path.abspath(work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
views_off = {v: 0 for v in ["cube-on-cube", "sphere-on-cube", "cube-on-sphere", "grazing"]}
assignment = {
    "name": "Late lab",
    "late": {"deadline": "2026-12-04T23:59:00+01:00", "grace_minutes": 15,
             "penalty_per_day": 10, "cap": 30},
    "stages": [{"stage": "rgb", "tree": "core", "files": ["rgb/lit.frag"], "points": 20,
                "lessons": {"rgb margin=0.01": 0}, "views": views_off}],
}
lab = os.path.join(work, "lab.json")
json.dump(assignment, open(lab, "w"), indent=1)
deadline = calendar.timegm(time.strptime("2026-12-04T22:59:00", "%Y-%m-%dT%H:%M:%S"))  # UTC

klass = os.path.join(work, "class")
correct = open(os.path.join(repo, "shaders_core/rgb/lit.frag")).read()
for name in ["late", "grace", "filetime"]:
    os.makedirs(os.path.join(klass, name, "rgb"))
    open(os.path.join(klass, name, "rgb/lit.frag"), "w").write(correct)
os.utime(os.path.join(klass, "filetime/rgb/lit.frag"), (deadline + 3.5 * 86400, deadline + 3.5 * 86400))
times = os.path.join(work, "times.csv")
open(times, "w").write("hand-in,time\n"
                       "late,2026-12-06T11:59:00+01:00\n"      # 36 hours after the deadline
                       "grace,2026-12-04T23:09:00Z\n")         # 10 minutes after it


out = os.path.join(work, "out")
r = grade(exe, klass, lab, out, "--times", times, "--time-limit", "300")
assert r.returncode == 0, r.returncode
expect("warning: the file times" not in r.stdout, "a download warning for one hand-in's file time")
rows = {row["student"]: row for row in csv.DictReader(open(os.path.join(out, "grades.csv")))}
want = {"late": ("4.000", "16.000", "--times", 2), "grace": ("0.000", "20.000", "--times", 0),
        "filetime": ("6.000", "14.000", "file times", 4)}
for who, (penalty, total, source, days) in want.items():
    row = rows[who]
    rec = json.load(open(os.path.join(out, "students", who + ".json")))
    print(who, row["late_penalty"], row["total"], rec["late"])
    expect(rec["score"] == 20, "%s: graded %s, expected 20 (the shader is correct)" % (who, rec["score"]))
    expect(row["late_penalty"] == penalty and row["total"] == total,
           "%s: penalty %s total %s, expected %s %s" % (who, row["late_penalty"], row["total"], penalty, total))
    expect(rec["late"]["source"] == source and rec["late"]["days"] == days, "%s: %s" % (who, rec["late"]))
# The LMS exports carry the total after the penalty (no roster: Canvas's Student is the hand-in).
canvas = {row[0]: row[5] for row in csv.reader(open(os.path.join(out, "gradebook-canvas.csv")))}
expect(canvas == {"Student": "Late lab", "late": "16.00", "grace": "20.00", "filetime": "14.00"},
       "canvas export %s" % canvas)
page = open(os.path.join(out, "feedback", "late.html"), encoding="utf-8").read()
expect("36.0 hours late, 2 days charged by the late policy: 4.00 points off, 16.00 of 20.00" in page,
       "late's page does not say what the policy took")

# TAs' adjustments: applied to the totals without regrading, shown with their reason, kept for
# later runs (a regrade without --adjust keeps them), the total within [0, max].
adjust = os.path.join(work, "adjust.csv")
open(adjust, "w").write('hand-in,stage,points,reason\n'
                        'late,rgb,+2,extra credit for the write-up\n'
                        'grace,rgb/core,-1.5,"README missing, see the syllabus"\n'
                        'filetime,rgb,100,a generous TA\n')
r = grade(exe, klass, lab, out, "--times", times, "--adjust", adjust, "--time-limit", "300")
expect(r.returncode == 0 and "3 already graded, 0 to grade" in r.stdout, "adjustments regraded someone")
totals = {row["student"]: (row["adjustments"], row["total"])
          for row in csv.DictReader(open(os.path.join(out, "grades.csv")))}
want = {"late": ("2.000", "18.000"), "grace": ("-1.500", "18.500"), "filetime": ("100.000", "20.000")}
expect(totals == want, "adjusted totals %s, expected %s" % (totals, want))
page = open(os.path.join(out, "feedback", "grace.html"), encoding="utf-8").read()
expect("-1.50 points on rgb/core: README missing, see the syllabus" in page, "grace's page: no reason")
r = grade(exe, klass, lab, out, "--times", times, "--regrade", "late", "--time-limit", "300")
totals = {row["student"]: (row["adjustments"], row["total"])
          for row in csv.DictReader(open(os.path.join(out, "grades.csv")))}
expect(r.returncode == 0 and r.stdout.count("[student ") == 1, "the regrade: %s" % r.stdout)
expect(totals == want, "after a regrade without --adjust: %s, expected %s" % (totals, want))
rec = json.load(open(os.path.join(out, "students", "late.json")))
expect(rec["adjustments"] == [{"stage": "rgb", "points": 2.0, "reason": "extra credit for the write-up"}],
       "late's record: %s" % rec["adjustments"])

# One total (issue 39): with a late penalty and an adjustment, the class page, each student's
# page, grades.csv, both LMS exports and the progress line show the same number.
klass_page = open(os.path.join(out, "class.html"), encoding="utf-8").read()
moodle = list(csv.reader(open(os.path.join(out, "gradebook-moodle.csv"))))[1:]
canvas = {row[0]: row[5] for row in csv.reader(open(os.path.join(out, "gradebook-canvas.csv")))}
order = [row["student"] for row in csv.DictReader(open(os.path.join(out, "grades.csv")))]
for who, (adjusted, total) in want.items():
    shown = "%.2f" % float(total)
    row = re.search(r'<a href="feedback/%s\.html">%s</a>.*?<td class="total">([^<]*)</td>' % (who, who),
                    klass_page)
    expect(row and row.group(1) == shown + " / 20.00", "class.html's total for %s: %s, expected %s"
           % (who, row and row.group(1), shown))
    page = open(os.path.join(out, "feedback", who + ".html"), encoding="utf-8").read()
    head = re.search(r'<span class="total">([^<]*)</span>', page)
    expect(head and head.group(1) == shown + " of 20.00 points", "%s's page heads with %s, expected %s"
           % (who, head and head.group(1), shown))
    expect(canvas[who] == shown and moodle[order.index(who)][2] == shown,
           "%s: exports %s %s, expected %s" % (who, canvas[who], moodle[order.index(who)][2], shown))
progress = re.search(r"\[student \d+ of 3\] late +(\S+) / 20\.00", r.stdout)
expect(progress and progress.group(1) == "18.00", "the regrade's progress line shows %s, expected 18.00 "
       "(the total after the penalty and the adjustment)" % (progress and progress.group(1)))
# The cap said where it applied: filetime is charged 4 days (40 %), capped at 30 %; late's 2 days
# (20 %) are not.
page = open(os.path.join(out, "feedback", "filetime.html"), encoding="utf-8").read()
expect("4 days charged by the late policy: 6.00 points off (the policy's cap" in page,
       "filetime's page does not say the cap applied")
page = open(os.path.join(out, "feedback", "late.html"), encoding="utf-8").read()
expect("the policy's cap" not in page, "late's page says a cap applied to 2 days")
expect(re.search(r'filetime</a>.*?<td>-6\.00 \(4 days, capped\)</td><td>\+100\.00</td>', klass_page),
       "class.html does not show filetime's capped penalty and adjustment beside the total")
open(adjust, "w").write("hand-in,stage,points,reason\nlate,rgb,2,ok\nnobody,rgb,1,x\n")
r = subprocess.run([exe, "grade", klass, "--assignment", lab, "--out", out, "--adjust", adjust],
                   capture_output=True, text=True, timeout=120)
expect(r.returncode == 2 and "adjust.csv: line 3: no hand-in named 'nobody' in the class" in r.stderr,
       "bad adjust: exit %d %s" % (r.returncode, r.stderr))

# File times that look like a download (issue 39): the same hand-ins, every file written within
# a minute, three days after the deadline, no --times: one warning line saying how to give the
# times; nobody regraded (the records stand: same content).
downloaded, out2 = os.path.join(work, "downloaded"), os.path.join(work, "out-downloaded")
shutil.copytree(klass, downloaded)
shutil.copytree(out, out2)
for k, name in enumerate(["late", "grace", "filetime"]):
    t = deadline + 3 * 86400 + 20 * k
    os.utime(os.path.join(downloaded, name, "rgb/lit.frag"), (t, t))
r = grade(exe, downloaded, lab, out2, "--time-limit", "300")
warning = [line for line in r.stdout.splitlines() if line.startswith("warning: the file times")]
expect(r.returncode == 0 and "0 to grade" in r.stdout, "the downloaded class was regraded: %s" % r.stdout)
expect(len(warning) == 1 and "3 hand-ins all lie after the deadline, within 1 min" in warning[0]
       and "--times times.csv" in warning[0], "no download warning: %s" % r.stdout)

# Malformed manifests and a manifest without a policy: exit 2, one line with file and line.
bad = os.path.join(work, "bad.csv")
open(bad, "w").write("hand-in,time\nlate,2026-12-06 noon\n")
r = subprocess.run([exe, "grade", klass, "--assignment", lab, "--out", work + "/bad", "--times", bad],
                   capture_output=True, text=True, timeout=120)
expect(r.returncode == 2 and "bad.csv: line 2: '2026-12-06 noon' is not ISO 8601" in r.stderr,
       "bad times: exit %d %s" % (r.returncode, r.stderr))
plain = os.path.join(work, "plain.json")
del assignment["late"]
json.dump(assignment, open(plain, "w"))
r = subprocess.run([exe, "grade", klass, "--assignment", plain, "--out", work + "/bad", "--times", times],
                   capture_output=True, text=True, timeout=120)
expect(r.returncode == 2 and "has no late policy" in r.stderr, "no policy: exit %d %s" % (r.returncode, r.stderr))

finish("late: the policy's points exactly, within the grace nothing, the cap, the sources")
