#!/usr/bin/env python3
"""ctest course_same_figures (issue 28): what `grade` shares across a class (one Mesa shader cache
for the run, the views' truths and our shaders' pictures per job, students in rounds stage by
stage, jobs on a share of the cores) changes no figure: each student's rows from `grade` (one
job: rounds of two; two jobs: a core each) are those of `check --assignment` for that student alone, figure for
figure, bit for bit, with the same seed; and so are the verdicts and the points. Hand-ins: the
solution, an acne margin, the starter, a mirror that shows its own surface, each with a
displaced view and an instructor's extra view.
usage: test_same_figures.py SHADOWLAB REPO WORKDIR"""
import json, os, shutil, subprocess, sys

exe, repo, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
core = os.path.join(repo, "shaders_core")
assignment = work + "/three.json"
json.dump({"name": "three stages",
           "stages": [{"stage": "depth", "files": ["depth/lit.frag"], "points": 10},
                      {"stage": "margin", "files": ["margin/lit.frag"], "points": 10},
                      {"stage": "mirror", "files": ["mirror/surface.frag", "mirror/surface.vert"], "points": 10}],
           "extra_views": [{"name": "backlight", "scene": "slides", "eye": [-2.4, 1.6, 2.2], "at": [0, 0.2, 0],
                            "why": "a camera the students were not told about"}]},
          open(assignment, "w"))
subprocess.run([exe, "release", "--assignment", assignment, "--out", work + "/rel"], check=True,
               stdout=subprocess.DEVNULL)


def shipped(rel):
    return open(os.path.join(core, rel)).read()


solution = {f: shipped(f) for f in ("depth/lit.frag", "margin/lit.frag", "mirror/surface.frag", "mirror/surface.vert")}
starter = {f: open(os.path.join(work, "rel/shaders", f)).read() for f in solution}
acne = dict(solution)
acne["margin/lit.frag"] = solution["margin/lit.frag"].replace("return margin;", "return 0.0;")
assert acne["margin/lit.frag"] != solution["margin/lit.frag"]
flat_mirror = dict(solution)
body = solution["mirror/surface.frag"]
flat_mirror["mirror/surface.frag"] = body[:body.rindex("}")] + "    fragColor = vec4(0.5, 0.5, 0.5, 1.0);\n}\n"
hand_ins = {"ann": solution, "ben": acne, "cy": starter, "dee": flat_mirror}
for name, files in hand_ins.items():
    for rel, text in files.items():
        os.makedirs(os.path.dirname(os.path.join(work, "class", name, rel)), exist_ok=True)
        open(os.path.join(work, "class", name, rel), "w").write(text)

seed = os.environ.get("SL_TEST_CHECK_SEED", "4242")  # another seed here must fail the test
# One job (rounds of two students, stage by stage) and two jobs (a core each).
for jobs in ("1", "2"):
    r = subprocess.run([exe, "grade", work + "/class", "--assignment", assignment, "--out", work + "/out-" + jobs,
                        "--jobs", jobs, "--seed", "4242", "--time-limit", "300"],
                       capture_output=True, text=True, timeout=1500)
    print(r.stdout[-3000:], r.stderr[-3000:])
    assert r.returncode == 0, r.returncode


def rows_of(record):
    return {(s["stage"], s["tree"], row["view"], row["lesson"]): row for s in record["stages"] for row in s["rows"]}


compared = 0
verdicts = set()
for name in hand_ins:
    report = work + "/%s-check.json" % name
    c = subprocess.run([exe, "check", "--assignment", assignment, "--shaders", os.path.join(work, "class", name),
                        "--seed", seed, "--time-limit", "300", "--report", report],
                       capture_output=True, text=True, timeout=1500)
    assert c.returncode in (0, 1), (name, c.returncode, c.stderr[-2000:])
    alone = rows_of(json.load(open(report)))
    for jobs in ("1", "2"):
        graded = rows_of(json.load(open(work + "/out-%s/students/%s.json" % (jobs, name))))
        assert sorted(graded) == sorted(alone), (name, sorted(set(graded) ^ set(alone)))
        for key, row in alone.items():
            other = graded[key]
            # JSON numbers as written: repr-exact floats, None for NaN
            assert row["figures"] == other["figures"], (name, jobs, key, row["figures"], other["figures"])
            assert row["verdict"] == other["verdict"] and row["points"] == other["points"], (name, jobs, key)
            verdicts.add(row["verdict"])
            compared += 1
# the class is not all alike: passing and failing rows were compared
assert {"PASS", "FAIL"} <= verdicts, verdicts
print("course_same_figures: %d rows (%d students, two gradings) identical to check alone" % (compared, len(hand_ins)))
