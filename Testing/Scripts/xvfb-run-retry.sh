#!/usr/bin/env bash
# Runs a command under a fresh Xvfb display (xvfb-run -a, from a random display
# number). If the X server could not be reached ("bad X server connection":
# another process took the display number in between, or a loaded machine was
# slow to start it), it tries again, up to five times; any other failure is the
# command's own and is returned at once.
set -u
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for attempt in 1 2 3 4 5; do
  # A random first display number: parallel tests (and a display left
  # behind by another program) then rarely race for the same one.
  xvfb-run -a -n $((100 + RANDOM % 800)) -s "-screen 0 1280x1024x24" "$@" 2>&1 | tee "$log"
  status=${PIPESTATUS[0]}
  if [ "$status" -eq 0 ] || ! grep -q "bad X server connection" "$log"; then
    exit "$status"
  fi
  echo "xvfb-run-retry: X server unreachable (attempt $attempt), retrying" >&2
  sleep $((2 * attempt))
done
exit "$status"
