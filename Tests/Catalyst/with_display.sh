#!/bin/sh
# Runs a command under an X display of its own: an Xvfb started here on a
# free display number, without access control, and stopped after. Debian's
# ParaView renders through X. (xvfb-run's cookie set-up fails for ParaView
# on some hosts with "bad X server connection".)
# usage: XVFB=... with_display.sh COMMAND [ARGS...]
set -e
xvfb=${XVFB:-Xvfb}
if ! command -v "$xvfb" >/dev/null 2>&1; then
  echo "with_display: no Xvfb at '$xvfb' (Debian: xvfb; bash Demos/scripts/install-deps.sh)" >&2
  exit 1
fi
n=$(( 200 + $$ % 700 ))
while [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ]; do n=$((n + 1)); done
"$xvfb" ":$n" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT INT TERM
tries=0
until [ -e "/tmp/.X11-unix/X$n" ]; do
  tries=$((tries + 1))
  if [ $tries -gt 100 ] || ! kill -0 $server 2>/dev/null; then
    echo "with_display: Xvfb :$n did not start" >&2
    exit 1
  fi
  sleep 0.1
done
DISPLAY=":$n" "$@"
