#!/usr/bin/env bash
# Builds the browser edition (GUIDE section 9, docs/web.md) with Debian's emscripten into
# build-web/site/: index.html and one self-contained shadowlab.js. Serve the folder with any
# static host (python3 -m http.server -d build-web/site) or open index.html from the disk.
# usage: scripts/web.sh [BUILD_DIR]   (default build-web)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build-web}
for tool in emcmake emcc glslangValidator spirv-cross; do
  command -v "$tool" >/dev/null ||
    { echo "web: $tool missing: install emscripten glslang-tools spirv-cross (scripts/deps.sh --web)" >&2; exit 2; }
done
# Debian's emscripten runs its JavaScript tools with the node on PATH, which may not be Debian's
# (then it finds Debian's acorn only through NODE_PATH).
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
start=$SECONDS
echo "web: configuring $out (emcmake cmake)" >&2
emcmake cmake -S . -B "$out" -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "web: compiling with $(nproc) jobs" >&2
cmake --build "$out" -j"$(nproc)" >&2
echo "web: $out/site ready in $((SECONDS - start)) s ($(du -k "$out/site/shadowlab.js" | cut -f1) KiB of .js)" >&2
