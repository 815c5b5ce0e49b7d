#!/usr/bin/env python3
"""Runs the bad-input corpus (cases.txt plus the generated cases below) against the shadowlab
executable and reports every failure, then a closing line `N passed, M failed`.

usage: run_cases.py SHADOWLAB_EXE [--only TEXT] [--times] [--time-scale K] [--list]

--time-scale K: the executable does the same work K times slower (an instrumented build:
scripts/sanitizers.sh), so the budgets follow: each case's own bound is K times longer, a
case's --time-limit N becomes N*K (and the messages it expects name N*K s), and a command that
runs workers without one gets K times the program's default (read from its --help).
"""
import copy
import json
import os
import re
import resource
import shlex
import signal
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # keep the corpus folder clean
from intake_cases import intake_cases  # noqa: E402  (issue 19: intake, snapshot, bounds)

HERE = os.path.dirname(os.path.abspath(__file__))
TIMEOUT = 60  # seconds per command: a hang is a failure, not a stuck CI
SMALL = "render --repeat 0 --out {out}"  # and --size 160x120 unless the case gives a size


class Case:
    """`one_line`: a failing command's stderr is one line. `check --all` prints one line per
    stage that fails (and its notes), so its cases set it False and name the line they expect."""
    def __init__(self, name, expect, fragment, args, timeout=TIMEOUT, setup=None, check=None,
                 preexec=None, one_line=True, crashes=False, stdin=None, kill_after=None,
                 outcomes=None):
        self.name, self.expect, self.fragment, self.args = name, expect, fragment, args
        # outcomes {exit code: fragment}: where the driver decides (how fast Mesa compiles a
        # shader, whether it crashes on it), each outcome the user may get, with its line.
        self.outcomes = outcomes
        # stdin(tmp): what the command reads as stdin (a file object, or None for /dev/null).
        # kill_after: (seconds, signal): a grading harness's timeout ends shadowlab itself.
        self.stdin, self.kill_after = stdin, kill_after
        self.timeout, self.setup, self.check, self.preexec = timeout, setup, check, preexec
        self.one_line = one_line
        # A worker that dies inside Mesa may have the driver print its own last words first
        # (Mesa 26's "LLVM ERROR: out of memory"): those lines are the driver's, written by the
        # worker before it died; ours must still follow, starting with "shadowlab:".
        self.crashes = crashes
        # A case whose worker dies inside Mesa: under AddressSanitizer the signal must reach
        # the worker as it does without (the sanitizer would catch it and report Mesa's crash).
        self.env = None
        if crashes:
            self.env = dict(os.environ)
            self.env["ASAN_OPTIONS"] = (os.environ.get("ASAN_OPTIONS", "") +
                                        ":handle_segv=0:handle_abort=0:handle_sigbus=0").lstrip(":")



def report_rows(report):
    """Every row of a check report (a student record: stages, each with its rows)."""
    return [row for stage in report["stages"] for row in stage["rows"]]

def parse_cases(path):
    cases = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            expect, fragment, args = (p.strip() for p in line.split("|", 2))
            cases.append(Case(f"cases.txt:{number}", int(expect), fragment, args))
    return cases


def out_path(args):
    words = shlex.split(args)
    for i, w in enumerate(words):
        if w == "--out" and i + 1 < len(words):
            return words[i + 1]
        if w.startswith("--out="):
            return w[len("--out="):]
    return None


def run(exe, case):
    """Returns a list of problems (empty: the case passed)."""
    expected = case.expect if isinstance(case.expect, tuple) else (case.expect,)
    tmp = tempfile.mkdtemp(prefix="sl-bad-")
    out = os.path.join(tmp, "out.png")
    args = case.args
    if "{R}" in args:
        args = args.replace("{R}", SMALL + ("" if "--size" in args else " --size 160x120"))
    for key, value in (("{out}", out), ("{tmp}", tmp), ("{here}", HERE)):
        args = args.replace(key, value)
    if case.setup:
        args = case.setup(tmp, args)
    case, args = scale_time(case, args)
    timeout = case.timeout * TIME_SCALE
    target = out_path(args)
    existed = bool(target) and os.path.lexists(target)  # a case's own file: refused, kept
    before = os.listdir(tmp)
    start = time.monotonic()
    stdin = case.stdin(tmp) if case.stdin else subprocess.DEVNULL
    if case.kill_after:
        p, problems = run_and_kill(exe, args, case, stdin, tmp)
    else:
        problems = []
        try:
            p = subprocess.run([exe] + shlex.split(args), capture_output=True, text=True,
                               errors="replace", timeout=timeout,
                               preexec_fn=case.preexec, env=case.env, stdin=stdin)
        except subprocess.TimeoutExpired:
            return [f"did not finish within {timeout:g} s (hang?)"], args
    seconds = time.monotonic() - start
    CASE_SECONDS[case.name] = seconds
    if case.outcomes and p.returncode in case.outcomes:
        case = copy.copy(case)
        case.expect, case.fragment = p.returncode, case.outcomes[p.returncode]
    if case.outcomes is not None:  # the driver decides which of these the user gets
        expected = tuple(case.outcomes)
    if p.returncode < 0 and not case.kill_after:
        problems.append(f"killed by signal {-p.returncode} (crash)")
    elif p.returncode not in expected:
        problems.append(f"exit code {p.returncode}, expected "
                        f"{case.expect if case.outcomes is None else sorted(case.outcomes)}")
    failing = p.returncode != 0  # (a case may allow several exit codes: a race's outcomes)
    text = p.stderr if failing else p.stdout + p.stderr
    if case.fragment and case.fragment not in text:
        problems.append(f"output lacks '{case.fragment}'")
    for bad in ("runtime error:", "AddressSanitizer", "LeakSanitizer", "terminate called"):
        if bad in p.stderr:
            problems.append(f"stderr reports '{bad}'")
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    if case.crashes:
        ours = [k for k, l in enumerate(lines) if l.startswith("shadowlab:")]
        lines = lines[ours[0]:] if ours else lines
    if case.kill_after:
        pass  # killed: whatever it printed so far
    elif failing:
        if not lines or not lines[0].startswith("shadowlab:"):
            problems.append("stderr's first line does not start with 'shadowlab:'")
        elif case.one_line and len(lines) > 1 and "shader error:" not in lines[0]:
            problems.append(f"stderr has {len(lines)} lines, expected one")
        if target and target.startswith(tmp) and os.path.isfile(target) and not existed:
            problems.append(f"a file was left at {target}")
    elif target and not is_png(target) and not case.kill_after:
        problems.append(f"{target} is not a PNG")
    left = [os.path.relpath(os.path.join(base, f), tmp) for base, _, names in os.walk(tmp)
            for f in names if ".tmp" in f and f not in before]
    if left:
        problems.append(f"temporary files left behind: {left}")
    if case.check:
        problems += case.check(tmp, p)
    if problems:
        problems.append(f"stderr: {p.stderr.strip()[:600]!r} ({seconds:.1f} s)")
    subprocess.run(["rm", "-rf", tmp])
    return problems, args


CASE_SECONDS = {}  # each case's wall time, printed with --times
TIME_SCALE = 1.0  # --time-scale
WORKER_COMMANDS = ("check", "render", "grade", "example")  # the ones with --time-limit
DEFAULT_TIME_LIMIT = None  # the program's, from its --help (with --time-scale only)


def default_time_limit(exe):
    """The worker's default time limit in seconds, as `check --help` states it; None when the
    default is `auto` (a CPU-time budget calibrated on our shaders in the same run, so an
    instrumented build's slower work is in it already: nothing to scale)."""
    text = subprocess.run([exe, "check", "--help"], capture_output=True, text=True).stdout
    if re.search(r"--time-limit[^\n]*auto \(default", text):
        return None
    found = re.search(r"--time-limit.*?\(default (\d+(?:\.\d+)?)", text, re.S)
    if not found:
        sys.exit("run_cases: `check --help` states no default for --time-limit: "
                 "--time-scale cannot scale it")
    return float(found.group(1))


def scale_time(case, args):
    """The case and its args with every worker time limit K times longer: a --time-limit N
    becomes N*K and the texts the case expects name N*K; a command that runs workers without
    one gets K times the program's default."""
    if TIME_SCALE == 1 or not args.split() or args.split()[0] not in WORKER_COMMANDS:
        return case, args
    given = re.search(r"--time-limit[= ](\d+(?:\.\d+)?)", args)
    if not given and DEFAULT_TIME_LIMIT is None:  # auto: the budget follows the work
        return case, args
    if not given:  # right after the command: a case's malformed last option stays last
        command, rest = args.split(None, 1) if " " in args.strip() else (args.strip(), "")
        return case, f"{command} --time-limit {DEFAULT_TIME_LIMIT * TIME_SCALE:g} {rest}".rstrip()
    old = float(given.group(1))
    if old == 0:  # no limit stays no limit
        return case, args
    new = old * TIME_SCALE
    args = args[:given.start(1)] + f"{new:g}" + args[given.end(1):]
    rename = lambda text: text.replace(f"time limit of {old:g} s", f"time limit of {new:g} s") \
        .replace(f"time budget of {old:g} s", f"time budget of {new:g} s") \
        if isinstance(text, str) else text
    case = copy.copy(case)
    case.fragment = rename(case.fragment)
    if case.outcomes:
        case.outcomes = {code: rename(text) for code, text in case.outcomes.items()}
    return case, args


class Completed:
    def __init__(self, returncode, stdout, stderr):
        self.returncode, self.stdout, self.stderr = returncode, stdout, stderr


def shadowlab_processes_under(pid):
    """Every live (not zombie) process whose parent chain reaches `pid`, or which is in a
    process group a child of `pid` led: the workers and anything they started."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        state, ppid, pgrp = fields[0], int(fields[1]), int(fields[2])
        if state != "Z" and (ppid == pid or pgrp in WORKER_GROUPS.get(pid, ())):
            found.append(int(entry))
    return found


WORKER_GROUPS = {}


def run_and_kill(exe, args, case, stdin, tmp):
    """Starts shadowlab, kills it after kill_after = (seconds, signal) as a harness's timeout
    would, and checks that no worker of it is left running a second later, and that its
    private folders (the snapshot, the shader cache) are gone: at once for a signal it can
    catch, with the next run after SIGKILL. Its $TMPDIR is the case's own, to see them."""
    seconds, sig = case.kill_after
    env = dict(case.env or os.environ)
    env["TMPDIR"] = os.path.join(tmp, "system-tmp")
    os.makedirs(env["TMPDIR"])
    # A shell's background job inherits SIGINT ignored: give shadowlab the default action, as
    # a harness's child has.
    p = subprocess.Popen([exe] + shlex.split(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         stdin=stdin, env=env,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    time.sleep(seconds)
    # Then until a worker runs (bounded): a slower build (AddressSanitizer's) may still be
    # calibrating when the fixed delay is over, and the case is about killing a run mid-grade.
    deadline = time.monotonic() + case.timeout / 2
    workers = shadowlab_processes_under(p.pid)
    while not workers and p.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
        workers = shadowlab_processes_under(p.pid)
    WORKER_GROUPS[p.pid] = set(workers)
    problems = [] if workers else ["no worker was running when the signal came"]
    p.send_signal(sig)
    out, err = p.communicate(timeout=case.timeout)
    deadline = time.monotonic() + 2
    alive = shadowlab_processes_under(p.pid)
    while alive and time.monotonic() < deadline:
        time.sleep(0.05)
        alive = shadowlab_processes_under(p.pid)
    if alive:
        problems.append(f"workers still running after the parent died: {alive}")
        for pid in alive:
            os.kill(pid, signal.SIGKILL)
    private = lambda: sorted(n for n in os.listdir(env["TMPDIR"]) if n.startswith("shadowlab-"))
    if "--shaders" in args and not private() and sig == signal.SIGKILL:
        problems.append("no private folder was there to outlive SIGKILL")
    if sig == signal.SIGKILL:  # nothing catches it: the next run removes what it left
        subprocess.run([exe, "check", "--stage", "phong", "--size", "80x60", "--shaders",
                        os.path.join(ROOT, "shaders_core")], env=env, capture_output=True,
                       timeout=60)
    if private():
        problems.append(f"private folders left in $TMPDIR: {private()}")
    return Completed(p.returncode, out.decode(errors="replace"), err.decode(errors="replace")), \
        problems


def is_png(path):
    try:
        with open(path, "rb") as f:
            return f.read(8) == b"\x89PNG\r\n\x1a\n"
    except OSError:
        return False


# ---- generated cases -------------------------------------------------------------------------

def scene_with_spheres(count, radius, spacing):
    """A floor and `count` spheres on a grid; the camera looks at them from above."""
    side = int(count ** 0.5) + 1
    objects = [{"type": "box", "center": [0, -0.05, 0], "size": [side * spacing + 1, 0.1,
                                                                  side * spacing + 1]}]
    for k in range(count):
        x, z = (k % side - side / 2) * spacing, (k // side - side / 2) * spacing
        objects.append({"type": "sphere", "center": [x, radius, z], "radius": radius})
    height = side * spacing + 3 * radius
    return {"camera": {"eye": [0, height, height], "at": [0, 0, 0],
                       "near": 0.1, "far": 1000},
            "light": {"position": [0.3, side * spacing + 2 * radius + 1, 0.2]}, "objects": objects}


def write_scene(name, scene):
    def setup(tmp, args):
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            json.dump(scene, f)
        return args.replace("{scene}", path)
    return setup


def mount_tiny_tmpfs(tmp, args):
    """A 4 KiB tmpfs (one page): the PNG does not fit, the write fails with ENOSPC."""
    disk = os.path.join(tmp, "full")
    os.mkdir(disk)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=4k", "tmpfs", disk],
                      capture_output=True).returncode != 0:
        raise Skip("cannot mount a tmpfs here (needs root)")
    return args.replace("{disk}", disk)


def unmount_and_check(tmp, p):
    disk = os.path.join(tmp, "full")
    left = os.listdir(disk)
    subprocess.run(["umount", disk])
    return [f"files left on the full disk: {left}"] if left else []


def limit_file_size():
    """RLIMIT_FSIZE of 16 KiB with SIGXFSZ ignored: writes past it fail with EFBIG."""
    resource.setrlimit(resource.RLIMIT_FSIZE, (16384, 16384))
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)


def dev_null_intact(tmp, p):
    import stat
    return [] if stat.S_ISCHR(os.stat("/dev/null").st_mode) else ["/dev/null was replaced!"]


class Skip(Exception):
    pass


# ---- shaders that outlast or crash their worker (generated: big, and Mesa-version specific) ----
ROOT = os.path.dirname(os.path.dirname(HERE))


def overlay(make_frag):
    """A setup: {overlay} = a student folder whose margin/lit.frag is ours changed by
    make_frag(text)."""
    def setup(tmp, args):
        with open(os.path.join(ROOT, "shaders_core", "margin", "lit.frag")) as f:
            ours = f.read()
        folder = os.path.join(tmp, "overlay", "margin")
        os.makedirs(folder)
        with open(os.path.join(folder, "lit.frag"), "w") as f:
            f.write(make_frag(ours))
        # Every other stage handed in too (a copy of ours), so that they are graded, not MISSING.
        for rel, data in other_stages("margin").items():
            os.makedirs(os.path.join(tmp, "overlay", os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(tmp, "overlay", rel), "wb") as f:
                f.write(data)
        return args.replace("{overlay}", os.path.join(tmp, "overlay"))
    return setup


def other_stages(but):
    """One shipped file of every core stage except `but` (relative path -> bytes): a submission
    that hands in every stage, so a check --all grades them all."""
    files = {}
    core = os.path.join(ROOT, "shaders_core")
    for stage in sorted(os.listdir(core)):
        if stage in ("common", "hud", but):
            continue
        first = sorted(os.listdir(os.path.join(core, stage)))[0]
        with open(os.path.join(core, stage, first), "rb") as f:
            files[f"{stage}/{first}"] = f.read()
    return files


def called_from_main(ours, function, call):
    """Our margin shader with `function` added and its value (times 1e-9) in the colour."""
    ours = ours.replace("void main()", function + "\nvoid main()")
    return ours.replace("fragColor = shade(", f"fragColor = 1e-9 * {call} + shade(")


def nested_loops(count):
    """`count` nested loops of two iterations: Mesa unrolls them, 2^count bodies (20: minutes)."""
    def make(ours):
        loops = "".join(f"{'    ' * (k + 1)}for (int i{k} = 0; i{k} < 2; i{k}++)\n"
                        for k in range(count))
        index = " + ".join(f"i{k}" for k in range(count))
        body = f"{'    ' * (count + 1)}s += sin(p.x * float({index}));\n"
        function = f"float busy(vec3 p)\n{{\n    float s = 0.0;\n{loops}{body}    return s;\n}}\n"
        return called_from_main(ours, function, "busy(worldPosition)")
    return make


def statement_chain(count):
    """`count` statements, each depending on the one before (Mesa 22.3: SIGSEGV from 50,000)."""
    def make(ours):
        # Ten bytes a statement on one line: 100,000 of them stay under the 1 MB file cap.
        function = ("float chain(float x)\n{\n" + "x=x*.5+.2;" * count + "\n" +
                    "    return x;\n}\n")
        return called_from_main(ours, function, "chain(worldPosition.x)")
    return make


def skip_in_asan_build(reason):
    """A setup: skip the case when the shadowlab under test is an AddressSanitizer build."""
    def setup(tmp, args):
        with open(EXE, "rb") as f:
            if b"__asan_init" in f.read():
                raise Skip(reason)
        return args
    return setup


# Under AddressSanitizer every stage runs slower than a short time limit, not only the slow shader.
release_speed = skip_in_asan_build(
    "an AddressSanitizer build grades a stage slower than this case's limit")
# ASan's allocator (redzones, quarantine) serves the driver's and glslang's allocations too: a
# compile that stays far inside the budget in a release build passes it there.
release_memory = skip_in_asan_build(
    "an AddressSanitizer build's allocator takes this compile past the memory budget")
# Mesa compiling a huge shader for minutes or crashing on it: the time is the driver's (not
# instrumented), and what our code does then (the worker's TIMEOUT and CRASH, the other stages
# graded, the report) runs under the sanitizers in 'a million-float array in a function' and
# the looping shaders. Under ASan these two took 811 s and 899 s of the corpus's 2817 s (load 20).
driver_stress = skip_in_asan_build(
    "a driver stress case: Mesa's time, not our code's (scripts/sanitizers.sh)")


def report_says(verdicts, graded, exit_code=2):
    """A check: {tmp}/report.json is valid JSON (strict UTF-8) with these verdicts (a tuple:
    any of them), `graded` other results judged (PASS or FAIL), `exit_code` in its summary
    (None: the command's own)."""
    def check(tmp, p):
        try:
            with open(os.path.join(tmp, "report.json"), encoding="utf-8") as f:
                report = json.load(f)
        except (OSError, ValueError) as e:
            return [f"no valid report: {e}"]
        got = {f"{r['stage']}/{r['tree']}": r["verdict"] for r in report_rows(report)}
        problems = [f"report: {key} is {got.get(key)}, expected {verdict}"
                    for key, verdict in verdicts.items()
                    if got.get(key) not in (verdict if isinstance(verdict, tuple) else (verdict,))]
        judged = sum(1 for key, v in got.items() if key not in verdicts and v in ("PASS", "FAIL"))
        if judged != graded:
            problems.append(f"report: {judged} other stages judged, expected {graded}: {got}")
        want = p.returncode if exit_code is None else exit_code
        if report["summary"]["exit_code"] != want:
            problems.append(f"report: exit_code {report['summary']['exit_code']}, expected {want}")
        return problems
    return check


def generated_cases():
    return [
        Case("huge scene: 5000 spheres", 2, "at most 4096 are allowed",
             "{R} --scene {scene}", setup=write_scene("s5000.json", scene_with_spheres(5000, 0.2, 0.5))),
        # The largest scene allowed renders (or errors cleanly) within the time limit.
        Case("huge scene: 4096 spheres", 0, "rendered hardware",
             "{R} --stage hardware --scene {scene}", timeout=120,
             setup=write_scene("s4096.json", scene_with_spheres(4095, 0.2, 0.5))),
        # check traces the largest scene's reference inside the default 30 s a stage (a loop over
        # every object per ray took about 2 minutes: exit 3). phong's lesson (no shadows at all)
        # holds on any scene, so the reference is all this case asks for.
        Case("huge scene: 4096 spheres, check at 640x480", 0, "checked 2: 2 passed",
             "check --stage phong --scene {scene} --size 640x480", timeout=120,
             setup=write_scene("s4096.json", scene_with_spheres(4095, 0.2, 0.5))),
        # 4096 large spheres close to the camera: each alone would be tessellated with 512
        # segments (130k vertices); the tessellation budget must keep memory bounded.
        Case("huge scene: 4096 big spheres near the camera", 0, "rendered phong",
             "render --size 1024x768 --repeat 0 --out {out} --scene {scene}", timeout=120,
             setup=write_scene("big.json", scene_with_spheres(4095, 5.0, 0.01))),
        Case("full disk (4 KiB tmpfs)", 2, "No space left on device",
             "render --size 640x480 --repeat 0 --out {disk}/out.png", setup=mount_tiny_tmpfs,
             check=unmount_and_check),
        Case("file size limit (RLIMIT_FSIZE)", 2, "File too large", "{R} --size 640x480",
             preexec=limit_file_size),
        Case("/dev/null survives --out /dev/null", 2, "is not a regular file",
             "render --repeat 0 --size 160x120 --out /dev/null", check=dev_null_intact),
        # Shaders whose fate is the driver's: Mesa 22.3 takes minutes on 20 nested loops and
        # crashes on 50,000 chained statements; Mesa 25 compiles the loops in seconds and times
        # out on the chain. What holds for the user whatever the driver: the command ends in
        # bounded time (the case's timeout), the stage is TIMEOUT or CRASH with its one line
        # and exit 2, or graded like any other with exit 0; the other seven are graded and the
        # report is written either way.
        Case("worker: 20 nested loops, check", None, None,
             # 160x120: the other stages well inside 5 s on a loaded machine (peers at 640x480
             # took over 5 s in a parallel ctest run).
             "check --all --glsl core --size 160x120 --shaders {overlay} --time-limit 5 "
             "--report {tmp}/report.json",
             timeout=90, one_line=False,
             setup=lambda tmp, args: overlay(nested_loops(20))(tmp, release_speed(tmp, args)),
             outcomes={2: "stage margin (core): used up its time budget of 5 s of CPU time "
                          "(--time-limit)", 0: "checked 8: 8 passed"},
             check=report_says({"margin/core": ("TIMEOUT", "PASS")}, 7, exit_code=None)),
        Case("worker: 20 nested loops, render", None, None,
             "{R} --stage margin --shaders {overlay} --time-limit 3", timeout=30,
             setup=lambda tmp, args: overlay(nested_loops(20))(tmp, release_memory(tmp, args)),
             outcomes={2: "stage margin (core): used up its time budget of 3 s of CPU time "
                          "(--time-limit)", 0: "rendered margin"}),
        # Where Mesa times out (25) rather than crashes (22.3) the stage takes its whole 60 s
        # and the other seven follow on a loaded machine: 240 s bounds the whole command.
        Case("worker: 50,000 chained statements", None, None,
             "check --all --glsl core --shaders {overlay} --time-limit 60 --report {tmp}/report.json",
             timeout=240, one_line=False, crashes=True,
             setup=lambda tmp, args: overlay(statement_chain(50000))(tmp, driver_stress(tmp, args)),
             outcomes={2: "stage margin (core): ", 0: "checked 8: 8 passed"},
             check=report_says({"margin/core": ("CRASH", "TIMEOUT", "PASS")}, 7, exit_code=None)),
        # Past the memory limit: inside Mesa a crash, in our code std::bad_alloc; both name it.
        Case("worker: 100,000 chained statements under --memory-limit 1024", None, None,
             "check --all --glsl core --shaders {overlay} --memory-limit 1024 --time-limit 60 "
             "--report {tmp}/report.json", timeout=240,
             setup=lambda tmp, args: overlay(statement_chain(100000))(tmp, driver_stress(tmp, args)),
             one_line=False, crashes=True,
             outcomes={2: "stage margin (core): ", 0: "checked 8: 8 passed"},
             check=report_says({"margin/core": ("CRASH", "TIMEOUT", "PASS")}, 7, exit_code=None)),
        # No submission: our own shaders run out of memory at the size asked for, which is the
        # machine's or the request's problem: NOT GRADED (exit 3, with what to raise), never a
        # student's 2.
        Case("worker: 8192x8192 under --memory-limit 1024", 3,
             "stage margin (core): ran out of memory within the memory limit of 1024 MB "
             "(--memory-limit); these are our shipped shaders: a platform problem",
             "check --stage margin --size 8192x8192 --memory-limit 1024 "
             "--report {tmp}/report.json", timeout=60,
             check=report_says({"margin/core": "NOT GRADED"}, 0, exit_code=3)),
    ]


# ---- hostile or unlucky student folders (issue 12): generated at test time ---------------------
# Every file is made in the case's temporary folder; big and special files (FIFOs, links to
# devices, a million-character line) are never stored in the repository.

ROOT = os.path.dirname(os.path.dirname(HERE))
SECRET = "db_password = S3CRET-7731-never-shown"


def shipped(relative):
    with open(os.path.join(ROOT, "shaders_core", relative), "rb") as f:
        return f.read()


def student(files, links=(), fifos=(), name="student"):
    """A setup writing an overlay folder {tmp}/NAME (files: relative -> bytes), plus symlinks
    (relative -> target, "{tmp}" expanded), FIFOs, and a secret at {tmp}/secret/app.conf."""
    def setup(tmp, args):
        secret = os.path.join(tmp, "secret")
        os.makedirs(secret, exist_ok=True)
        with open(os.path.join(secret, "app.conf"), "w") as f:
            f.write(SECRET + "\n")
        folder = os.path.join(tmp.encode(), name.encode() if isinstance(name, str) else name)
        for rel, data in files.items():
            path = os.path.join(folder, rel.encode())
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "wb") as f:
                f.write(data)
        for rel, target in dict(links).items():
            path = os.path.join(folder, rel.encode())
            os.makedirs(os.path.dirname(path), exist_ok=True)
            target = target.replace("{cwd-relative secret}", "/proc/self/cwd/" + os.path.relpath(
                os.path.join(tmp, "secret", "app.conf")))
            os.symlink(target.replace("{tmp}", tmp), path)
        for rel in fifos:
            path = os.path.join(folder, rel.encode())
            os.makedirs(os.path.dirname(path), exist_ok=True)
            os.mkfifo(path)
        return args.replace("{student}",
                            shlex.quote(folder.decode(errors="surrogateescape")))
    return setup


def lit_including(*includes):
    """phong/lit.frag with extra #include lines after the shipped one."""
    text = shipped("phong/lit.frag").decode()
    extra = "".join(f'#include "{i}"\n' for i in includes)
    return text.replace('#include "common/phong.glsl"\n', '#include "common/phong.glsl"\n' + extra)


def no_secret(tmp, p):
    """The secret's content appears nowhere: stdout, stderr, any file the run wrote."""
    problems = []
    if "S3CRET" in p.stdout + p.stderr:
        problems.append("the secret's content appears in the output")
    secret = os.path.join(tmp, "secret", "app.conf")
    for base, _, names in os.walk(tmp):
        if os.path.join(tmp, "secret") in base:
            continue
        for n in names:
            path = os.path.join(base, n)
            # A hard link the case planted is the secret itself, not something the run wrote.
            if os.path.isfile(path) and not os.path.islink(path) and not (
                    os.path.exists(secret) and os.path.samefile(path, secret)):
                with open(path, "rb") as f:
                    if b"S3CRET" in f.read():
                        problems.append(f"the secret's content appears in {path}")
    return problems


def report_valid(*expect):
    """The report {tmp}/report.json exists, is valid JSON, and each (stage, verdict) in expect
    is in it; plus no_secret and no control characters on stderr."""
    def check(tmp, p):
        problems = no_secret(tmp, p)
        if any(ord(c) < 32 and c not in "\n\t" for c in p.stdout + p.stderr):
            problems.append("stdout or stderr holds control characters")
        path = os.path.join(tmp, "report.json")
        try:
            with open(path, "rb") as f:
                report = json.loads(f.read().decode("utf-8"))
        except (OSError, ValueError) as e:
            return problems + [f"no valid report: {e}"]
        got = {(r["stage"], r["verdict"]) for r in report_rows(report)}
        problems += [f"report lacks {e} (has {sorted(got)})" for e in expect if e not in got]
        return problems
    return check


def unchanged(path_in_tmp, content):
    def check(tmp, p):
        with open(os.path.join(tmp, path_in_tmp), "rb") as f:
            return [] if f.read() == content else [f"{path_in_tmp} was written through"]
    return check


def plant_temp_links(tmp, args):
    """Symlinks at every name the old writer would have used (OUT.tmpPID for the next PIDs),
    pointing at a victim file, and OUT itself absent."""
    with open(os.path.join(tmp, "victim"), "wb") as f:
        f.write(b"victim")
    try:
        with open("/proc/sys/kernel/ns_last_pid") as f:
            last = int(f.read())
    except OSError:
        last = os.getpid()
    for pid in range(last + 1, last + 400):
        os.symlink(os.path.join(tmp, "victim"), os.path.join(tmp, f"out.png.tmp{pid}"))
    return args


def existing_file(name, content, mode=None, link_to=None):
    def setup(tmp, args):
        path = os.path.join(tmp, name)
        if link_to:
            target = os.path.join(tmp, link_to)
            with open(target, "wb") as f:
                f.write(content)
            os.symlink(target, path)
        else:
            with open(path, "wb") as f:
                f.write(content)
            if mode is not None:
                os.chmod(path, mode)
        return args
    return setup


def fifo_scene(tmp, args):
    os.mkfifo(os.path.join(tmp, "scene.json"))
    return args


def link_scene(tmp, args):
    os.symlink("/dev/zero", os.path.join(tmp, "scene.json"))
    return args


def report_folder(tmp, args):
    os.mkdir(os.path.join(tmp, "report.json"))
    return args


def nothing_in(folder):
    def check(tmp, p):
        path = os.path.join(tmp, folder)
        return [f"{folder} was created before the report path was checked"] if os.path.exists(
            path) else []
    return check


def bomb():
    """Six levels, each file including the next eight times: 8^6 expansions if unbounded."""
    files = {"phong/lit.frag": lit_including("common/b0.glsl").encode()}
    for k in range(6):
        files[f"common/b{k}.glsl"] = "".join(f'#include "common/b{k + 1}.glsl"\n'
                                             for _ in range(8)).encode()
    files["common/b6.glsl"] = b"float bombLeaf;\n"
    return files


def margin_int():
    text = shipped("margin/lit.frag").decode()
    text = text.replace("uniform float margin;", "uniform int margin;")
    return {"margin/lit.frag": text.replace("return margin;", "return float(margin);").encode()}


CHECK = "check --glsl core --size 160x120 --shaders {student} --report {tmp}/report.json"


def hostile_cases():
    lit = "phong/lit.frag"
    return [
        Case("FIFO include in the overlay", 2, "it is a FIFO, not a regular file",
             "{R} --shaders {student}", timeout=20, check=no_secret,
             setup=student({lit: lit_including("common/pipe.glsl").encode()},
                           fifos=["common/pipe.glsl"])),
        Case("the overlay's stage file is a FIFO", 2, "it is a FIFO, not a regular file",
             "{R} --shaders {student}", timeout=20, setup=student({}, fifos=[lit])),
        Case("the overlay's stage file is a symlink loop", 2, "cannot read shader file",
             "{R} --shaders {student}", timeout=20,
             setup=student({}, links={lit: "lit.frag"})),
        Case("the overlay's stage file links to /dev/zero", 2, "resolves outside the shader folders",
             "{R} --shaders {student}", timeout=20,
             setup=student({}, links={"phong/lit.vert": "{tmp}/../../dev/zero"})),
        Case("FIFO include through ../", 2, "a path that leaves the shader folder",
             "{R} --shaders {student}", timeout=20,
             setup=student({lit: lit_including("../pipe").encode()}, fifos=["../pipe"])),
        Case("FIFO scene", 2, "cannot read scene file: it is a FIFO", "{R} --scene {tmp}/scene.json",
             timeout=20, setup=fifo_scene),
        Case("scene symlinked to /dev/zero", 2, "cannot read scene file: it is a device",
             "{R} --scene {tmp}/scene.json", timeout=20, setup=link_scene),
        Case("include bomb", 2, "#include expansions (an include bomb?)",
             "{R} --shaders {student}", timeout=20, setup=student(bomb())),
        Case("include of ../../dev/zero", 2, "a path that leaves the shader folder",
             "{R} --shaders {student}", timeout=20,
             setup=student({lit: lit_including("../../../../../../../../dev/zero").encode()})),
        Case("include of a secret outside the folder", 2, "phong/lit.frag:5: #include \"../secret/app.conf\"",
             "{R} --shaders {student}", timeout=20, check=no_secret,
             setup=student({lit: lit_including("../secret/app.conf").encode()})),
        Case("include of a secret, check --all reports", 2, "a path that leaves the shader folder",
             CHECK + " --all", timeout=120,
             check=report_valid(("phong", "ERROR"), ("hardware", "PASS")),
             setup=student({lit: lit_including("../secret/app.conf").encode(),
                            **other_stages("phong")})),
        Case("another student's folder via ../", 2, "a path that leaves the shader folder",
             "{R} --shaders {student}", timeout=20,
             setup=student({lit: lit_including("../other/common/helper.glsl").encode(),
                            "../other/common/helper.glsl": b"float helper;\n"})),
        Case("a symlink in the overlay pointing out (stage file)", 2,
             "resolves outside the shader folders", "{R} --shaders {student}", timeout=20,
             check=no_secret, setup=student({}, links={lit: "{tmp}/secret/app.conf"})),
        Case("a symlinked include pointing out", 2, "resolves outside the shader folders",
             "{R} --shaders {student}", timeout=20, check=no_secret,
             setup=student({lit: lit_including("common/link.glsl").encode()},
                           links={"common/link.glsl": "{tmp}/secret/app.conf"})),
        Case("a symlink to a folder outside", 2, "resolves outside the shader folders",
             "{R} --shaders {student}", timeout=20, check=no_secret,
             setup=student({lit: lit_including("up/secret/app.conf").encode()},
                           links={"up": "{tmp}"})),
        Case("a line of 1,000,000 spaces", 0, "rendered phong", "{R} --shaders {student}",
             timeout=30,
             setup=student({lit: shipped(lit) + b" " * 1000000 + b"\n"})),
        Case("a 1,000,000-character include name", 2, "#include name of 1000000 characters",
             "{R} --shaders {student}", timeout=20,
             setup=student({lit: lit_including("a" * 1000000).encode()})),
        Case("a shader of 2 MB", 2, "at most 1048576 are allowed", "{R} --shaders {student}",
             timeout=20, setup=student({lit: shipped(lit) + b"// padding\n" * 200000})),
        Case("uniform int margin (render)", 2,
             "uniform 'margin' is declared int, but the stage sets a float",
             "{R} --stage margin --shaders {student}", timeout=20, setup=student(margin_int())),
        Case("uniform int margin (check --all: ERROR, later stages graded)", 2,
             "uniform 'margin' is declared int", CHECK + " --all", timeout=120,
             check=report_valid(("margin", "ERROR"), ("hardware", "PASS")),
             setup=student({**margin_int(), **other_stages("margin")})),
        Case("a vertex input the meshes do not supply", 2, "vertex input 'pos' is not supplied",
             "{R} --shaders {student}", timeout=20,
             setup=student({"phong/lit.vert": shipped("phong/lit.vert").replace(
                 b"position", b"pos")})),
        Case("#error with bytes that are not UTF-8", 2, "'#error' : bad", CHECK + " --stage phong",
             timeout=60, check=report_valid(("phong", "ERROR")),
             setup=student({lit: b"#version 330 core\n#error bad \xff\xfe\x1b[31m bytes\n"})),
        Case("a folder name that is not UTF-8", 2, "fragment shader did not compile",
             CHECK + " --stage phong --diff {tmp}/diff.png", timeout=60,
             check=report_valid(("phong", "ERROR")),
             setup=student({lit: b"#version 330 core\nvoid main() { oops }\n"}, name=b"st\xffu\x1bdent")),
        Case("symlinks planted at the old temporary names", 0, "rendered phong", "{R}",
             setup=plant_temp_links, check=unchanged("victim", b"victim")),
        Case("--out is a symlink", 2, "it is a symbolic link", "{R}",
             setup=existing_file("out.png", b"victim", link_to="victim"),
             check=unchanged("victim", b"victim")),
        Case("--out is read-only", 2, "it is read-only", "{R}",
             setup=existing_file("out.png", b"keep me", mode=0o444),
             check=unchanged("out.png", b"keep me")),
        Case("check --all --report DIR fails before any GL work", 2,
             "--report: cannot write", "check --all --report {tmp}/report.json --diff-dir {tmp}/diffs",
             timeout=10, setup=report_folder, check=nothing_in("diffs")),
    ]


# ---- more hostile folders, scenes, outputs and harnesses (issue 12, second round) -------------
# Each kind was tried against the first round's mechanisms; those that got through (a hard link
# to the secret, a folder at a stage file's name, a newline in a folder's name splitting the
# message, a draw-time GL error from a student's shader ending check without a report, a full
# diff folder ending it likewise) are fixed in the mechanism, not per case.

def exactly_one_line(tmp, p):
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    return [] if len(lines) == 1 else [f"stderr has {len(lines)} lines, expected one"]


def both(*checks):
    def check(tmp, p):
        return [problem for c in checks for problem in c(tmp, p)]
    return check


def secret_at_stdin(tmp):
    return open(os.path.join(tmp, "secret", "app.conf"), "rb")


def with_secret(setup):
    """A setup that first writes the secret (for cases whose folder is made by `setup`)."""
    def wrapped(tmp, args):
        os.makedirs(os.path.join(tmp, "secret"), exist_ok=True)
        with open(os.path.join(tmp, "secret", "app.conf"), "w") as f:
            f.write(SECRET + "\n")
        return setup(tmp, args)
    return wrapped


def hard_links(*relatives):
    """After student(): each relative path in the overlay a hard link to the secret."""
    def setup(tmp, args):
        for rel in relatives:
            path = os.path.join(tmp, "student", rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            os.link(os.path.join(tmp, "secret", "app.conf"), path)
        return args
    return setup


def chain(*setups):
    def setup(tmp, args):
        for s in setups:
            args = s(tmp, args)
        return args
    return setup


def folder_at(relative):
    def setup(tmp, args):
        os.makedirs(os.path.join(tmp, "student", relative))
        return args
    return setup


def linked_overlay(tmp, args):
    """{student} given through a symlink to the real folder."""
    os.symlink(os.path.join(tmp, "student"), os.path.join(tmp, "link"))
    return args.replace(os.path.join(tmp, "student"), os.path.join(tmp, "link"))


def margin_with(function, call):
    text = shipped("margin/lit.frag").decode()
    text = text.replace("void main()", function + "\nvoid main()")
    return {"margin/lit.frag": text.replace("fragColor = shade(",
                                            f"fragColor = 1e-9 * {call} + shade(").encode()}


# A loop too long to unroll: it runs. llvmpipe ends a shader's loops after 65,535 iterations in
# all, so each iteration does 200 sines: 13 million a pixel or vertex, minutes for a frame.
BUSY = ("{ float s = x; for (int i = 0; i < 2000000000; i++) { " + "s = sin(s + y); " * 200 +
        "} return s; }")
RUNTIME_LOOP = margin_with("float busy(float x, float y) " + BUSY,
                           "busy(worldPosition.x, worldPosition.y)")
# A million floats in a function: Mesa's compiler takes gigabytes or minutes, never a result.
GIANT_ARRAY = margin_with("float big(vec3 p) { float a[1000000]; for (int i = 0; i < 1000000; "
                          "i++) a[i] = p.x * float(i); return a[int(p.y)]; }", "big(worldPosition)")


def vertex_loop():
    text = shipped("phong/lit.vert").decode()
    text = text.replace("void main()", "float spin(float x, float y) " + BUSY + "\nvoid main()")
    return {"phong/lit.vert": text.replace("gl_Position = ", "gl_Position = 1e-9 * spin("
                                           "position.x, position.y) * vec4(1.0) + ", 1).encode()}


def two_sampler_types():
    """Two samplers of different types on texture unit 0: GL_INVALID_OPERATION at draw time
    (refused by us before the draw, naming both, as for a rule Mesa waives)."""
    text = shipped("phong/lit.frag").decode()
    text = text.replace("out vec4 fragColor;", "out vec4 fragColor;\nuniform sampler2D flat2d;\n"
                        "uniform sampler3D deep3d;", 1)
    text = text.replace("fragColor = ", "fragColor = 1e-9 * (texture(flat2d, vec2(0.5)) + "
                        "texture(deep3d, vec3(0.5))) + ", 1)
    return {"phong/lit.frag": text.encode()}


def many_files(count):
    """`count` small files in the overlay (common/fNNNN.glsl), a chain of 200 of them included."""
    files = {f"common/f{k:05d}.glsl": f"float f{k};\n".encode() for k in range(count)}
    files["common/chain.glsl"] = "".join(f'#include "common/f{k:05d}.glsl"\n'
                                         for k in range(200)).encode()
    files["phong/lit.frag"] = lit_including("common/chain.glsl").encode()
    return files


def growing_scene(tmp, args):
    """A scene file a writer keeps appending to while shadowlab reads it."""
    import threading
    path = os.path.join(tmp, "grow.json")
    with open(path, "w") as f:
        f.write('{"objects": [')
    stop = threading.Event()

    def grow():
        with open(path, "a") as f:
            while not stop.is_set() and f.tell() < 64 << 20:
                f.write('{"type": "sphere", "center": [0, 0, 0], "radius": 1},' * 1000)
                f.flush()
    thread = threading.Thread(target=grow, daemon=True)
    thread.start()
    time.sleep(0.2)
    GROWERS.append((stop, thread))
    return args.replace("{scene}", path)


GROWERS = []


def stop_growing(tmp, p):
    for stop, thread in GROWERS:
        stop.set()
        thread.join()
    GROWERS.clear()
    return []


def deep_json(levels):
    def setup(tmp, args):
        path = os.path.join(tmp, "deep.json")
        with open(path, "w") as f:
            f.write('{"camera": ' + "[" * levels + "]" * levels + "}")
        return args.replace("{scene}", path)
    return setup


def diff_dir_with(kind):
    """{tmp}/diffs with the first diff image's name taken: a symlink to a victim, or dangling."""
    def setup(tmp, args):
        diffs = os.path.join(tmp, "diffs")
        os.mkdir(diffs)
        with open(os.path.join(tmp, "victim"), "wb") as f:
            f.write(b"victim")
        target = os.path.join(tmp, "victim") if kind == "link" else "/nonexistent/victim"
        os.symlink(target, os.path.join(diffs, "phong-core-lecture.png"))
        return args
    return setup


def diff_dir_linked(tmp, args):
    os.mkdir(os.path.join(tmp, "real"))
    os.symlink(os.path.join(tmp, "real"), os.path.join(tmp, "diffs"))
    return args


def images_in(folder, count):
    def check(tmp, p):
        names = sorted(os.listdir(os.path.join(tmp, folder)))
        bad = [n for n in names if not is_png(os.path.join(tmp, folder, n))]
        if len(names) != count or bad:
            return [f"{folder} holds {names}, expected {count} PNG images"]
        return []
    return check


def full_disk_for(kib):
    """A tmpfs of `kib` KiB at {disk}: a report of 10 KB does not fit in 4, diff images of 4 KB
    one by one fill 8."""
    def setup(tmp, args):
        disk = os.path.join(tmp, "full")
        os.mkdir(disk)
        if subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={kib}k", "tmpfs", disk],
                          capture_output=True).returncode != 0:
            raise Skip("cannot mount a tmpfs here (needs root)")
        return args.replace("{disk}", disk)
    return setup


def report_json_says(verdicts, exit_code, name="report.json"):
    """{tmp}/NAME is valid strict-UTF-8 JSON, each stage/tree has its verdict (every row of it),
    and its summary's exit code."""
    def check(tmp, p):
        try:
            with open(os.path.join(tmp, name), "rb") as f:
                report = json.loads(f.read().decode("utf-8"))
        except (OSError, ValueError) as e:
            return [f"no valid report: {e}"]
        problems = []
        for key, verdict in verdicts.items():
            got = {r["verdict"] for r in report_rows(report) if f"{r['stage']}/{r['tree']}" == key}
            if got != {verdict}:
                problems.append(f"report: {key} is {sorted(got)}, expected {verdict}")
        if report["summary"]["exit_code"] != exit_code:
            problems.append(f"report: exit_code {report['summary']['exit_code']}, "
                            f"expected {exit_code}")
        return problems
    return check


def no_report(tmp, p):
    return ["a report was written by a killed run"] if os.path.exists(
        os.path.join(tmp, "report.json")) else []


def parallel_agree(runs):
    """Runs `runs` of the same check at once and compares every verdict and figure with theirs
    and with the case's own run (alone)."""
    def check(tmp, p):
        reports = []
        procs = []
        for k in range(runs):
            args = [EXE, "check", "--all", "--glsl", "core", "--size", "160x120", "--shaders",
                    os.path.join(tmp, "student"), "--report", os.path.join(tmp, f"r{k}.json")]
            procs.append(subprocess.Popen(args, stdout=subprocess.DEVNULL,
                                          stderr=subprocess.DEVNULL))
        for proc in procs:
            proc.wait(timeout=TIMEOUT * 2)
        for k in range(runs):
            with open(os.path.join(tmp, f"r{k}.json")) as f:
                report = json.load(f)
            reports.append([(r["stage"], r["tree"], r["view"], r["verdict"],
                             json.dumps(r.get("figures"), sort_keys=True))
                            for r in report_rows(report)])
        with open(os.path.join(tmp, "report.json")) as f:
            first = json.load(f)
        reports.append([(r["stage"], r["tree"], r["view"], r["verdict"],
                         json.dumps(r.get("figures"), sort_keys=True)) for r in report_rows(first)])
        return [] if all(r == reports[0] for r in reports) else [
            "parallel check runs disagree on verdicts or figures"]
    return check


def attack_cases():
    lit = "phong/lit.frag"
    R = "{R} --shaders {student}"
    sandbox = "a path that leaves the shader folder"
    outside = "resolves outside the shader folders"
    cases = [
        # Include names that climb out however they are spelled.
        Case("#include \"./../secret\"", 2, sandbox, R, timeout=20, check=no_secret,
             setup=student({lit: lit_including("./../secret/app.conf").encode()})),
        Case("#include \"common/../../secret\"", 2, sandbox, R, timeout=20, check=no_secret,
             setup=student({lit: lit_including("common/../../secret/app.conf").encode()})),
        Case("#include \"common//../..//secret\"", 2, sandbox, R, timeout=20, check=no_secret,
             setup=student({lit: lit_including("common//../..//secret/app.conf").encode()})),
        Case("#include of the overlay folder itself (\".\")", 2, sandbox, R, timeout=20,
             setup=student({lit: lit_including(".").encode()})),
        Case("#include of a folder (\"common/.\")", 2, "it is a folder, not a regular file", R,
             timeout=20, setup=student({lit: lit_including("common/.").encode()})),
        Case("#include with tabs and spaces around every part", 2, sandbox, R, timeout=20,
             check=no_secret, setup=student({lit: shipped(lit).replace(
                 b'#include "common/phong.glsl"\n',
                 b'#include "common/phong.glsl"\n \t#\t include \t"../secret/app.conf"\t \r\n')})),
        # The preprocessor expands before the compiler sees comments or #if: still refused.
        Case("#include inside a block comment", 2, sandbox, R, timeout=20, check=no_secret,
             setup=student({lit: shipped(lit).replace(b"void main", b'/*\n#include '
                                                      b'"../secret/app.conf"\n*/\nvoid main')})),
        Case("#include inside #if 0", 2, sandbox, R, timeout=20, check=no_secret,
             setup=student({lit: shipped(lit).replace(b"void main", b'#if 0\n#include '
                                                      b'"../secret/app.conf"\n#endif\nvoid main')})),
        # Links that end outside, however indirectly.
        Case("a symlink chain inside the overlay that ends outside", 2, outside, R, timeout=20,
             check=no_secret, setup=student({lit: lit_including("common/l1.glsl").encode()},
                                            links={"common/l1.glsl": "l2", "common/l2": "l3",
                                                   "common/l3": "{tmp}/secret/app.conf"})),
        Case("a symlink through /proc/self/root", 2, outside, R, timeout=20, check=no_secret,
             setup=student({lit: lit_including("common/r.glsl").encode()},
                           links={"common/r.glsl": "/proc/self/root{tmp}/secret/app.conf"})),
        Case("a symlink through /proc/self/cwd", 2, outside, R, timeout=20, check=no_secret,
             setup=student({lit: lit_including("common/c.glsl").encode()},
                           links={"common/c.glsl": "{cwd-relative secret}"})),
        Case("a symlink to /proc/self/fd/0 (the secret open as stdin)", 2, outside, R,
             timeout=20, check=no_secret, stdin=secret_at_stdin,
             setup=student({lit: lit_including("common/fd.glsl").encode()},
                           links={"common/fd.glsl": "/proc/self/fd/0"})),
        Case("the overlay given through a symlink, #include ../secret", 2, sandbox, R,
             timeout=20, check=no_secret,
             setup=chain(student({lit: lit_including("../secret/app.conf").encode()}),
                         linked_overlay)),
        # A hard link is the secret under a name inside the folder: refused by its link count.
        Case("an include that is a hard link to a file outside", 2, "has 2 hard links", R,
             timeout=20, check=no_secret,
             setup=chain(student({lit: lit_including("common/h.glsl").encode()}),
                         hard_links("common/h.glsl"))),
        Case("a stage file that is a hard link to a file outside", 2, "has 2 hard links", R,
             timeout=20, check=no_secret, setup=chain(student({}), hard_links(lit))),
        Case("a stage file that is a folder", 2, "lit.frag: cannot read shader file: it is a "
             "folder", R, timeout=20, setup=chain(student({}), folder_at(lit))),
        # Names that would break the one-line message or the terminal.
        Case("a newline and an ESC in the overlay folder's name", 2, "cannot read shader file",
             R, timeout=20, check=both(exactly_one_line, report_valid_or_none),
             setup=student({lit: lit_including("common/missing.glsl").encode()},
                           name=b"stu\ndent\x1b[2J")),
        Case("an include name with an ESC and bytes that are not UTF-8", 2,
             "cannot read shader file (missing?)", R, timeout=20, check=exactly_one_line,
             setup=student({lit: shipped(lit).replace(
                 b'#include "common/phong.glsl"\n',
                 b'#include "common/phong.glsl"\n#include "common/a\x1b[31m\xff.glsl"\n')})),
        # `#line 1 1` would make the compiler blame source string 1 (our common/phong.glsl).
        Case("#line spoofing another source string", 2, "fragment shader did not compile", R,
             timeout=20, check=errors_named_in("student/phong/lit.frag:", "common/phong.glsl:"),
             setup=student({lit: shipped(lit).replace(b"void main",
                                                      b"#line 1 1\nfoo bar;\nvoid main")})),
        Case("5,000 small files, a chain of 200 includes", 0, "rendered phong", R, timeout=30,
             setup=student(many_files(5000))),
        # Shaders that hang or balloon when they RUN, not when they compile.
        Case("a fragment shader looping 2e9 times a pixel (render)", 2,
             "stage margin (core): used up its time budget of 3 s of CPU time (--time-limit)",
             "{R} --stage margin --shaders {student} --time-limit 3", timeout=30,
             setup=student(RUNTIME_LOOP)),
        Case("a fragment shader looping 2e9 times a pixel (check)", 2,
             "stage margin (core): used up its time budget of 3 s of CPU time (--time-limit)",
             CHECK + " --stage margin --time-limit 3", timeout=30, one_line=False,
             setup=chain(release_speed, student(RUNTIME_LOOP)),
             check=report_json_says({"margin/core": "TIMEOUT"}, 2)),
        Case("a vertex shader looping 2e9 times a vertex", 2,
             "stage phong (core): used up its time budget of 3 s of CPU time (--time-limit)",
             "{R} --shaders {student} --time-limit 3", timeout=30,
             setup=lambda tmp, args: student(vertex_loop())(tmp, release_speed(tmp, args))),
        Case("a million-float array in a function", 2, "stage margin (core): ",
             CHECK + " --stage margin --time-limit 3 --memory-limit 1024", timeout=30,
             one_line=False, crashes=True, setup=student(GIANT_ARRAY),
             check=lambda tmp, p: [] if re.search(r"\b(TIMEOUT|CRASH)\b", p.stdout) else [
                 "margin is neither TIMEOUT nor CRASH"]),
        # A GL rule broken at draw time is the shader's fault, and check goes on.
        Case("two sampler types on one texture unit (render)", 2,
             "sampler2D 'flat2d' and sampler3D 'deep3d' both read texture unit 0", R, timeout=20,
             check=exactly_one_line, setup=student(two_sampler_types())),
        Case("two sampler types on one texture unit (check --all)", 2,
             "sampler2D 'flat2d' and sampler3D 'deep3d' both read texture unit 0", CHECK + " --all",
             timeout=120, one_line=False,
             setup=student({**two_sampler_types(), **other_stages("phong")}),
             check=both(report_valid(("phong", "ERROR"), ("hardware", "PASS")),
                        report_json_says({"phong/core": "ERROR"}, 2))),
        # Scenes that are not plain files, or not plain JSON.
        Case("scene /proc/self/environ (a regular file of size 0 that streams)", 2,
             "scene error: /proc/self/environ: not valid JSON",
             "{R} --scene /proc/self/environ", timeout=20),
        Case("scene /dev/stdin, a pipe", 2, "it is a FIFO, not a regular file",
             "{R} --scene /dev/stdin", timeout=20, stdin=lambda tmp: subprocess.PIPE),
        Case("scene a folder", 2, "cannot read scene file: it is a folder", "{R} --scene {tmp}",
             timeout=20),
        Case("scene growing while it is read", 2, "at most 16777216 are allowed",
             "{R} --scene {scene}", timeout=30, setup=growing_scene, check=stop_growing),
        Case("scene nested 1,000,000 levels deep inside a field", 2, "/camera: must be an object",
             "{R} --scene {scene}", timeout=30, setup=deep_json(1000000)),
        Case("scene with NaN", 2, "not valid JSON", "{R} --scene {scene}", timeout=20,
             setup=lambda tmp, args: write_raw_scene(tmp, args, "NaN")),
        Case("scene with Infinity", 2, "not valid JSON", "{R} --scene {scene}", timeout=20,
             setup=lambda tmp, args: write_raw_scene(tmp, args, "Infinity")),
        # Outputs: links inside --diff-dir refused before any GL work, never written through.
        Case("--diff-dir holding a symlink at an image's name", 2, "it is a symbolic link",
             "check --stage phong --glsl core --size 160x120 --diff-dir {tmp}/diffs "
             "--report {tmp}/report.json", timeout=20, setup=diff_dir_with("link"),
             check=both(unchanged("victim", b"victim"), no_file("report.json"))),
        Case("--diff-dir holding a dangling symlink at an image's name", 2,
             "it is a symbolic link", "check --stage phong --glsl core --size 160x120 "
             "--diff-dir {tmp}/diffs", timeout=20, setup=diff_dir_with("dangling"),
             check=lambda tmp, p: [] if not os.path.exists("/nonexistent/victim") else [
                 "written through a dangling link"]),
        Case("--diff-dir a symlink to a folder (the grader's own choice: followed)", 0, "",
             "check --stage phong --glsl core --size 160x120 --diff-dir {tmp}/diffs",
             timeout=30, setup=diff_dir_linked, check=images_in("real", 6)),  # 5 views + displaced
        Case("--report on a full disk, written at the end", 2,
             "--report: cannot write", "check --stage phong --glsl core --size 160x120 "
             "--report {disk}/report.json --junit {disk}/junit.xml", timeout=30,
             setup=full_disk_for(4), check=unmount_and_check),
        Case("--diff-dir on a full disk: a note per image, the report still written", 0,
             "no diff image: cannot write", "check --stage phong --glsl core --size 160x120 "
             "--diff-dir {disk}/diffs --report {tmp}/report.json", timeout=30, one_line=False,
             setup=full_disk_for(8),
             check=both(report_json_says({"phong/core": "PASS"}, 0), unmount_keeping_images)),
        # A grading harness's timeout kills shadowlab: its workers die too, no report is left.
    ]
    for sig in (signal.SIGTERM, signal.SIGKILL, signal.SIGINT):
        cases.append(Case(f"shadowlab killed by {sig.name} during check --all", -sig, "",
                          "check --all --glsl core --report {tmp}/report.json "
                          "--diff-dir {tmp}/diffs --shaders " + os.path.join(ROOT, "shaders_core"),
                          timeout=30, kill_after=(2.5, sig),
                          check=no_report))
    cases.append(Case("check --all of one submission: 3 at once agree with one alone", 2, "",
                      CHECK + " --all", timeout=120, one_line=False,
                      setup=student(margin_int()), check=parallel_agree(3)))
    return cases


def write_raw_scene(tmp, args, number):
    with open(os.path.join(ROOT, "scenes", "slides.json")) as f:
        text = f.read()
    path = os.path.join(tmp, "raw.json")
    with open(path, "w") as f:
        f.write(re.sub(r'"fovy":\s*[0-9.]+', f'"fovy": {number}', text, count=1))
    return args.replace("{scene}", path)


def unmount_keeping_images(tmp, p):
    """The images that fitted are whole PNGs, nothing else (no temporary) is on the disk."""
    disk = os.path.join(tmp, "full")
    left = [os.path.join(base, n) for base, _, names in os.walk(disk) for n in names]
    problems = [f"{path} is not a whole PNG" for path in left if not is_png(path)]
    subprocess.run(["umount", disk])
    return problems


def errors_named_in(expected, never):
    """The compiler's error lines name `expected`, never `never`."""
    def check(tmp, p):
        errors = [l for l in p.stderr.splitlines() if "error:" in l and "shader error" not in l]
        problems = [f"an error line names {never}: {l}" for l in errors if never in l]
        if not any(expected in l for l in errors):
            problems.append(f"no error line names {expected}")
        return problems
    return check


def no_file(name):
    def check(tmp, p):
        return [f"{name} was written"] if os.path.exists(os.path.join(tmp, name)) else []
    return check


def report_valid_or_none(tmp, p):
    return [] if not os.path.exists(os.path.join(tmp, "report.json")) else report_valid()(tmp, p)


EXE = None  # the shadowlab under test


def main():
    global EXE, TIME_SCALE, DEFAULT_TIME_LIMIT
    exe = EXE = sys.argv[1]
    only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else ""
    if "--time-scale" in sys.argv:
        TIME_SCALE = float(sys.argv[sys.argv.index("--time-scale") + 1])
        DEFAULT_TIME_LIMIT = default_time_limit(exe)
        print(f"run_cases: time scale {TIME_SCALE:g}: given limits scaled; the worker default "
              + ("is auto (calibrated on our shaders in this build): kept" if DEFAULT_TIME_LIMIT is None
                 else f"{DEFAULT_TIME_LIMIT:g} s -> {DEFAULT_TIME_LIMIT * TIME_SCALE:g} s"))
    kinds = [("in cases.txt", parse_cases(os.path.join(HERE, "cases.txt"))),
             ("generated", generated_cases()), ("hostile", hostile_cases()),
             ("attack", attack_cases()), ("intake", intake_cases(sys.modules[__name__]))]
    cases = [case for _, some in kinds for case in some]
    if "--list" in sys.argv:  # the corpus without running it (docs/robustness.md states the counts)
        for case in cases:
            print(case.name)
        print(f"{len(cases)} cases (" + ", ".join(f"{len(some)} {kind}" for kind, some in kinds) + ")")
        return 0
    passed = failed = skipped = 0
    for case in cases:
        if only and only not in case.name and only not in case.args:
            continue
        try:
            problems, args = run(exe, case)
        except Skip as e:
            print(f"SKIP {case.name}: {e}")
            skipped += 1
            continue
        if problems:
            failed += 1
            print(f"FAIL {case.name}: shadowlab {args}")
            for problem in problems:
                print(f"     {problem}")
        else:
            passed += 1
    if "--times" in sys.argv:  # how long each case took, slowest first
        for name, seconds in sorted(CASE_SECONDS.items(), key=lambda item: -item[1]):
            print(f"{seconds:6.1f} s  {name}")
    print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
