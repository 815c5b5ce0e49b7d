#!/usr/bin/env python3
"""ctest course_assignment_errors: a broken assignment file is exit 2 with one line naming the
file, the JSON path and the line of what is wrong (or the line and column of a syntax error):
its syntax, types and ranges, any number JSON can hold, and what it may not mean (a degenerate
extra view, a due stage that can earn nothing); `release` refuses what it cannot release (a
stage without solution regions, an instructor's trees in the wrong layout, a marked file a graded
row draws with that the stage does not list) before grading.
usage: test_assignment_errors.py SHADOWLAB WORKDIR"""
import os, shutil, subprocess, sys

exe, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work + "/s/rgb")
open(work + "/s/rgb/lit.frag", "w").write("x")
GOOD_STAGE = '{"stage": "rgb", "files": ["rgb/lit.frag"], "points": 10}'
MARGIN = '{"name": "x", "stages": [\n {"stage": "margin", "files": ["margin/lit.frag"], "points": %s}]}'
def extra(view):
    return '{"name": "x", "stages": [' + GOOD_STAGE + '],\n "extra_views": [\n  ' + view + ']}'
ALL_VIEWS_ZERO = ', '.join('"%s": 0' % v for v in
                           ["lecture", "cube-on-cube", "sphere-on-cube", "cube-on-sphere", "grazing", "displaced", "scene"])
cases = [
    ('{"name": "x",\n "stages": [\n  {"stage": "rgbb", "files": ["rgb/lit.frag"], "points": 10}\n]}',
     "/stages/0/stage (line 3): unknown stage 'rgbb'"),
    ('{"name": "x",\n "stages": [\n  ' + GOOD_STAGE + ',\n  {"stage": "depth",\n   "files": ["depth/lit.frag"],\n   "points": -1}\n]}',
     "/stages/1/points (line 6): must be a number in [0, 1e+06], got -1"),
    ('{"name": "x", "stages": [\n {"stage": "margin", "files": ["margin/lit.frag"], "points": 1,\n  "views": {"grazing": {"visibility": "later"}}}]}',
     "/stages/0/views/grazing/visibility (line 3): 'later' is not one of visible, hidden, after_due_date, after_published"),
    ('{"name": "x", "stages": [\n {"stage": "rgb", "files": ["../../etc/passwd"], "points": 1}]}',
     "/stages/0/files/0 (line 2): '../../etc/passwd' must be a file of the stage's folder"),
    ('{"name": "x", "stages": [\n {"stage": "rgb", "files": ["rgb/lit.frag"], "points": 1,\n  "lessons": {"rgb margin=0.5": 2}}]}',
     "/stages/0/lessons/rgb margin=0.5 (line 3): no lesson 'rgb margin=0.5' for rgb/core"),
    ('{"name": "x", "stages": [' + GOOD_STAGE + '],\n "extra_views": [{"name": "lecture", "eye": [1, 2, 3]}]}',
     "/extra_views/0/name (line 2): view 'lecture' is already defined"),
    ('{"name": "x", "stages": [' + GOOD_STAGE + '], "bonus": 3}', "/bonus (line 1): unknown field"),
    # The student's own check report: a plain .json name at the top of the hand-in.
    ('{"name": "x", "stages": [' + GOOD_STAGE + '],\n "own_check_report": "rgb/report.json"}',
     "/own_check_report (line 2): 'rgb/report.json' must be a file name ending in .json"),
    ('{"name": "x", "stages": [' + GOOD_STAGE + '],\n "own_check_report": "report.txt"}',
     "/own_check_report (line 2): 'report.txt' must be a file name ending in .json"),
    ('{"name": "x", "stages": [' + GOOD_STAGE + '],\n "own_check_report": 3}',
     "/own_check_report (line 2): must be a string, got number"),
    ('{"name": "x",\n "stages": [' + GOOD_STAGE + ',]}', "line 2, column"),
    ('{"name": "x", "stages": [\n {"stage": "fixed", "tree": "core", "files": ["fixed/lit.frag"], "points": 1}]}',
     "/stages/0/tree (line 2): stage fixed runs in the legacy tree only"),
    # The fixed-function stage has no shader to hand in.
    ('{"name": "x", "stages": [\n {"stage": "fixed", "tree": "legacy", "files": ["fixed/lit.frag"], "points": 1}]}',
     "/stages/0/stage (line 2): stage fixed has no shaders in the legacy tree"),
    # Any number JSON can hold: out of a double's range, huge, negative zero.
    (MARGIN % "1e400", "/stages/0/points (line 2): the number 1e400 is out of range"),
    (MARGIN % "-1e999", "/stages/0/points (line 2): the number -1e999 is out of range"),
    (MARGIN % ("9" * 400), "/stages/0/points (line 2): the number 999999999"),
    (MARGIN % "123456789012345678901234567890", "/stages/0/points (line 2): must be a number in [0, 1e+06], got 1.23457e+29"),
    (MARGIN % "-0", "/stages/0/points (line 2): a due stage needs points above 0"),
    (MARGIN % "0", "/stages/0/points (line 2): a due stage needs points above 0"),
    ('{"name": "x", "stages": [\n {"stage": "margin", "files": ["margin/lit.frag"], "points": 1,\n  "views": {"grazing": 1e400}}]}',
     "/stages/0/views/grazing (line 3): the number 1e400 is out of range"),
    (extra('{"name": "v", "eye": [1e400, 1, 1]}'), "/extra_views/0/eye/0 (line 3): the number 1e400 is out of range"),
    # Weights: a due stage whose rows all weigh 0 could earn nothing.
    ('{"name": "x", "stages": [\n {"stage": "depth", "files": ["depth/lit.frag"], "points": 5,\n  "lessons": {"depth": 0}}]}',
     "/stages/0/lessons (line 3): every row of depth/core weighs 0"),
    ('{"name": "x", "stages": [\n {"stage": "margin", "files": ["margin/lit.frag"], "points": 5,\n  "views": {' + ALL_VIEWS_ZERO + '}}]}',
     "/stages/0/views (line 3): every row of margin/core weighs 0"),
    ('{"name": "x", "stages": [\n {"stage": "margin", "files": ["margin/lit.frag"], "points": 5,\n  "views": {"lecture": -2}}]}',
     "/stages/0/views/lecture (line 3): must be a number in [0, 1e+06], got -2"),
    # Degenerate extra views.
    (extra('{"name": "v", "eye": [0, 0.2, 0], "at": [0, 0.2, 0]}'),
     "/extra_views/0/eye (line 3): the eye (0, 0.2, 0) is at the point it looks at (0, 0.2, 0)"),
    (extra('{"name": "v", "eye": [0.3, 4, 0.2], "at": [0.3, 0, 0.2]}'),
     "/extra_views/0/eye (line 3): the camera looks straight down"),
    (extra('{"name": "v", "eye": [0.5, 0.3, 0.2]}'),
     "/extra_views/0/eye (line 3): the eye (0.5, 0.3, 0.2) is inside or on 'standing cube' of scene slides"),
    (extra('{"name": "v", "light": [0.5, 0.5, -0.5]}'),
     "/extra_views/0/light (line 3): the light (0.5, 0.5, -0.5) is inside or on 'sphere' of scene slides"),
    (extra('{"name": "v", "light": [1, 0, 1]}'),
     "/extra_views/0/light (line 3): the light (1, 0, 1) is inside or on 'floor' of scene slides"),
    (extra('{"name": "v", "fovy": 180}'), "/extra_views/0/fovy (line 3): must be a number in [1, 170], got 180"),
    (extra('{"name": "v", "fovy": 0}'), "/extra_views/0/fovy (line 3): must be a number in [1, 170], got 0"),
]
def run(args):
    r = subprocess.run([exe] + args, capture_output=True, text=True, timeout=120)
    return r.returncode, r.stderr.strip()

def expect(k, args, path, want):
    code, err = run(args)
    assert code == 2, (k, code, err)
    assert path in err and want in err, "case %s: %r does not say %r" % (k, err, want)
    assert err.count("\n") == 0, "case %s: more than one line: %r" % (k, err)
    print("ok:", err)

for k, (text, want) in enumerate(cases):
    path = work + "/a%d.json" % k
    open(path, "w").write(text)
    expect(k, ["check", "--assignment", path, "--shaders", work + "/s"], path, want)

# `release` refuses before it grades or writes anything.
os.makedirs(work + "/full")
open(work + "/full/x", "w").write("x")
release_cases = [
    # displaced is a graded view: accepted (the release stops at the full --out folder).
    ('{"name": "x", "stages": [\n {"stage": "margin", "files": ["margin/lit.frag"], "points": 5,\n  "views": {"displaced": {"weight": 2, "visibility": "hidden"}}}]}',
     work + "/full", "the folder exists and is not empty"),
    # phong's lit pass has no region (it is the lighting every stage is graded against).
    ('{"name": "x", "stages": [\n {"stage": "phong", "files": ["phong/lit.frag"], "points": 5}]}',
     work + "/out", "phong/lit.frag: no BEGIN SOLUTION region"),
]
for k, (text, out, want) in enumerate(release_cases):
    path = work + "/r%d.json" % k
    open(path, "w").write(text)
    expect("release %d" % k, ["release", "--assignment", path, "--out", out], "", want)
    assert not os.path.exists(work + "/out"), "release %d wrote its folder" % k
# A marked file a graded row draws with but the stage does not list (hardware's pcf3x3 lesson
# draws with lit_pcf3x3.frag, weighted 1 by default) is seen from the files alone: refused before
# the solution is rendered (issue 39: it took the solution's grading, 43-80 s, to find it).
import time
path = work + "/unlisted.json"
open(path, "w").write('{"name": "x", "stages": [\n {"stage": "hardware", "files": ["hardware/lit.frag"], "points": 5}]}')
start = time.monotonic()
expect("unlisted", ["release", "--assignment", path, "--out", work + "/out"], path,
       "/stages/0/files (line 2): hardware/lit_pcf3x3.frag (the shipped shaders) holds a solution region")
took = time.monotonic() - start
assert took < 3 and not os.path.exists(work + "/out"), ("found after %.1f s" % took)
print("ok: the unlisted marked file found in %.2f s, before any rendering" % took)
said = subprocess.run([exe, "release", "--assignment", path, "--out", work + "/out"],
                      capture_output=True, text=True, timeout=120).stdout
assert "grading the solution" not in said, "said it grades the solution before refusing: %r" % said
print("ok: no 'grading the solution' line before a refusal seen from the files")
expect("solutions", ["release", "--assignment", work + "/r0.json", "--out", work + "/out",
                     "--solutions", work + "/s"], "--solutions", "holds neither shaders_core/ nor shaders_legacy/")
print("course_assignment_errors: ok")
