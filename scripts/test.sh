#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite (unit, render, window under Xvfb,
# the bad-input corpus, the course cycle), then the memory checks: AddressSanitizer + UBSan, the
# scene fuzzer and valgrind (docs/robustness.md), once, on this system. Every step runs even
# when an earlier one failed, so one run shows every problem; the exit code is 1 if any failed.
#
# In CI (CI=true; elsewhere SHADOWLAB_CHROOT=1, as root) this machine orchestrates instead of
# testing itself: the README's two commands, `bash scripts/run.sh` then `bash scripts/test.sh`,
# on the same tree in fresh debootstrap chroots of Debian 12, 13 and testing
# (scripts/chroot_suite.sh): Debian 12's the whole suite; 13's and testing's with
# SHADOWLAB_TEST_SCOPE=system, what can differ by system (the build, every render, window, GLSL,
# command and course test), leaving to Debian 12's run of the same sources the memory checks,
# the benchmarks and the load test. Then the Gradescope zip that Debian 12's installed copy
# writes, built and graded as Gradescope does (scripts/gradescope_suite.sh). README "Systems".
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh --test || exit 1
failed=()
step() {
  local name=$1 start=$SECONDS
  shift
  "$@" || failed+=("$name")
  echo "test.sh: $name took $((SECONDS - start)) s"
}
if [ -n "${CI:-}" ] || [ -n "${SHADOWLAB_CHROOT:-}" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  # One suite at a time: each takes both cores (ctest -j2, the builds) and X's abstract sockets.
  step chroot-bookworm bash scripts/chroot_suite.sh bookworm --zip "$work/autograder.zip"
  for suite in trixie testing; do
    step "chroot-$suite" env SHADOWLAB_TEST_SCOPE=system bash scripts/chroot_suite.sh "$suite"
  done
  if [ -s "$work/autograder.zip" ]; then
    step gradescope bash scripts/gradescope_suite.sh "$work/autograder.zip"
  else
    echo "test.sh: gradescope not run: the Debian 12 suite wrote no autograder.zip"
    failed+=(gradescope)
  fi
else
  bash scripts/build.sh || exit 1
  if [ "${SHADOWLAB_TEST_SCOPE:-all}" = system ]; then
    step ctest ctest --test-dir build --output-on-failure -j2 -LE '^(bench|load)$'
    echo "test.sh: scope 'system': the benchmarks, the load test and the memory checks are left to Debian 12's suite"
  else
    step ctest ctest --test-dir build --output-on-failure -j2
    step sanitizers bash scripts/sanitizers.sh
    step fuzz bash scripts/fuzz.sh
    step valgrind bash scripts/valgrind.sh
  fi
fi
if [ ${#failed[@]} -gt 0 ]; then
  echo "test.sh: FAILED: ${failed[*]}"
  exit 1
fi
echo "test.sh: all passed"
