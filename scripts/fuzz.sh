#!/usr/bin/env bash
# Builds the scene-parser fuzzer with clang (tests/fuzz, build-fuzz/) and runs it for
# FUZZ_SECONDS (default 60) from a seed corpus: the built-in scenes, the bad-input scenes and
# tests/fuzz/corpus/ (inputs that once crashed). A crash fails and leaves its input in build-fuzz/.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
cxx=$(command -v clang++-14 || command -v clang++)
CXX=$cxx cmake -S tests/fuzz -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j"$(nproc)"
echo "fuzz: built in $((SECONDS - start)) s"
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
# Regressions first: every stored input must pass on its own.
seeds=(tests/fuzz/corpus/* tests/bad_inputs/scenes/*.json scenes/*.json)
if ! build-fuzz/fuzz_scene -runs=0 "${seeds[@]}" >"$corpus.log" 2>&1; then
  grep -v "^INFO" "$corpus.log"; rm -f "$corpus.log"; echo "fuzz: a stored input fails"; exit 1
fi
rm -f "$corpus.log"
echo "fuzz: ${#seeds[@]} stored inputs pass"
# Seeds for mutation: the small ones (a 200 KB nesting bomb would eat the minute).
mkdir "$corpus/seeds" "$corpus/new"
for f in "${seeds[@]}"; do
  [ "$(stat -c %s "$f")" -le 8192 ] && cp "$f" "$corpus/seeds/$(basename "$(dirname "$f")")-$(basename "$f")"
done
# libFuzzer's whole output goes to a log: its exit code is kept (a pipe would lose it), and a
# run that never started (a binary that does not load, a flag it refuses) is a failure too.
log="$corpus/fuzz.log"
rc=0
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
build-fuzz/fuzz_scene -max_total_time="${FUZZ_SECONDS:-60}" -timeout=10 -rss_limit_mb=2048 \
  -max_len=65536 -dict=tests/fuzz/scene.dict -artifact_prefix=build-fuzz/ \
  -print_final_stats=1 "$corpus/new" "$corpus/seeds" >"$log" 2>&1 || rc=$?
grep -E "^#[0-9]+ +DONE|stat::number_of_executed_units|ERROR|SUMMARY|Test unit written" "$log" || true
if ls build-fuzz/crash-* build-fuzz/timeout-* build-fuzz/oom-* build-fuzz/leak-* >/dev/null 2>&1; then
  echo "fuzz: FAILED, inputs kept in build-fuzz/"; exit 1
fi
if [ "$rc" -ne 0 ]; then
  tail -n 20 "$log"; echo "fuzz: FAILED, the fuzzer exited $rc"; exit 1
fi
units=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$log" | tail -n 1)
if [ -z "$units" ] || [ "$units" -eq 0 ]; then
  tail -n 20 "$log"; echo "fuzz: FAILED, the fuzzer ran no input"; exit 1
fi
echo "fuzz: done in $((SECONDS - start)) s, $units inputs run"
