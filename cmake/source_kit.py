#!/usr/bin/env python3
"""Writes the source kit's list (BUILD/source_kit.txt): every file of the source tree that
building the program read, one relative path a line, sorted. The Gradescope zip (`release
--gradescope`, src/course/autograder.cpp) holds exactly these files, and `cmake --install` ships
them, so an installed copy writes the same zip.

Derived from what the build itself recorded, so the list cannot drift from the build:
  - configure: every CMake file the configure read (the generator's own list of the files that
    make it configure again: CMakeFiles/Makefile.cmake, or build.ninja's RERUN_CMAKE inputs);
  - compile: every source and header the compiler read for the program's objects (the
    dependency files gcc/clang write with -MD; Ninja keeps them in its log: `ninja -t deps`);
  - --also: what the program reads at run time (the install's data) and what the zip's
    setup.sh runs (scripts/deps.sh): paths, folders taken whole.
Files outside the source tree (system headers, the generated GL loader) and under --exclude
(the tests/ folder, which the zip configures without: BUILD_TESTING=OFF) are left out.

usage: source_kit.py --source DIR --build DIR --generator NAME --make-program EXE
                     --objects FILE --out FILE [--exclude DIR]... --also PATH...
"""
import argparse
import os
import re
import subprocess
import sys


def fail(message):
    sys.exit("source_kit: " + message)


def makefile_configure_inputs(build):
    text = open(os.path.join(build, "CMakeFiles", "Makefile.cmake")).read()
    block = re.search(r"set\(CMAKE_MAKEFILE_DEPENDS\n(.*?)\n\s*\)", text, re.S)
    if not block:
        fail("CMakeFiles/Makefile.cmake has no CMAKE_MAKEFILE_DEPENDS")
    return re.findall(r'"([^"]*)"', block.group(1))


def ninja_words(text):
    """Splits ninja's `a$ b c` (escaped space) into words."""
    words, word, i = [], "", 0
    while i < len(text):
        c = text[i]
        if c == "$" and i + 1 < len(text):
            word += text[i + 1]
            i += 2
            continue
        if c.isspace():
            if word:
                words.append(word)
            word = ""
        else:
            word += c
        i += 1
    return words + ([word] if word else [])


def ninja_configure_inputs(build):
    text = open(os.path.join(build, "build.ninja")).read().replace("$\n", " ")
    for line in text.splitlines():
        if line.startswith("build build.ninja") and "RERUN_CMAKE" in line:
            words = ninja_words(line.split("RERUN_CMAKE", 1)[1])
            return [w for w in words if w not in ("|", "||")]
    fail("build.ninja has no RERUN_CMAKE build statement")


def depfile_inputs(path):
    """The prerequisites of a make-format dependency file (gcc -MD)."""
    text = open(path).read().replace("\\\n", " ")
    inputs = []
    for rule in text.splitlines():
        if ":" not in rule:
            continue
        rest = re.split(r"(?<!\\):\s", rule, maxsplit=1)[-1]
        inputs += [w.replace("\\ ", " ") for w in re.split(r"(?<!\\)\s+", rest) if w]
    return inputs


def ninja_deps(build, make_program, objects):
    rel = [os.path.relpath(o, build) for o in objects]
    out = subprocess.run([make_program, "-C", build, "-t", "deps"] + rel, check=True,
                         capture_output=True, text=True).stdout
    found = {}
    current = None
    for line in out.splitlines():
        if line and not line[0].isspace():
            current = line.split(":", 1)[0]
            found[current] = []
        elif line.strip() and current:
            found[current].append(line.strip())
    for r in rel:
        if not found.get(r):
            fail(f"ninja has no dependencies recorded for {r}: build the program first")
    return [p for ps in found.values() for p in ps]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--generator", required=True)
    ap.add_argument("--make-program", required=True)
    ap.add_argument("--objects", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--exclude", action="append", default=[])
    ap.add_argument("--also", nargs="+", default=[])
    a = ap.parse_args()
    source, build = os.path.realpath(a.source), os.path.realpath(a.build)
    objects = [l for l in open(a.objects).read().splitlines() if l.strip()]
    if not objects:
        fail(f"{a.objects} lists no objects")

    if a.generator.endswith("Makefiles"):
        read = makefile_configure_inputs(build)
        for o in objects:
            d = o + ".d"
            if not os.path.isfile(d):
                fail(f"{d} is missing (the compiler writes it with the object): build the program first")
            read += depfile_inputs(d)
    elif a.generator == "Ninja":
        read = ninja_configure_inputs(build) + ninja_deps(build, a.make_program, objects)
    else:
        fail(f"the generator '{a.generator}' is not one this script reads (Unix Makefiles, Ninja)")

    kit = set()
    excluded = [os.path.join(source, e) + os.sep for e in a.exclude] + [build + os.sep]
    for path in read:
        full = os.path.realpath(os.path.join(build, path))
        if not full.startswith(source + os.sep) or any(full.startswith(e) for e in excluded):
            continue
        if os.path.isfile(full):
            kit.add(os.path.relpath(full, source))
    for also in a.also:
        full = os.path.join(source, also)
        if os.path.isdir(full):
            for base, dirs, files in os.walk(full):
                dirs.sort()
                kit.update(os.path.relpath(os.path.join(base, f), source) for f in files
                           if os.path.isfile(os.path.join(base, f)))
        elif os.path.isfile(full):
            kit.add(also)
        else:
            fail(f"{full} (named with --also) does not exist")
    text = "".join(p + "\n" for p in sorted(kit))
    old = open(a.out).read() if os.path.exists(a.out) else None
    if text != old:  # unchanged: left alone, so nothing that depends on it is redone
        with open(a.out + ".tmp", "w") as f:
            f.write(text)
        os.replace(a.out + ".tmp", a.out)
        print(f"source_kit: {len(kit)} files in {os.path.relpath(a.out, build)}")


if __name__ == "__main__":
    main()
