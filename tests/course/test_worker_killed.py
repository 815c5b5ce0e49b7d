#!/usr/bin/env python3
"""ctest course_worker_killed: a worker killed from outside is the machine's, never the student's
(issue 38). `check --assignment` grades a correct hand-in while this script sends SIGKILL to its
first worker 0.5 s after that worker starts (what an administrator or the kernel's OOM killer
does): the rows must be NOT GRADED with the evidence named (the signal, the CPU seconds), the run
exits 3, no points are charged, and the rerun grades the same hand-in PASS with full points.
(A stopped worker, SIGSTOP, is the unit test WorkerEnd.AStoppedWorkerAtTheBackstopIsTheMachines:
its backstop is 300 s here.)
usage: test_worker_killed.py SHADOWLAB REPO WORKDIR"""
import json, os, shutil, signal, subprocess, sys, time

exe, repo, work = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
sub = work + "/ann"
os.makedirs(sub + "/margin")
shutil.copy(os.path.join(repo, "shaders_core/margin/lit.frag"), sub + "/margin/lit.frag")
lab = work + "/lab.json"
json.dump({"name": "margin only",
           "stages": [{"stage": "margin", "tree": "core", "files": ["margin/lit.frag"], "points": 10,
                       "lessons": {"margin margin-kind=slope": 0},
                       "views": {"cube-on-cube": {"weight": 0}}}]}, open(lab, "w"))
import expect  # noqa: E402
from expect import check  # noqa: E402


def children(pid):
    kids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = open("/proc/%s/stat" % entry).read()
            except OSError:
                continue
            if int(stat[stat.rfind(")") + 2:].split()[1]) == pid:
                kids.append(int(entry))
    return kids


def run_check(report, kill_after=None):
    cmd = [exe, "check", "--assignment", lab, "--shaders", sub, "--report", report]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    killed = None
    if kill_after is not None:
        deadline = time.time() + 120
        while not killed and time.time() < deadline and p.poll() is None:
            kids = children(p.pid)
            if kids:
                time.sleep(kill_after)
                os.kill(kids[0], signal.SIGKILL)
                killed = kids[0]
            time.sleep(0.01)
    out, err = p.communicate(timeout=600)
    return p.returncode, out, err, killed


code, out, err, killed = run_check(work + "/killed.json", kill_after=0.5)
check("a worker was killed 0.5 s after it started", killed is not None, err[-500:])
check("the run exits 3 (the machine's: rerun)", code == 3, (code, err[-1500:]))
check("the line names the signal and that the grader did not send it",
      "killed by SIGKILL, a signal the grader did not send" in err and "s of CPU time" in err,
      err[-1500:])
report = json.load(open(work + "/killed.json"))
text = json.dumps(report)
check("the report's rows are NOT GRADED", "NOT GRADED" in text and "CRASH" not in text,
      text[:1500])
check("no points charged: nothing earned or possible counted",
      report.get("score", 0) == 0 and report.get("max_score", 0) == 0, 
      {k: report.get(k) for k in ("score", "max_score", "status")})
code, out, err, _ = run_check(work + "/rerun.json")
rerun = json.load(open(work + "/rerun.json"))
check("the rerun grades it: exit 0, PASS, full points",
      code == 0 and rerun.get("status") == "PASS" and rerun.get("score") == rerun.get("max_score")
      and rerun.get("max_score", 0) > 0, (code, err[-800:], {k: rerun.get(k) for k in ("score", "max_score", "status")}))
print("%d checks" % expect.checks)
