# Sourced by scripts/chroot_suite.sh and scripts/gradescope_suite.sh (root; debootstrap): makes a
# fresh debootstrap chroot of a Debian suite and runs commands in it as a new user's shell would,
# in a network namespace of its own. Every mount and process it makes is undone on any exit
# (failure and Ctrl-C too). The caller has set -euo pipefail and has re-run itself in a private
# mount namespace (chroot_private_mounts "$@" first thing).
#
# Kept between runs in $SHADOWLAB_CHROOT_CACHE (default /var/cache/shadowlab-chroot): the .deb
# files (debootstrap's and apt's, per suite) and the harness's compiler cache; a machine without
# that folder downloads and builds everything. Nothing else is prepared in the chroot.
#
# The network namespace: a chroot shares the host's X abstract sockets (and so its displays)
# unless it has its own namespace, and the README's commands both install packages and run the
# window tests under Xvfb. So every command runs in a namespace of its own whose only way out is
# apt's: a proxy on 127.0.0.1:3142 relayed through a Unix socket to the archive's host
# (scripts/chroot_relay.py; set in the chroot's apt.conf.d, the harness's like Valid-Until).

# Its own mount namespace, private: nothing mounted here reaches the host's tree (even where / is
# a shared mount), and the kernel drops every mount should the script be killed outright.
chroot_private_mounts() {
  if [ -z "${SHADOWLAB_CHROOT_NS:-}" ]; then
    SHADOWLAB_CHROOT_NS=1 exec unshare --mount --propagation private bash "$0" "$@"
  fi
}

chroot_needs() {
  [ "$(id -u)" -eq 0 ] || { echo "$chroot_name: needs root (debootstrap, mount, chroot)" >&2; exit 3; }
  local t
  for t in debootstrap unshare /usr/bin/python3; do
    command -v "$t" >/dev/null || { echo "$chroot_name: needs $t (bash scripts/deps.sh --test)" >&2; exit 3; }
  done
}

# The Debian archive this machine's apt already uses (its main archive, not -security): the
# chroot reaches what the host reaches.
chroot_host_mirror() {
  local f
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
    [ -r "$f" ] && grep -v '^[[:space:]]*#' "$f"
  done | grep -oE 'http://[^ ]*/debian/?( |$)' | head -1 | tr -d ' ' || true
}

chroot_step_start=$SECONDS
chroot_say() { echo "$chroot_name: $* ($((SECONDS - chroot_step_start)) s)"; }

chroot_mounted=()
chroot_pids=()
chroot_cleanup() {
  local rc=$? i m
  trap - EXIT INT TERM
  for ((i = ${#chroot_pids[@]} - 1; i >= 0; i--)); do
    kill "${chroot_pids[i]}" 2>/dev/null || true
  done
  wait 2>/dev/null || true
  if declare -F chroot_extra_cleanup >/dev/null; then chroot_extra_cleanup; fi
  for ((i = ${#chroot_mounted[@]} - 1; i >= 0; i--)); do
    m=${chroot_mounted[i]}
    umount "$m" 2>/dev/null || umount -l "$m" || echo "$chroot_name: could not unmount $m" >&2
  done
  # Only once nothing is mounted below it: rm must never reach the host's /dev or /proc.
  if [ -n "${root:-}" ]; then
    if ! grep -q " $root/" /proc/self/mounts; then rm -rf "$root"; else
      echo "$chroot_name: $root still has mounts; left in place" >&2; fi
  fi
  exit "$rc"
}

chroot_mount() {  # chroot_mount TARGET MOUNT-ARGS...: mounts and remembers it for cleanup
  local target=$root$1
  shift
  mkdir -p "$target"
  mount "$@" "$target"
  chroot_mounted+=("$target")
}

# chroot_wait_base SUITE: true once scripts/chroot_prefetch.sh has SUITE's base ready in
# $SHADOWLAB_CHROOT_BASES (waiting for it while it is being made); false where there is none.
chroot_wait_base() {
  local bases=${SHADOWLAB_CHROOT_BASES:-}
  [ -n "$bases" ] && [ -d "$bases" ] || return 1
  local waited=0
  while [ ! -e "$bases/$1.ready" ] && [ ! -e "$bases/$1.failed" ] && [ $waited -lt 1800 ]; do
    [ $waited -eq 0 ] && chroot_say "waiting for $1's base (scripts/chroot_prefetch.sh)"
    sleep 2
    waited=$((waited + 2))
  done
  [ -e "$bases/$1.ready" ]
}

# chroot_make SUITE DEB-CACHE CCACHE: debootstraps SUITE (bookworm, trixie, testing) into a new
# $root with the .deb caches named DEB-CACHE (suites that are the same system share them) and
# the compiler cache named CCACHE, mounts /proc, /sys, /dev, and starts the apt relay.
chroot_make() {
  local suite=$1 cachename=$2 ccachename=$3
  local mirror=${SHADOWLAB_DEBIAN_MIRROR:-$(chroot_host_mirror)}
  [ -n "$mirror" ] || { echo "$chroot_name: no http Debian archive in /etc/apt/sources*; set SHADOWLAB_DEBIAN_MIRROR" >&2; exit 3; }
  local cache=${SHADOWLAB_CHROOT_CACHE:-/var/cache/shadowlab-chroot}
  mkdir -p "$cache/debootstrap-$cachename" "$cache/apt-$cachename/partial" "$cache/ccache-$ccachename"
  root=$(mktemp -d "/var/tmp/shadowlab-$ccachename.XXXXXX")
  trap chroot_cleanup EXIT
  trap 'exit 130' INT TERM
  # testing: this bookworm debootstrap has no script for the newest codename; sid's fits.
  local script=()
  [ "$suite" = testing ] && script=(/usr/share/debootstrap/scripts/sid)
  if chroot_wait_base "$suite"; then
    # The same fresh minbase system, debootstrapped while the host's suite ran
    # (scripts/chroot_prefetch.sh): a copy, so the Gradescope suite's Debian 12 is fresh too.
    chroot_say "a copy of $suite's fresh debootstrap base"
    cp -a "$SHADOWLAB_CHROOT_BASES/$suite/." "$root/"
  else
    chroot_say "debootstrap $suite from $mirror"
    debootstrap --variant=minbase --cache-dir="$cache/debootstrap-$cachename" "$suite" "$root" \
      "$mirror" "${script[@]}" >"$root.debootstrap.log" 2>&1 || { tail -20 "$root.debootstrap.log"; exit 3; }
    rm -f "$root.debootstrap.log"
  fi
  # The harness only: the archive reached here may serve testing's Release past its
  # Valid-Until; apt's way out of the network namespace.
  printf '%s\n' 'Acquire::Check-Valid-Until "false";' 'Acquire::http::Proxy "http://127.0.0.1:3142";' \
    >"$root/etc/apt/apt.conf.d/99shadowlab-harness"
  # dpkg without an fsync per file: a throwaway chroot loses nothing by it, and the README's
  # installs spend their time unpacking instead of waiting on the disk (the harness only).
  echo force-unsafe-io >"$root/etc/dpkg/dpkg.cfg.d/99shadowlab-harness"
  chroot_mount /proc -t proc proc
  chroot_mount /sys --bind /sys
  chroot_mount /dev --bind /dev
  chroot_mount /dev/pts --bind /dev/pts
  chroot_mount /dev/shm -t tmpfs tmpfs
  chroot_mount /var/cache/apt/archives --bind "$cache/apt-$cachename"
  chroot_mount /root/.ccache --bind "$cache/ccache-$ccachename"
  local hostport=${mirror#http://}
  hostport=${hostport%%/*}
  local host=${hostport%%:*} port=80
  [ "$host" != "$hostport" ] && port=${hostport#*:}
  chroot_relay_sock=$root/run/shadowlab-apt.sock
  mkdir -p "$root/run"
  /usr/bin/python3 "$chroot_lib_dir/chroot_relay.py" host "$chroot_relay_sock" "$host" "$port" &
  chroot_pids+=($!)
  # A new user's shell; the harness's compiler cache (SHADOWLAB_CHROOT_CCACHE=0 builds as a
  # fresh machine would: minutes more).
  chroot_env=(/usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb
              PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin)
  if [ "${SHADOWLAB_CHROOT_CCACHE:-1}" = 1 ]; then
    # CCACHE_BASEDIR: paths below it are hashed relative to the build folder, so the host's
    # build of the same sources (scripts/test.sh in CI, the same cache for Debian 12) hits.
    chroot_env+=(CCACHE_DIR=/root/.ccache CCACHE_MAXSIZE=2G CCACHE_BASEDIR=${chroot_ccache_basedir:-/root}
                 CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache)
    chroot_run / 'DEBIAN_FRONTEND=noninteractive apt-get update -q >/dev/null 2>&1 &&
      DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends ccache >/dev/null 2>&1' ||
      { echo "$chroot_name: could not install ccache (the harness's compiler cache)" >&2; exit 3; }
  fi
}

# chroot_run DIR COMMAND [WRAPPER...]: bash -c COMMAND in DIR inside the chroot, in a network
# namespace of its own (apt's relay its only way out), with the new user's environment.
# WRAPPER (e.g. taskset -c 0) goes before chroot.
chroot_run() {
  local dir=$1 command=$2
  shift 2
  local ready=$root/run/shadowlab-relay.ready
  rm -f "$ready"
  unshare --net bash -c '
    ready=$1 relay=$2 sock=$3 root=$4 dir=$5 command=$6 n=$7
    shift 7
    wrapper=("${@:1:n}")
    envs=("${@:n+1}")
    /usr/bin/python3 "$relay" inner 3142 "$sock" "$ready" &
    inner=$!
    trap "kill $inner 2>/dev/null" EXIT
    for _ in $(seq 100); do [ -e "$ready" ] && break; sleep 0.05; done
    [ -e "$ready" ] || { echo "chroot_run: the apt relay did not start" >&2; exit 3; }
    "${wrapper[@]}" chroot "$root" "${envs[@]}" bash -c "cd \"$dir\" && $command"
  ' _ "$ready" "$chroot_lib_dir/chroot_relay.py" "$chroot_relay_sock" "$root" "$dir" "$command" \
    "$#" "$@" "${chroot_env[@]}"
}
chroot_lib_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
