#!/usr/bin/env bash
# The main job: install what is missing, build, render every stage headless (OSMesa) in both
# shader trees into out/, and print a table of stage, tree, file and milliseconds per frame.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh >/dev/null
mkdir -p out
printf '%-10s %-7s %-28s %14s %14s\n' stage glsl file "first ms" "ms/frame"
for stage in $(./build/shadowlab stages --json | python3 -c 'import json,sys; print(" ".join(s["id"]+":"+",".join(s["trees"]) for s in json.load(sys.stdin)))'); do
  id=${stage%%:*}
  for tree in $(echo "${stage#*:}" | tr ',' ' '); do
    file="out/$id-$tree.png"
    line=$(./build/shadowlab render --stage "$id" --glsl "$tree" --out "$file")
    first=$(echo "$line" | sed -n 's/.*first frame \([0-9.]*\) ms.*/\1/p')
    median=$(echo "$line" | sed -n 's/.*median \([0-9.]*\) ms.*/\1/p')
    printf '%-10s %-7s %-28s %14.1f %14.1f\n' "$id" "$tree" "$file" "$first" "$median"
  done
done
