#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite (unit, render, window under Xvfb,
# the bad-input corpus), then the memory checks: AddressSanitizer + UBSan, the scene fuzzer and
# valgrind (docs/robustness.md), once, on this system; in CI also the suite in fresh Debian 13
# and testing chroots (scripts/chroot_suite.sh). Every step runs even when an earlier one
# failed, so one CI run shows every problem; the exit code is 1 if any failed.
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
step ctest ctest --test-dir build --output-on-failure -j2
# Debian 13 and testing in fresh debootstrap chroots (README "Systems"), one after the other
# and after the host's window tests (a chroot and the host share X's abstract sockets). CI runs
# them (CI=true); elsewhere SHADOWLAB_CHROOT=1 asks for them (root, debootstrap).
if [ -n "${CI:-}" ] || [ -n "${SHADOWLAB_CHROOT:-}" ]; then
  for suite in trixie testing; do step "chroot-$suite" bash scripts/chroot_suite.sh "$suite"; done
else
  echo "test.sh: chroot suites (Debian 13, testing) skipped: CI or SHADOWLAB_CHROOT=1 runs them"
fi
step sanitizers bash scripts/sanitizers.sh
step fuzz bash scripts/fuzz.sh
step valgrind bash scripts/valgrind.sh
if [ ${#failed[@]} -gt 0 ]; then
  echo "test.sh: FAILED: ${failed[*]}"
  exit 1
fi
echo "test.sh: all passed"
