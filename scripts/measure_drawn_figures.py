#!/usr/bin/env python3
"""Writes src/stages/drawn_figures.json: our shaders' figures in the drawn rows (expectations.json
"drawn", src/stages/drawn.h) at a fixed set of seeds, the figures each row's tolerance names and
nothing else (no code, no picture). A student edition has only stubs to render with: its `check`
draws its drawn rows at one of these seeds and holds the student's render to these figures by the
grader's rule (src/stages/drawn_figures.h, docs/check.md "Graded by the method").

    python3 scripts/measure_drawn_figures.py build/shadowlab --seeds 1-8 [--out FILE]
        [--stages depth,bias]

`--stages` measures those stages' rows again and keeps the other stages' rows of the file as they
are (the same seeds): for a change to one stage's drawn entries or shaders.

Run from a build of the source tree (its shaders are the solutions): per seed, stage and tree,
one `check --stage ID --glsl TREE --shaders shaders_TREE --seed S`, the solution checked as a
hand-in (its drawn rows are then ours). Rerun it when a drawn entry or a stage's shaders change:
ctest `unit` (DrawnFigures.*) finds a drawn row or value the data misses.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, ".."))


def seeds_of(text):
    out = []
    for part in text.split(","):
        lo, _, hi = part.partition("-")
        out += list(range(int(lo), int(hi or lo) + 1))
    return out


def label_of(entry):
    """DrawnRow::label(): the stage, its scene, its fixed settings in the file's order."""
    text = entry["stage"]
    if entry.get("scene"):
        text += " scene=" + entry["scene"]
    for name, value in entry.get("set", {}).items():
        text += " %s=%s" % (name, value)
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("exe")
    ap.add_argument("--seeds", required=True, help="e.g. 1-8 or 3,17,101")
    ap.add_argument("--out", default=os.path.join(SOURCE, "src", "stages", "drawn_figures.json"))
    ap.add_argument("--stages", help="only these stages (comma-separated); the rest kept")
    args = ap.parse_args()
    seeds = seeds_of(args.seeds)
    entries = json.load(open(os.path.join(SOURCE, "src", "stages", "expectations.json")))["drawn"]
    tolerance = {label_of(e): sorted(e["tolerance"]) for e in entries}
    # An entry's second row (its "response": the same values, one moved by a drawn ratio) has
    # figures of its own: the student edition judges the pair from both rows' figures.
    tolerance.update({label_of(e) + " response:" + e["response"]["param"]:
                      sorted(set(e["tolerance"]) | {e["response"]["figure"]})
                      for e in entries if "response" in e})
    listed = json.loads(subprocess.run([args.exe, "stages", "--json"], capture_output=True,
                                       text=True, check=True).stdout)
    trees = {s["id"]: s["trees"] for s in listed}
    runs = sorted({(e["stage"], t) for e in entries for t in e.get("trees") or trees[e["stage"]]})
    rows = {}
    if args.stages:
        only = args.stages.split(",")
        kept = json.load(open(args.out))
        if kept["seeds"] != seeds:
            sys.exit("--stages keeps the other rows of %s, measured at seeds %s: measure at those"
                     % (args.out, kept["seeds"]))
        rows = {k: v for k, v in kept["rows"].items() if k.split("/")[0] not in only}
        runs = [(stage, tree) for stage, tree in runs if stage in only]
    with tempfile.TemporaryDirectory() as tmp:
        for seed in seeds:
            for stage, tree in runs:
                report = os.path.join(tmp, "r.json")
                what = ["check", "--stage", stage, "--glsl", tree, "--shaders",
                        os.path.join(SOURCE, "shaders_" + tree), "--seed", str(seed),
                        "--time-limit", "900", "--report", report]
                r = subprocess.run([args.exe] + what, capture_output=True, text=True)
                if r.returncode not in (0, 1) or not os.path.exists(report):
                    sys.exit("%s: exit %d\n%s" % (" ".join(what), r.returncode, r.stderr[-2000:]))
                for st in json.load(open(report))["stages"]:
                    for row in st["rows"]:
                        if row["view"] != "drawn":
                            continue
                        label, _, drawn = row["lesson"].partition(" (drawn: ")
                        if row["verdict"] != "PASS":
                            sys.exit("seed %d: our own %s/%s %s is %s: %s" % (
                                seed, stage, tree, row["lesson"], row["verdict"], row["message"]))
                        figures = {}
                        for f in tolerance[label]:
                            v = row["figures"].get(f)
                            if v is not None and not (isinstance(v, float) and math.isnan(v)):
                                figures[f] = round(v, 6)
                        key = "%s/%s/%s" % (stage, tree, label)
                        rows.setdefault(key, {})[str(seed)] = {"drawn": drawn.rstrip(")"),
                                                               "figures": figures}
            print("seed %d: %d drawn rows" % (seed, len(rows)), flush=True)
    doc = {"why": "our shaders' figures in the drawn rows at these seeds, those the rows' tolerances "
                  "name (scripts/measure_drawn_figures.py); a student edition draws its drawn rows "
                  "at one of these seeds and holds them to these figures",
           "seeds": seeds,
           "rows": {k: rows[k] for k in sorted(rows)}}
    with open(args.out, "w") as f:
        # One line per row and seed: small, and a diff shows which figures moved.
        f.write('{"why": %s,\n "seeds": %s,\n "rows": {\n' % (json.dumps(doc["why"]),
                                                            json.dumps(seeds)))
        keys = list(doc["rows"])
        for i, key in enumerate(keys):
            by_seed = doc["rows"][key]
            f.write("  %s: {\n" % json.dumps(key))
            items = list(by_seed.items())
            for j, (seed, entry) in enumerate(items):
                f.write("   %s: %s%s\n" % (json.dumps(seed), json.dumps(entry),
                                          "," if j + 1 < len(items) else ""))
            f.write("  }%s\n" % ("," if i + 1 < len(keys) else ""))
        f.write(" }\n}\n")
    json.load(open(args.out))
    print("wrote %s: %d rows over %d seeds, %d bytes" % (args.out, len(rows), len(seeds),
                                                        os.path.getsize(args.out)))


if __name__ == "__main__":
    main()
