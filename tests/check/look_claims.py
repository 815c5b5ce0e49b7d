#!/usr/bin/env python3
"""Every lesson's words are true of its picture (issue 27: "Lessons that are true").

The window shows each entry of src/stages/expectations.json as its `outcome` (the lesson's name)
and its `look` line over the picture. This reads both with the vocabulary of look_claims.json
and checks each claim against the lesson's own figures in its own view (the scene's own camera,
as the window shows it), in every tree the lesson runs in:
  - a figure claim ("clean", "a few specks", "acne", "shadows in place"...) bounds the figures;
  - a setting claim ("map-size 512", "LearnOpenGL's method", "packed"...) must be the value the
    lesson uses;
  - an object noun ("the sphere", "the pillar", "slopes") must name an object of its scene.
Every look line must make a figure claim. A text that says what its picture does not show fails.

    look_claims.py EXE WORK               runs `check --all --report WORK/look.json` first
    look_claims.py --report R.json        reads a report of `check --all` instead
    look_claims.py --self-test            the claim reader on made-up lines (no GL)
"""
import json
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from report_rows import report_rows  # noqa: E402


def load_vocabulary():
    with open(os.path.join(HERE, "look_claims.json")) as f:
        return json.load(f)


def figure_claims(text, vocabulary):
    """The figure claims a text makes: [(phrase as written, claim)], longest match first, each
    span of the text read once."""
    found = []
    for claim in vocabulary["figures"]:
        for pattern in claim["say"]:
            for m in re.finditer(r"(?<![\w-])(?:" + pattern + r")(?![\w-])", text, re.IGNORECASE):
                found.append((m.start(), m.end(), claim))
    found.sort(key=lambda f: (-(f[1] - f[0]), f[0]))
    taken, claims = [], []
    for start, end, claim in found:
        if any(start < e and s < end for s, e in taken):
            continue
        taken.append((start, end))
        claims.append((text[start:end], claim))
    return claims


def setting_claims(text, vocabulary):
    """[(phrase, parameter, value)] for each setting the text names."""
    claims = []
    for s in vocabulary["settings"]:
        for m in re.finditer(r"(?<![\w-])(?:" + s["pattern"] + r")(?![\w-])", text, re.IGNORECASE):
            value = s.get("value")
            if value is None:
                value = next(g for g in m.groups() if g is not None)
            claims.append((m.group(0), s["parameter"], value))
    return claims


def object_nouns(text, vocabulary):
    nouns = []
    for noun in vocabulary["objects"]:
        if re.search(r"\b" + re.escape(noun) + r"(e?s)?\b", text, re.IGNORECASE):
            nouns.append(noun)
    return nouns


def amount_claims(text, vocabulary):
    """[(phrase, amount claim, number said)] for each amount the text states."""
    found = []
    for a in vocabulary.get("amounts", []):
        for m in re.finditer(a["pattern"], text, re.IGNORECASE):
            found.append((m.group(0), a, float(m.group(1))))
    return found


def place_nouns(where, vocabulary, places):
    nouns = [n for n in vocabulary["objects"]
             if re.search(r"\b" + re.escape(n) + r"(e?s)?\b", where, re.IGNORECASE)]
    if re.search(r"\bcasters?\b", where, re.IGNORECASE):
        nouns.append("casters")
    return nouns


def named(obj, noun, places):
    """Whether a report object is what a noun of a lesson text names."""
    name = obj["name"].lower()
    if noun == "casters":
        return not any(r in name for r in places["receivers"])
    return noun in name


def place_problems(text, row, vocabulary, where_said, lines, problems):
    """Where the text says errors lie (`places` in look_claims.json), against the row's objects."""
    places = vocabulary["places"]
    objects = row.get("objects") or []
    for m in re.finditer(places["errors"], text, re.IGNORECASE):
        nouns = place_nouns(m.group("where"), vocabulary, places)
        if not nouns:
            continue
        total = sum(o["false_shadow"] for o in objects)
        on = sum(o["false_shadow"] for o in objects if any(named(o, n, places) for n in nouns))
        share = 100.0 * on / total if total else None
        ok = share is not None and share >= places["share_min"]
        lines.append(f"  {'ok ' if ok else 'BAD'} {where_said}: '{m.group(0)}' -> "
                     f"{on} of {total} false-shadow pixels on {'/'.join(nouns)}")
        if not ok:
            problems.append(f"{where_said} says '{m.group(0)}', but {on} of the {total} "
                            f"false-shadow pixels lie on {'/'.join(nouns)} (at least "
                            f"{places['share_min']} % must): " + ", ".join(
                                f"{o['name']} {o['false_shadow']}" for o in objects))
    for rate in places.get("rates", []):
        for m in re.finditer(rate["pattern"], text, re.IGNORECASE):
            noun = m.group("noun").lower()
            hit = [o for o in objects if named(o, noun, places)]
            lit = sum(o["lit"] for o in hit)
            dark = sum(o["false_shadow"] for o in hit)
            value = 100.0 * dark / lit if lit else None
            ok = value is not None and value <= rate["rate_max"]
            lines.append(f"  {'ok ' if ok else 'BAD'} {where_said}: '{m.group(0)}' -> "
                         f"{dark} of {lit} lit {noun} pixels dark")
            if not ok:
                problems.append(f"{where_said} says '{m.group(0)}' ({rate['means']}), but "
                                f"{dark} of its {lit} lit pixels render dark")


def same_value(a, b):
    try:
        return math.isclose(float(a), float(b), rel_tol=1e-9)
    except ValueError:
        return str(a) == str(b)


def scene_has(scene_name, noun):
    with open(os.path.join(REPO, "scenes", scene_name + ".json")) as f:
        scene = json.load(f)
    if noun == "mirror":
        return "mirror" in scene
    return any(noun in o.get("name", "").lower() for o in scene.get("objects", []))


def label(entry):
    text = entry["stage"]
    if entry.get("scene"):
        text += " scene=" + entry["scene"]
    for name, value in sorted(entry.get("set", {}).items()):
        text += f" {name}={value}"
    return text


def own_view(book, scene):
    """The view with the scene's own camera: the one of expectations.json's views that names no
    eye, or the single view "scene" of a scene without views."""
    for v in book.get("views", {}).get(scene, []):
        if "eye" not in v:
            return v["name"]
    return "scene"


def check_entry(entry, rows, vocabulary):
    """Problems with one entry's outcome and look against its rows (one per tree)."""
    problems, lines = [], []
    name = label(entry)
    look_claims = figure_claims(entry.get("look", ""), vocabulary)
    if not look_claims:
        problems.append(f"{name}: its look line claims nothing measurable: '{entry.get('look')}'")
    for field in ("outcome", "look"):
        text = entry.get(field, "")
        claims = figure_claims(text, vocabulary)
        for row in rows:
            where = f"{name} [{row['tree']}, view {row['view']}] {field}"
            for phrase, claim in claims:
                for figure, bound in claim["bounds"].items():
                    value = row["figures"].get(figure)
                    low, high = bound.get("min"), bound.get("max")
                    ok = value is not None and (low is None or value >= low) and (
                        high is None or value <= high)
                    lines.append(f"  {'ok ' if ok else 'BAD'} {where}: '{phrase}' -> {figure} "
                                 f"{value} in [{low}, {high}]")
                    if not ok:
                        problems.append(f"{where} says '{phrase}' ({claim['means']}), but "
                                        f"{figure} is {value}, not in [{low}, {high}]")
            for phrase, parameter, value in setting_claims(text, vocabulary):
                used = row["parameters"].get(parameter)
                ok = used is not None and same_value(used, value)
                lines.append(f"  {'ok ' if ok else 'BAD'} {where}: '{phrase}' -> {parameter}={value}"
                             f" (in use: {used})")
                if not ok:
                    problems.append(f"{where} says '{phrase}' ({parameter}={value}) while "
                                    f"{parameter}={used} is in use")
            for phrase, amount, said in amount_claims(text, vocabulary):
                value = row["figures"].get(amount["figure"])
                low, high = said / amount["factor"], said * amount["factor"]
                ok = value is not None and low <= value <= high
                lines.append(f"  {'ok ' if ok else 'BAD'} {where}: '{phrase}' -> "
                             f"{amount['figure']} {value} in [{low:.3g}, {high:.3g}]")
                if not ok:
                    problems.append(f"{where} says '{phrase}' ({amount['means']}), but "
                                    f"{amount['figure']} is {value}")
            place_problems(text, row, vocabulary, where, lines, problems)
            for noun in object_nouns(text, vocabulary):
                ok = scene_has(row["scene"], noun)
                lines.append(f"  {'ok ' if ok else 'BAD'} {where}: '{noun}' in scene {row['scene']}")
                if not ok:
                    problems.append(f"{where} names a {noun}, and scene {row['scene']} has none")
    return problems, lines


def check_report(report_path):
    with open(report_path) as f:
        report = json.load(f)
    with open(report["expectations"]) as f:
        book = json.load(f)
    vocabulary = load_vocabulary()
    results = report_rows(report)
    problems = []
    for entry in book["expectations"]:
        name = label(entry)
        rows = [r for r in results
                if r.get("lesson") == name and r["view"] == own_view(book, r["scene"])]
        trees = entry.get("trees") or sorted({r["tree"] for r in results
                                              if r["stage"] == entry["stage"]})
        if sorted(r["tree"] for r in rows) != sorted(trees):
            problems.append(f"{name}: rows in its own view for trees "
                            f"{sorted(r['tree'] for r in rows)}, expected {sorted(trees)}")
            continue
        found, lines = check_entry(entry, rows, vocabulary)
        print(f"{name}: look '{entry.get('look')}'")
        print("\n".join(lines))
        problems += found
    return problems


def self_test():
    """The reader on lines whose claims are known, against made-up rows."""
    vocabulary = load_vocabulary()
    row = {"tree": "core", "view": "lecture", "scene": "slides",
           "figures": {"false_shadow_pct": 0.067, "false_lit_pct": 0.0, "edge_p95_px": 0.0,
                       "false_shadow_speckle_pct": 100.0, "false_lit_band_pct": 9.1},
           "parameters": {"map-size": "512", "margin": "0.01"},
           "objects": [{"name": "floor", "lit": 1000, "false_shadow": 0, "shadow": 500, "false_lit": 0},
                       {"name": "sphere", "lit": 100, "false_shadow": 10, "shadow": 0,
                        "false_lit": 0}]}
    cases = [
        # (look, expected number of problems)
        ("no acne; the lit line is one map texel (map-size 2048)", 2),  # specks, and 512 in use
        ("a few specks on the sphere; the lit line is one map texel (map-size 512)", 0),
        ("clean shadows", 1),
        ("acne on the slopes", 3),  # not acne here, none of it on slopes, and no slope in the scene
        ("the acne gone, but for a few specks where the light grazes the sphere", 0),
        ("our method beside the peers'", 1),  # claims nothing measurable
        ("the 0.01 margin: the shadows still touch their casters", 0),
        ("a few specks on the floor", 1),  # they lie on the sphere
        ("a few specks on the casters' lit sides", 0),  # the sphere is a caster
        ("a few specks, and most of the lit floor stays bright", 0),
        ("a few specks, and most of the lit sphere stays bright", 0),  # 10 of its 100 dark
        ("the shadow shrinks (about 3 % of the shadow)", 2),  # nothing lit in the shadow
        ("the shadows in place, leaving their casters", 0),  # no claim in "leaving"
        ("the shadows leave their casters", 1),
    ]
    bad = 0
    for look, expected in cases:
        problems, _ = check_entry({"stage": "test", "look": look, "outcome": ""}, [row], vocabulary)
        status = "ok " if len(problems) == expected else "BAD"
        bad += len(problems) != expected
        print(f"{status} {len(problems)} problem(s), expected {expected}: '{look}'")
        for p in problems:
            print("      " + p)
    return bad


def main():
    args = sys.argv[1:]
    if args == ["--self-test"]:
        sys.exit(1 if self_test() else 0)
    if len(args) == 2 and args[0] == "--report":
        report = args[1]
    elif len(args) == 2:
        exe, work = args
        os.makedirs(work, exist_ok=True)
        report = os.path.join(work, "look.json")
        if os.path.exists(report):
            os.remove(report)
        run = subprocess.run([exe, "check", "--all", "--report", report],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, check=False)
        if run.returncode != 0 or not os.path.isfile(report):
            sys.stdout.write(run.stdout.decode("utf-8", errors="replace")[-4000:])
            sys.exit(f"FAIL: check --all exited {run.returncode}: every lesson must show first")
    else:
        sys.exit(__doc__)
    problems = check_report(report)
    if problems:
        print(f"FAIL: {len(problems)} claim(s) not true of their pictures:")
        for p in problems:
            print("  " + p)
        sys.exit(1)
    print("OK: every lesson's outcome and look line is true of its own figures")


if __name__ == "__main__":
    main()
