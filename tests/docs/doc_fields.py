#!/usr/bin/env python3
"""A page's table of fields against a JSON file the program wrote: every field the table names
is in the file, and every field of the file at a level the table describes is in the table.

usage: doc_fields.py PAGE.md "LINE BEFORE THE TABLE" FILE.json [--prefix PATH]

The table is the first markdown table after the first line holding the given text; its first
column names fields in backticks (`a`, `b`; nested as `machine.backend`, in a list as
`tests[].name`). --prefix puts the table's names under a path of the file (`stages[].rows[]`).
Prints each difference with the page's line; exit 1 if any.
"""
import json
import re
import sys


def table_fields(page, anchor):
    lines = open(page, encoding="utf-8").read().split("\n")
    in_comment, start = False, None
    for i, l in enumerate(lines):  # the anchor in the prose, not in a docs-test mark naming it
        if "<!--" in l:
            in_comment = True
        if anchor in l and not in_comment:
            start = i
            break
        if "-->" in l:
            in_comment = False
    if start is None:
        sys.exit(f"{page}: no line holds '{anchor}'")
    fields, i = {}, start + 1
    while i < len(lines) and not lines[i].startswith("|"):
        i += 1
    while i < len(lines) and lines[i].startswith("|"):
        first, above = lines[i].split("|")[1], ""
        for name in re.findall(r"`([A-Za-z_][\w.\[\]]*)`", first):
            if re.search(r"[.\[]", name):
                above = parent(name)
            elif above:  # `tests[].name`, `number`: a sibling of the name before it
                name = above + "." + name
            fields.setdefault(name, i + 1)
        i += 1
    if not fields:
        sys.exit(f"{page}:{start + 1}: no table of fields after '{anchor}'")
    return fields


def values_at(data, path):
    """Every value at a path like tests[].name (lists fanned out)."""
    values = [data]
    for part in re.findall(r"[^.\[\]]+|\[\]", path):
        nxt = []
        for v in values:
            if part == "[]":
                nxt.extend(v if isinstance(v, list) else [])
            elif isinstance(v, dict) and part in v:
                nxt.append(v[part])
        values = nxt
    return values


def parent(path):
    m = re.match(r"(.*?)(?:\.|(?=\[\]))?([^.\[\]]+|\[\])$", path)
    return m.group(1).rstrip(".")


def ancestors(path):
    out = []
    while parent(path):
        path = parent(path)
        out.append(path)
    return out


def main():
    if len(sys.argv) not in (4, 6):
        sys.exit(__doc__)
    page, anchor, report = sys.argv[1:4]
    prefix = sys.argv[5] if len(sys.argv) == 6 and sys.argv[4] == "--prefix" else ""
    data = json.load(open(report, encoding="utf-8"))
    documented = {(prefix + "." + name if prefix else name): line
                  for name, line in table_fields(page, anchor).items()}
    problems = []
    for path, line in sorted(documented.items(), key=lambda x: x[1]):
        if not values_at(data, path):
            problems.append(f"{page}:{line}: `{path}` is in the table but not in {report}")
    for level in sorted({parent(p) for p in documented}):
        # a level's documented keys: the names at that level and the parents of deeper ones
        named = {p for p in documented if parent(p) == level}
        named |= {q for p in documented for q in ancestors(p) if parent(q) == level}
        for obj in values_at(data, level):
            if not isinstance(obj, dict):
                continue
            for key in obj:
                path = f"{level}.{key}" if level else key
                if path not in named:
                    problems.append(f"{page}: `{path}` is in {report} but not in the table after '{anchor}'")
                    named.add(path)
    for p in problems:
        print(p)
    print(f"{len(documented)} fields named, {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
