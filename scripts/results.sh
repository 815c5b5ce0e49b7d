#!/usr/bin/env bash
# Regenerates docs/results.md and everything it shows: a full `shadowlab bench` and every
# `shadowlab sweep`, on this machine (a few minutes on 2 cores). Run it on a quiet machine.
# SL_INSTRUCTIONS=1 adds `bench --instructions` (callgrind, about 25 s per 640x480 configuration
# on a loaded 2-core machine: far beyond the 5-minute budget, so only on request).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh >/dev/null
out=docs/results
start=$SECONDS
./build/shadowlab bench --out "$out/bench" ${SL_INSTRUCTIONS:+--instructions}
echo "results: bench took $((SECONDS - start)) s"
start=$SECONDS
for axis in elevation margin offset near-far map-size; do
  ./build/shadowlab sweep "$axis" --out "$out/sweep"
done
echo "results: sweeps took $((SECONDS - start)) s"
python3 scripts/results_md.py "$out" > docs/results.md.tmp
mv docs/results.md.tmp docs/results.md
echo "wrote docs/results.md"
