#!/usr/bin/env bash
# Regenerates docs/results.md and everything it shows: a full `shadowlab bench` and every
# `shadowlab sweep`, on this machine (a few minutes on 2 cores). Run it on a quiet machine.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh >/dev/null
out=docs/results
./build/shadowlab bench --out "$out/bench"
for axis in elevation margin offset near-far map-size; do
  ./build/shadowlab sweep "$axis" --out "$out/sweep"
done
python3 scripts/results_md.py "$out" > docs/results.md.tmp
mv docs/results.md.tmp docs/results.md
echo "wrote docs/results.md"
