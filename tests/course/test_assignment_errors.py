#!/usr/bin/env python3
"""ctest course_assignment_errors: a broken assignment file is exit 2 with one line naming the
file, the JSON path and the line of what is wrong (or the line and column of a syntax error).
usage: test_assignment_errors.py SHADOWLAB WORKDIR"""
import os, shutil, subprocess, sys

exe, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work + "/s/rgb")
open(work + "/s/rgb/lit.frag", "w").write("x")
GOOD_STAGE = '{"stage": "rgb", "files": ["rgb/lit.frag"], "points": 10}'
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
    ('{"name": "x",\n "stages": [' + GOOD_STAGE + ',]}', "line 2, column"),
    ('{"name": "x", "stages": [\n {"stage": "fixed", "tree": "core", "files": ["fixed/lit.frag"], "points": 1}]}',
     "/stages/0/tree (line 2): stage fixed runs in the legacy tree only"),
]
for k, (text, want) in enumerate(cases):
    path = work + "/a%d.json" % k
    open(path, "w").write(text)
    r = subprocess.run([exe, "check", "--assignment", path, "--shaders", work + "/s"],
                       capture_output=True, text=True, timeout=120)
    err = r.stderr.strip()
    assert r.returncode == 2, (k, r.returncode, err)
    assert path in err and want in err, "case %d: %r does not say %r" % (k, err, want)
    assert err.count("\n") == 0, "case %d: more than one line: %r" % (k, err)
    print("ok:", err)
print("course_assignment_errors: ok")
