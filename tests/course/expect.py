"""What the course tests share: failures collected (every check runs, all are reported), and
`grade` run on a class with its output printed."""
import subprocess, sys

failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)


def grade(exe, klass, assignment, out, *extra, timeout=1100):
    """`grade KLASS --assignment ASSIGNMENT --out OUT EXTRA...` with its output printed."""
    r = subprocess.run([exe, "grade", klass, "--assignment", assignment, "--out", out, *extra],
                       capture_output=True, text=True, timeout=timeout)
    print(r.stdout, r.stderr)
    return r


def finish(passed):
    """Exit 1 listing every failure, else print `passed`."""
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print(passed)
