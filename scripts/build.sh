#!/usr/bin/env bash
# Configures and builds the Release preset into build/. Progress goes to stderr (callers that
# silence stdout still show it): the first build takes minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
echo "build: configuring (cmake --preset default)" >&2
cmake --preset default >/dev/null
echo "build: compiling with $(nproc) jobs ([ N%] lines below)" >&2
cmake --build build -j"$(nproc)" >&2
echo "build: done in $((SECONDS - start)) s" >&2
