#!/usr/bin/env python3
"""ctest course_student_page: a student's page read at a glance (issue 39 items 6 and 9).
A class graded by rgb (its default lesson's point is the 8-bit map's acne) and margin:
  acne   the shipped rgb/lit.frag (PASS: its pictures show acne, the lesson working) and a
         margin/lit.frag whose shadow test adds the constant `margin` (the slope rule's note)
  loop   margin/lit.frag with a loop that never ends in time (TIMEOUT); no rgb (MISSING)
Checks: each page leads with the stages' overview (status, points, the first thing to fix)
before any stage's section; loop's TIMEOUT says a loop is the usual cause, its MISSING names
the file to hand in; acne's rgb pictures are captioned as the lesson working; the source rule's
note is on acne's page and on the class page in the student's own file name, never the
snapshot's path.  usage: test_student_page.py SHADOWLAB REPO WORKDIR"""
import html, json, os, re, shutil, sys

sys.path.insert(0, os.path.dirname(__file__))
from expect import check, grade

exe, repo, work = sys.argv[1:4]
work = os.path.abspath(work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
views_off = {v: 0 for v in ["cube-on-cube", "sphere-on-cube", "cube-on-sphere", "grazing"]}
assignment = {
    "name": "Page lab",
    "stages": [
        {"stage": "rgb", "tree": "core", "files": ["rgb/lit.frag"], "points": 10,
         "lessons": {"rgb margin=0.01": 0}, "views": views_off},
        {"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
         "lessons": {"margin margin-kind=slope": 0}, "views": views_off},
    ],
}
lab = os.path.join(work, "lab.json")
json.dump(assignment, open(lab, "w"), indent=1)
core = os.path.join(repo, "shaders_core")
margin = open(os.path.join(core, "margin/lit.frag")).read()
TEST = "texture(shadowMap, shadowCoord.xy).r + marginFor(N, L) ? 1.0 : 0.0;"
assert TEST in margin, "the shipped margin/lit.frag changed: update this test's edits"
LOOP = """{
        float spin = 0.0;  // never ends in time: a loop the student forgot to bound
        for (int k = 0; k < 2000000000; ++k) spin += sin(float(k) + gl_FragCoord.x);
        visibility = spin > 1e30 ? 0.0 : 1.0;
    }"""
hand_ins = {
    "acne/rgb/lit.frag": open(os.path.join(core, "rgb/lit.frag")).read(),
    "acne/margin/lit.frag": margin.replace(TEST, "texture(shadowMap, shadowCoord.xy).r + margin ? 1.0 : 0.0;"),
    "loop/margin/lit.frag": margin.replace(
        "        visibility = shadowCoord.z <= " + TEST, "        " + LOOP),
}
assert hand_ins["loop/margin/lit.frag"] != margin
klass = os.path.join(work, "class")
for rel, text in hand_ins.items():
    os.makedirs(os.path.dirname(os.path.join(klass, rel)), exist_ok=True)
    open(os.path.join(klass, rel), "w").write(text)

out = os.path.join(work, "out")
# The calibrated budget (no --time-limit): the loop runs out of it, correct work does not.
r = grade(exe, klass, lab, out, "--jobs", "1")
check("grade exits 0", r.returncode == 0, r.returncode)


def page_of(who):
    return open(os.path.join(out, "feedback", who + ".html"), encoding="utf-8").read()


def summary_rows(page):
    """The overview's rows as {stage: (status, points, fix)}, and where the table ends."""
    at = page.find('<h2 id="summary">')
    end = page.find("</table>", at)
    rows = re.findall(r'<tr><td><a href="#([^"]+)">[^<]*</a></td><td class="[^"]*">([^<]*)</td>'
                      r'<td>([^<]*)</td><td class="msg">([^<]*)</td></tr>', page[at:end])
    return {s: (st, pts, html.unescape(fix)) for s, st, pts, fix in rows}, at, end


for who in ("acne", "loop"):
    page = page_of(who)
    rows, at, end = summary_rows(page)
    first_stage = min(page.find('<h2 id="rgb/core"'), page.find('<h2 id="margin/core"'))
    check(who + ": the overview comes before every stage's section",
          0 <= at < end < first_stage and set(rows) == {"rgb/core", "margin/core"}, (at, end, first_stage, rows))
    rec = json.load(open(os.path.join(out, "students", who + ".json")))
    for st in rec["stages"]:
        got = rows[st["stage"] + "/core"]
        check("%s: the overview shows %s's status and points" % (who, st["stage"]),
              got[0] == st["status"] and got[1] == "%.2f of %.2f" % (st["points"], st["max_points"]),
              (got, st["status"], st["points"]))

loop, _, _ = summary_rows(page_of("loop"))
check("loop: margin is TIMEOUT and its first fix says a loop is the usual cause",
      loop["margin/core"][0] == "TIMEOUT" and "usually a loop that never ends" in loop["margin/core"][2],
      loop["margin/core"])
check("loop: rgb is MISSING and its first fix names the file to hand in",
      loop["rgb/core"] == ("MISSING", "0.00 of 10.00", "hand in rgb/lit.frag"), loop["rgb/core"])
loop_rows = page_of("loop")[page_of("loop").find('<h2 id="margin/core"'):]
check("loop: the TIMEOUT rows say a loop is the usual cause",
      "TIMEOUT" in loop_rows and "usually a loop that never ends" in loop_rows, loop_rows[:2000])

acne = page_of("acne")
rgb = acne[acne.find('<h2 id="rgb/core"'):]
rgb = rgb[:rgb.find("<h2", 4)]
check("acne: rgb passes", summary_rows(acne)[0]["rgb/core"][0] == "PASS", summary_rows(acne)[0])
caption = re.search(r'<p class="caption">([^<]*)</p>', rgb)
check("acne: rgb's pictures are captioned as the lesson working (acne is its point)",
      caption and "show the lesson working: this setting should show acne, and yours does" in caption.group(1),
      caption and caption.group(1))
check("acne: margin's pictures (a correct lesson) have no such caption",
      'class="caption"' not in acne[acne.find('<h2 id="margin/core"'):])

note = re.search(r'<ul class="notes">\s*<li>([^<]*)</li>', acne)
check("acne: the source rule's note is on the page, in the student's file name",
      note and re.match(r"margin/lit\.frag:\d+: the shadow comparison does not depend on the normal",
                        html.unescape(note.group(1))), note and note.group(1))
klass_page = open(os.path.join(out, "class.html"), encoding="utf-8").read()
check("the class page names the note by the student's file, not the snapshot",
      note.group(1) in klass_page and "/snapshot/" not in klass_page
      and "/snapshot/" not in acne)
import expect
print("student page: overview, captions, TIMEOUT's cause and source notes (%d checks)" % expect.checks)
