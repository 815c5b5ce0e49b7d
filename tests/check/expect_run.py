#!/usr/bin/env python3
"""Runs a command and checks both its exit code and its output.

CMake's PASS_REGULAR_EXPRESSION ignores the exit code, so a test that needs both (exit 1 for a
FAIL, 2 for bad input, 0 and a figure) runs through this instead:

    expect_run.py --exit N [--output REGEX]... [--absent REGEX]... [--writes FILE]... -- COMMAND [ARG]...

stdout and stderr are read together and printed. Each --output must be found (Python `re.search`,
`.` matching newlines too, as CMake's regular expressions do across lines); no --absent may be.
Each --writes FILE is deleted before the command runs and must exist, not empty, after it: a
file left by an earlier run cannot pass. Exits 0 when every condition holds, else 1 naming each
that does not."""
import argparse
import os
import re
import subprocess
import sys


def main(argv):
    if "--" not in argv:
        sys.exit("expect_run.py: give the command after --")
    split = argv.index("--")
    parser = argparse.ArgumentParser(prog="expect_run.py")
    parser.add_argument("--exit", type=int, required=True, help="the exit code the command must give")
    parser.add_argument("--output", action="append", default=[], help="a regex the output must match")
    parser.add_argument("--absent", action="append", default=[], help="a regex the output must not match")
    parser.add_argument("--writes", action="append", default=[], help="a file this run must write")
    args = parser.parse_args(argv[:split])
    command = argv[split + 1:]
    if not command:
        sys.exit("expect_run.py: no command after --")
    for path in args.writes:
        if os.path.lexists(path):
            os.remove(path)
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, check=False)
    text = run.stdout.decode("utf-8", errors="replace")
    sys.stdout.write(text)
    problems = []
    if run.returncode != args.exit:
        problems.append(f"exit code {run.returncode}, expected {args.exit}")
    for pattern in args.output:
        if not re.search(pattern, text, re.DOTALL):
            problems.append(f"output does not match: {pattern}")
    for pattern in args.absent:
        if re.search(pattern, text, re.DOTALL):
            problems.append(f"output matches what must be absent: {pattern}")
    for path in args.writes:
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            problems.append(f"{path} was not written")
    if problems:
        print("expect_run: FAIL: " + "; ".join(problems))
        return 1
    print(f"expect_run: OK (exit {run.returncode}, {len(args.output)} pattern(s) found)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
