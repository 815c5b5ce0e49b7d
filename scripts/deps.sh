#!/usr/bin/env bash
# Installs the packages shadowlab needs on this system, only those missing (apt-get; sudo when
# not root). Reads /etc/os-release: Debian 12, 13 and testing, Ubuntu 22.04 and 24.04 have their
# package names below; any other system gets one message naming what to install.
#   bash scripts/deps.sh          what building and running need (scripts/run.sh)
#   bash scripts/deps.sh --test   also the fuzzer, sanitizer and valgrind packages (scripts/test.sh)
#   bash scripts/deps.sh --web    also the browser edition's (scripts/web.sh, ctest -L web): only
#                                 on Debian 12, the one system CI builds it on (emscripten is
#                                 109 MB to download, 800 MB installed: not in every chroot)
#   bash scripts/deps.sh --print  print the package names for this system and install nothing
set -euo pipefail
mode=run
for a in "$@"; do
  case $a in
    --test) mode=test ;;
    --web) web_wanted=1 ;;
    --print) print=1 ;;
    *) echo "deps: unknown option '$a' (--test, --web, --print)" >&2; exit 2 ;;
  esac
done
os_release=${SHADOWLAB_OS_RELEASE:-/etc/os-release}  # a test can point it elsewhere
ID="" VERSION_ID="" VERSION_CODENAME="" PRETTY_NAME=""
# shellcheck disable=SC1090
[ -r "$os_release" ] && . "$os_release"

# Building and running (the tests' configure step needs xvfb and xdotool too: ctest is built
# with the program). The Mesa drivers are named: --no-install-recommends would leave out the
# EGL and GLX vendors and llvmpipe itself.
common=(cmake g++ make pkg-config python3 python3-glad libx11-dev libegl-dev libglm-dev
        libcli11-dev nlohmann-json3-dev libstb-dev libpng-dev libgtest-dev xvfb xauth xdotool gnuplot-nox
        libegl-mesa0 libglx-mesa0 libgl1-mesa-dri)
# The course cycle: libarchive unpacks students' zips (safely: src/course/archive.h); glslang,
# Khronos' reference GLSL compiler, decides what a shader may say on every driver alike
# (src/gl/glsl_standard.h; glslang 11 on Ubuntu 22.04 .. 16 on Debian testing: cmake/glslang.cmake).
# glslang-tools too: Debian testing's glslang CMake package names its /usr/bin/glslang and stops
# the configure step where that file is missing (glslang-dev 16.6 does not pull it in).
course=(libarchive-dev glslang-dev glslang-tools)
case "$ID:${VERSION_ID:-}" in
  debian:12)
    system="Debian 12"
    run=(freeglut3-dev libosmesa6-dev)
    test=(clang libclang-rt-14-dev valgrind debootstrap chromium) ;;  # CI's chroots; the pages' browser
  debian:13)
    system="Debian 13"
    run=(libglut-dev libosmesa6-dev)  # Mesa 25.0: the last with OSMesa
    test=(clang libclang-rt-dev valgrind debootstrap chromium) ;;
  debian:)  # testing and sid carry no VERSION_ID; Mesa 25.1 on has no OSMesa (EGL headless)
    system="Debian testing ($VERSION_CODENAME)"
    run=(libglut-dev)
    test=(clang libclang-rt-dev valgrind debootstrap chromium) ;;
  ubuntu:22.04)
    system="Ubuntu 22.04"
    run=(freeglut3-dev libosmesa6-dev)  # glad 0.1 and no glut.pc: CMakeLists.txt handles both
    test=(clang libfuzzer-14-dev valgrind) ;;  # chromium is a snap here: course_grade is skipped
  ubuntu:24.04)
    system="Ubuntu 24.04"
    run=(libglut-dev)  # libosmesa6-dev only while the archive still has it (added below)
    test=(clang libclang-rt-18-dev valgrind) ;;  # (chromium: a snap, as on 22.04)
  *)
    echo "deps: ${PRETTY_NAME:-this system} is not one deps.sh knows (Debian 12, 13, testing;" \
         "Ubuntu 22.04, 24.04). Install by hand: CMake >= 3.20, a C++17 compiler, pkg-config," \
         "python3 with glad (python3-glad), GLM, CLI11, nlohmann-json, stb, libpng, GoogleTest, freeglut," \
         "X11, EGL with Mesa's llvmpipe (OSMesa optional), glslang, Xvfb, xauth, xdotool, gnuplot;" \
         "for scripts/test.sh also clang with libFuzzer and valgrind." >&2
    exit 1 ;;
esac
packages=("${common[@]}" "${run[@]}" "${course[@]}")
[ "$mode" = test ] && packages+=("${test[@]}")
# The browser edition (docs/web.md): Debian 12's emscripten 3.1.6 with its prebuilt system
# libraries; spirv-cross (its version names the source package scripts/web_sources.py fetches
# with glslang's, unpacked by dpkg-dev's dpkg-source) and the browser tests.
if [ -n "${web_wanted:-}" ]; then
  if [ "$system" = "Debian 12" ]; then
    packages+=(emscripten spirv-cross dpkg-dev chromium chromium-driver python3-selenium)
  else
    echo "deps: --web: the browser edition is built and tested on Debian 12 only; skipped on $system" >&2
  fi
fi
if [ -n "${print:-}" ]; then
  echo "${packages[*]}"
  exit 0
fi

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
for p in "${packages[@]}"; do
  installed "$p" || missing+=("$p")
done
optional=()
[ "$system" = "Ubuntu 24.04" ] && ! installed libosmesa6-dev && optional+=(libosmesa6-dev)
if [ ${#missing[@]} -eq 0 ] && [ ${#optional[@]} -eq 0 ]; then
  echo "deps: $system, all ${#packages[@]} packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
# -q (not -qq, not >/dev/null): one line per download, unpack and set-up, so a first run that
# takes minutes shows what it is doing.
echo "deps: $system, apt-get update"
$sudo apt-get update -q
for p in "${optional[@]}"; do  # installed when the archive has it, else the build goes EGL-only
  apt-cache show "$p" >/dev/null 2>&1 && missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && { echo "deps: $system, nothing to install"; exit 0; }
echo "deps: installing ${#missing[@]} packages: ${missing[*]}"
echo "deps: apt-get install (downloads, then one line per package set up)"
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "deps: done"
