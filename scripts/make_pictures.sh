#!/usr/bin/env bash
# Regenerates the README's pictures (docs/images/) with the program itself.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p docs/images
for id in $(./build/shadowlab stages --json | python3 -c 'import json,sys; print(" ".join(s["id"] for s in json.load(sys.stdin)))'); do
  tree=core
  ./build/shadowlab stages --json | python3 -c "import json,sys; s=[x for x in json.load(sys.stdin) if x['id']=='$id'][0]; sys.exit(0 if 'core' in s['trees'] else 1)" || tree=legacy
  ./build/shadowlab render --stage "$id" --glsl "$tree" --size 320x240 --repeat 0 --out "docs/images/$id.png" >/dev/null
done
./build/shadowlab render --stage hardware --view shadow-map --size 320x240 --repeat 0 --out docs/images/hardware-shadow-map.png >/dev/null
./build/shadowlab render --stage rgb --view light-depth --size 320x240 --repeat 0 --out docs/images/rgb-light-depth.png >/dev/null
./build/shadowlab render --stage bias --set light-z=flipped --size 320x240 --repeat 0 --out docs/images/bias-flipped.png >/dev/null
./build/shadowlab render --stage rgb --set map-size=2048 --set margin=0.001 --size 320x240 --repeat 0 --out docs/images/rgb-2048-single.png >/dev/null
./build/shadowlab render --stage rgb --set map-size=2048 --set margin=0.001 --set encoding=packed --size 320x240 --repeat 0 --out docs/images/rgb-2048-packed.png >/dev/null
echo "pictures in docs/images/"
