#!/usr/bin/env python3
"""No stage id outside src/stages/: every string literal of src/ against the ids of stage_list.h.

usage: check_stage_ids.py [--repo ROOT]

The ids are read from src/stages/stage_list.h (one SL_STAGE(id) a line), so a new stage is
checked as soon as it is listed. A string literal in code (comments are skipped) of a file of
src/ outside src/stages/ that is an id, or starts with "id/" (a series such as "margin/slope"),
fails, naming file:line. A literal that only spells like an id (the scene "mirror", the light
fit "fixed") is allowed where a comment on its line or the line above says "not a stage id".
The files docs/architecture.md lists under "## Stage ids outside src/stages/" ("- `PATH`: why")
are known and skipped until their redesign lands; one that no longer names a stage id fails too
(the list only shrinks).
Exit 0 when none is found, 1 with one line per literal, 2 when stage_list.h lists no stage.
"""
import argparse
import os
import re
import sys

MARKER = "not a stage id"


def stage_ids(repo):
    with open(os.path.join(repo, "src", "stages", "stage_list.h"), encoding="utf-8") as f:
        return re.findall(r"^SL_STAGE\((\w+)\)", f.read(), re.M)


def known_files(repo):
    """The files of src/ docs/architecture.md still allows to name stage ids."""
    known, section = set(), None
    with open(os.path.join(repo, "docs", "architecture.md"), encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                section = line[3:].strip().lower()
            elif section == "stage ids outside src/stages/":
                m = re.match(r"^- `(src/[^`]+)`", line.strip())
                if m:
                    known.add(m.group(1))
    return known


def literals(text):
    """(line, literal) of each string literal of C++ source, with the comment text per line."""
    found, comments, i, line, n = [], {}, 0, 1, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            comments.setdefault(line, []).append(text[i:end])
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            comments.setdefault(line, []).append(text[i:end])
            line += text.count("\n", i, end)
            i = end
        elif c == "R" and text.startswith('R"', i) and not (text[i - 1:i].isalnum() or text[i - 1:i] == "_"):
            open_paren = text.find("(", i + 2)
            close = ")" + text[i + 2:open_paren] + '"'
            end = text.find(close, open_paren)
            end = n if end < 0 else end + len(close)
            found.append((line, text[open_paren + 1:end - len(close)]))
            line += text.count("\n", i, end)
            i = end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            if c == '"':
                found.append((line, text[i + 1:j]))
            i = j + 1
        else:
            i += 1
    return found, comments


def faults(repo):
    ids = stage_ids(repo)
    if not ids:
        print("check_stage_ids: src/stages/stage_list.h lists no stage", file=sys.stderr)
        sys.exit(2)
    src, out, known = os.path.join(repo, "src"), [], known_files(repo)
    named_in, reported = set(), set()  # files that name an id; (file, line) already reported
    for root, dirs, files in sorted(os.walk(src)):
        dirs.sort()
        if os.path.relpath(root, src).split(os.sep)[0] == "stages":
            continue
        for name in sorted(files):
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(root, name)
            with open(path, encoding="utf-8", errors="replace") as f:
                found, comments = literals(f.read())
            relpath = os.path.relpath(path, repo)
            for line, text in found:
                named = [s for s in ids if text == s or text.startswith(s + "/")]
                said = comments.get(line, []) + comments.get(line - 1, [])
                if not named or any(MARKER in c for c in said):
                    continue
                named_in.add(relpath)
                if relpath not in known and (relpath, line) not in reported:
                    reported.add((relpath, line))
                    out.append(f"{relpath}:{line}: \"{text}\" names the stage "
                               f"'{named[0]}' outside src/stages/ (ask the registry, or say "
                               f"\"// {MARKER}: why\" above it)")
    for path in sorted(known - named_in):
        out.append(f"docs/architecture.md: {path} no longer names a stage id: remove it from the "
                   "list")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repo", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    args = parser.parse_args()
    found = faults(os.path.abspath(args.repo))
    for line in found:
        print(line)
    if found:
        print(f"check_stage_ids: {len(found)} stage id(s) outside src/stages/", file=sys.stderr)
        return 1
    print("check_stage_ids: no file of src/ outside src/stages/ names a stage id")
    return 0


if __name__ == "__main__":
    sys.exit(main())
