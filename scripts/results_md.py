#!/usr/bin/env python3
"""Writes docs/results.md from what `shadowlab bench` and `shadowlab sweep` wrote.

usage: results_md.py RESULTS_DIR  (RESULTS_DIR/bench/bench.json, RESULTS_DIR/sweep/*.csv)
The page is generated: edit this script, not the page."""
import csv
import json
import os
import re
import sys
import datetime

AXES = [
    ("elevation", "the light lowered from 85 to 1 degree above the floor (grazing light)"),
    ("margin", "the margin from 0 to 0.05 (acne on one side, shadows sliding off on the other)"),
    ("offset", "the polygon offset factor from 0 to 40 (the lab report's experiment)"),
    ("near-far", "the light's far/near ratio from 2 to 10,000 (depth precision)"),
    ("map-size", "the map from 32 to 4096 texels (aliasing, blocky edges)"),
]


def f(value, digits=3):
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    if abs(value) >= 100:
        return f"{value:.0f}"
    return f"{value:.{digits}g}"


def ratio(r):
    """A ratio to phong with its spread (half the interquartile range of the per-block ratios),
    or why it is not a figure: a spread over 10 % of the ratio is flagged, not published."""
    if r.get("ratio_to_phong") is None:
        return "-"
    if "ratio_trusted" not in r:  # a bench.json from before the per-block ratios
        return f(r["ratio_to_phong"])
    if not r["ratio_trusted"]:
        spread = 100 * r["ratio_iqr"] / r["ratio_to_phong"] if r["ratio_to_phong"] else float("nan")
        return f"not quoted (spread {spread:.0f} %)"
    return f"{r['ratio_to_phong']:.2f} ± {r['ratio_iqr'] / 2:.2f}"


def verdict(r, target):
    if "ratio_trusted" in r and not r["ratio_trusted"]:
        return "not judged (spread too wide)"
    return "met" if r["ratio_to_phong"] <= target else "missed"


# The figures the page shows a column of (their headers: figure_headers).
FIGURES_SHOWN = ("false_shadow_pct", "false_lit_pct", "edge_p95_px", "mirror_id_pct",
                 "mirror_psnr_db")


def figure_headers(bench):
    """A column header per figure, from the figure table bench wrote into bench.json
    (metrics/figures.h, `shadowlab stages --figures`): the name without its unit's suffix, in
    words, then the unit (false_shadow_pct: "false shadow %"). A figure renamed there renames its
    column here; one this page names but the table lacks stops it."""
    if "figures" not in bench:
        sys.exit("results_md: bench.json has no figure table (written by an older shadowlab: "
                 "run scripts/results.sh)")
    headers = {f["name"]: f"{f['name'].rsplit('_', 1)[0].replace('_', ' ')} {f['unit']}"
               for f in bench["figures"]}

    def header(name):
        if name not in headers:
            sys.exit(f"results_md: the figure {name!r} is not in bench.json's figure table "
                     "(renamed in metrics/figures.h?)")
        return headers[name]
    return header


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(f(c) for c in row) + " |" for row in rows]
    return "\n".join(out)


def cost_of(r):
    """The cost a comparison uses: instructions per frame against phong where counted (they do not
    move with the load), else the milliseconds ratio."""
    i = r.get("instructions_ratio_to_phong")
    return (i, "instructions") if i is not None else (r.get("ratio_to_phong"), "ms")


def front_section(rows):
    """Does our front dominate or tie the peers' at every accuracy? For each peer configuration of
    the map-size group, look for one of ours (same light) at most as costly and at most as wrong."""
    out = ["## Our methods against the tutorials' (map-size group, 640x480)\n"]
    pts = [r for r in rows if r["group"] == "map-size" and r.get("error_pct") is not None]
    lines = []
    for light in ("still", "moving"):
        peers = [r for r in pts if r["light"] == light and r["series"].startswith("peers/")]
        ours = [r for r in pts if r["light"] == light and not r["series"].startswith("peers/")]
        beaten, unbeaten = 0, []
        unit = None
        for p in peers:
            pc, unit = cost_of(p)
            best = [o for o in ours if cost_of(o)[0] is not None and pc is not None
                    and cost_of(o)[0] <= pc and o["error_pct"] <= p["error_pct"]]
            if best:
                beaten += 1
            else:
                unbeaten.append(f"{p['series']} {int(p['map_size'])} (error {f(p['error_pct'])} %, "
                                f"{f(pc)}x phong)")
        # The wording: no peer configuration both cheaper and more accurate than a point
        # of our front (our configurations no other of ours beats in both).
        front = [o for o in ours if cost_of(o)[0] is not None and not any(
            cost_of(x)[0] is not None and cost_of(x)[0] <= cost_of(o)[0]
            and x["error_pct"] <= o["error_pct"] and (cost_of(x)[0], x["error_pct"]) != (cost_of(o)[0], o["error_pct"])
            for x in ours)]
        beats = [(p, o) for p in peers for o in front
                 if cost_of(p)[0] is not None and cost_of(p)[0] < cost_of(o)[0]
                 and p["error_pct"] < o["error_pct"]]
        lines.append(f"- light {light}, cost in {unit}: {beaten} of {len(peers)} peer configurations "
                     "have one of ours at most as costly and at most as wrong"
                     + ("." if not unbeaten else "; not matched: " + "; ".join(unbeaten) + ".")
                     + f" Our front ({len(front)} points): "
                     + ("no peer configuration is both cheaper and more accurate than a point of it."
                        if not beats else "beaten in both by " + "; ".join(
                            f"{p['series']} {int(p['map_size'])} ({f(p['error_pct'])} %, {f(cost_of(p)[0])}x) "
                            f"over {o['series']} {int(o['map_size'])} ({f(o['error_pct'])} %, {f(cost_of(o)[0])}x)"
                            for p, o in beats) + "."))
    out.append("\n".join(lines))
    out.append("\nOurs: `rgb`, `depth`, `bias`, `margin`, `hardware`, `fixed`; theirs: the `peers` "
               "stage (LearnOpenGL, opengl-tutorial, normal offset). With milliseconds the answer "
               "can change between runs where two points are within each other's spread.\n")
    return out


def advice_section(bench, rows, root):
    """Which method for which goal, each answer computed from a row of this page."""
    out = ["## Which method should I use\n"]
    reached = [e for e in bench.get("equal_accuracy", []) if e["reached"]]

    def pick(key_instr, key_ms):
        have = [e for e in reached if e.get(key_instr) is not None]
        if have:
            e = min(have, key=lambda e: e[key_instr])
            return e, f"{e[key_instr] / 1e6:.1f} M instructions a frame"
        have = [e for e in reached if e.get(key_ms) is not None]
        if not have:
            return None, ""
        e = min(have, key=lambda e: e[key_ms])
        return e, f"{e[key_ms]:.2f}x phong (milliseconds)"

    items = []
    for goal, ki, km in (("Fastest with a still light", "instructions_still", "ratio_still"),
                         ("Fastest with the light moving", "instructions_moving", "ratio_moving")):
        e, why = pick(ki, km)
        if e:
            items.append(f"- **{goal}**, at the accuracy bar (edge p95 <= 2 px, error <= 0.1 %): "
                         f"`{e['method']}` with `{e['settings']}`: {why}, error {f(e['error_pct'])} % "
                         "(row in the equal-accuracy table).")
    soft = [e for e in bench.get("equal_accuracy", []) if e["method"] == "hardware/pcf3x3"]
    if soft:
        e = soft[0]
        items.append("- **Softest edges**: `hardware` with `filter=pcf3x3`: nine compares one texel "
                     "apart average into a ramp three texels wide (the 2x2 filter's is one texel); "
                     f"at the bar it needs `{e['settings']}`, error {f(e['error_pct'])} %, "
                     + (f"{e['instructions_moving'] / 1e6:.1f} M instructions moving"
                        if e.get("instructions_moving") is not None else
                        f"{e['ratio_moving']:.2f}x phong moving") + ".")
    path = os.path.join(root, "sweep", "sweep-elevation-breaks.csv")
    pts = os.path.join(root, "sweep", "sweep-elevation.csv")
    if os.path.exists(path) and os.path.exists(pts):
        breaks = [b for b in csv.DictReader(open(path)) if b["works"] == "yes"]
        points = list(csv.DictReader(open(pts)))
        def error_at_lowest(b):  # the error at the lowest light it still works at
            at = [p for p in points if p["stage"] == b["stage"] and p["tree"] == b["tree"]
                  and float(p["value"]) == float(b["works_to"])]
            return float(at[0]["error_pct"]) if at else float("inf")
        if breaks:
            b = min(breaks, key=lambda b: (float(b["works_to"]), error_at_lowest(b)))
            lower = [p for p in points if p["stage"] == b["stage"] and p["tree"] == b["tree"]
                     and float(p["value"]) < float(b["works_to"])]
            unmeasured = [p["value"] for p in lower if p["error_pct"] == "na"]
            items.append(f"- **Most robust at grazing light**: `{b['stage']}` ({b['tree']}) at its "
                         f"defaults: under the {b['threshold_pct']} % threshold down to "
                         f"{b['works_to']} degrees above the floor, error {f(error_at_lowest(b))} % "
                         "there (the elevation sweep, below; ties broken by the error at that "
                         "lowest light)"
                         + (f"; at {', '.join(unmeasured)} degrees no shadow can be measured "
                            "(error undefined), for any method." if unmeasured else "."))
    out.append("\n".join(items) + "\n")
    return out


def main():
    root = sys.argv[1]
    rel = os.path.relpath(root, "docs")
    bench = json.load(open(os.path.join(root, "bench", "bench.json")))
    rows = bench["rows"]
    fig = figure_headers(bench)
    by = lambda **kw: [r for r in rows if all(r[k] == v for k, v in kw.items())]
    out = []
    out.append("# Results: speed against accuracy\n")
    out.append("Generated by `bash scripts/results.sh` (a full `shadowlab bench` and every "
               "`shadowlab sweep`); do not edit by hand. How the figures are defined: "
               "[check.md](check.md) and [bench.md](bench.md).\n")
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    out.append(f"**Machine:** {bench['machine']}; load average {load} (1, 5, 15 min) when this "
               f"page was written. Generated {datetime.date.today()}. Times are "
               "medians after warm-up, measured with glFinish and a steady clock. Each "
               "configuration is timed in short blocks interleaved with `phong` on the same "
               "context (ABBA order); its ratio is the median of the per-block ratios, ± half "
               "their interquartile range, and a ratio whose spread is over 10 % of it is flagged "
               "instead of quoted. `phong` draws no map, so one measurement serves its still and "
               "moving rows. Milliseconds move with the machine's load: compare ratios.\n")

    out.append("## Each method at its defaults (640x480)\n")
    rs = []
    for r in rows:
        if r["width"] == 640 and r["light"] == "still" and (
                r["group"] == "window" or (r["group"] == "baseline" and r["scene"] == "slides")):
            moving = next(m for m in rows if m["light"] == "moving" and m["group"] == r["group"]
                          and m["series"] == r["series"] and m["width"] == 640 and m["tree"] == r["tree"])
            rs.append([r["stage"], r["tree"], r["error_pct"], r["false_shadow_pct"], r["false_lit_pct"],
                       r["edge_p95_px"], r["mirror_id_pct"], r["frame_ms"], moving["frame_ms"],
                       ratio(r), ratio(moving)])
    out.append(table(["stage", "tree", "error %", fig("false_shadow_pct"), fig("false_lit_pct"),
                      fig("edge_p95_px"), fig("mirror_id_pct"), "still ms", "moving ms",
                      "x phong still", "x phong moving"], rs))
    counted = [r for r in rows if r.get("instructions_per_frame") is not None and r["group"] != "map-size"]
    if counted:
        out.append("\n**Instructions per frame** (`bench --instructions`: valgrind's callgrind, "
                   "`LP_NUM_THREADS=0`, counted over the steady frames only; they repeat to a "
                   "fraction of a percent where milliseconds do not):\n")
        irows = []
        for r in counted:
            if r["light"] != "still":
                continue
            moving = next(m for m in counted if m["light"] == "moving" and m["group"] == r["group"]
                          and m["series"] == r["series"] and m["scene"] == r["scene"] and m["tree"] == r["tree"])
            label = r["stage"] if r["group"] in ("window", "baseline") else f"{r['series']} ({r['settings']})"
            irows.append([label, r["group"], r["tree"], r["scene"], r["instructions_per_frame"] / 1e6,
                          r["instructions_ratio_to_phong"], moving["instructions_per_frame"] / 1e6,
                          moving["instructions_ratio_to_phong"]])
        out.append(table(["configuration", "group", "tree", "scene", "M instr still", "x phong still", "M instr moving",
                          "x phong moving"], irows))
    out.append("\nerror % = (false shadow % + false lit %) / 2 outside the 1-pixel edge band "
               "(mirror: 100 - object-id agreement inside the mirror). `phong` has no shadows, so "
               "every true shadow is false lit: 50 %. `bias` keeps the slides' -0.5 under the "
               "standard projection and is inverted on purpose (see the stage table in the README).\n")

    out.append("## Targets (640x480)\n")
    out.append("Issue 14's targets: with a still light `hardware` 2x2 PCF <= 1.12x `phong` and "
               "`filter=nearest` <= 1.06x (the still cost does not depend on the map size: the 1024 "
               "rows); with the light moving <= 1.3x at the accuracy of the 1024 default (the "
               "cheapest `hardware` configuration that reaches the equal-accuracy bar, below, and "
               "the 1024 row itself); the mirror <= 2.2x. Judged on the milliseconds ratio (a "
               "flagged spread is not judged) and, where counted, on instructions, which do not "
               "move with the load.\n")
    trs = []

    def target_row(label, r, target):
        instr = r.get("instructions_ratio_to_phong")
        trs.append([label, r["frame_ms"], ratio(r), f"<= {target}", verdict(r, target),
                    "-" if instr is None else f"{instr:.3f}",
                    "-" if instr is None else ("met" if instr <= target else "missed")])

    def row(series, light):  # the 1024 map
        m = [r for r in rows if r["group"] == "map-size" and r["series"] == series
             and r["map_size"] == 1024 and r["light"] == light]
        return m[0] if m else None

    for series, light, target in (("hardware/linear", "still", 1.12),
                                  ("hardware/nearest", "still", 1.06),
                                  ("hardware/linear", "moving", 1.3)):
        r = row(series, light)
        if r:
            target_row(f"{series}, 1024 map, light {light}", r, target)
    # "At the accuracy of the 1024 default": the cheapest hardware/linear map size (same light
    # fit) at most as wrong and with an edge p95 at most the 1024 row's.
    ref = row("hardware/linear", "moving")
    if ref:
        same = [r for r in rows if r["group"] == "map-size" and r["series"] == "hardware/linear"
                and r["light"] == "moving" and r["error_pct"] <= ref["error_pct"]
                and r["edge_p95_px"] <= ref["edge_p95_px"]]
        if same:
            r = min(same, key=lambda r: cost_of(r)[0])
            target_row(f"hardware/linear, {int(r['map_size'])} map (as accurate as the 1024 default: "
                       f"error {f(r['error_pct'])} %, edge p95 {f(r['edge_p95_px'])} px), light moving",
                       r, 1.3)
    for e in bench.get("equal_accuracy", []):
        if e["method"] == "hardware/linear" and e["reached"]:
            r = [x for x in rows if x["group"] == "equal-accuracy" and x["series"] == e["method"]
                 and x["light"] == "moving"]
            if r:
                target_row(f"hardware/linear at the bar ({e['settings']}), light moving", r[0], 1.3)
    for r in [r for r in rows if r["series"] == "mirror/texture" and r["width"] == 640]:
        target_row(f"mirror (texture), light {r['light']}", r, 2.2)
    out.append(table(["configuration", "ms/frame", "x phong (ms)", "target", "verdict (ms)",
                      "x phong (instructions)", "verdict (instructions)"], trs))
    out.append("\nWhere each miss goes and what was tried: [bench.md](bench.md), \"Where the time "
               "goes\".\n")

    out.extend(front_section(rows))
    out.extend(advice_section(bench, rows, root))
    equal = bench.get("equal_accuracy", [])
    if equal:
        out.append("## Cost at equal accuracy (edge p95 <= 2 px, error <= 0.1 %)\n")
        out.append("Per method the cheapest configuration (map size, light fit) that reaches the bar "
                   "on the lecture scene, or, marked *not reached*, the one that came closest. "
                   "See [bench.md](bench.md).\n")
        def rq(value, iqr, trusted):
            if value is None:
                return "-"
            return f"{value:.2f} ± {iqr / 2:.2f}" if trusted else f"not quoted (spread {100 * iqr / value:.0f} %)"
        erows = [[e["method"], "yes" if e["reached"] else "*not reached*", e["settings"], e["edge_p95_px"],
                  e["error_pct"], rq(e["ratio_still"], e["ratio_still_iqr"], e["ratio_still_trusted"]),
                  rq(e["ratio_moving"], e["ratio_moving_iqr"], e["ratio_moving_trusted"]),
                  "-" if e["instructions_moving"] is None else f"{e['instructions_moving'] / 1e6:.1f} M "
                  f"({e['instructions_ratio_moving']:.2f}x)"] for e in equal]
        out.append(table(["method", "reached", "configuration", fig("edge_p95_px"), "error %", "x phong still",
                          "x phong moving", "instr/frame moving"], erows))
        out.append("")

    out.append("## Charts\n")
    charts = [("error-vs-time.png", "Error against frame time, each method's Pareto front as a line")]
    if os.path.exists(os.path.join(root, "bench", "error-vs-instructions.png")):
        charts.append(("error-vs-instructions.png", "Error against instructions per frame (callgrind)"))
    for png, caption in charts + [
                         ("time-vs-map-size.png", "Frame time against map size, light moving (map re-rendered every frame)"),
                         ("time-vs-window.png", "Frame time against window size, still light")]:
        out.append(f"**{caption}**\n\n![{caption}]({rel}/bench/{png})\n")

    out.append("## Map size (light moving, 640x480)\n")
    series = sorted({r["series"] for r in rows if r["group"] == "map-size"})
    sizes = sorted({r["map_size"] for r in rows if r["group"] == "map-size"})
    srows = []
    for s in series:
        cells = [s]
        for size in sizes:
            m = [r for r in rows if r["group"] == "map-size" and r["series"] == s and r["map_size"] == size
                 and r["light"] == "moving"]
            cells.append(f"{f(m[0]['frame_ms'])} ms, {f(m[0]['error_pct'])} %" if m else "-")
        srows.append(cells)
    out.append(table(["method"] + [str(int(s)) for s in sizes], srows))
    out.append("")

    out.append("## Storage formats and the mirror (1024 map, 640x480, still light)\n")
    frows = [[r["series"], r["settings"], r["frame_ms"], ratio(r), r["error_pct"], r["edge_p95_px"],
              r["mirror_psnr_db"]]
             for r in rows if r["group"] in ("format", "mirror") and r["light"] == "still"]
    out.append(table(["configuration", "settings", "ms/frame", "x phong", "error %",
                      fig("edge_p95_px"), fig("mirror_psnr_db")], frows))
    out.append("")

    out.append("## Where each method breaks\n")
    out.append("A method breaks where its error rises above the threshold (stated per sweep). "
               "`works from .. to` is the range around its best point that stays under it.\n")
    for axis, what in AXES:
        path = os.path.join(root, "sweep", f"sweep-{axis}-breaks.csv")
        if not os.path.exists(path):
            continue
        breaks = list(csv.DictReader(open(path)))
        out.append(f"### {axis}: {what}\n")
        out.append(f"Threshold {breaks[0]['threshold_pct']} %.\n")
        out.append(table(["stage", "tree", "best (error %)", "works from", "to", "breaks at"],
                         [[b["stage"], b["tree"], f"{b['best_value']} ({b['best_error_pct']})",
                           b["works_from"], b["works_to"],
                           " / ".join(x for x in (b["breaks_before"], b["breaks_after"]) if x != "na") or "never"]
                          for b in breaks]))
        out.append(f"\n![sweep {axis}]({rel}/sweep/sweep-{axis}.png)\n")
    # The class-grading benchmark is run apart (tests/course/bench_grade.py): its page is kept.
    extra = os.path.join(os.path.dirname(__file__), "..", "docs", "results-class.md")
    if os.path.exists(extra):
        # Its commands are run by its own page's docs test: here they are a copy.
        out.append(re.sub(r"<!-- docs-test: long;.*?-->",
                          "<!-- docs-test: skip: a copy of docs/results-class.md, whose docs test runs these -->",
                          open(extra).read(), flags=re.S))
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
