#!/usr/bin/env bash
# Builds the fuzzers with clang (tests/fuzz, build-fuzz/) and runs them: the scene parser for
# FUZZ_SECONDS (default 60) from the built-in scenes, the bad-input scenes and tests/fuzz/corpus/
# (inputs that once crashed); the course's CSV and ISO time parsers for FUZZ_TEXT_SECONDS
# (default 20) from tests/fuzz/course_text/. A crash fails and leaves its input in build-fuzz/.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
cxx=$(command -v clang++-14 || command -v clang++)
CXX=$cxx cmake -S tests/fuzz -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j"$(nproc)"
echo "fuzz: built in $((SECONDS - start)) s"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# fuzz NAME SECONDS DICT SEED... : the stored inputs must pass on their own first, then NAME
# mutates the small ones for SECONDS. libFuzzer's whole output goes to a log: its exit code is
# kept (a pipe would lose it), and a run that never started (a binary that does not load, a flag
# it refuses) is a failure too.
fuzz() {
  local name=$1 seconds=$2 dict=$3; shift 3
  local dir="$work/$name" log="$work/$name.log" rc=0
  if ! "build-fuzz/$name" -runs=0 "$@" >"$log" 2>&1; then
    grep -v "^INFO" "$log"; echo "fuzz: $name: a stored input fails"; exit 1
  fi
  echo "fuzz: $name: $# stored inputs pass"
  # Seeds for mutation: the small ones (a 200 KB nesting bomb would eat the time).
  mkdir -p "$dir/seeds" "$dir/new"
  for f in "$@"; do
    [ "$(stat -c %s "$f")" -le 8192 ] && cp "$f" "$dir/seeds/$(basename "$(dirname "$f")")-$(basename "$f")"
  done
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "build-fuzz/$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 ${dict:+-dict=$dict} -artifact_prefix=build-fuzz/ \
    -print_final_stats=1 "$dir/new" "$dir/seeds" >"$log" 2>&1 || rc=$?
  grep -E "^#[0-9]+ +DONE|stat::number_of_executed_units|ERROR|SUMMARY|Test unit written" "$log" || true
  if ls build-fuzz/crash-* build-fuzz/timeout-* build-fuzz/oom-* build-fuzz/leak-* >/dev/null 2>&1; then
    echo "fuzz: $name: FAILED, inputs kept in build-fuzz/"; exit 1
  fi
  if [ "$rc" -ne 0 ]; then
    tail -n 20 "$log"; echo "fuzz: $name: FAILED, the fuzzer exited $rc"; exit 1
  fi
  local units
  units=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$log" | tail -n 1)
  if [ -z "$units" ] || [ "$units" -eq 0 ]; then
    tail -n 20 "$log"; echo "fuzz: $name: FAILED, the fuzzer ran no input"; exit 1
  fi
  echo "fuzz: $name: $units inputs run in $seconds s"
}

# Regressions first in each: every stored input must pass on its own.
fuzz fuzz_scene "${FUZZ_SECONDS:-60}" tests/fuzz/scene.dict \
  tests/fuzz/corpus/* tests/bad_inputs/scenes/*.json scenes/*.json
fuzz fuzz_course_text "${FUZZ_TEXT_SECONDS:-20}" "" tests/fuzz/course_text/*
echo "fuzz: done in $((SECONDS - start)) s"
