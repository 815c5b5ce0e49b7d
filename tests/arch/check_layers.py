#!/usr/bin/env python3
"""The layering test: every #include "..." of src/ against the floors of docs/architecture.md.

usage: check_layers.py [--repo ROOT]

The page lists the floors from the top ("## Floors": one numbered line per floor, the folders
of src/ on it separated by commas) and the arrows allowed against them ("## Known exceptions":
"- `FROM -> TO`: why"). An include is an arrow from the including file's folder to the
included file's folder. Down is allowed; on one floor too, but never both ways (a folder
cycle); up is not. Each arrow not allowed fails, naming file:line and both folders; so does a
folder of src/ the page does not place, and an exception that no longer occurs (the list only
shrinks). Exit 0 when the graph fits, 1 with one line per fault, 2 when the page cannot be read.
"""
import argparse
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def read_layers(page):
    """(floor of each folder, set of (from, to) exceptions) from docs/architecture.md."""
    floors, exceptions, section = {}, set(), None
    with open(page, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                section = line[3:].strip().lower()
                continue
            if section == "floors":
                m = re.match(r"^(\d+)\.\s+(.*)$", line.strip())
                if m:
                    for name in re.findall(r"`([a-z_]+)/?`", m.group(2)):
                        floors[name] = int(m.group(1))
            elif section == "known exceptions":
                m = re.match(r"^- `([a-z_]+) -> ([a-z_]+)`", line.strip())
                if m:
                    exceptions.add((m.group(1), m.group(2)))
    return floors, exceptions


def arrows(src):
    """(file, line, from folder, to folder) for every include between two folders of src/."""
    for root, _, files in sorted(os.walk(src)):
        for name in sorted(files):
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(root, name)
            here = os.path.relpath(root, src).split(os.sep)[0]
            with open(path, encoding="utf-8", errors="replace") as f:
                for number, text in enumerate(f, 1):
                    m = INCLUDE.match(text)
                    if not m:
                        continue
                    target = m.group(1)
                    if os.path.exists(os.path.join(root, target)):  # beside the file
                        there = os.path.relpath(os.path.join(root, target), src).split(os.sep)[0]
                    elif "/" in target and os.path.exists(os.path.join(src, target)):
                        there = target.split("/")[0]
                    else:
                        continue  # not ours (glad, stb, ...)
                    if there != here:
                        yield os.path.relpath(path, os.path.dirname(src)), number, here, there


def faults(repo):
    src = os.path.join(repo, "src")
    floors, exceptions = read_layers(os.path.join(repo, "docs", "architecture.md"))
    if not floors:
        print("check_layers: docs/architecture.md lists no floors", file=sys.stderr)
        sys.exit(2)
    out, seen = [], {}
    for folder in sorted(os.listdir(src)):
        if os.path.isdir(os.path.join(src, folder)) and folder not in floors:
            out.append(f"src/{folder}/: a folder docs/architecture.md places on no floor")
    for path, number, a, b in arrows(src):
        seen.setdefault((a, b), (path, number))
    used = set()
    for (a, b), (path, number) in sorted(seen.items(), key=lambda kv: kv[1]):
        if a not in floors or b not in floors:
            continue  # named above
        if (a, b) in exceptions:
            used.add((a, b))
            continue
        if floors[b] < floors[a]:
            out.append(f"{path}:{number}: {a} -> {b}: an arrow up "
                       f"({a}/ is on floor {floors[a]}, {b}/ on floor {floors[b]})")
        elif floors[b] == floors[a] and (b, a) in seen and (b, a) not in exceptions:
            out.append(f"{path}:{number}: {a} -> {b}: both ways on floor {floors[a]} "
                       f"(a folder cycle: {b}/ includes {a}/ at {':'.join(map(str, seen[(b, a)]))})")
    for a, b in sorted(exceptions - used):
        out.append(f"docs/architecture.md: the known exception {a} -> {b} no longer occurs: "
                   "remove it from the list")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repo", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    args = parser.parse_args()
    found = faults(os.path.abspath(args.repo))
    for line in found:
        print(line)
    if found:
        print(f"check_layers: {len(found)} arrow(s) against docs/architecture.md", file=sys.stderr)
        return 1
    print("check_layers: every include of src/ points down or along its floor")
    return 0


if __name__ == "__main__":
    sys.exit(main())
