#!/usr/bin/env python3
"""ctest course_load: a grade does not depend on how busy the machine is. A class (correct work,
a shader that does not build, a shader that loops, a missing stage, a heavy but correct 9x9
filter) is graded by a one-stage assignment with --jobs 2 twice: on the idle machine, and with a
busy loop pinned to every core (`taskset -c N sh -c 'while :; do :; done'`). Every student's
status, exit code and every row's verdict and points must be equal (equality, not timing).
usage: test_load.py SHADOWLAB REPO WORKDIR"""
import json, os, shutil, signal, subprocess, sys

exe, repo, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work + "/class")
assignment = {
    "name": "margin under load",
    "stages": [{"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
                "lessons": {"margin margin-kind=slope": 0},
                "views": {"cube-on-cube": {"weight": 0}, "sphere-on-cube": {"weight": 0},
                          "cube-on-sphere": {"weight": 0}}}]}
lab = work + "/lab.json"
json.dump(assignment, open(lab, "w"))
shipped = open(os.path.join(repo, "shaders_core/margin/lit.frag")).read()
TEST = "        visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + marginFor(N, L) ? 1.0 : 0.0;"
assert TEST in shipped
PCF = """    {
        const int R = 4;  // 9x9 texels: heavier, still the method
        vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
        float m = marginFor(N, L), lit = 0.0;
        for (int y = -R; y <= R; ++y)
            for (int x = -R; x <= R; ++x)
                lit += shadowCoord.z <= texture(shadowMap, shadowCoord.xy + vec2(x, y) * texel).r + m ? 1.0 : 0.0;
        visibility = lit / 81.0 > 0.5 ? 1.0 : 0.0;
    }"""
LOOP = """    {
        float spin = 0.0;  // never ends in time: a loop the student forgot to bound
        for (int k = 0; k < 2000000000; ++k) spin += sin(float(k) + gl_FragCoord.x);
        visibility = spin > 1e30 ? 0.0 : 1.0;
    }"""
students = {
    "ann": shipped,
    "bo": shipped.replace("float visibility = 1.0;", "float visibility = 1.0"),
    "cy": None,
    "di": shipped.replace(TEST, PCF),
    "ed": shipped.replace(TEST, LOOP),
}
for name, text in students.items():
    folder = os.path.join(work, "class", name)
    os.makedirs(os.path.join(folder, "margin"))
    if text is None:
        open(os.path.join(folder, "notes.txt"), "w").write("no time\n")
    else:
        open(os.path.join(folder, "margin", "lit.frag"), "w").write(text)


def grade(out):
    r = subprocess.run([exe, "grade", work + "/class", "--assignment", lab, "--out", out,
                        "--jobs", "2", "--seed", "77"], capture_output=True, text=True, timeout=1500)
    print(r.stdout, r.stderr[-1500:])
    records = {}
    for f in os.listdir(out + "/students"):
        rec = json.load(open(os.path.join(out, "students", f)))
        records[rec["student"]] = (rec["status"], rec["exit_code"], rec["score"], [
            (row["view"], row["verdict"], row["points"]) for st in rec["stages"] for row in st["rows"]])
    return r.returncode, records


idle = grade(work + "/idle")
cores = sorted(os.sched_getaffinity(0))
loops = [subprocess.Popen(["taskset", "-c", str(c), "sh", "-c", "while :; do :; done"],
                          start_new_session=True) for c in cores]
try:
    busy = grade(work + "/busy")
finally:
    for p in loops:
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
print("idle:", json.dumps(idle, indent=1))
print("busy (a loop on each of %d cores):" % len(cores), json.dumps(busy, indent=1))
assert idle == busy, "the grade moved with the load"
code, records = idle
assert code == 0, code
assert records["ann"][0] == "PASS" and records["bo"][0] == "ERROR" and records["cy"][0] == "MISSING"
assert records["ed"][0] == "TIMEOUT", records["ed"]
assert records["di"][0] in ("PASS", "FAIL"), records["di"]  # graded, whatever its figures say
print("course_load: ok")
