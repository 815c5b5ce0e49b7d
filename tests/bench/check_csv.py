#!/usr/bin/env python3
"""Checks a bench or sweep CSV: the expected columns, at least MIN rows, no empty cell, and the
listed columns numeric on every row ("na" marks a figure that does not apply; it is refused in
the columns named here).

usage: check_csv.py FILE MIN_ROWS COLUMN [COLUMN ...]"""
import csv
import math
import sys


def main():
    path, min_rows, numeric = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
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
