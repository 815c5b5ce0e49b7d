#!/usr/bin/env python3
"""docs/check.md's JUnit paragraph against a JUnit file: one <testsuite> named
"ASSIGNMENT: STUDENT" in <testsuites>, both with tests/failures/errors/skipped/time, one
<testcase classname="shadowlab.STAGE/TREE" name="TEST NAME" time="S"> per row, named as
Gradescope's tests, with the properties points, max_points and visibility.

usage: junit_names.py J.xml RESULTS.json REPORT.json   (the three of one check run's settings)
"""
import json
import sys
import xml.etree.ElementTree as ET

COUNTS = ("tests", "failures", "errors", "skipped", "time")


def main():
    junit, gradescope, report = sys.argv[1:4]
    root = ET.parse(junit).getroot()
    tests = json.load(open(gradescope, encoding="utf-8"))["tests"]
    record = json.load(open(report, encoding="utf-8"))
    problems = []
    suites = root.findall("testsuite")
    if root.tag != "testsuites" or len(suites) != 1:
        problems.append(f"want <testsuites> holding one <testsuite>, got <{root.tag}> with {len(suites)}")
    suite = suites[0] if suites else root
    want_name = f"{record['assignment']}: {record['student']}"
    if suite.get("name") != want_name:
        problems.append(f"testsuite name '{suite.get('name')}', the docs say '{want_name}'")
    for element in (root, suite):
        missing = [a for a in COUNTS if element.get(a) is None]
        if missing:
            problems.append(f"<{element.tag}> lacks {', '.join(missing)}")
    cases = suite.findall("testcase")
    if [c.get("name") for c in cases] != [t["name"] for t in tests]:
        problems.append("testcase names differ from Gradescope's tests[].name")
    rows = [(s["stage"], s["tree"]) for s in record["stages"] for _ in s["rows"]]
    for case, (stage, tree) in zip(cases, rows):
        if case.get("classname") != f"shadowlab.{stage}/{tree}" or case.get("time") is None:
            problems.append(f"testcase '{case.get('name')}': classname '{case.get('classname')}', "
                            f"time {case.get('time')}")
        props = {p.get("name") for p in case.iter("property")}
        if props != {"points", "max_points", "visibility"}:
            problems.append(f"testcase '{case.get('name')}': properties {sorted(props)}")
    for p in problems[:10]:
        print(p)
    print(f"{len(cases)} testcases, {len(problems)} differences from docs/check.md")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
