#!/bin/sh
# with_xvfb.sh WxHxD COMMAND [ARG...]: runs COMMAND on a virtual X server of its own and exits
# with COMMAND's status. What xvfb-run -a did for the window tests, without its two failures
# seen in CI: two servers started at once racing for one display number (-a reads lock files),
# and exit 5 after the command ("problem while cleaning up temporary directory"). Xvfb picks a
# free display itself and says which once it accepts connections (-displayfd).
# A server that does not start is exit 3 (the machine's, never the program's, failure).
set -u
screen=${1:?usage: with_xvfb.sh WxHxD COMMAND [ARG...]}
shift
dir=$(mktemp -d) || exit 3
Xvfb -displayfd 3 -ac -nolisten tcp -screen 0 "$screen" 3>"$dir/display" >"$dir/log" 2>&1 &
xserver=$!
cleanup() { kill "$xserver" 2>/dev/null; wait "$xserver" 2>/dev/null; rm -rf "$dir"; }
tries=0
until grep -q '^[0-9][0-9]*$' "$dir/display" 2>/dev/null && [ "$(wc -l <"$dir/display")" -ge 1 ]; do
  if ! kill -0 "$xserver" 2>/dev/null || [ "$tries" -ge 600 ]; then
    echo "with_xvfb: Xvfb did not start: $(tail -3 "$dir/log")" >&2
    cleanup
    exit 3
  fi
  tries=$((tries + 1))
  sleep 0.05
done
DISPLAY=:$(head -1 "$dir/display")
export DISPLAY
# In the background, so that a TERM from `timeout` reaches both the command and the server.
"$@" &
command=$!
trap 'kill "$command" 2>/dev/null' TERM INT HUP
wait "$command"
status=$?
cleanup
exit "$status"
