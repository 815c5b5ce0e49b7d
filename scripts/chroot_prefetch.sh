#!/usr/bin/env bash
# CI's downloads, done while the host's suite runs: for each SUITE, a fresh debootstrap (minbase)
# into BASES/SUITE, then the packages the README's two commands will install there
# (`scripts/deps.sh --test --print`, and the harness's ccache) downloaded only, into the suite's
# apt cache (the one scripts/chroot_lib.sh gives the chroot). Nothing is installed in the base:
# scripts/chroot_suite.sh and scripts/gradescope_suite.sh copy it (SHADOWLAB_CHROOT_BASES=BASES)
# instead of debootstrapping, and the README's commands install as on any fresh system, from a
# cache that a warm machine would already have. A suite's base is usable once BASES/SUITE.ready
# exists; BASES/SUITE.failed says it could not be made (the suite then debootstraps itself).
#   bash scripts/chroot_prefetch.sh BASES SUITE...     (root; debootstrap; logs in BASES/SUITE.log)
# The suites run at once: debootstrap and apt spend most of their time waiting for the archive.
set -uo pipefail
bases=${1:?usage: chroot_prefetch.sh BASES SUITE...}
shift
repo=$(cd "$(dirname "$0")/.." && pwd)
source "$repo/scripts/chroot_lib.sh"  # chroot_host_mirror
cache=${SHADOWLAB_CHROOT_CACHE:-/var/cache/shadowlab-chroot}
mirror=${SHADOWLAB_DEBIAN_MIRROR:-$(chroot_host_mirror)}
mkdir -p "$bases"

prefetch_one() {
  local suite=$1 base=$bases/$1 start=$SECONDS
  local script=()
  [ "$suite" = testing ] && script=(/usr/share/debootstrap/scripts/sid)  # see chroot_lib.sh
  mkdir -p "$cache/debootstrap-$suite" "$cache/apt-$suite/partial"
  echo "prefetch $suite: debootstrap from $mirror"
  debootstrap --variant=minbase --cache-dir="$cache/debootstrap-$suite" "$suite" "$base" \
    "$mirror" "${script[@]}" || return 1
  touch "$bases/$suite.base"
  echo "prefetch $suite: base ready in $((SECONDS - start)) s"
  # The downloads in a scratch copy (apt's lists and lock stay out of the base), moved into the
  # suite's cache afterwards.
  local scratch=$base.scratch
  cp -a "$base" "$scratch" || return 1
  cp "$repo/scripts/deps.sh" "$scratch/tmp/deps.sh"
  local packages apt=(-o Acquire::Check-Valid-Until=false -q)
  packages=$(chroot "$scratch" bash /tmp/deps.sh --test --print) || return 1
  # shellcheck disable=SC2086  # a list of package names
  chroot "$scratch" apt-get "${apt[@]}" update >/dev/null &&
    DEBIAN_FRONTEND=noninteractive chroot "$scratch" apt-get "${apt[@]}" install -y \
      --download-only --no-install-recommends $packages ccache >/dev/null || return 1
  find "$scratch/var/cache/apt/archives" -maxdepth 1 -name '*.deb' -exec mv -f {} "$cache/apt-$suite/" \;
  rm -rf "$scratch"
  echo "prefetch $suite: $(ls "$cache/apt-$suite" | grep -c '\.deb$') packages in its cache, $((SECONDS - start)) s"
}

for suite in "$@"; do
  (
    prefetch_one "$suite" >"$bases/$suite.log" 2>&1 || echo "prefetch $suite: FAILED" >>"$bases/$suite.log"
    rm -rf "$bases/$suite.scratch"
    # A base without the downloads is still a fresh system (the chroot's apt downloads them).
    if [ -e "$bases/$suite.base" ]; then touch "$bases/$suite.ready"; else
      rm -rf "${bases:?}/$suite"; touch "$bases/$suite.failed"; fi
    tail -1 "$bases/$suite.log"
  ) &
done
wait
