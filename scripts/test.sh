#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite (unit, render, window under Xvfb).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
