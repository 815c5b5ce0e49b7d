#!/usr/bin/env bash
# The student edition (docs/assignment.md, "A student edition"): the default `cmake --install`
# ships both shader trees with every marked solution region stubbed and no line of any region
# anywhere under the prefix (the program included); the installed program runs from it (a stage
# draws its "not done yet" picture, a student's own solution is graded PASS at home) and cannot
# release (no solutions); with the `solutions` component added, the marked trees are used again
# (the lecture's stage passes, `release` works).
#   student_edition.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "student edition test: FAIL: $*"; exit 1; }
cmake --install "$build" --prefix "$tmp/p" >/dev/null
exe=$tmp/p/bin/shadowlab
data=$tmp/p/share/shadowlab
[ -f "$data/shaders_core/margin/lit.frag" ] || fail "no shaders_core installed"
[ ! -e "$data/solutions" ] || fail "the default install holds the solutions component"
python3 - "$src" "$tmp/p" <<'PY' || fail "a solution line is installed"
import os, re, sys
src, prefix = sys.argv[1:3]
lines, files = set(), 0
for tree in ("shaders_core", "shaders_legacy"):
    for d, _, names in os.walk(os.path.join(src, tree)):
        for f in names:
            regions = re.findall(r"// BEGIN SOLUTION\n(.*?)// END SOLUTION", open(os.path.join(d, f)).read(), re.S)
            files += bool(regions)
            for region in regions:
                lines |= {l.strip() for l in region.splitlines()
                          if len(l.strip()) >= 4 and not l.strip().startswith("//")}
assert files >= 20 and len(lines) >= 40, (files, len(lines))
found = []
for d, _, names in os.walk(prefix):
    for f in names:
        data = open(os.path.join(d, f), "rb").read()
        found += [(os.path.join(d, f), l) for l in lines if l.encode() in data]
assert not found, found[:5]
print("student edition: none of %d solution lines of %d marked files is installed" % (len(lines), files))
PY
run() { (cd / && env -u SHADOWLAB_DATA_DIR SHADOWLAB_NO_SOURCE_DIR=1 "$exe" "$@"); }
# The stubs build and draw; the stage does not pass.
run render --stage margin --size 64x48 --repeat 0 --out "$tmp/margin.png" >/dev/null ||
  fail "the student edition's margin stage does not render"
# A student's own work is graded at home against the same references as the instructor's (the
# mirror's too, although its surface shaders are stubs here).
printf '{"name": "margin", "stages": [{"stage": "margin", "files": ["margin/lit.frag"], "points": 10}]}' \
  > "$tmp/margin.json"
printf '{"name": "two", "stages": [{"stage": "margin", "files": ["margin/lit.frag"], "points": 10},
  {"stage": "mirror", "files": ["mirror/surface.frag", "mirror/surface.vert"], "points": 10}]}' \
  > "$tmp/two.json"
mkdir -p "$tmp/handin/margin" "$tmp/handin/mirror"
cp "$src/shaders_core/margin/lit.frag" "$tmp/handin/margin/"
cp "$src/shaders_core/mirror/surface.frag" "$src/shaders_core/mirror/surface.vert" "$tmp/handin/mirror/"
out=$(run check --assignment "$tmp/two.json" --shaders "$tmp/handin" --time-limit 300 \
      --report "$tmp/two-report.json") ||
  fail "a correct hand-in is not graded full marks in the student edition: $out"
python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); assert r["score"] == r["max_score"] == 20, r["score"]' \
  "$tmp/two-report.json" || fail "no full marks: $out"
# One grading truth (issue 39): a corpus of hand-ins checked at home with the student edition,
# then checked and graded with the instructor's install, at one seed: the same rows, verdicts,
# points and score in each (the untouched starter 0; the correct one full marks; a shader that
# knows the fixed cameras loses its displaced row; a constant margin dressed as the slope formula
# loses its drawn rows). The displaced rows' bounds and the drawn rows' figures of ours are data
# measured on the solution (src/stages/displaced_bounds.json, drawn_figures.json), not measured
# on the installed (here stubbed) shaders. The seed is one the data ships (the home check draws
# its drawn rows at a shipped seed; at any other it picks one of them, checked below).
seed=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["seeds"][-1])' \
  "$data/src/stages/drawn_figures.json")
corpus="starter correct known_eyes constant"
for who in $corpus; do mkdir -p "$tmp/corpus/$who/margin"; done
cp "$data/shaders_core/margin/lit.frag" "$tmp/corpus/starter/margin/"
cp "$src/shaders_core/margin/lit.frag" "$tmp/corpus/correct/margin/"
cp "$src/tests/students/margin_game_known_eyes/margin/lit.frag" "$tmp/corpus/known_eyes/margin/"
cp "$src/tests/students/margin_game_slope_times_zero/margin/lit.frag" "$tmp/corpus/constant/margin/"
corpus_check() {  # corpus_check LABEL [SEED]: each hand-in checked into $tmp/LABEL-NAME.json
  for who in $corpus; do
    set +e
    run check --assignment "$tmp/margin.json" --shaders "$tmp/corpus/$who" --seed "${2:-$seed}" \
      --time-limit 300 --report "$tmp/$1-$who.json" >/dev/null 2>"$tmp/$1-$who.err"
    set -e
    [ -f "$tmp/$1-$who.json" ] || fail "check of $who ($1) wrote no report: $(cat "$tmp/$1-$who.err")"
  done
}
corpus_check home
# The depth entry's pair (its second drawn row, the margin moved by a ratio the seed draws, judged
# by how the picture changes: docs/check.md "the response"): at home from the shipped figures of
# both rows, as the grader judges it with ours. A constant picked by testing the margin's value
# passes each picture's band and fails the pair in both.
mkdir -p "$tmp/depth/correct/depth" "$tmp/depth/by_value/depth"
cp "$src/shaders_core/depth/lit.frag" "$tmp/depth/correct/depth/"
cp "$src/tests/students/depth_game_margin_by_value/depth/lit.frag" "$tmp/depth/by_value/depth/"
depth_check() {  # depth_check LABEL: both depth hand-ins checked into $tmp/depth-LABEL-NAME.json
  for who in correct by_value; do
    set +e
    run check --stage depth --shaders "$tmp/depth/$who" --seed "$seed" --time-limit 300 \
      --report "$tmp/depth-$1-$who.json" >/dev/null 2>"$tmp/depth-$1-$who.err"
    set -e
    [ -f "$tmp/depth-$1-$who.json" ] ||
      fail "check of depth $who ($1) wrote no report: $(cat "$tmp/depth-$1-$who.err")"
  done
}
depth_check home
# The second row's values typed back with --set at home: judged by its band from the shipped
# figures of that row (not a SKIP), as `check --set` repeats any drawn row.
sets=$(python3 -c 'import json, sys
rows = [x for st in json.load(open(sys.argv[1]))["stages"] for x in st["rows"]]
second = [x for x in rows if "response:margin" in x["lesson"]][0]
print(" ".join("--set %s=%s" % (k, second["parameters"][k]) for k in ("depth-format", "map-size", "margin")))' \
  "$tmp/depth-home-by_value.json")
set +e  # the fixed views at these settings are judged by the defaults' lesson: acne, FAIL
# shellcheck disable=SC2086
run check --stage depth --shaders "$tmp/depth/by_value" --seed "$seed" $sets --time-limit 300 \
  --report "$tmp/depth-set.json" >/dev/null 2>"$tmp/depth-set.err"
set -e
python3 -c 'import json, sys
rows = [x for st in json.load(open(sys.argv[1]))["stages"] for x in st["rows"]]
row = [x for x in rows if x["view"] == "displaced"][0]
assert row["verdict"] == "PASS" and "student edition: our figures shipped for seed" in row["message"], row' \
  "$tmp/depth-set.json" ||
  fail "the depth pair's second row typed back with --set is not judged from the shipped figures: $(tail -2 "$tmp/depth-set.err")"
# The installed tree itself checked (no folder laid over) is the starter: its displaced and drawn
# rows are judged by the solution's data too, never against its own stubs (it has no drawn rows:
# those draw a folder's values against ours).
set +e
run check --stage margin --seed "$seed" --time-limit 300 --report "$tmp/home-installed.json" \
  >/dev/null 2>"$tmp/home-installed.err"
set -e
python3 -c 'import json, sys
rows = lambda p: {(st["stage"], st["tree"], x["view"], x["lesson"]): x["verdict"]
                  for st in json.load(open(p))["stages"] for x in st["rows"]}
a, b = rows(sys.argv[1]), rows(sys.argv[2])
assert a and all(b[k] == v for k, v in a.items()), [(k, v, b.get(k)) for k, v in a.items() if b.get(k) != v]' \
  "$tmp/home-installed.json" "$tmp/home-starter.json" ||
  fail "the installed student edition checked as it is is not judged as its starter: $(tail -2 "$tmp/home-installed.err")"
# A run's seed the data does not ship: the drawn rows are drawn at a shipped one, and say so.
all=$corpus; corpus=constant; corpus_check other 4242; corpus=$all
# Nothing to release from: the edition has no solution regions.
set +e
run release --assignment "$tmp/margin.json" --out "$tmp/rel" >/dev/null 2>"$tmp/err"
code=$?
set -e
[ $code -eq 2 ] && grep -q "no BEGIN SOLUTION region" "$tmp/err" ||
  fail "release in the student edition gave exit $code: $(cat "$tmp/err")"
# The instructor's install: the solutions component beside it is what the program draws with.
cmake --install "$build" --prefix "$tmp/p" --component solutions >/dev/null
[ -f "$data/solutions/shaders_legacy/margin/lit.frag" ] || fail "the solutions component is not installed"
# Where docs/assignment.md ("Gradescope") says the source kit lands is where it is.
kit=$(tr '\n' ' ' <"$src/docs/assignment.md" | grep -o 'installs the kit into `[^`]*`' | head -1 | cut -d'`' -f2)
[ -n "$kit" ] && [ -f "$tmp/p/$kit/CMakeLists.txt" ] ||
  fail "docs/assignment.md says the source kit is installed into '$kit': not there"
out=$(run check --stage margin --time-limit 300) || fail "check --stage margin with the solutions: $out"
corpus_check instructor
depth_check instructor
python3 - "$tmp" <<'PY' || fail "the student edition does not judge the depth pair as the grader"
import json, sys
tmp = sys.argv[1]
def drawn(path):  # by lesson: the verdict and each reason's figure and whether it held
    return {x["lesson"]: (x["verdict"], [(f["figure"], f.get("change_from", ""), f["passed"])
                                         for f in x["reasons"]])
            for st in json.load(open(path))["stages"] for x in st["rows"] if x["view"] == "drawn"}
for who in ("correct", "by_value"):
    home, mine = drawn(f"{tmp}/depth-home-{who}.json"), drawn(f"{tmp}/depth-instructor-{who}.json")
    assert home == mine, (who, home, mine)
    second = [v for k, v in home.items() if "response:margin" in k]
    assert len(second) == 1 and any(c.startswith("margin=") for _, c, _ in second[0][1]), home
    print(f"depth {who}: drawn rows {[v[0] for v in home.values()]} at home and with the solutions")
verdicts = lambda who: [v[0] for v in drawn(f"{tmp}/depth-home-{who}.json").values()]
assert verdicts("correct") == ["PASS", "PASS"], verdicts("correct")
assert verdicts("by_value") == ["PASS", "FAIL"], verdicts("by_value")
PY
run grade "$tmp/corpus" --assignment "$tmp/margin.json" --out "$tmp/graded" --seed $seed \
  --time-limit 300 >/dev/null || fail "grade of the corpus with the solutions"
python3 - "$tmp" "$data/src/stages/drawn_figures.json" <<'PY' || fail "the student edition does not judge as the grader"
import json, sys
tmp, shipped = sys.argv[1], json.load(open(sys.argv[2]))["seeds"]
def rows(path):
    r = json.load(open(path))
    return r["score"], {(x["stage"], x["tree"], x["view"], x["lesson"]): (x["verdict"], x["points"])
                        for st in r["stages"] for x in st["rows"]}
def drawn_rows(path):
    return [x for st in json.load(open(path))["stages"] for x in st["rows"] if x["view"] == "drawn"]
want = {"starter": lambda s: s == 0, "correct": lambda s: s == 10,
        "known_eyes": lambda s: 0 < s < 10, "constant": lambda s: 0 < s < 10}
for who, ok in want.items():
    home, mine = rows(f"{tmp}/home-{who}.json"), rows(f"{tmp}/instructor-{who}.json")
    graded = rows(f"{tmp}/graded/students/{who}.json")
    # One grading truth: every row, verdict and point the same at home as graded, drawn rows too.
    assert home == mine == graded, (who, home, mine, graded)
    drawn = drawn_rows(f"{tmp}/home-{who}.json")
    assert drawn and all("student edition: our figures shipped for seed" in x["message"]
                         for x in drawn if x["verdict"] in ("PASS", "FAIL")), (who, drawn)
    assert ok(home[0]), (who, home[0])
    assert any(v == "displaced" for (_, _, v, _) in home[1]), who
    print(f"{who}: {home[0]} of 10 at home, with the solutions and graded ({len(home[1])} rows, "
          f"{len(drawn)} drawn: {[x['verdict'] for x in drawn]})")
fails = lambda path: [x["verdict"] for x in drawn_rows(path)].count("FAIL")
assert fails(f"{tmp}/home-constant.json") > 0, "the constant passes its drawn rows at home"
assert all(x["verdict"] == "PASS" for x in drawn_rows(f"{tmp}/home-correct.json"))
# At a seed the data does not ship, the home check draws at one it does, and fails the constant.
other = drawn_rows(f"{tmp}/other-constant.json")
assert other and all(x["seed"] in shipped and x["seed"] != 4242 for x in other), other
assert [x["verdict"] for x in other].count("FAIL") > 0, other
print(f"constant at seed 4242: drawn at seed {other[0]['seed']} of {shipped}: "
      f"{[x['verdict'] for x in other]}")
PY
run release --assignment "$tmp/margin.json" --out "$tmp/rel" --time-limit 300 >/dev/null ||
  fail "release with the solutions component"
grep -q "TODO" "$tmp/rel/shaders/margin/lit.frag" || fail "the release is not stubbed"
echo "student edition test: ok"
