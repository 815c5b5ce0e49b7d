#!/usr/bin/env bash
# valgrind memcheck on small headless renders (hardware and mirror, 160x120) of the Release
# build, through the build's headless backend (`--backend auto`: OSMesa where the build has it,
# else EGL's surfaceless platform, as on Debian testing): no invalid read or write, no use of
# uninitialised memory in our code. llvmpipe runs on one thread (LP_NUM_THREADS=0) and
# Mesa/LLVM's JIT noise is suppressed by tests/sanitizers/valgrind.supp (Mesa's frames only).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Stages: hardware (shadow map, sampler2DShadow) and mirror (the most GL state: FBOs, stencil).
for stage in ${VALGRIND_STAGES:-hardware mirror}; do
  if ! LP_NUM_THREADS=0 valgrind --tool=memcheck --error-exitcode=1 --leak-check=no \
      --suppressions=tests/sanitizers/valgrind.supp --num-callers=30 \
      build/shadowlab render --stage "$stage" --backend auto --size 160x120 --repeat 1 \
      --out "$out/$stage.png" >"$out/log" 2>&1; then
    cat "$out/log"; echo "valgrind: FAILED on $stage"; exit 1
  fi
  test -s "$out/$stage.png"
  echo "valgrind: $stage: $(grep -o "ERROR SUMMARY.*" "$out/log")"
done
echo "valgrind: done in $((SECONDS - start)) s"
