"""Hostile cases for intake, the snapshot and grading's output bounds (issue 19), generated at
test time and run by run_cases.py with the rest of the corpus. `h` is run_cases' namespace
(Case, student, shipped, no_secret, other_stages, chain)."""
import os
import signal
import subprocess
import sys

SMALL_CHECK = "check --glsl core --size 160x120 --stage margin --shaders {student}"

# A student process racing the grader: it swaps the folder inc/ of its submission for a link to
# the secret's folder and back, as fast as it can, until the case stops it.
SWAPPER = r"""
import os, sys, time
folder, secret = sys.argv[1], sys.argv[2]
inc, real = os.path.join(folder, "inc"), os.path.join(folder, "inc.real")
end = time.monotonic() + 120
while time.monotonic() < end and os.path.isdir(folder):
    try:
        os.rename(inc, real); os.symlink(secret, inc); time.sleep(0.0003)
        os.unlink(inc); os.rename(real, inc); time.sleep(0.0003)
    except OSError:
        pass
"""

SWAPPERS = {}  # tmp -> the swapper's Popen


def racing_submission(h):
    """margin/lit.frag includes inc/app.conf (a harmless file) while a process swaps inc/ for a
    link to the folder holding the secret app.conf."""
    lit = h.shipped("margin/lit.frag").replace(
        b'#include "common/phong.glsl"\n', b'#include "common/phong.glsl"\n#include "inc/app.conf"\n')
    make = h.student({"margin/lit.frag": lit, "inc/app.conf": b"// nothing here\n"})

    def setup(tmp, args):
        args = make(tmp, args)
        SWAPPERS[tmp] = subprocess.Popen(
            [sys.executable, "-c", SWAPPER, os.path.join(tmp, "student"),
             os.path.join(tmp, "secret")], start_new_session=True)
        return args
    return setup


def stop_swapper_then(check):
    def run(tmp, p):
        swapper = SWAPPERS.pop(tmp, None)
        if swapper:
            os.killpg(swapper.pid, signal.SIGKILL)
            swapper.wait()
        return check(tmp, p)
    return run


def long_error_include(h):
    """margin/lit.frag includes, 4 times, a 500-byte file whose token pasting builds a 1 MiB
    identifier: every inclusion is an error line quoting it, the compiler's log runs to 4 MB
    (on main at 1014c05: a 1 MB report, a 2 MB JUnit file, 1 MB of stdout, 4 MB of stderr; more
    inclusions exhaust the worker's memory first, a CRASH). glslang now reads it before the
    driver: it refuses the pasted token ("combined tokens are too long", at most 20 error lines
    kept), so the driver's 4 MB log is never made; the outputs must stay small all the same."""
    include = (b"#ifndef BOOM\n#define BOOM\n#define P_(a,b) a##b\n#define P(a,b) P_(a,b)\n"
               b"#define X0 xxxxxxxx\n" +
               b"".join(b"#define X%d P(X%d,X%d)\n" % (i, i - 1, i - 1) for i in range(1, 18)) +
               b"#endif\nfloat boom = X17;\n")
    lit = h.shipped("margin/lit.frag").replace(
        b"void main", b'#include "common/boom.glsl"\n' * 4 + b"void main", 1)
    return h.student({"margin/lit.frag": lit, "common/boom.glsl": include})


def files_small(*names, limit=64 * 1024):
    """Each named file in {tmp} exists and holds at most `limit` bytes, and so do stdout and
    stderr."""
    def check(tmp, p):
        problems = []
        for name in names:
            path = os.path.join(tmp, name)
            if not os.path.isfile(path):
                problems.append(f"{name} was not written")
            elif os.path.getsize(path) > limit:
                problems.append(f"{name} holds {os.path.getsize(path)} bytes (> {limit})")
        for stream, text in (("stdout", p.stdout), ("stderr", p.stderr)):
            if len(text) > limit:
                problems.append(f"{stream} holds {len(text)} characters (> {limit})")
        return problems
    return check


def planted_link_in_submission(tmp, args):
    """The submission holds diffs -> another student's folder (a planted link)."""
    victim = os.path.join(tmp, "victim")
    os.makedirs(victim, exist_ok=True)
    with open(os.path.join(victim, "keep.txt"), "w") as f:
        f.write("another student's work\n")
    os.symlink(victim, os.path.join(tmp, "student", "diffs"))
    return args


def victim_untouched(tmp, p):
    names = sorted(os.listdir(os.path.join(tmp, "victim")))
    return [] if names == ["keep.txt"] else [f"the planted link was written through: {names}"]


def many_files(h, count):
    files = {"margin/lit.frag": h.shipped("margin/lit.frag")}
    files.update({f"notes/n{i}.txt": b"x\n" for i in range(count)})
    return h.student(files)


def link_mismatch(h):
    """margin/lit.frag takes worldNormal as a vec4; our lit.vert writes a vec3: a link error."""
    lit = h.shipped("margin/lit.frag").replace(b"in vec3 worldNormal;", b"in vec4 worldNormal;")
    lit = lit.replace(b"normalize(worldNormal)", b"normalize(worldNormal.xyz)")
    lit = lit.replace(b"worldNormal, visibility", b"worldNormal.xyz, visibility")
    return h.student({"margin/lit.frag": lit})


def report_message_names(*parts):
    """Every row of {tmp}/report.json names each of `parts` in its message."""
    def check(tmp, p):
        import json
        with open(os.path.join(tmp, "report.json")) as f:
            rows = [r for st in json.load(f)["stages"] for r in st["rows"]]
        return [f"a row's message lacks '{part}': {r['message'][:200]}"
                for r in rows for part in parts if part not in r["message"]]
    return check


def intake_cases(h):
    Case = h.Case
    cases = [
        Case(f"a folder swapped for a link to the secret during check (run {k})", (0, 2), "",
             SMALL_CHECK + " --report {tmp}/report.json", timeout=120, one_line=False,
             setup=racing_submission(h), check=stop_swapper_then(h.no_secret))
        for k in range(1, 7)
    ]
    cases += [
        # glslang refuses the pasted token before any driver compiles it, in a few short lines
        # (the cutting of a long message itself: test_grade_bounds).
        Case("an include that repeats a 1 MiB error line: outputs stay small", 2,
             "did not compile by the GLSL standard",
             SMALL_CHECK + " --report {tmp}/report.json --junit {tmp}/junit.xml", timeout=60,
             one_line=False,
             setup=lambda tmp, args: long_error_include(h)(tmp, h.release_memory(tmp, args)),
             check=files_small("report.json", "junit.xml")),
        Case("a link error names both files in the report", 2, "program did not link",
             SMALL_CHECK + " --report {tmp}/report.json", timeout=30, one_line=False,
             setup=link_mismatch(h),
             check=report_message_names(
                 "shaders_core/margin/lit.vert + ",
                 "student/margin/lit.frag: program did not link by the GLSL standard (glslang",
                 "student/margin/lit.frag:7: error: Linking vertex and fragment stages: Types "
                 "must match")),
        Case("an include that is a hard link to the secret (check)", 2, "has 2 hard links",
             SMALL_CHECK + " --report {tmp}/report.json", timeout=30, one_line=False,
             check=h.no_secret,
             setup=h.chain(h.student({"margin/lit.frag": h.shipped("margin/lit.frag").replace(
                 b'#include "common/phong.glsl"\n',
                 b'#include "common/phong.glsl"\n#include "common/h.glsl"\n')}),
                 h.hard_links("common/h.glsl"))),
        Case("--report and --junit the same file", 2, "--report and --junit: both are",
             SMALL_CHECK + " --report {tmp}/r.out --junit {tmp}/r.out", timeout=20,
             setup=h.student({"margin/lit.frag": h.shipped("margin/lit.frag")})),
        Case("--diff and --report the same file, spelled differently", 2, "both are",
             SMALL_CHECK + " --diff {tmp}/x.png --report {tmp}/./sub/../x.png", timeout=20,
             setup=h.chain(h.student({"margin/lit.frag": h.shipped("margin/lit.frag")}),
                           lambda tmp, args: os.makedirs(os.path.join(tmp, "sub")) or args)),
        Case("--report inside the submission folder", 2, "lies inside the submission folder",
             SMALL_CHECK + " --report {student}/report.json", timeout=20,
             setup=h.student({"margin/lit.frag": h.shipped("margin/lit.frag")})),
        Case("--diff-dir inside the submission, through a planted link", 2,
             "lies inside the submission folder",
             "check --glsl core --size 160x120 --all --shaders {student} --diff-dir "
             "{student}/diffs", timeout=20, check=victim_untouched,
             setup=h.chain(h.student({"margin/lit.frag": h.shipped("margin/lit.frag")}),
                           planted_link_in_submission)),
        Case("--shaders with an empty folder name", 2, "--shaders: empty",
             "check --stage margin --shaders ''", timeout=20),
        Case("a submission that replaces nothing (a README)", 2,
             "no file replaces a shipped shader", SMALL_CHECK, timeout=20,
             setup=h.student({"README.md": b"done!\n"})),
        Case("a submission of 3,000 files", 2, "more than 2048 files and folders",
             SMALL_CHECK, timeout=30, setup=many_files(h, 3000)),
        Case("a shader of the submission is a link to the secret", 2, "MISSING",
             SMALL_CHECK + " --report {tmp}/report.json", timeout=30, one_line=False,
             check=h.no_secret,
             setup=h.student({"margin/notes.txt": b"see lit.frag\n",
                              "depth/lit.vert": h.shipped("depth/lit.vert")},
                             links={"margin/lit.frag": "{tmp}/secret/app.conf"})),
    ]
    return cases
