#!/usr/bin/env bash
# Proves the README's commands on another Debian: makes a fresh debootstrap chroot of SUITE
# (trixie = Debian 13, testing), copies a clean clone of this repository's HEAD in, and runs
# there what scripts/test.sh runs on the host minus the host-only memory checks: deps.sh --test,
# the build, the whole ctest. Every mount it makes is undone on any exit (failure and Ctrl-C too).
#   bash scripts/chroot_suite.sh trixie|testing      (root; needs debootstrap)
# The .deb files are kept in $SHADOWLAB_CHROOT_CACHE (default /var/cache/shadowlab-chroot) so a
# rerun downloads less; a machine without that folder simply downloads everything.
# The chroot shares the host's X abstract sockets unless it has its own network namespace, which
# the build and tests get here (unshare --net); still, run suites one at a time, never beside the
# host's window tests (scripts/test.sh runs them after the host's ctest).
set -euo pipefail
suite=${1:?usage: chroot_suite.sh trixie|testing}
case $suite in
  trixie | testing) ;;
  *) echo "chroot_suite: suite '$suite' is not trixie or testing" >&2; exit 2 ;;
esac
[ "$(id -u)" -eq 0 ] || { echo "chroot_suite: needs root (debootstrap, mount, chroot)" >&2; exit 3; }
command -v debootstrap >/dev/null || { echo "chroot_suite: install debootstrap" >&2; exit 3; }
# Its own mount namespace, private: nothing mounted here reaches the host's tree (even where
# / is a shared mount), and the kernel drops every mount should this script be killed outright.
if [ -z "${SHADOWLAB_CHROOT_NS:-}" ]; then
  SHADOWLAB_CHROOT_NS=1 exec unshare --mount --propagation private bash "$0" "$@"
fi
repo=$(cd "$(dirname "$0")/.." && pwd)
# The Debian archive this machine's apt already uses (its main archive, not -security): the
# chroot reaches what the host reaches.
host_mirror() {
  local f
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
    [ -r "$f" ] && grep -v '^[[:space:]]*#' "$f"
  done | grep -oE '(https?|file)://[^ ]*/debian/?( |$)' | head -1 | tr -d ' ' || true
}
mirror=${SHADOWLAB_DEBIAN_MIRROR:-$(host_mirror)}
[ -n "$mirror" ] || { echo "chroot_suite: no Debian archive in /etc/apt/sources*; set SHADOWLAB_DEBIAN_MIRROR" >&2; exit 3; }
cache=${SHADOWLAB_CHROOT_CACHE:-/var/cache/shadowlab-chroot}
# The harness's compiler cache (not the README's steps): reruns build in a minute, not ten.
# SHADOWLAB_CHROOT_CCACHE=0 builds as a fresh machine would.
use_ccache=${SHADOWLAB_CHROOT_CCACHE:-1}
mkdir -p "$cache/debootstrap-$suite" "$cache/apt-$suite/partial" "$cache/ccache-$suite"
root=$(mktemp -d "/var/tmp/shadowlab-$suite.XXXXXX")
mounted=()
cleanup() {
  local rc=$? m
  trap - EXIT INT TERM
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    m=${mounted[i]}
    umount "$m" 2>/dev/null || umount -l "$m" || echo "chroot_suite: could not unmount $m" >&2
  done
  # Only once nothing is mounted below it: rm must never reach the host's /dev or /proc.
  if ! grep -q " $root/" /proc/self/mounts; then rm -rf "$root"; else
    echo "chroot_suite: $root still has mounts; left in place" >&2; fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
mnt() {  # mnt TARGET MOUNT-ARGS...: mounts and remembers it for cleanup
  local target=$root$1
  shift
  mkdir -p "$target"
  mount "$@" "$target"
  mounted+=("$target")
}
step_start=$SECONDS
say() { echo "chroot_suite[$suite]: $* ($((SECONDS - step_start)) s)"; }

# testing: this bookworm debootstrap has no script for the newest codename; sid's fits.
script=()
[ "$suite" = testing ] && script=(/usr/share/debootstrap/scripts/sid)
say "debootstrap $suite from $mirror"
debootstrap --variant=minbase --cache-dir="$cache/debootstrap-$suite" "$suite" "$root" "$mirror" \
  "${script[@]}" >"$root.debootstrap.log" 2>&1 || { tail -20 "$root.debootstrap.log"; exit 3; }
rm -f "$root.debootstrap.log"
# The harness only: the archive reached here may serve testing's Release past its Valid-Until.
echo 'Acquire::Check-Valid-Until "false";' >"$root/etc/apt/apt.conf.d/99shadowlab-harness"
mnt /proc -t proc proc
mnt /sys --bind /sys
mnt /dev --bind /dev
mnt /dev/pts --bind /dev/pts
mnt /dev/shm -t tmpfs tmpfs
mnt /var/cache/apt/archives --bind "$cache/apt-$suite"
mnt /root/.ccache --bind "$cache/ccache-$suite"
git clone --quiet --no-hardlinks "$repo" "$root/root/shadowlab"
say "chroot ready, $(git -C "$repo" rev-parse --short HEAD) cloned"

envs=(/usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb
      PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin)  # a new user's shell
[ "$use_ccache" = 1 ] && envs+=(CCACHE_DIR=/root/.ccache CCACHE_MAXSIZE=2G
                                CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache)
in_chroot() { chroot "$root" "${envs[@]}" bash -c "cd /root/shadowlab && $1"; }
# Build and tests without the network: their own abstract sockets (X displays), no downloads.
offline() { unshare --net chroot "$root" "${envs[@]}" bash -c "cd /root/shadowlab && $1"; }
# --test as scripts/test.sh does: ctest's bench_instructions needs valgrind.
in_chroot 'bash scripts/deps.sh --test' >"$root.deps.log" 2>&1 ||
  { tail -30 "$root.deps.log"; rm -f "$root.deps.log"; exit 1; }
tail -1 "$root.deps.log"
rm -f "$root.deps.log"
if [ "$use_ccache" = 1 ]; then
  in_chroot 'DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends ccache' \
    >/dev/null || exit 3
fi
in_chroot 'grep ^PRETTY_NAME /etc/os-release; dpkg-query -W -f "\${Package} \${Version}\n" \
  g++ cmake libegl-mesa0 libosmesa6-dev python3-glad 2>/dev/null' || true
say "deps installed"
offline 'bash scripts/build.sh 2>&1 | grep -E "warning|error|build:"; test -x build/shadowlab' ||
  { say "build failed"; exit 1; }
say "built"
status=0
offline 'ctest --test-dir build --output-on-failure -j2' || status=1
say "ctest done (exit $status)"
exit $status
