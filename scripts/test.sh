#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite (unit, render, window under Xvfb,
# the bad-input corpus), then the memory checks: the scene fuzzer and valgrind
# (docs/robustness.md; each step prints its time).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
bash scripts/fuzz.sh
bash scripts/valgrind.sh
