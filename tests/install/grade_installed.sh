#!/usr/bin/env bash
# Installs the program into a temporary prefix, moves the prefix elsewhere, and grades a
# submission with the moved copy from / with the source tree's fallback switched off: the
# installed program must find shaders, scenes and expectations under its own prefix, and write
# the same Gradescope zip as the build tree (its source kit is installed too).
#   grade_installed.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
mv "$tmp/prefix" "$tmp/moved"
exe=$tmp/moved/bin/shadowlab
data=$tmp/moved/share/shadowlab
fail() { echo "install test: FAIL: $*"; exit 1; }
for f in shaders_core/phong/lit.frag shaders_legacy/phong/lit.frag scenes/slides.json \
         slides_examples/acne.json src/stages/expectations.json; do
  [ -e "$data/$f" ] || fail "$data/$f is not installed"
done
run() { (cd / && env -u SHADOWLAB_DATA_DIR SHADOWLAB_NO_SOURCE_DIR=1 "$exe" "$@"); }
stages=$(run stages) && grep -q hardware <<<"$stages" || fail "'shadowlab stages' does not list hardware"
# A correct submission (our hardware stage, copied) passes; a broken one is exit 2.
mkdir -p "$tmp/good/hardware" "$tmp/bad/hardware"
cp "$src/shaders_core/hardware/lit.frag" "$tmp/good/hardware/"
printf '#version 330 core\nvoid main() { oops }\n' > "$tmp/bad/hardware/lit.frag"
out=$(run check --stage hardware --set filter=linear --shaders "$tmp/good" --report "$tmp/good.json") ||
  fail "the correct submission did not pass: $out"
echo "$out" | grep -q "check against $data/src/stages/expectations.json" ||
  fail "expectations not read from the prefix: $out"
grep -q '"verdict": "PASS"' "$tmp/good.json" || fail "report lacks PASS"
set +e
run check --stage hardware --set filter=linear --shaders "$tmp/bad" --report "$tmp/bad.json" \
  >/dev/null 2>"$tmp/err"
code=$?
set -e
[ $code -eq 2 ] || fail "a broken submission gave exit $code, expected 2: $(cat "$tmp/err")"
grep -q '"verdict": "ERROR"' "$tmp/bad.json" || fail "report lacks ERROR"
# The installed copy writes the Gradescope zip from its installed source kit, entry for entry
# (names, bytes, modes) the zip the build tree's program writes.
# The kit comes with the instructor's `solutions` component (the student edition has none).
cmake --install "$build" --prefix "$tmp/moved" --component solutions >/dev/null
[ -s "$data/solutions/source_kit.txt" ] || fail "source_kit.txt is not installed"
run release --assignment "$src/assignments/lab4.json" --gradescope --out "$tmp/release-installed" \
  >/dev/null 2>"$tmp/err" || fail "the installed copy could not write the Gradescope zip: $(cat "$tmp/err")"
"$build/shadowlab" release --assignment "$src/assignments/lab4.json" --gradescope \
  --out "$tmp/release-build" >/dev/null
python3 - "$tmp/release-installed/autograder.zip" "$tmp/release-build/autograder.zip" <<'PY' ||
import sys, zipfile
def entries(path):
    z = zipfile.ZipFile(path)
    return {i.filename: (z.read(i), i.external_attr >> 16) for i in z.infolist()}
installed, built = (entries(p) for p in sys.argv[1:3])
if installed != built:
    differ = sorted(n for n in installed.keys() | built.keys() if installed.get(n) != built.get(n))
    sys.exit(f"the zips differ in {len(differ)} entries: {differ[:10]}")
print(f"install test: the installed copy's autograder.zip equals the build's ({len(built)} files)")
PY
  fail "the installed copy's autograder.zip is not the build tree's"
# Without its share/ folder the moved program says what is missing (no fallback to the sources).
rm -rf "$data/shaders_core" "$data/solutions"
set +e
run render --stage phong --size 64x48 --repeat 0 --out "$tmp/x.png" >/dev/null 2>"$tmp/err"
code=$?
set -e
[ $code -ne 0 ] || fail "rendered without installed shaders (fell back to the sources?)"
echo "install test: ok (installed to a prefix, moved, graded from /)"
