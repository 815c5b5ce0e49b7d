"""What the course tests share: failures collected (every check runs, all are reported), and
`grade` run on a class with its output printed."""
import subprocess, sys

failures = []
checks = 0  # how many `check` calls passed


def check(label, ok, detail=""):
    """One named check, printed; the first that fails ends the test (exit 1) with its detail."""
    global checks
    checks += 1
    print(("ok:   " if ok else "FAIL: ") + label + ("" if ok else " -- " + str(detail)[:1500]))
    if not ok:
        sys.exit(1)


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
