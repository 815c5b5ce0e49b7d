#!/usr/bin/env python3
"""Benchmark (not a test: the machines are shared and noisy): a class graded with `grade` (its
default `--jobs auto`) against the per-student loop the README replaced (one `check` per
student, one after the other), on a class of N_ONE one-stage hand-ins (margin; the loop runs
`check --stage margin`) and one of N_ALL all-stage hand-ins (the loop runs `check --all`, the
core tree's rows; grade uses bench_all_stages.json, the same rows). Hand-ins: the shipped
solution (half of them), the release's starter and an acne variant (margin 0), mixed.

Runs alternate, loop then grade, REPS times per class; both sides write their pictures (the loop
--diff-dir) and run with --time-limit 300 so a loaded machine cannot turn work into TIMEOUTs.
Each grade run starts from an empty --out (the solution check and the shader cache included).
--busy pins a busy loop to every core for the whole run (`taskset -c N sh -c 'while :; do :;
done'`). The progress estimate is read from grade's own lines ("time left about T"): the first
line at or past the class's midpoint (progress_error), and every line after the first quarter of
the class (progress_error_{max,median}_after_quarter); the error is |T - L| / L, L being what
was left: the run's end minus the line's time.

usage: bench_grade.py SHADOWLAB REPO WORKDIR [--reps N] [--one N] [--all N] [--busy]
       [--classes one,all] [--grade-only] [--lines FILE] [--trace FILE]
One JSON line per run, then one summary line per class: the ratio grade / loop of wall times,
paired by rep (median, min, max), and the progress errors."""
import argparse, glob, json, os, re, resource, shutil, statistics, subprocess, sys, threading, time

ap = argparse.ArgumentParser()
ap.add_argument("exe")
ap.add_argument("repo")
ap.add_argument("work")
ap.add_argument("--reps", type=int, default=3)
ap.add_argument("--one", type=int, default=100)
ap.add_argument("--all", type=int, default=20)
ap.add_argument("--busy", action="store_true")
ap.add_argument("--classes", default="one,all")
ap.add_argument("--grade-only", action="store_true", help="no loop: grade's time and progress error only")
ap.add_argument("--lines", help="write every student line after the first quarter here (JSON): "
                "its time, what it said was left, what was left, the line")
ap.add_argument("--trace", help="append each grade run here (JSON): its lines and the jobs' progress files "
                "as they changed, read every 0.05 s: what tests/course/replay_progress.py replays")
a = ap.parse_args()
exe, repo, work = os.path.abspath(a.exe), a.repo, a.work
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
assert acne != solution, "the acne variant changes nothing"
variants = [solution, starter, acne, solution]
for k in range(a.one):
    put(work + "/class-one/s%03d" % k, "margin/lit.frag", variants[k % 4])
for k in range(a.all):
    for s in lab["stages"]:
        for f in s["files"]:
            text = open(os.path.join(core, f)).read()
            if f == "margin/lit.frag":
                text = variants[k % 4]
            put(work + "/class-all/s%02d" % k, f, text)


def seconds_of(text):  # grade's duration(): "12 s", "3 min 05 s", "4.5 s"
    m = re.match(r"(?:(\d+) min )?(\d+(?:\.\d)?) s", text)
    return int(m.group(1) or 0) * 60 + float(m.group(2))


def loop(cls, args):
    out = work + "/loop-" + os.path.basename(cls)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    for d in sorted(os.listdir(cls)):
        subprocess.run([exe, "check"] + args + ["--time-limit", "300", "--shaders", os.path.join(cls, d), "--report",
                        "%s/%s.json" % (out, d), "--diff-dir", "%s/%s-diff" % (out, d)],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return {}


def grade(cls, assignment):
    out = work + "/grade-" + os.path.basename(cls)
    shutil.rmtree(out, ignore_errors=True)
    start = time.time()
    p = subprocess.Popen([exe, "grade", cls, "--assignment", assignment, "--out", out, "--time-limit", "300"],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    progress, reading = [], threading.Event()

    def watch():  # the jobs' progress files (class/class_progress.h) each time they change
        seen = {}
        while not reading.is_set():
            for path in glob.glob(out + "/logs/job-*.progress"):
                try:
                    text = open(path).read().split()
                except OSError:
                    continue
                # "DONE TOTAL ROWS VIEWS STAGE", then "DONE TOTAL VIEWSDONE VIEWSTOTAL KEY" for each
                # stage (since stop 51; class/class_progress.h)
                if len(text) >= 5 and len(text) % 5 == 0 and seen.get(path) != text:
                    seen[path] = text
                    job = int(re.search(r"job-(\d+)", path).group(1))
                    n = [int(x) for x in text[:5]]
                    keys = text[9::5]
                    stages = {k: [int(x) for x in text[i:i + 4]] for k, i in zip(keys, range(5, len(text), 5))}
                    step = [n[2], n[3], keys[n[4]]] if n[4] < len(keys) else [0, 0, ""]
                    progress.append([round(time.time() - start, 3), job, n[0], n[1], stages, step])
            time.sleep(0.05)

    watcher = threading.Thread(target=watch)
    if a.trace:
        watcher.start()
    lines = [(time.time(), line) for line in p.stdout]
    assert p.wait() == 0, p.returncode
    end = time.time()
    reading.set()
    if a.trace:
        watcher.join()
        with open(a.trace, "a") as f:
            f.write(json.dumps({"class": os.path.basename(cls), "end_s": round(end - start, 3),
                                "load": round(os.getloadavg()[0], 2), "progress": progress,
                                "lines": [[round(t - start, 3), l.rstrip()] for t, l in lines]}) + "\n")
    info = {}
    # Every line after the first quarter of the class: |said - left| / left, where left is the
    # run's end minus the line's time; the end is grade's "graded N of N" line, said once the
    # class's outputs are written (the process's exit after it took 0.02-0.03 s: a "0 s" line was
    # 0.3 off by the 0.1 s floor below).
    end = next((t for t, line in lines if line.startswith("graded ")), end)
    errors, abs_errors, kept = [], [], []
    last_student = None
    for t, line in lines:
        m = re.match(r"\[student (\d+) of (\d+)\].*time left about (.+)$", line)
        if not m:
            continue
        i, n = int(m.group(1)), int(m.group(2))
        said, left = seconds_of(m.group(3)), end - t
        last_student = t
        if 2 * i >= n and "midpoint_said_s" not in info:
            info.update({"midpoint_said_s": said, "midpoint_left_s": round(left, 1),
                         "progress_error": round(abs(said - left) / max(left, 1.0), 3)})
        if 4 * i > n:
            errors.append(abs(said - left) / max(left, 0.1))
            abs_errors.append(abs(said - left))
            kept.append({"at_s": round(t - start, 2), "said_s": said, "left_s": round(left, 2),
                         "error": round(errors[-1], 3), "line": line.rstrip()})
    # The same against the last student's line (the rows the estimate follows all done): what is
    # left after it (the jobs' exit, the class's pages) is not in any row.
    to_last = [abs(seconds_of(m.group(3)) - (last_student - t)) / (last_student - t)
               for t, m in ((t, re.match(r"\[student (\d+) of (\d+)\].*time left about (.+)$", line))
                            for t, line in lines)
               if m and 4 * int(m.group(1)) > int(m.group(2)) and last_student - t >= 1.0]
    if to_last:
        info["progress_error_max_to_last_line"] = round(max(to_last), 3)
        info["progress_error_median_to_last_line"] = round(statistics.median(to_last), 3)
    if errors:
        info.update({"progress_lines_after_quarter": len(errors),
                     "progress_error_max_after_quarter": round(max(errors), 3),
                     "progress_error_median_after_quarter": round(statistics.median(errors), 3),
                     "progress_lines_over_25pct": sum(e > 0.25 for e in errors),
                     "progress_abs_error_max_s": round(max(abs_errors), 1),
                     "after_last_student_line_s": round(end - last_student, 1)})
    if a.lines:
        with open(a.lines, "a") as f:
            f.write(json.dumps({"class": os.path.basename(cls), "lines": kept}) + "\n")
    jobs = [line for _, line in lines if " on " in line and "(--jobs" in line]
    info["jobs"] = jobs[0].strip() if jobs else ""
    return info


busy = []
if a.busy:
    for cpu in sorted(os.sched_getaffinity(0)):
        busy.append(subprocess.Popen(["taskset", "-c", str(cpu), "sh", "-c", "while :; do :; done"]))
machine = subprocess.run(["sh", "-c", "nproc; uname -srm; grep -m1 'model name' /proc/cpuinfo"],
                         capture_output=True, text=True).stdout.split("\n")
print(json.dumps({"machine": " / ".join(l.strip() for l in machine if l.strip()), "busy_loops": len(busy)}),
      flush=True)
try:
    classes = {"one": ("%d one-stage" % a.one, ["--stage", "margin"], margin_only, work + "/class-one"),
               "all": ("%d all-stage" % a.all, ["--all"], all_stages, work + "/class-all")}
    summary = []
    for key in a.classes.split(","):
        name, loop_args, assignment, cls = classes[key]
        walls = {"loop": [], "grade": []}
        errors, quarter = [], []
        for rep in range(a.reps):
            for kind in ("grade",) if a.grade_only else ("loop", "grade"):
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                start = time.time()
                info = loop(cls, loop_args) if kind == "loop" else grade(cls, assignment)
                wall = time.time() - start
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
                walls[kind].append(wall)
                if "progress_error" in info:
                    errors.append(info["progress_error"])
                if "progress_error_max_after_quarter" in info:
                    quarter.append(info)
                print(json.dumps(dict({"class": name, "run": kind, "rep": rep, "seconds": round(wall, 1),
                                       "cpu_seconds": round(cpu, 1), "load": round(os.getloadavg()[0], 2)},
                                      **info)), flush=True)
        ratios = [g / l for g, l in zip(walls["grade"], walls["loop"])]
        line = {"class": name, "busy": bool(busy), "reps": a.reps,
                "grade_s_median": round(statistics.median(walls["grade"]), 1),
                "progress_error_max": max(errors) if errors else None}
        if quarter:  # over the reps: the worst line's error, the median of the runs' medians
            line.update({"progress_error_max_after_quarter":
                         max(q["progress_error_max_after_quarter"] for q in quarter),
                         "progress_error_median_after_quarter":
                         statistics.median(q["progress_error_median_after_quarter"] for q in quarter)})
        if ratios:
            line.update({"loop_s_median": round(statistics.median(walls["loop"]), 1),
                         "ratio_median": round(statistics.median(ratios), 3),
                         "ratio_min": round(min(ratios), 3), "ratio_max": round(max(ratios), 3)})
        summary.append(line)
    for s in summary:
        print(json.dumps(s), flush=True)
finally:
    for b in busy:
        b.kill()
