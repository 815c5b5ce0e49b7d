#!/usr/bin/env bash
# Proves the README's quick start on a fresh Debian: makes a fresh debootstrap chroot of SUITE
# (bookworm = Debian 12, trixie = 13, testing), copies a clean clone of this repository's HEAD
# in, and runs there exactly what a user runs, in the README's order on the same tree:
#   bash scripts/run.sh     (installs what building and running need, builds, the main job)
#   bash scripts/test.sh    (installs the test packages, builds again, the tests and memory checks;
#                            with SHADOWLAB_TEST_SCOPE=system set here, the tests that can differ
#                            by system only: scripts/test.sh)
# Nothing is installed before them but the harness's compiler cache (scripts/chroot_lib.sh).
#   bash scripts/chroot_suite.sh bookworm|trixie|testing [--zip FILE]     (root; debootstrap)
# --zip FILE: afterwards, installs the build (cmake --install) and has the installed copy write
# assignments/lab4.json's Gradescope zip into FILE, for scripts/gradescope_suite.sh.
# The whole output is kept in $SHADOWLAB_CHROOT_LOGS/SUITE.log (default
# /var/tmp/shadowlab-chroot-logs); the progress lines and, on a failure, the log's end show here.
set -euo pipefail
suite=${1:?usage: chroot_suite.sh bookworm|trixie|testing [--zip FILE]}
case $suite in
  bookworm | trixie | testing) ;;
  *) echo "chroot_suite: suite '$suite' is not bookworm, trixie or testing" >&2; exit 2 ;;
esac
zip=""
if [ $# -ge 2 ]; then
  [ "$2" = --zip ] && [ $# -eq 3 ] || { echo "chroot_suite: usage: chroot_suite.sh SUITE [--zip FILE]" >&2; exit 2; }
  zip=$(realpath -m "$3")
fi
chroot_name="chroot_suite[$suite]"
source "$(dirname "$0")/chroot_lib.sh"
chroot_private_mounts "$@"
chroot_needs
repo=$(cd "$(dirname "$0")/.." && pwd)
logs=${SHADOWLAB_CHROOT_LOGS:-/var/tmp/shadowlab-chroot-logs}
mkdir -p "$logs"
log=$logs/$suite.log
: >"$log"

chroot_make "$suite" "$suite" "$suite"
git clone --quiet --no-hardlinks "$repo" "$root/root/shadowlab"
chroot_say "chroot ready, $(git -C "$repo" rev-parse --short HEAD) cloned"

# readme_command NAME COMMAND: one of the README's commands, its lines in the log; the lines
# that say how far it got shown here.
readme_command() {
  local name=$1 command=$2 start=$SECONDS status
  echo "== $command" >>"$log"
  set +e
  chroot_run /root/shadowlab "$command" 2>&1 | tee -a "$log" |
    grep --line-buffered -E '^(deps: (installing|done|Debian)|build: done|test\.sh: |sanitizers: (built|done)|fuzz: done|valgrind: done)' |
    sed -u "s/^/$chroot_name:   /"
  status=${PIPESTATUS[0]}
  set -e
  chroot_say "$name: exit $status in $((SECONDS - start)) s"
  if [ "$status" -ne 0 ]; then
    tail -60 "$log"
    echo "$chroot_name: the whole output is in $log"
  fi
  return "$status"
}
# The chroot's system and the versions that decide the build (the log's first lines).
status=0
readme_command "command 1 (bash scripts/run.sh)" 'bash scripts/run.sh' || status=1
chroot_run / 'grep ^PRETTY_NAME /etc/os-release; dpkg-query -W -f "\${Package} \${Version}\n" \
  g++ cmake libegl-mesa0 libosmesa6-dev python3-glad valgrind 2>/dev/null' >>"$log" 2>&1 || true
if [ $status -eq 0 ]; then
  # SHADOWLAB_TEST_SCOPE=system (scripts/test.sh sets it for Debian 13 and testing) passes on.
  readme_command "command 2 (bash scripts/test.sh)" \
    "${SHADOWLAB_TEST_SCOPE:+SHADOWLAB_TEST_SCOPE=$SHADOWLAB_TEST_SCOPE }bash scripts/test.sh" || status=1
fi
if [ -n "$zip" ] && [ $status -eq 0 ]; then
  chroot_run /root/shadowlab 'cmake --install build --prefix /tmp/installed >/dev/null &&
    cmake --install build --prefix /tmp/installed --component solutions >/dev/null &&
    cd / && /tmp/installed/bin/shadowlab release --assignment /root/shadowlab/assignments/lab4.json \
      --gradescope --out /tmp/lab4-release >/dev/null' >>"$log" 2>&1 ||
    { chroot_say "the installed copy could not write the Gradescope zip"; tail -20 "$log"; exit 1; }
  cp "$root/tmp/lab4-release/autograder.zip" "$zip"
  chroot_say "the installed copy wrote $zip"
fi
chroot_say "done (exit $status)"
exit $status
