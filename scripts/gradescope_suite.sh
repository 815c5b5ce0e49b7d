#!/usr/bin/env bash
# Builds and runs a Gradescope autograder.zip the way Gradescope does, in a fresh debootstrap
# chroot of Debian 12 (the closest system reachable here to Gradescope's Ubuntu 22.04 base;
# scripts/deps.sh knows Ubuntu's names too): the zip unpacked into /autograder/source,
# run_autograder copied to /autograder/run_autograder, `setup.sh` run as root, then for each
# hand-in /autograder/run_autograder inside a 768 MB memory cgroup (no swap) pinned to one core
# beside a busy loop on that core (Gradescope's default container: 768 MB, under one CPU), and
# /autograder/results/results.json checked:
#   correct  the shipped solution of every due file          -> full marks
#   broken   the same with one due stage's file not compiling -> full marks less that stage's
#            points, its tests failed with their output
#   bash scripts/gradescope_suite.sh ZIP     (root; debootstrap; ZIP from chroot_suite.sh --zip)
# SHADOWLAB_GRADESCOPE_CORE picks the core (default 0), SHADOWLAB_GRADESCOPE_MB the limit.
set -euo pipefail
zip=$(realpath "${1:?usage: gradescope_suite.sh AUTOGRADER.zip}")
chroot_name=gradescope_suite
source "$(dirname "$0")/chroot_lib.sh"
chroot_private_mounts "$@"
chroot_needs
core=${SHADOWLAB_GRADESCOPE_CORE:-0}
mb=${SHADOWLAB_GRADESCOPE_MB:-768}
logs=${SHADOWLAB_CHROOT_LOGS:-/var/tmp/shadowlab-chroot-logs}
mkdir -p "$logs"
log=$logs/gradescope.log
: >"$log"

# A memory cgroup of $mb MB, a child of this process's own (cgroup v1's memory hierarchy, or
# v2 where the parent can hand the memory controller down); $cg is its folder.
cg=""
make_cgroup() {
  local own
  if [ -d /sys/fs/cgroup/memory ]; then
    own=$(awk -F: '$2 == "memory" {print $3}' /proc/self/cgroup)
    cg=/sys/fs/cgroup/memory${own%/}/shadowlab-gradescope-$$
    mkdir "$cg"
    echo $((mb << 20)) >"$cg/memory.limit_in_bytes"
    [ -e "$cg/memory.memsw.limit_in_bytes" ] && echo $((mb << 20)) >"$cg/memory.memsw.limit_in_bytes"
    cg_kind=v1
  elif grep -qw memory /sys/fs/cgroup/cgroup.controllers 2>/dev/null; then
    own=$(awk -F: '$1 == "0" {print $3}' /proc/self/cgroup)
    # v2 hands a controller to children only from a cgroup without processes of its own.
    echo +memory >"/sys/fs/cgroup${own%/}/cgroup.subtree_control" 2>/dev/null || {
      echo "$chroot_name: cgroup v2: cannot enable the memory controller below ${own} (it has processes); run it from a cgroup of its own" >&2
      exit 3
    }
    cg=/sys/fs/cgroup${own%/}/shadowlab-gradescope-$$
    mkdir "$cg"
    echo $((mb << 20)) >"$cg/memory.max"
    [ -e "$cg/memory.swap.max" ] && echo 0 >"$cg/memory.swap.max"
    cg_kind=v2
  else
    echo "$chroot_name: no memory cgroup (v1 or v2) to limit the autograder with" >&2
    exit 3
  fi
}
cg_peak_mb() {
  local f=$cg/memory.max_usage_in_bytes
  [ "$cg_kind" = v2 ] && f=$cg/memory.peak
  [ -r "$f" ] && echo $(($(cat "$f") >> 20)) || echo "?"
}
cg_oom_kills() {
  local f=$cg/memory.oom_control
  [ "$cg_kind" = v2 ] && f=$cg/memory.events
  local n
  n=$(awk '$1 == "oom_kill" {print $2}' "$f" 2>/dev/null)
  echo "${n:-0}"
}
chroot_extra_cleanup() {
  [ -n "$cg" ] && [ -d "$cg" ] && { rmdir "$cg" 2>/dev/null || echo "$chroot_name: $cg left (processes still in it?)" >&2; }
  return 0
}

# Debian 12's .deb cache and compiler cache: the chroot suite's (and in CI the host's) build of
# the same sources fills it, so setup.sh's build of the kit hits (CCACHE_BASEDIR /autograder).
chroot_ccache_basedir=/autograder
chroot_make bookworm bookworm bookworm
ag=$root/autograder
mkdir -p "$ag/source" "$ag/submission" "$ag/results"
# Unpacked with the modes the zip records (Gradescope keeps setup.sh's and run_autograder's).
/usr/bin/python3 - "$zip" "$ag/source" <<'PY'
import os, sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
for info in z.infolist():
    path = z.extract(info, sys.argv[2])
    mode = info.external_attr >> 16
    if mode & 0o777:
        os.chmod(path, mode & 0o777)
PY
cp "$ag/source/run_autograder" "$ag/run_autograder"
chroot_say "$(basename "$zip") unpacked into /autograder/source"

start=$SECONDS
if ! chroot_run /autograder/source 'bash ./setup.sh' >>"$log" 2>&1; then
  tail -40 "$log"
  chroot_say "setup.sh FAILED (the whole output: $log)"
  exit 1
fi
chroot_say "setup.sh: packages and build in $((SECONDS - start)) s"

# The hand-ins, from the zip's own assignment and shipped solution; the points each must get.
handins=$root/var/tmp/handins
/usr/bin/python3 - "$ag/source" "$handins" <<'PY'
import json, os, sys
source, out = sys.argv[1:3]
lab = json.load(open(os.path.join(source, "assignment.json")))
due = [s for s in lab["stages"] if s.get("due", True)]
broken = due[1] if len(due) > 1 else due[0]
for name in ("correct", "broken"):
    for s in due:
        for f in s["files"]:
            text = open(os.path.join(source, "shadowlab", "shaders_" + s.get("tree", "core"), f)).read()
            if name == "broken" and s is broken:
                text += "\n#error this hand-in does not compile\n"
            path = os.path.join(out, name, f)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            open(path, "w").write(text)
total = sum(s["points"] for s in due)
json.dump({"correct": {"score": total, "broken_stage": None},
           "broken": {"score": total - broken["points"], "broken_stage": broken["stage"]},
           "max_score": total}, open(os.path.join(out, "expected.json"), "w"))
PY

make_cgroup
taskset -c "$core" bash -c 'while :; do :; done' &
chroot_pids+=($!)
status=0
for handin in correct broken; do
  rm -rf "$ag/submission" "$ag/results"
  mkdir -p "$ag/results"
  cp -r "$handins/$handin" "$ag/submission"
  [ "$cg_kind" = v1 ] && echo 0 >"$cg/memory.max_usage_in_bytes"  # the peak of this run only
  kills_before=$(cg_oom_kills)
  start=$SECONDS
  echo "== run_autograder: $handin" >>"$log"
  # In the cgroup (this shell's pid first, then exec), on one core, bounded by the harness.
  chroot_run /autograder '/autograder/run_autograder' \
    bash -c 'echo $$ >"$0/cgroup.procs" && exec timeout 1800 taskset -c "$1" "${@:2}"' "$cg" "$core" \
    >>"$log" 2>&1 || true
  seconds=$((SECONDS - start))
  if /usr/bin/python3 - "$ag/results/results.json" "$handins/expected.json" "$handin" <<'PY'
import json, sys
path, expected_path, name = sys.argv[1:4]
expected = json.load(open(expected_path))
want = expected[name]
problems = []
try:
    res = json.load(open(path))
except (OSError, ValueError) as e:
    print(f"  no results.json: {e}")
    sys.exit(1)
for key, kind in (("score", (int, float)), ("tests", list), ("output", str)):
    if not isinstance(res.get(key), kind):
        problems.append(f"results.json lacks {key}")
tests = res.get("tests") or []
if not tests:
    problems.append("no tests in results.json")
max_score = res.get("max_score", sum(t.get("max_score", 0) for t in tests))
if abs(max_score - expected["max_score"]) > 0.01:
    problems.append(f"max_score {max_score}, expected {expected['max_score']}")
if abs(res.get("score", -1) - want["score"]) > 0.05:
    problems.append(f"score {res.get('score')}, expected {want['score']}")
for t in tests:
    if not isinstance(t.get("output"), str) or not t.get("name"):
        problems.append(f"a test without name or output: {t}")
    lost = t.get("max_score", 0) - t.get("score", 0)
    if lost > 1e-6:
        broken = want["broken_stage"]
        tag = "" if broken and broken in t["name"] else " (not the broken stage)"
        print(f"  lost {lost:g} of {t['max_score']:g}{tag}: {t['name']}: {t['output'][:300]}")
if want["broken_stage"]:
    mine = [t for t in tests if want["broken_stage"] in t.get("name", "")]
    if not mine or any(t.get("score", 0) > 0 or t.get("status") != "failed" for t in mine):
        problems.append(f"{want['broken_stage']}'s tests are not all failed with 0 points")
print(f"  score {res.get('score')} of {max_score} (expected {want['score']}), {len(tests)} tests")
for p in problems:
    print("  FAIL: " + p)
sys.exit(1 if problems else 0)
PY
  then
    chroot_say "run_autograder $handin: ok in ${seconds} s, cgroup peak $(cg_peak_mb) MB of $mb, OOM kills $(($(cg_oom_kills) - kills_before))"
  else
    status=1
    chroot_say "run_autograder $handin: FAILED in ${seconds} s, cgroup peak $(cg_peak_mb) MB of $mb, OOM kills $(($(cg_oom_kills) - kills_before)) (output: $log)"
  fi
done
chroot_say "done (exit $status)"
exit $status
