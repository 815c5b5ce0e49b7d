#!/usr/bin/env python3
"""ctest course_feedback: feedback that tells the student what to fix (issue 29 item 7).
A small class graded by an assignment with the mirror and hardware stages due:
  dim       mirror/surface.frag returns half the reflection (its PSNR fails, its ids do not);
            hardware/lit_pcf3x3.frag only (a file of a due stage's folder the assignment does not
            list); a top-level lit.frag; bias/Lit.frag (a stage the assignment does not grade)
  s05.zip   an empty zip
  twin      dim's surface.frag reformatted, recommented, a name changed (copy flags)
  sol       the shipped surface.frag (the published solution: it has a solution region)
            reformatted with a comment: flagged as the published solution
Checks: the failing mirror row names its failing figure against its bound in plain words; the
mirror section shows three pictures (theirs, the stencil reflection, the difference) that decode
in headless Chromium; the unlisted file gets a note; no near-miss hint names a stage the
assignment does not grade; no page holds the --out path, the class folder's path or the
snapshot's; the copy flags are in the records and on the class page, not on a student's.  usage: test_feedback.py SHADOWLAB REPO WORKDIR"""
import json, os, re, shutil, subprocess, sys, zipfile

sys.path.insert(0, os.path.dirname(__file__))
from expect import expect, finish, grade

import pages

exe, repo, work = sys.argv[1:4]
work = os.path.abspath(work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
core = os.path.join(repo, "shaders_core")
views_off = {v: 0 for v in ["cube-on-cube", "sphere-on-cube", "cube-on-sphere", "grazing"]}
assignment = {
    "name": "Feedback lab",
    "stages": [
        {"stage": "mirror", "tree": "core", "files": ["mirror/surface.frag", "mirror/surface.vert"],
         "points": 10},
        # lit_pcf3x3.frag is not listed (dim's copy of it gets a note), so its lesson weighs 0.
        {"stage": "hardware", "tree": "core", "files": ["hardware/lit.frag"], "points": 10,
         "views": views_off, "lessons": {"hardware filter=pcf3x3": 0}},
    ],
}
lab = os.path.join(work, "lab.json")
json.dump(assignment, open(lab, "w"), indent=1)


def put(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    open(path, "w").write(text)


klass = os.path.join(work, "class")
surface = open(os.path.join(core, "mirror/surface.frag")).read()
dimmed = surface.replace("reflectance * texture(mirrorTexture, uv).rgb",
                         "0.5 * reflectance * texture(mirrorTexture, uv).rgb")
assert dimmed != surface, "the shipped surface.frag changed: update this test's edit"
put(klass, "dim/mirror/surface.frag", dimmed)
surface_vert = open(os.path.join(core, "mirror/surface.vert")).read()
# The vertex shader as shipped (the published solution: flagged for all three, as it should be;
# the checks below are about surface.frag).
for student in ("dim", "twin", "sol"):
    put(klass, student + "/mirror/surface.vert", surface_vert)
put(klass, "dim/hardware/lit_pcf3x3.frag", open(os.path.join(core, "hardware/lit_pcf3x3.frag")).read())
put(klass, "dim/lit.frag", open(os.path.join(core, "hardware/lit.frag")).read())
put(klass, "dim/bias/Lit.frag", open(os.path.join(core, "bias/lit.frag")).read())
zipfile.ZipFile(os.path.join(klass, "s05.zip"), "w").close()
# twin: dim's surface.frag reformatted, recommented, its names changed (a copy flag, no points
# lost for it); sol: the shipped file (the published solution) with a comment added.
twin = "// my own\n" + dimmed.replace("fragColor", "outColour").replace("    ", "\t").replace(" * ", "*")
put(klass, "twin/mirror/surface.frag", twin)
put(klass, "sol/mirror/surface.frag", "/* written by me */\n" + surface.replace("    ", "  "))

out = os.path.join(work, "out")
r = grade(exe, klass, lab, out, "--jobs", "1", "--time-limit", "300")
assert r.returncode == 0, r.returncode


dim = json.load(open(os.path.join(out, "students", "dim.json")))
mirror = [st for st in dim["stages"] if st["stage"] == "mirror"][0]
expect(mirror["status"] == "FAIL", "mirror: %s, expected FAIL" % mirror["status"])
page = open(os.path.join(out, "feedback", "dim.html"), encoding="utf-8").read()
text = re.sub(r"<[^>]+>", " ", page)
# The failing figure against its bound, in plain words, with the numbers of the record's
# reasons (the verdict's bounds as data; the page never reads the message).
psnr = [(f["value"], f["bound"]) for row in mirror["rows"] for f in row["reasons"]
        if f["figure"] == "mirror_psnr_db" and f["side"] == ">=" and not f["passed"]]
expect(psnr, "no row's reasons hold mirror_psnr_db failing: %s" % [r["reasons"] for r in mirror["rows"]])
for value, bound in psnr:
    expect("your mirror&#39;s PSNR against the exact (stencil) reflection is %.3g dB, and should "
           "be at least %.3g dB" % (value, bound) in text,
           "the page does not name the PSNR %.3g dB against %.3g dB in plain words" % (value, bound))
# The mirror's pictures: theirs, our stencil reflection, the difference.
section = page[page.index('<h2 id="mirror/core"'):]
section = section[:section.find("<h2", 4)]
for caption in ["your picture", "the exact reflection (stencil method, our shaders)",
                "the difference inside the mirror"]:
    expect('alt="%s" src="data:image/png;base64,' % caption in section,
           "the mirror section has no picture '%s'" % caption)
# Notes: the unlisted file of a due stage's folder; hints only towards the assignment's stages.
notes = dim["notes"]
print("notes:", notes)
expect(any("`hardware/lit_pcf3x3.frag` is not graded" in n for n in notes),
       "no note for hardware/lit_pcf3x3.frag")
# The top-level lit.frag: the due stages' listed files of that name (mirror/lit.frag is mirror's,
# but this assignment grades only mirror's surface shaders), issue 39 item 5.
expect("`lit.frag` was not used: did you mean `hardware/lit.frag`?" in notes, "no hint for lit.frag")
for n in notes:
    m = re.search(r"did you mean `([^/`]+)/", n)
    if m:
        expect(m.group(1) in ("mirror", "hardware"), "a hint names a stage not due: " + n)
expect("lit_pcf3x3.frag` is not graded" in page, "the note is not on the page")

# Copy flags: in the records and on the class page, never on a student's page, no points.
recs = {n: json.load(open(os.path.join(out, "students", n + ".json"))) for n in ["dim", "twin", "sol"]}
print("flags:", {n: r["flags"] for n, r in recs.items()})
expect(any("mirror/surface.frag: the same as the hand-in of twin" in f for f in recs["dim"]["flags"]),
       "dim not flagged as twin's copy")
expect(any("the same as the hand-in of dim" in f for f in recs["twin"]["flags"]), "twin not flagged")
# The shipped surface.frag holds a solution region: handed in reformatted, it is the solution.
expect(any("mirror/surface.frag: the same as the published solution" in f for f in recs["sol"]["flags"]),
       "sol (the published solution, reformatted) not flagged: %s" % recs["sol"]["flags"])
expect(not any(f.startswith("mirror/surface.frag: the same as the published solution") for f in recs["dim"]["flags"]),
       "dim's changed surface.frag flagged as the solution")
expect(recs["twin"]["score"] == recs["dim"]["score"], "a flag changed points")
klass_page = open(os.path.join(out, "class.html"), encoding="utf-8").read()
# One row per pair, ranked by the share of their written due code in common (issue 39 item 8).
expect(re.search(r'<tr><td><a href="feedback/dim\.html">dim</a> and <a href="feedback/twin\.html">twin</a>'
                 r'</td><td class="share">100 %</td><td>2 \(\d+ written tokens\)</td><td class="msg">'
                 r'mirror/surface\.frag, mirror/surface\.vert</td></tr>', klass_page),
       "the class page does not show dim and twin as one pair sharing 100 %")
expect("the same as" not in page, "a copy flag on the student's page")

# No instructor path in anything a student sees.
snapshot_dirs = [os.path.join(out, "work")]
secrets = [out, os.path.relpath(out), klass, os.path.relpath(klass)] + snapshot_dirs
for f in sorted(os.listdir(os.path.join(out, "feedback"))):
    body = open(os.path.join(out, "feedback", f), encoding="utf-8").read()
    for s in secrets:
        expect(s not in body, "%s shows the instructor's path %s" % (f, s))
    expect("/unpacked" not in body and "/snapshot" not in body, f + " shows a snapshot path")
empty = open(os.path.join(out, "feedback", "s05.html"), encoding="utf-8").read()
expect("s05.zip" in empty, "the empty zip's page does not name s05.zip")

# The pages in a browser: every image decodes, nothing overflows.
found = pages.check_page(os.path.join(out, "feedback", "dim.html"), os.path.join(work, "dim.png"))
print("dim.html in Chromium:", found)
expect(found["images"] >= 3 and found["broken"] == 0, "images not decoded: %s" % found)
expect(found["overflowing"] == 0 and not found["pageWider"], "the page overflows: %s" % found)

finish("feedback: the failing figures named, the mirror's pictures shown, notes right, no paths")
