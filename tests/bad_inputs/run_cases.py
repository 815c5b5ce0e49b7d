#!/usr/bin/env python3
"""Runs the bad-input corpus (cases.txt plus the generated cases below) against the shadowlab
executable and reports every failure, then a closing line `N passed, M failed`.

usage: run_cases.py SHADOWLAB_EXE [--only TEXT]
"""
import json
import os
import resource
import shlex
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TIMEOUT = 60  # seconds per command: a hang is a failure, not a stuck CI
SMALL = "render --repeat 0 --out {out}"  # and --size 160x120 unless the case gives a size


class Case:
    def __init__(self, name, expect, fragment, args, timeout=TIMEOUT, setup=None, check=None,
                 preexec=None):
        self.name, self.expect, self.fragment, self.args = name, expect, fragment, args
        self.timeout, self.setup, self.check, self.preexec = timeout, setup, check, preexec


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
    tmp = tempfile.mkdtemp(prefix="sl-bad-")
    out = os.path.join(tmp, "out.png")
    args = case.args
    if "{R}" in args:
        args = args.replace("{R}", SMALL + ("" if "--size" in args else " --size 160x120"))
    for key, value in (("{out}", out), ("{tmp}", tmp), ("{here}", HERE)):
        args = args.replace(key, value)
    if case.setup:
        args = case.setup(tmp, args)
    target = out_path(args)
    before = os.listdir(tmp)
    start = time.monotonic()
    try:
        p = subprocess.run([exe] + shlex.split(args), capture_output=True, text=True,
                           errors="replace", timeout=case.timeout, preexec_fn=case.preexec)
    except subprocess.TimeoutExpired:
        return [f"did not finish within {case.timeout} s (hang?)"], args
    seconds = time.monotonic() - start
    problems = []
    if p.returncode < 0:
        problems.append(f"killed by signal {-p.returncode} (crash)")
    elif p.returncode != case.expect:
        problems.append(f"exit code {p.returncode}, expected {case.expect}")
    text = p.stderr if case.expect != 0 else p.stdout + p.stderr
    if case.fragment and case.fragment not in text:
        problems.append(f"output lacks '{case.fragment}'")
    for bad in ("runtime error:", "AddressSanitizer", "LeakSanitizer", "terminate called"):
        if bad in p.stderr:
            problems.append(f"stderr reports '{bad}'")
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    if case.expect != 0:
        if not lines or not lines[0].startswith("shadowlab:"):
            problems.append("stderr's first line does not start with 'shadowlab:'")
        elif len(lines) > 1 and "shader error:" not in lines[0]:
            problems.append(f"stderr has {len(lines)} lines, expected one")
        if target and target.startswith(tmp) and os.path.isfile(target):
            problems.append(f"a file was left at {target}")
    elif target and not is_png(target):
        problems.append(f"{target} is not a PNG")
    left = [f for f in os.listdir(tmp) if ".tmp" in f and f not in before]
    if left:
        problems.append(f"temporary files left behind: {left}")
    if case.check:
        problems += case.check(tmp, p)
    if problems:
        problems.append(f"stderr: {p.stderr.strip()[:600]!r} ({seconds:.1f} s)")
    subprocess.run(["rm", "-rf", tmp])
    return problems, args


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


def generated_cases():
    return [
        Case("huge scene: 5000 spheres", 2, "at most 4096 are allowed",
             "{R} --scene {scene}", setup=write_scene("s5000.json", scene_with_spheres(5000, 0.2, 0.5))),
        # The largest scene allowed renders (or errors cleanly) within the time limit.
        Case("huge scene: 4096 spheres", 0, "rendered hardware",
             "{R} --stage hardware --scene {scene}", timeout=120,
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
    ]


def main():
    exe = sys.argv[1]
    only = sys.argv[3] if len(sys.argv) > 3 and sys.argv[2] == "--only" else ""
    cases = parse_cases(os.path.join(HERE, "cases.txt")) + generated_cases()
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
    print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
