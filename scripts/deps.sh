#!/usr/bin/env bash
# Installs the Debian 12 packages shadowlab needs, only those missing (apt-get; sudo when not root).
set -euo pipefail
packages=(cmake g++ make pkg-config python3 freeglut3-dev libx11-dev libosmesa6-dev libegl-dev libglm-dev
          python3-glad libarchive-dev libcli11-dev nlohmann-json3-dev libstb-dev libgtest-dev xvfb xauth xdotool gnuplot-nox
          clang libclang-rt-14-dev valgrind)  # the last three: fuzzer and memory checks in CI
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#packages[@]} packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "deps: installing ${#missing[@]} packages: ${missing[*]}"
# -q (not -qq, not >/dev/null): one line per download, unpack and set-up, so a first run that
# takes minutes shows what it is doing.
echo "deps: apt-get update"
$sudo apt-get update -q
echo "deps: apt-get install (downloads, then one line per package set up)"
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "deps: done"
