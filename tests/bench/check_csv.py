#!/usr/bin/env python3
"""Checks a bench or sweep CSV: the expected columns, at least MIN rows, no empty cell, and the
listed columns numeric on every row ("na" marks a figure that does not apply; it is refused in
the columns named here). With --na-below X, "na" is allowed in them on rows whose `value` is
below X: a sweep point where a figure measured nothing (the elevation sweep's lowest lights show
no measurable shadow) is undefined, not 0. With --where COLUMN=VALUE (repeatable) only the rows
holding that value are checked and counted: `bench --instructions` counts the 640x480 rows only,
so its instruction columns are checked on those (width=640 --where height=480).

usage: check_csv.py FILE MIN_ROWS [--where COLUMN=VALUE ...] [--na-below X] COLUMN [COLUMN ...]"""
import csv
import math
import sys


def main():
    path, min_rows, numeric = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    where = []
    while numeric[:1] == ["--where"]:
        column, _, value = numeric[1].partition("=")
        where.append((column, value))
        numeric = numeric[2:]
    na_below = None
    if numeric[:1] == ["--na-below"]:
        na_below, numeric = float(numeric[1]), numeric[2:]
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if all(r.get(c) == v for c, v in where)]
    problems = []
    if len(rows) < min_rows:
        problems.append(f"{len(rows)} rows, expected at least {min_rows}")
    header = rows[0].keys() if rows else []
    for column in numeric:
        if column not in header:
            problems.append(f"column '{column}' is missing")
    for n, row in enumerate(rows, start=2):
        for column, value in row.items():
            if value is None or value.strip() == "":
                problems.append(f"line {n}: column '{column}' is empty")
        for column in numeric:
            if na_below is not None and row.get(column) == "na" and float(row["value"]) < na_below:
                continue
            try:
                if not math.isfinite(float(row.get(column, ""))):
                    raise ValueError
            except ValueError:
                problems.append(f"line {n}: column '{column}' is not a finite number: {row.get(column)!r}")
    for p in problems[:20]:
        print(f"{path}: {p}")
    if problems:
        sys.exit(1)
    print(f"{path}: {len(rows)} rows, every cell filled, {len(numeric)} numeric columns checked")


main()
