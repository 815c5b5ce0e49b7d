#!/usr/bin/env python3
"""Checks the graders' formats of one `shadowlab check` run with real parsers: Gradescope's
results.json (json, against the fields and types Gradescope documents) and JUnit XML
(xml.etree.ElementTree: counts agree with the testcases, failures and errors carry a message).

usage: check_formats.py --gradescope FILE --junit FILE [--count N] [--errors N] [--failures N]
       [--verdict NAME=VERDICT]...
NAME is the test name (e.g. margin/core); VERDICT PASS, FAIL, SKIP, ERROR, TIMEOUT or CRASH."""
import json
import sys
import xml.etree.ElementTree as ET

# Gradescope's autograder specification (results.json): the documented keys and their types.
TOP = {"score": (int, float), "execution_time": (int, float), "output": str,
       "output_format": str, "test_output_format": str, "test_name_format": str,
       "visibility": str, "stdout_visibility": str, "extra_data": dict, "tests": list,
       "leaderboard": list}
TEST = {"score": (int, float), "max_score": (int, float), "status": str, "name": str,
        "name_format": str, "number": str, "output": str, "output_format": str, "tags": list,
        "visibility": str, "extra_data": dict}
VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
ERROR_VERDICTS = {"ERROR", "TIMEOUT", "CRASH", "MISSING"}  # no figures


def check_gradescope(path, problems):
    with open(path, encoding="utf-8") as f:  # strict UTF-8: a bad byte fails here
        doc = json.load(f)
    if not isinstance(doc, dict):
        return problems.append("gradescope: the top level is not an object") or {}
    for key, value in doc.items():
        if key not in TOP:
            problems.append(f"gradescope: undocumented top-level key '{key}'")
        elif not isinstance(value, TOP[key]) or isinstance(value, bool):
            problems.append(f"gradescope: '{key}' has the wrong type {type(value).__name__}")
    for key in ("score", "tests"):
        if key not in doc:
            problems.append(f"gradescope: '{key}' missing")
    tests = {}
    total = 0.0
    for k, t in enumerate(doc.get("tests", [])):
        where = f"gradescope: tests[{k}]"
        for key, value in t.items():
            if key not in TEST:
                problems.append(f"{where}: undocumented key '{key}'")
            elif not isinstance(value, TEST[key]) or isinstance(value, bool):
                problems.append(f"{where}: '{key}' has the wrong type {type(value).__name__}")
        for key in ("name", "score", "max_score", "status", "output"):
            if key not in t:
                problems.append(f"{where}: '{key}' missing")
        if t.get("status") not in ("passed", "failed"):
            problems.append(f"{where}: status '{t.get('status')}' is not passed or failed")
        if t.get("visibility", "visible") not in VISIBILITY:
            problems.append(f"{where}: visibility '{t.get('visibility')}'")
        if not 0 <= t.get("score", -1) <= t.get("max_score", -1):
            problems.append(f"{where}: score {t.get('score')} outside 0..{t.get('max_score')}")
        if (t.get("status") == "passed") != (t.get("score") == t.get("max_score")):
            problems.append(f"{where}: status {t.get('status')} but {t.get('score')} of "
                            f"{t.get('max_score')}")
        verdict = t.get("extra_data", {}).get("verdict", "")
        if not t.get("output", "").startswith(verdict + ": "):
            problems.append(f"{where}: output does not start with its verdict {verdict}")
        if "diff image: " not in t.get("output", ""):
            problems.append(f"{where}: output does not name the diff image")
        if verdict not in ERROR_VERDICTS and "figures:" not in t.get("output", ""):
            problems.append(f"{where}: output lacks the figures")
        total += t.get("score", 0)
        if t.get("name") in tests:
            problems.append(f"{where}: name '{t.get('name')}' is not unique")
        tests[t.get("name")] = verdict
    if abs(doc.get("score", -1) - total) > 1e-9:
        problems.append(f"gradescope: score {doc.get('score')} is not the tests' sum {total}")
    return tests


def check_junit(path, problems):
    root = ET.parse(path).getroot()
    if root.tag != "testsuites":
        problems.append(f"junit: root is <{root.tag}>, not <testsuites>")
    suites = root.findall("testsuite")
    if len(suites) != 1:
        problems.append(f"junit: {len(suites)} testsuites, expected 1")
    tests = {}
    counts = {"tests": 0, "failures": 0, "errors": 0, "skipped": 0}
    for case in root.iter("testcase"):
        name = case.get("name")
        if not name or not case.get("classname"):
            problems.append("junit: a testcase without name or classname")
        float(case.get("time", "x"))  # a number, or ValueError
        counts["tests"] += 1
        verdict = "PASS"
        for tag, key in (("failure", "failures"), ("error", "errors"), ("skipped", "skipped")):
            for element in case.findall(tag):
                counts[key] += 1
                verdict = element.get("type", "SKIP" if tag == "skipped" else "")
                if not element.get("message"):
                    problems.append(f"junit: {name}: <{tag}> without a message")
        if name in tests:
            problems.append(f"junit: name '{name}' is not unique")
        tests[name] = verdict
    for element in [root] + suites:
        for key, value in counts.items():
            if int(element.get(key, -1)) != value:
                problems.append(f"junit: <{element.tag}> {key}={element.get(key)}, "
                                f"the testcases say {value}")
    return tests, counts


def main():
    args = sys.argv[1:]
    opts = {"--verdict": []}
    while args:
        flag, value = args.pop(0), args.pop(0)
        if flag == "--verdict":
            opts[flag].append(value)
        else:
            opts[flag] = value
    problems = []
    gradescope = check_gradescope(opts["--gradescope"], problems)
    junit, counts = check_junit(opts["--junit"], problems)
    if gradescope != junit:
        problems.append(f"the two formats disagree: {gradescope} vs {junit}")
    for flag, key in (("--count", "tests"), ("--errors", "errors"), ("--failures", "failures")):
        if flag in opts and counts[key] != int(opts[flag]):
            problems.append(f"junit {key} = {counts[key]}, expected {opts[flag]}")
    if "--count" in opts and len(gradescope) != int(opts["--count"]):
        problems.append(f"gradescope has {len(gradescope)} tests, expected {opts['--count']}")
    for claim in opts["--verdict"]:
        name, verdict = claim.split("=")
        for fmt, tests in (("gradescope", gradescope), ("junit", junit)):
            if tests.get(name) != verdict:
                problems.append(f"{fmt}: {name} is {tests.get(name)}, expected {verdict}")
    if problems:
        sys.exit("FAIL: " + "\n      ".join(problems))
    print(f"ok: {counts['tests']} tests, {counts['failures']} failures, {counts['errors']} "
          f"errors, {counts['skipped']} skipped; both formats agree")


if __name__ == "__main__":
    main()
