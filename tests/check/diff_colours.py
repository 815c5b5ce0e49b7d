#!/usr/bin/env python3
"""Counts the colours of a check diff image (red false shadow, blue false lit, their pale versions
inside the edge band, grey agreement, white not evaluated; src/metrics/shadow_metrics.h) and checks them against the report's pixel
counts for that stage.

usage: diff_colours.py DIFF.png REPORT.json STAGE TREE MIN_BLUE_OF_SHADOW MAX_RED_OF_EVALUATED
                       [MAX_BLUE_OF_SHADOW]
  MIN_BLUE_OF_SHADOW: blue pixels / truly shadowed pixels must be at least this (0..1)
  MAX_RED_OF_EVALUATED: red pixels / evaluated pixels must be at most this (0..1)
  MAX_BLUE_OF_SHADOW: blue pixels / truly shadowed pixels must be at most this (default 1)"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngread import read_png  # noqa: E402

RED, BLUE, WHITE = (220, 40, 40), (40, 80, 230), (255, 255, 255)


def main():
    png, report, stage, tree = sys.argv[1:5]
    min_blue, max_red = float(sys.argv[5]), float(sys.argv[6])
    max_blue = float(sys.argv[7]) if len(sys.argv) > 7 else 1.0
    _, _, pixels = read_png(png)
    red = sum(1 for p in pixels if p == RED)
    blue = sum(1 for p in pixels if p == BLUE)
    white = sum(1 for p in pixels if p == WHITE)
    pale = sum(1 for p in pixels if p in ((240, 170, 170), (170, 190, 240)))
    grey = sum(1 for p in pixels if p[0] == p[1] == p[2] and 60 <= p[0] <= 200)
    with open(report) as f:
        rows = [r for st in json.load(f)["stages"] for r in st["rows"]]
        results = [r for r in rows if r["stage"] == stage and r["tree"] == tree]
    if not results:  # --diff FILE is the first row's: the defaults seen from the first view
        sys.exit(f"FAIL: the report has no result for {stage}/{tree}")
    counts = results[0]["pixels"]
    print(f"red {red}  blue {blue}  grey {grey}  white {white}  of {len(pixels)}; "
          f"report: evaluated {counts['evaluated']}, truly shadowed {counts['truth_shadow']}")
    problems = []
    if red + blue + pale + grey + white != len(pixels):
        problems.append(f"{len(pixels) - red - blue - pale - grey - white} pixels of another colour")
    if blue < min_blue * counts["truth_shadow"]:
        problems.append(f"blue {blue} < {min_blue} x truly shadowed {counts['truth_shadow']}")
    if blue > max_blue * counts["truth_shadow"]:
        problems.append(f"blue {blue} > {max_blue} x truly shadowed {counts['truth_shadow']}")
    if red > max_red * counts["evaluated"]:
        problems.append(f"red {red} > {max_red} x evaluated {counts['evaluated']}")
    if problems:
        sys.exit("FAIL: " + "; ".join(problems))
    print("OK")


if __name__ == "__main__":
    main()
