#!/usr/bin/env bash
# The Gradescope zip holds what its build reads. `release --gradescope` (this build's program)
# writes autograder.zip; it must hold setup.sh, run_autograder, the assignment and exactly the
# files of the build's source_kit.txt (what configure and compile read: cmake/source_kit.py).
# Unpacked alone, its sources configure as its setup.sh does (BUILD_TESTING=OFF), generate the
# GL loader and preprocess every translation unit of the program (every header is found).
# Compiling them all is CI's part: scripts/gradescope_suite.sh runs setup.sh in a fresh chroot.
#   autograder_zip.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "autograder zip test: FAIL: $*"; exit 1; }
"$build/shadowlab" release --assignment "$src/assignments/lab4.json" --gradescope \
  --out "$tmp/release" >/dev/null || fail "release --gradescope failed"
python3 - "$tmp/release/autograder.zip" "$tmp/unpacked" "$build/source_kit.txt" <<'PY' || fail "the zip's content"
import os, stat, sys, zipfile
zip_path, dest, kit_path = sys.argv[1:4]
z = zipfile.ZipFile(zip_path)
names = set(z.namelist())
kit = {"shadowlab/" + l for l in open(kit_path).read().splitlines() if l}
want = kit | {"setup.sh", "run_autograder", "assignment.json"}
for what, paths in (("missing from the zip", want - names), ("in the zip, not in the kit", names - want)):
    if paths:
        sys.exit(f"{what}: {sorted(paths)[:10]}")
for must in ("shadowlab/CMakeLists.txt", "shadowlab/cmake/glad.cmake", "shadowlab/scripts/deps.sh",
             "shadowlab/src/app/main.cpp", "shadowlab/src/stages/expectations.json"):
    if must not in names:
        sys.exit(f"{must} is not in the zip")
for info in z.infolist():
    path = z.extract(info, dest)
    os.chmod(path, (info.external_attr >> 16) & 0o777 or 0o644)
for script in ("setup.sh", "run_autograder"):
    if not os.stat(os.path.join(dest, script)).st_mode & stat.S_IXUSR:
        sys.exit(f"{script} is not executable")
print(f"autograder zip: {len(names)} files, the kit's {len(kit)} among them")
PY
cmake -S "$tmp/unpacked/shadowlab" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
  >"$tmp/configure.log" 2>&1 || { tail -20 "$tmp/configure.log"; fail "the unpacked sources do not configure"; }
cmake --build "$tmp/build" --target glad >"$tmp/glad.log" 2>&1 ||
  { tail -20 "$tmp/glad.log"; fail "the unpacked sources do not generate the GL loader"; }
# Every compile command of the program, run as the preprocessor only: a missing header fails.
python3 - "$tmp/build/compile_commands.json" "$tmp/unpacked/shadowlab" <<'PY' || fail "a translation unit does not preprocess"
import json, os, shlex, subprocess, sys
from concurrent.futures import ThreadPoolExecutor
commands = json.load(open(sys.argv[1]))
root = os.path.realpath(sys.argv[2])
if not commands:
    sys.exit("compile_commands.json lists nothing")

def preprocess(entry):
    words = shlex.split(entry["command"])
    out = []
    skip = False
    for w in words:
        if skip:
            skip = False
        elif w in ("-o", "-MF", "-MT"):
            skip = True
        elif w not in ("-c", "-MD"):
            out.append(w)
    p = subprocess.run(out + ["-E", "-o", os.devnull], cwd=entry["directory"],
                       capture_output=True, text=True)
    return entry["file"], p.returncode, p.stderr

failed = 0
with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
    for source, code, err in pool.map(preprocess, commands):
        if not os.path.realpath(source).startswith(root + os.sep) and "glad" not in source:
            sys.exit(f"{source} is outside the unpacked sources")
        if code:
            failed += 1
            print(f"{source}: {err.strip()[:400]}")
print(f"autograder zip: {len(commands) - failed} of {len(commands)} translation units preprocess")
sys.exit(1 if failed else 0)
PY
echo "autograder zip test: ok (configures alone, every translation unit preprocesses)"
