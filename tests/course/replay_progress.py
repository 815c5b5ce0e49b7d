#!/usr/bin/env python3
"""Replays grade's time-left rules on recorded runs (not a test: an analysis of the benchmark's
recordings, docs/results-class.md). Each run is one line of `bench_grade.py --trace FILE`: the
jobs' progress files as they changed ([seconds, job, done, total(, first round)]) and grade's
lines. The rules are a model of class/class_progress.cpp's, so that variants can be compared on
the same runs; the unit tests (ClassProgress.*) replay the C++ itself on two of them.

Every run is read every POLL seconds (the interval of the grade that recorded it: 0.3 s before
issue 39's stop 50, 0.1 s after); each student's line is said at the first reading at or after
its recorded time, with the estimate of that reading. The error of a line after the first
quarter of the class (but the last, which says "0 s" in any case) is |said - left| / left, left
being the "graded" line's time (else the run's end) minus the line's.

usage: replay_progress.py FILE[:POLL] ...   (POLL defaults to the file's runs' poll_s, else 0.3)
Prints, for each rule, the lines over 25 % of all and the median of the runs' median errors."""
import json, re, statistics, sys

RULES = [  # name, the jobs' pace (else each job's own), a first round counted half, the lag
    ("each job's own pace, first round half (before stop 50)", False, True, False),
    ("  + the records' lag", False, True, True),
    ("each job's own pace + lag", False, False, True),
    ("jobs' pace, first round half + lag", True, True, True),
    ("jobs' pace + lag (shipped)", True, False, True),
    ("jobs' pace, no lag", True, False, False),
]


class Job:
    def __init__(self, t, done):
        self.first_at = self.last_at = t
        self.first_done = self.last_done = self.last_step = done
        self.round_done = None

    def pace(self, first_round_half):
        since_first = ((self.last_at - self.first_at) / (self.last_done - self.first_done)
                       if self.last_done > self.first_done and self.last_at > self.first_at
                       else self.first_at / self.first_done)
        r = self.round_done
        if not first_round_half or not r or self.last_done <= r[1] or self.last_at <= r[0]:
            return since_first
        return (since_first + (self.last_at - r[0]) / (self.last_done - r[1])) / 2


def estimate(state, t, jobs, rule):
    _, pooled, half, _ = rule
    paces = []
    for j, (done, total, first) in jobs.items():
        if done == 0:
            continue
        s = state.setdefault(j, Job(t, done))
        if done > s.last_done:
            s.last_at, s.last_step, s.last_done = t, done - s.last_done, done
        if s.round_done is None and first and done >= first:
            s.round_done = (t, done)
        paces.append(s.pace(half))
    if not paces:
        return None
    lag = statistics.mean(state["lags"]) if state["lags"] else 0.0
    left = 0.0
    for j, (done, total, _) in jobs.items():
        rows = total - done
        s = state.get(j) if done > 0 else None
        if s is None:
            left = max(left, lag + statistics.mean(paces) * rows if rows else 0)
        elif rows == 0:
            left = max(left, lag - (t - s.last_at))
        else:
            pace = statistics.mean(paces) if pooled else s.pace(half)
            after = pace * (rows - min(rows, s.last_step))
            left = max(left, lag + max(after, pace * rows - (t - s.last_at)))
    return left


def replay(run, poll, rule):
    lines = [(t, l) for t, l in run["lines"] if l.startswith("[student")]
    end = next((t for t, l in run["lines"] if l.startswith("graded")), run["end_s"])
    names = sorted(re.match(r"\[student \d+ of \d+\] (\S+)", l).group(1) for _, l in lines)
    njobs = 1 + max(p[1] for p in run["progress"])
    job_of = {name: i % njobs for i, name in enumerate(names)}  # grade deals students in turn
    state, jobs, errors = {"lags": []}, {}, []
    k, i, t = 0, 0, run["progress"][0][0]
    while i < len(lines):
        while k < len(run["progress"]) and run["progress"][k][0] <= t:
            p = run["progress"][k]
            jobs[p[1]] = (p[2], p[3], p[4] if len(p) > 4 else 0)
            k += 1
        said = estimate(state, t, jobs, rule)
        while i < len(lines) and lines[i][0] <= t + 1e-9:
            s = state.get(job_of[re.match(r"\[student \d+ of \d+\] (\S+)", lines[i][1]).group(1)])
            if rule[3] and s:
                state["lags"].append(t - s.last_at)
            left = end - lines[i][0]
            if 4 * (i + 1) > len(lines) and i + 1 < len(lines) and said is not None:
                errors.append(abs(said - left) / max(left, 0.1))
            i += 1
        t += poll
    return errors


runs = []
for arg in sys.argv[1:]:
    path, _, poll = arg.partition(":")
    for line in open(path):
        run = json.loads(line)
        if run["progress"]:
            runs.append((run, float(poll or run.get("poll_s", 0.3))))
print("%d runs" % len(runs))
for rule in RULES:
    errors = [replay(run, poll, rule) for run, poll in runs]
    over = sum(e > 0.25 for es in errors for e in es)
    print("%-55s %4d of %d over 25 %%, median of the runs' medians %.3f" % (
        rule[0], over, sum(map(len, errors)), statistics.median(statistics.median(es) for es in errors)))
