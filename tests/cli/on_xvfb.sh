#!/usr/bin/env bash
# on_xvfb.sh WxHxD COMMAND...: runs COMMAND on a private Xvfb server of one WxHxD screen and exits with
# COMMAND's status. The window tests use this instead of xvfb-run: xvfb-run's own clean-up fails now and then
# on a loaded machine ("problem while cleaning up temporary directory", exit 5), replacing the exit status
# under test (seen in CI on Debian 12 and Debian 13). The server picks a free display itself (-displayfd),
# so tests running side by side never race for one, and is stopped however COMMAND ends.
set -u
screen=$1
shift
state=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 "$screen" -nolisten tcp 3>"$state/display" >"$state/xvfb.log" 2>&1 &
xvfb=$!
stop() {
  kill "$xvfb" 2>/dev/null
  wait "$xvfb" 2>/dev/null
  rm -rf "$state" || echo "on_xvfb: could not remove $state (left behind)" >&2
}
trap stop EXIT
for _ in $(seq 300); do  # the server writes its display number once it accepts connections
  [ -s "$state/display" ] && break
  kill -0 "$xvfb" 2>/dev/null || { echo "on_xvfb: Xvfb failed to start:" >&2; cat "$state/xvfb.log" >&2; exit 1; }
  sleep 0.1
done
[ -s "$state/display" ] || { echo "on_xvfb: Xvfb gave no display in 30 s" >&2; exit 1; }
DISPLAY=":$(head -n 1 "$state/display")" "$@"
