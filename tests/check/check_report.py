#!/usr/bin/env python3
"""Checks a `shadowlab check --report` file: every documented field (docs/check.md) is there
with the right type, the summary agrees with the results, and optional claims hold.

usage: check_report.py REPORT.json --exe SHADOWLAB [--count N] [--exit N]
       [--verdict STAGE/TREE=VERDICT]... [--figure STAGE/TREE:NAME:lt:VALUE | ...:gt:VALUE]...
(lt/gt rather than < and > so the arguments survive a shell.) The figures every row must have
are the program's own table (`SHADOWLAB stages --figures --json`), not a list of this script's;
each row's `reasons` (the verdict's bounds as data) must agree with its verdict."""
import json
import re
import subprocess
import sys

RESULT_FIELDS = {"stage": str, "tree": str, "scene": str, "size": list, "parameters": dict,
                 "camera": dict, "light": list, "figures": dict, "pixels": dict,
                 "expectation": dict, "verdict": str, "message": str, "reasons": list,
                 "seconds": float, "student_files": list}


def figure_table(exe):
    """The names of the figure table, as the program lists them."""
    out = subprocess.run([exe, "stages", "--figures", "--json"], check=True,
                         capture_output=True, text=True).stdout
    return [f["name"] for f in json.loads(out)]


def named_figure(reason, figures):
    """A figure of the table, itself or, in a drawn pair's reason, its change from the first row
    at "change_from" (PARAM=VALUE ...: docs/check.md, "the response")."""
    start = reason.get("change_from")
    return reason.get("figure") in figures and (
        start is None or re.fullmatch(r"[a-z-]+=\S+( [a-z-]+=\S+)*", str(start)) is not None)


def reason_problems(name, row, figures):
    """A row's reasons: well formed, naming figures of the table, and agreeing with its verdict
    (a FAIL misses at least one bound; a PASS holds every one)."""
    problems = []
    for f in row.get("reasons", []):
        ok = (named_figure(f, figures) and f.get("side") in (">=", "<=")
              and isinstance(f.get("passed"), bool) and isinstance(f.get("bound"), (int, float))
              and (f.get("value") is None or isinstance(f.get("value"), (int, float))))
        if not ok:
            problems.append(f"{name}: a malformed reason {f}")
    missed = [f for f in row.get("reasons", []) if not f.get("passed")]
    if row.get("verdict") == "FAIL" and not missed:
        problems.append(f"{name}: FAIL with no reason that missed its bound")
    if row.get("verdict") == "PASS" and (missed or not row.get("reasons")):
        problems.append(f"{name}: PASS with reasons {row.get('reasons')}")
    return problems


# The one order of grade/status.h: later is worse.
SEVERITY = {v: k for k, v in enumerate(
    ["PASS", "SKIP", "FAIL", "MISSING", "ERROR", "TIMEOUT", "CRASH", "NOT GRADED"])}


def rows_of(results, key):
    """The rows of STAGE/TREE (every view and lesson), or the row named KEY."""
    named = [r for r in results if r.get("name") == key]
    return named or [r for r in results if f"{r['stage']}/{r['tree']}" == key]


def first_row(results, key):
    """The row named KEY, or STAGE/TREE's first row (its defaults seen from the first view)."""
    rows = rows_of(results, key)
    return rows[:1]


def main():
    args = sys.argv[1:]
    with open(args.pop(0)) as f:
        report = json.load(f)
    if "--exe" not in args[::2]:
        sys.exit("usage: check_report.py REPORT.json --exe SHADOWLAB ... (the figure table)")
    at = args[::2].index("--exe") * 2
    figures = figure_table(args[at + 1])
    del args[at:at + 2]
    problems = []
    for key in ("tool", "report_format", "report_version", "expectations", "machine", "summary",
                "stages"):
        if key not in report:
            problems.append(f"missing top-level '{key}'")
    if report.get("report_format") != "shadowlab-report" or report.get("report_version") != 3:
        problems.append(f"a report's format is shadowlab-report version 3, not "
                        f"{report.get('report_format')!r} version {report.get('report_version')!r}")
    if problems:
        sys.exit("FAIL: " + "; ".join(problems))
    if not report["machine"].get("renderer"):
        problems.append("machine.renderer is empty")
    summary = report["summary"]
    results = [row for stage in report["stages"] for row in stage["rows"]]
    for key in ("checked", "passed", "failed", "skipped", "errors", "missing", "not_graded",
                "exit_code", "seconds"):
        if key not in summary:
            problems.append(f"summary.{key} is missing")
    by_verdict = {v: sum(1 for r in results if r.get("verdict") == v) for v in SEVERITY}
    by_verdict["errors"] = by_verdict["ERROR"] + by_verdict["TIMEOUT"] + by_verdict["CRASH"]
    if summary.get("checked") != len(results):
        problems.append(f"summary.checked {summary.get('checked')} != {len(results)} results")
    for key, verdict in (("passed", "PASS"), ("failed", "FAIL"), ("skipped", "SKIP"),
                         ("errors", "errors"), ("missing", "MISSING"),
                         ("not_graded", "NOT GRADED")):
        if summary.get(key) != by_verdict[verdict]:
            problems.append(f"summary.{key} {summary.get(key)} != {by_verdict[verdict]} {verdict}")
    for r in results:
        name = f"{r.get('stage')}/{r.get('tree')}"
        for key, kind in RESULT_FIELDS.items():
            if not isinstance(r.get(key), (int, float) if kind is float else kind):
                problems.append(f"{name}: '{key}' missing or not {kind.__name__}")
        for fig in figures:
            if fig not in r.get("figures", {}):
                problems.append(f"{name}: figures.{fig} missing")
        problems += reason_problems(name, r, figures)
        exp = r.get("expectation", {})
        for key in ("id", "entry", "matched", "outcome", "why", "limits"):
            if key not in exp:
                problems.append(f"{name}: expectation.{key} missing")
        if "diff" not in r:
            problems.append(f"{name}: 'diff' missing (null when none)")
        if r.get("verdict") not in by_verdict or r.get("verdict") == "errors":
            problems.append(f"{name}: verdict '{r.get('verdict')}'")
    while args:
        flag, value = args.pop(0), args.pop(0)
        if flag == "--count" and len(results) != int(value):
            problems.append(f"{len(results)} results, expected {value}")
        elif flag == "--exit" and summary.get("exit_code") != int(value):
            problems.append(f"exit_code {summary.get('exit_code')}, expected {value}")
        elif flag == "--verdict":  # STAGE/TREE: the worst of its rows; or a row's full name
            key, verdict = value.split("=")
            got = [r["verdict"] for r in rows_of(results, key)]
            worst = max(got, key=lambda v: SEVERITY.get(v, 9)) if got else None
            if worst != verdict:
                problems.append(f"{key}: verdict {worst} of {got}, expected {verdict}")
        elif flag == "--figure":
            key, name, op, bound = value.split(":")
            if op not in ("lt", "gt"):
                sys.exit(f"usage: --figure STAGE/TREE:NAME:lt|gt:VALUE, not {value}")
            got = [r["figures"][name] for r in first_row(results, key)]
            if len(got) != 1 or got[0] is None or not (
                    got[0] < float(bound) if op == "lt" else got[0] > float(bound)):
                problems.append(f"{key}: {name} = {got}, expected {op} {bound}")
            else:
                print(f"{key}: {name} = {got[0]:.3f} {op} {bound}")
    if problems:
        sys.exit("FAIL: " + "; ".join(problems))
    print(f"OK: {len(results)} results, exit code {summary['exit_code']}")


if __name__ == "__main__":
    main()
