#!/usr/bin/env bash
# Builds the browser edition (GUIDE section 9, docs/web.md) with Debian's emscripten into
# build-web/site/: index.html and one self-contained shadowlab.js. Serve the folder with any
# static host (python3 -m http.server -d build-web/site) or open index.html from the disk.
# Where the native program is built (build/shadowlab, or $SHADOWLAB_NATIVE), also
# build-web/site-student/: the student edition's page (every solution region stubbed), the one a
# course publishes for its students.
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
native=${SHADOWLAB_NATIVE:-build/shadowlab}
[ -x "$native" ] && native=$(realpath "$native") || native=
emcmake cmake -S . -B "$out" -DCMAKE_BUILD_TYPE=Release -DSHADOWLAB_NATIVE="$native" >/dev/null
echo "web: compiling with $(nproc) jobs" >&2
cmake --build "$out" -j"$(nproc)" >&2
echo "web: $out/site ready in $((SECONDS - start)) s ($(du -k "$out/site/shadowlab.js" | cut -f1) KiB of .js)" >&2
if [ -n "$native" ]; then
  echo "web: $out/site-student ready: the student edition's page (solutions stubbed)" >&2
else
  echo "web: no native build (build/shadowlab): no student edition's page (site-student)" >&2
fi
