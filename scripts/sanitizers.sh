#!/usr/bin/env bash
# AddressSanitizer + UBSan (the `asan` preset, build-asan/): the unit tests, one small headless
# render of every stage in both shader trees (fixed: legacy only) and the bad-input corpus.
# Mesa's own leaks are suppressed by tests/sanitizers/lsan.supp; any report about our code fails.
# The instrumented program does the same work more slowly, so its workers' time budget follows:
# the corpus runs with --time-scale $SANITIZER_TIME_SCALE (default below, measured in
# docs/robustness.md "Sanitizers"): every case's bound and every --time-limit a case gives times
# that factor; the default, auto, is calibrated on our shaders in this same build already.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
start=$SECONDS
cmake --preset asan >/dev/null
units=$(ls tests/unit/test_*.cpp | xargs -n1 basename | sed 's/\.cpp$//')
cmake --build build-asan -j"$(nproc)" --target shadowlab $units
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:exitcode=99
export LSAN_OPTIONS=suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:exitcode=98
echo "sanitizers: built in $((SECONDS - start)) s"
failed=0  # a failing part is reported and the others still run
# Each unit-test executable once, all its tests in one process (ctest would start one process
# per test, 200 instrumented starts, and list each executable's tests first): the same tests.
logs=$(mktemp -d)
if ! printf '%s\n' $units | xargs -P "$(nproc)" -I{} sh -c \
    'cd build-asan/tests && ./{} --gtest_brief=1 >"$0/{}.log" 2>&1 || { echo "sanitizers: FAIL {}"; cat "$0/{}.log"; exit 1; }' "$logs"; then
  failed=1
fi
echo "sanitizers: unit tests: $(cat "$logs"/*.log | awk '/^\[  PASSED  \]/ {n += $4} END {print n + 0}') passed"
rm -rf "$logs"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
stages=$(build-asan/shadowlab stages | awk '$1 ~ /^[0-9]+$/ {print $2}')
for tree in core legacy; do
  for stage in $stages; do
    [ "$tree" = core ] && [ "$stage" = fixed ] && continue
    if ! build-asan/shadowlab render --stage "$stage" --glsl "$tree" --size 160x120 --repeat 1 \
         --out "$out/$stage-$tree.png" >"$out/log" 2>&1; then
      echo "sanitizers: FAIL render --stage $stage --glsl $tree"; cat "$out/log"; failed=1
    elif grep -q "runtime error:\|Sanitizer" "$out/log"; then
      echo "sanitizers: REPORT in render --stage $stage --glsl $tree"; cat "$out/log"; failed=1
    else
      echo "sanitizers: ok render --stage $stage --glsl $tree"
    fi
  done
done
# The bad-input corpus again: every error path under the sanitizers (a report changes the exit
# code or shows on stderr, and the runner fails the case).
python3 tests/bad_inputs/run_cases.py build-asan/shadowlab \
  --time-scale "${SANITIZER_TIME_SCALE:-6}" || failed=1
echo "sanitizers: done in $((SECONDS - start)) s"
exit $failed
