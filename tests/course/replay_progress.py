#!/usr/bin/env python3
"""Replays grade's time-left rules on recorded runs (not a test: an analysis of the benchmark's
recordings, docs/results-class.md). Each run is one line of `bench_grade.py --trace FILE`: the
jobs' progress files as they changed and grade's lines. A reading is [seconds, job, done, total]
and then, before stop 51, the first round's rows; since, {stage: [done, total, views done, views
total]} and the step under way [rows, views, stage]. The rules are a model of class/class_progress.cpp's, so that variants can be compared on
the same runs; the unit tests (ClassProgress.*) replay the C++ itself on two of them.

Every run is read every POLL seconds (the interval of the grade that recorded it: 0.3 s before
issue 39's stop 50, 0.1 s after); each student's line is said at the first reading at or after
its recorded time, with the estimate of that reading. The error of a line after the first
quarter of the class (but the last, which says "0 s" in any case) is |said - left| / left, left
being the "graded" line's time (else the run's end) minus the line's.

usage: replay_progress.py FILE[:POLL] ...   (POLL defaults to the file's runs' poll_s, else 0.3)
Prints, for each rule, the lines over 25 % of all and the median of the runs' median errors."""
import json, re, statistics, sys

RULES = [  # name, the jobs' pace (else each job's own), a first round counted half, the lag,
    # each stage's rows and its rounds' views at their prices, and the step under way as the job's
    # file says it (runs recorded since stop 51 only; on others as without)
    ("each job's own pace, first round half (before stop 50)", False, True, False, False),
    ("  + the records' lag", False, True, True, False),
    ("each job's own pace + lag", False, False, True, False),
    ("jobs' pace, first round half + lag", True, True, True, False),
    ("jobs' pace + lag (stop 50)", True, False, True, False),
    ("jobs' pace, no lag", True, False, False, False),
    ("jobs' pace + lag + stage and views prices, step (shipped)", True, False, True, True),
]


class Job:
    def __init__(self, t, done, stages):
        self.first_at = self.last_at = t
        self.first_done = self.last_done = self.last_step = done
        self.round_done = None
        self.last_stages = stages

    def pace(self, first_round_half):
        since_first = ((self.last_at - self.first_at) / (self.last_done - self.first_done)
                       if self.last_done > self.first_done and self.last_at > self.first_at
                       else self.first_at / self.first_done)
        r = self.round_done
        if not first_round_half or not r or self.last_done <= r[1] or self.last_at <= r[0]:
            return since_first
        return (since_first + (self.last_at - r[0]) / (self.last_done - r[1])) / 2


def time_steps(state, s, t, done, stages):  # the step's time to the stages whose rows came
    for key, now in stages.items():
        was = s.last_stages.get(key, [0, 0, 0, 0])
        added, views = now[0] - was[0], now[2] - was[2]
        if added + views <= 0 or was[0] + was[2] == 0:  # a job's first step of a stage calibrates
            continue
        c = state["costs"].setdefault(key, [0.0, 0, 0.0, 0, 0])  # plain s, rows; views s, rows, views
        share = (t - s.last_at) * (added + views) / (done - s.last_done)
        if views:
            c[2] += share
            c[3] += added
            c[4] += views
        else:
            c[0] += share
            c[1] += added


def mean_row(state):
    c = state["costs"].values()
    seconds, rows = sum(x[0] + x[2] for x in c), sum(x[1] + x[3] + x[4] for x in c)
    return seconds / rows if rows and seconds > 0 else 1.0


def views_against_rows(state):  # the views' cost against a row's, on the stages timed both ways
    views = as_rows = 0.0
    for c in state["costs"].values():
        if c[1] and c[4]:
            row = c[0] / c[1]
            views += max(0.0, c[2] - row * c[3])
            as_rows += row * c[4]
    return views / as_rows if as_rows else 1.0


def cost_of(state, key, rows, views):  # the seconds a stage's rows and views took so far
    c = state["costs"].get(key)
    if c is None:
        return mean_row(state) * (rows + views)
    if c[1]:
        row = c[0] / c[1]
        view = max(0.0, c[2] - row * c[3]) / c[4] if c[4] else row
    else:
        ratio = views_against_rows(state)
        row = c[2] / (c[3] + ratio * c[4])
        view = ratio * row
    return row * rows + view * views


def seconds_left(state, stages):  # each stage's rows and views left at their prices
    return sum(cost_of(state, k, v[1] - v[0], v[3] - v[2]) for k, v in stages.items())


def estimate(state, t, jobs, rule):
    _, pooled, half, _, priced = rule
    paces = []
    for j, (done, total, first, stages, _) in jobs.items():
        if done == 0:
            continue
        s = state.setdefault(j, Job(t, done, stages))
        if done > s.last_done:
            if priced:
                time_steps(state, s, t, done, stages)
            s.last_at, s.last_step, s.last_done, s.last_stages = t, done - s.last_done, done, stages
        if s.round_done is None and first and done >= first:
            s.round_done = (t, done)
        paces.append(s.pace(half))
    if not paces:
        return None
    lag = statistics.mean(state["lags"]) if state["lags"] else 0.0
    left = 0.0
    for j, (done, total, _, stages, (step_rows, step_views, step_key)) in jobs.items():
        rows = total - done
        pace = statistics.mean(paces)
        s = state.get(j) if done > 0 else None
        if not pooled and s:
            pace = s.pace(half)
        priceable = priced and stages and state["costs"]
        need = seconds_left(state, stages) if priceable else pace * rows
        if s is None:
            left = max(left, lag + need if rows else 0)
        elif rows == 0:
            left = max(left, lag - (t - s.last_at))
        else:
            if priceable and step_rows:  # the step under way, as its file says (since stop 51)
                after = max(0.0, need - cost_of(state, step_key, step_rows, step_views))
            else:
                after = need * (1 - min(rows, s.last_step) / rows)
            left = max(left, lag + max(after, need - (t - s.last_at)))
    return left


def replay(run, poll, rule):
    lines = [(t, l) for t, l in run["lines"] if l.startswith("[student")]
    end = next((t for t, l in run["lines"] if l.startswith("graded")), run["end_s"])
    names = sorted(re.match(r"\[student \d+ of \d+\] (\S+)", l).group(1) for _, l in lines)
    njobs = 1 + max(p[1] for p in run["progress"])
    job_of = {name: i % njobs for i, name in enumerate(names)}  # grade deals students in turn
    state, jobs, errors = {"lags": [], "costs": {}}, {}, []
    k, i, t = 0, 0, run["progress"][0][0]
    while i < len(lines):
        while k < len(run["progress"]) and run["progress"][k][0] <= t:
            p = run["progress"][k]
            extra = p[4] if len(p) > 4 else 0  # FIRST (stop 50's runs) or the stages (since 51)
            jobs[p[1]] = (p[2], p[3], extra if isinstance(extra, int) else 0,
                          extra if isinstance(extra, dict) else {}, p[5] if len(p) > 5 else [0, 0, ""])
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
