#!/usr/bin/env python3
"""Writes src/stages/displaced_bounds.json: what the solution (the source tree's marked shaders)
measures in displaced views, per stage, tree and lesson: the lowest and highest value of each
figure a lesson bounds, over the displaced views of the seeds given. The student edition has no
solution to draw, so `check` and `grade` both widen a displaced row's bounds from this data
(src/stages/displaced_bounds.h, docs/check.md "The figures"): one grading truth.

    python3 scripts/measure_displaced_bounds.py build/shadowlab --seeds 1-12 [--out FILE]
    [--merge FILE: add the seeds not yet in FILE, keeping its ranges]
    [--stage ID: with --merge, measure that stage alone at every seed of FILE (and --seeds),
     replacing its entries and keeping every other stage's]

Run from a build of the source tree (its shaders are the solutions); each seed is one
`check --all --seed S` (a few minutes here). Rerun it when a stage's shaders or a lesson's
bounds change: ctest `unit` (DisplacedBounds.*) finds a displaced lesson the data misses.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile


def seeds_of(text):
    out = []
    for part in text.split(","):
        lo, _, hi = part.partition("-")
        out += list(range(int(lo), int(hi or lo) + 1))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("exe")
    ap.add_argument("--seeds", required=True, help="e.g. 1-8 or 3,17,101")
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--out", default=os.path.join(here, "..", "src", "stages", "displaced_bounds.json"))
    ap.add_argument("--merge", help="a file this script wrote: its seeds and ranges are kept")
    ap.add_argument("--stage", help="with --merge: this stage alone, at every seed of the file")
    args = ap.parse_args()
    if args.stage and not args.merge:
        sys.exit("--stage needs --merge FILE (the other stages' entries come from it)")
    seeds = seeds_of(args.seeds)
    lessons = {}
    if args.merge:
        old = json.load(open(args.merge))
        seeds = sorted(set(old["seeds"]) | set(seeds))
        lessons = {k: {f: list(r) for f, r in v.items()} for k, v in old["lessons"].items()
                   if not (args.stage and k.startswith(args.stage + "/"))}
        # One seed list for the whole file: a stage measured alone is measured at all of them.
        todo = seeds if args.stage else sorted(set(seeds_of(args.seeds)) - set(old["seeds"]))
    else:
        todo = seeds
    runs = [["--all"]]
    if args.stage:
        listed = json.loads(subprocess.run([args.exe, "stages", "--json"], capture_output=True,
                                           text=True, check=True).stdout)
        trees = [s["trees"] for s in listed if s["id"] == args.stage]
        if not trees:
            sys.exit("--stage %s: no such stage" % args.stage)
        runs = [["--stage", args.stage, "--glsl", t] for t in trees[0]]
    with tempfile.TemporaryDirectory() as tmp:
        for seed in todo:
            rows = []
            for what in runs:
                report = os.path.join(tmp, "r%d.json" % seed)
                r = subprocess.run([args.exe, "check"] + what + ["--seed", str(seed), "--time-limit",
                                    "900", "--report", report], capture_output=True, text=True)
                if r.returncode not in (0, 1) or not os.path.exists(report):
                    sys.exit("check %s --seed %d: exit %d\n%s" % (" ".join(what), seed, r.returncode,
                                                                  r.stderr[-2000:]))
                rows += [row for st in json.load(open(report))["stages"] for row in st["rows"]]
            for row in rows:
                entry = row.get("expectation") or {}
                if row["view"] != "displaced" or not entry or row["verdict"] not in ("PASS", "FAIL"):
                    continue
                key = "%s/%s/%s" % (row["stage"], row["tree"], entry["entry"])
                for figure in entry["limits"]:
                    v = row["figures"].get(figure)
                    if v is None or (isinstance(v, float) and math.isnan(v)):
                        continue
                    lo, hi = lessons.setdefault(key, {}).get(figure, [v, v])
                    lessons[key][figure] = [min(lo, v), max(hi, v)]
            print("seed %d: %d displaced lessons so far" % (seed, len(lessons)), flush=True)
    doc = {"why": "the solution's figures in displaced views, lowest and highest per lesson "
                  "(scripts/measure_displaced_bounds.py); a displaced row's bounds widen to them",
           "seeds": seeds,
           "lessons": {k: {f: [round(lo, 4), round(hi, 4)] for f, (lo, hi) in sorted(v.items())}
                       for k, v in sorted(lessons.items())}}
    with open(args.out, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    print("wrote %s: %d lessons over %d seeds" % (args.out, len(lessons), len(seeds)))


if __name__ == "__main__":
    main()
