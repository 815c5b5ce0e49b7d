#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite (unit, render, window under Xvfb,
# the bad-input corpus, the course cycle), then the memory checks: AddressSanitizer + UBSan, the
# scene fuzzer and valgrind (docs/robustness.md), once, on this system. Every step runs even
# when an earlier one failed, so one run shows every problem; the exit code is 1 if any failed.
#
# In CI (CI=true; elsewhere SHADOWLAB_CHROOT=1, as root) also, after this system's suite: the
# README's two commands, `bash scripts/run.sh` then `bash scripts/test.sh`, in fresh debootstrap
# chroots of Debian 13 and testing (scripts/chroot_suite.sh), and the Gradescope zip of
# assignments/lab4.json built and graded as Gradescope does in a fresh Debian 12 chroot
# (scripts/gradescope_suite.sh). In those chroots SHADOWLAB_TEST_SCOPE=system: what can differ
# by system (the build, every render, window, GLSL, command and course test) runs; the memory
# checks, the benchmarks and the load test, which the host just ran on the same sources, do not.
# README "Systems" has the times.
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh --test || exit 1
bash scripts/build.sh || exit 1
failed=()
step() {
  local name=$1 start=$SECONDS
  shift
  "$@" || failed+=("$name")
  echo "test.sh: $name took $((SECONDS - start)) s"
}
if [ "${SHADOWLAB_TEST_SCOPE:-all}" = system ]; then
  step ctest ctest --test-dir build --output-on-failure -j2 -LE '^(bench|load)$'
  echo "test.sh: scope 'system': benchmarks, the load test and the memory checks left to the host's suite"
else
  step ctest ctest --test-dir build --output-on-failure -j2
  step sanitizers bash scripts/sanitizers.sh
  step fuzz bash scripts/fuzz.sh
  step valgrind bash scripts/valgrind.sh
fi
if [ -n "${CI:-}" ] || [ -n "${SHADOWLAB_CHROOT:-}" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  # One suite at a time, after the host's window tests: each takes both cores, and a chroot
  # shares the host's X abstract sockets.
  for suite in trixie testing; do step "chroot-$suite" bash scripts/chroot_suite.sh "$suite"; done
  if ./build/shadowlab release --assignment assignments/lab4.json --gradescope \
    --out "$work/lab4-release" >/dev/null; then
    step gradescope bash scripts/gradescope_suite.sh "$work/lab4-release/autograder.zip"
  else
    echo "test.sh: gradescope not run: this build could not write lab4's autograder.zip"
    failed+=(gradescope)
  fi
elif [ "${SHADOWLAB_TEST_SCOPE:-all}" != system ]; then
  echo "test.sh: chroot and Gradescope suites skipped: CI or SHADOWLAB_CHROOT=1 runs them (root, debootstrap)"
fi
if [ ${#failed[@]} -gt 0 ]; then
  echo "test.sh: FAILED: ${failed[*]}"
  exit 1
fi
echo "test.sh: all passed"
