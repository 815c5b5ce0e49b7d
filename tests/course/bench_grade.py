#!/usr/bin/env python3
"""Benchmark (not a test): a class graded with `grade --jobs 2` against the README's old loop of
`check` calls, alternating runs, on 100 one-stage submissions (margin; the loop runs
`check --stage margin`) and 20 all-stage submissions (the loop runs `check --all`, core tree,
as the README's script does; grade uses bench_all_stages.json, the same rows).
Submissions: the shipped solution, the release's starter and an acne variant (margin 0), mixed.
usage: bench_grade.py SHADOWLAB REPO WORKDIR [REPS_100 REPS_20 [N_ONE N_ALL]]   one JSON line per run
(N_ONE, N_ALL: the class sizes, 100 and 20 by default). Both sides run with --time-limit 300 so a
loaded machine does not turn slow stages into TIMEOUTs."""
import json, os, resource, shutil, statistics, subprocess, sys, time

exe, repo, work = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
reps100 = int(sys.argv[4]) if len(sys.argv) > 4 else 1
reps20 = int(sys.argv[5]) if len(sys.argv) > 5 else 2
n_one = int(sys.argv[6]) if len(sys.argv) > 6 else 100
n_all = int(sys.argv[7]) if len(sys.argv) > 7 else 20
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
core = os.path.join(repo, "shaders_core")
all_stages = os.path.join(repo, "tests/course/bench_all_stages.json")
lab = json.load(open(all_stages))


def put(root, rel, text):
    os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
    open(os.path.join(root, rel), "w").write(text)


margin_only = work + "/margin.json"
json.dump({"name": "margin only", "stages": [{"stage": "margin", "files": ["margin/lit.frag"], "points": 10}]},
          open(margin_only, "w"))
subprocess.run([exe, "release", "--assignment", margin_only, "--out", work + "/rel"], check=True,
               stdout=subprocess.DEVNULL)
solution = open(os.path.join(core, "margin/lit.frag")).read()
starter = open(work + "/rel/shaders/margin/lit.frag").read()
acne = solution.replace("return margin;", "return 0.0;")
for k in range(n_one):
    put(work + "/class100/s%03d" % k, "margin/lit.frag", [solution, solution, starter, acne][k % 4])
for k in range(n_all):
    for s in lab["stages"]:
        for f in s["files"]:
            text = open(os.path.join(core, f)).read()
            if f == "margin/lit.frag":
                text = [solution, starter, acne, solution][k % 4]
            put(work + "/class20/s%02d" % k, f, text)


def old_loop(cls, args):
    out = work + "/old-" + os.path.basename(cls)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    start = time.time()
    for d in sorted(os.listdir(cls)):
        subprocess.run([exe, "check"] + args + ["--time-limit", "300", "--shaders", os.path.join(cls, d), "--report",
                        "%s/%s.json" % (out, d), "--diff-dir", "%s/%s-diff" % (out, d)],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.time() - start


def new_grade(cls, assignment):
    out = work + "/new-" + os.path.basename(cls)
    shutil.rmtree(out, ignore_errors=True)
    start = time.time()
    r = subprocess.run([exe, "grade", cls, "--assignment", assignment, "--out", out, "--jobs", "2", "--time-limit", "300"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    assert r.returncode == 0, r.returncode
    return time.time() - start


results = {}
for name, reps, old_args, assignment, cls in (
        ("%d one-stage" % n_one, reps100, ["--stage", "margin"], margin_only, work + "/class100"),
        ("%d all-stage" % n_all, reps20, ["--all"], all_stages, work + "/class20")):
    for rep in range(reps):
        for kind in ("old", "new"):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t = old_loop(cls, old_args) if kind == "old" else new_grade(cls, assignment)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
            results.setdefault((name, kind), []).append(t)
            print(json.dumps({"class": name, "run": kind, "rep": rep, "seconds": round(t, 1),
                              "cpu_seconds": round(cpu, 1), "load": os.getloadavg()[0]}), flush=True)
for (name, kind), ts in results.items():
    print(json.dumps({"class": name, "run": kind, "median": round(statistics.median(ts), 1),
                      "min": round(min(ts), 1), "max": round(max(ts), 1), "n": len(ts)}))
