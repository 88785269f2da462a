#!/bin/sh
# The kiosk's desktop emulation under Xvfb, driven by synthetic key presses (xdotool):
# a space changes the method (every press, also many within one frame), l toggles the
# overlay, q quits with status 0; the window destroyed by another client or closed by the
# window manager stops it with one line and status 0, the X server killed with one line
# and status 1; a board whose GPIO chip is missing warns and runs on; bad input exits 2;
# KMS without a DRM device is one clear error, and a DISPLAY then gets the x11 window.
# No GPU, no DRM, no GPIO.
# Usage: tests/kiosk_x11.sh path/to/lixel
set -u
lixel=${1:?usage: kiosk_x11.sh path/to/lixel}
tmp=$(mktemp -d)
pass=0
fail=0
ok() { pass=$((pass + 1)); }
no() { fail=$((fail + 1)); echo "FAIL: $*"; }
xvfb_pid=
xvfb2_pid=
# wait for Xvfb to be gone, so that the next run does not find it dying on its display
cleanup() {
  for p in $xvfb_pid $xvfb2_pid; do kill "$p" 2>/dev/null && wait "$p" 2>/dev/null; done
  rm -rf "$tmp"
}
trap cleanup EXIT

. "$(dirname "$0")/xvfb.sh"

start_xvfb 91
display=$started_display
xvfb_pid=$started_pid
if [ -z "$display" ]; then
  echo "FAIL: no Xvfb display could be started"
  echo "kiosk: 0 passed, 1 failed"
  exit 1
fi
export DISPLAY=$display

# waits for the kiosk's window; prints its id
find_window() {
  for i in $(seq 1 100); do
    w=$(xdotool search --name '^lixel$' 2>/dev/null | head -n 1)
    [ -n "$w" ] && { echo "$w"; return; }
    sleep 0.1
  done
}
key() { xdotool key --window "$wid" "$1" >/dev/null 2>&1; }

# 1. `lixel kiosk --platform x11 --frames 400` changes the method on a space key and
#    exits 0; l toggles the overlay. 400 frames: 120 took 0.66 s here, about when the l
#    arrives (the window found, 0.5 s of sleeps, two xdotool runs), so it was sometimes lost
"$lixel" kiosk --platform x11 --size 640x480 --frames 400 >"$tmp/out" 2>&1 &
pid=$!
wid=$(find_window)
if [ -n "$wid" ]; then
  sleep 0.2
  key space; sleep 0.3
  key l
fi
wait "$pid"; st=$?
[ "$st" -eq 0 ] && ok || no "kiosk --frames 400: exit status $st: $(cat "$tmp/out")"
grep -q '^lixel kiosk: GL_VENDOR .*GL_RENDERER .*GL_VERSION .*x11 640x480; fragment precision .*; depth highp24-texture, self-test passed; board desktop' "$tmp/out" && ok ||
  no "no start line: $(head -n 2 "$tmp/out")"
grep -q '^method: plane -> uniform$' "$tmp/out" && ok || no "space did not change the method: $(cat "$tmp/out")"
grep -q '^overlay: on$' "$tmp/out" && ok || no "l did not toggle the overlay: $(cat "$tmp/out")"
grep -q '^[0-9]* frames in .* s = .* FPS (uniform)$' "$tmp/out" && ok || no "no status line at the end: $(cat "$tmp/out")"

# 2. two spaces walk the board's order; q quits with status 0
"$lixel" kiosk --platform x11 --size 320x240 --frames 100000 --max-fps 30 >"$tmp/out" 2>&1 &
pid=$!
wid=$(find_window)
if [ -n "$wid" ]; then
  sleep 0.2
  key space; sleep 0.3
  key space; sleep 0.3
  key q
fi
for i in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2>/dev/null; then kill "$pid"; no "kiosk did not quit on q"; fi
wait "$pid"; st=$?
[ "$st" -eq 0 ] && ok || no "kiosk exit status $st after q: $(cat "$tmp/out")"
grep -q '^method: uniform -> psm$' "$tmp/out" && ok || no "the second space did not: $(cat "$tmp/out")"

# 2a. with filters (a board's filters key, here --filters) a space steps through the
# method's filters first, then to the next method's first; none reads no map: one step
"$lixel" kiosk --platform x11 --size 320x240 --methods plane,none,uniform --filters none,pcf3x3 --frames 100000 --max-fps 30 \
  >"$tmp/out" 2>&1 &
pid=$!
wid=$(find_window)
if [ -n "$wid" ]; then
  sleep 0.2
  for k in 1 2 3 4; do key space; sleep 0.3; done
  key q
fi
for i in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2>/dev/null; then kill "$pid"; no "kiosk with filters did not quit on q"; fi
wait "$pid"; st=$?
steps=$(grep '^method: ' "$tmp/out" | tr '\n' ' ')
[ "$st" -eq 0 ] && [ "$steps" = "method: plane -> plane+pcf3x3 method: plane+pcf3x3 -> none method: none -> uniform method: uniform -> uniform+pcf3x3 " ] &&
  ok || no "kiosk --filters: status $st, steps '$steps': $(cat "$tmp/out")"

# 2b. SIGHUP (a closed session) stops it as SIGTERM does: status 0 (the old output removed
#     first, as for wait_started below)
rm -f "$tmp/out"
"$lixel" kiosk --platform x11 --size 320x240 --frames 100000 --max-fps 30 >"$tmp/out" 2>&1 &
pid=$!
for i in $(seq 1 100); do grep -q 'frames in\|^lixel kiosk: GL_VENDOR' "$tmp/out" 2>/dev/null && break; sleep 0.1; done
sleep 0.3
kill -HUP "$pid" 2>/dev/null
for i in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2>/dev/null; then kill -9 "$pid"; no "kiosk did not stop on SIGHUP"; fi
wait "$pid"; st=$?
[ "$st" -eq 0 ] && ok || no "kiosk exit status $st after SIGHUP: $(cat "$tmp/out")"

# 3. --frames 120 stops by itself with status 0, with the overlay on from the start
"$lixel" kiosk --platform x11 --size 320x240 --frames 120 --overlay >"$tmp/out" 2>&1; st=$?
[ "$st" -eq 0 ] && grep -q '^120 frames in ' "$tmp/out" && ok || no "--frames 120: status $st: $(cat "$tmp/out")"

# 4. a board whose GPIO chip is missing (no GPIO here): one warning, and it runs on
"$lixel" kiosk --platform x11 --board raspberry-pi-4 --gpio-chip lixel-no-chip --size 320x240 --frames 10 >"$tmp/out" 2>&1; st=$?
[ "$st" -eq 0 ] && grep -q '^lixel kiosk: warning: gpio: no chip named lixel-no-chip' "$tmp/out" &&
  grep -q 'board raspberry-pi-4; light point$' "$tmp/out" && ok || no "missing chip: status $st: $(cat "$tmp/out")"

# 4b. --gpio-chip before --gpio-line on a board without a button: accepted, the chip
# missing here is one warning and it runs on
"$lixel" kiosk --platform x11 --gpio-chip lixel-no-chip --gpio-line 3 --size 320x240 --frames 5 >"$tmp/out" 2>&1; st=$?
[ "$st" -eq 0 ] && grep -q 'warning: gpio: no chip named lixel-no-chip' "$tmp/out" && ok || no "--gpio-chip then --gpio-line: status $st: $(cat "$tmp/out")"
# a line break in an override would smuggle in a profile line: refused
nl='
'
"$lixel" kiosk --platform x11 --gpio-line "5${nl}methods none" --frames 1 >"$tmp/out" 2>"$tmp/err"; st=$?
[ "$st" -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q 'without line breaks' "$tmp/err" && ok || no "override with a line break: status $st: $(cat "$tmp/err")"

# 5. bad input: exit 2, one line
for args in "--board no-such-board" "--gpio-line seventeen" "--frames 0" "--methods plane,teapot" "--methods ," \
    "--size big" "--shadows" "--depth-precision fp16" "--filters pcf9" "--filters none,none" "--filters ," \
    "--max-fps 0" "--max-fps 1001" "--snapshot x.png"; do
  # shellcheck disable=SC2086
  "$lixel" kiosk --platform x11 $args >"$tmp/out" 2>"$tmp/err"; st=$?
  [ "$st" -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && ok || no "kiosk $args: status $st: $(cat "$tmp/err")"
done
# 6. no display for x11: a clear error, status 1
DISPLAY=:1234 "$lixel" kiosk --platform x11 --frames 1 >"$tmp/out" 2>"$tmp/err"; st=$?
[ "$st" -eq 1 ] && grep -q "cannot open display ':1234'" "$tmp/err" && ok || no "no display: status $st: $(cat "$tmp/err")"

# 7. KMS where there is no DRM device (this machine, CI): one clear error naming the
# device and the reason, status 1; without --platform a DISPLAY gets the x11 window
if [ ! -e /dev/dri ]; then
  "$lixel" kiosk --platform kms --frames 1 >"$tmp/out" 2>"$tmp/err"; st=$?
  [ "$st" -eq 1 ] && grep -q '^lixel kiosk: kms: no display to drive (no DRM device found)$' "$tmp/err" && ok ||
    no "kms without DRM: status $st: $(cat "$tmp/err")"
  "$lixel" kiosk --platform kms --device /dev/dri/card7 --frames 1 >"$tmp/out" 2>"$tmp/err"; st=$?
  [ "$st" -eq 1 ] && grep -q 'kms: /dev/dri/card7: cannot open: No such file or directory' "$tmp/err" && ok ||
    no "kms --device: status $st: $(cat "$tmp/err")"
  "$lixel" kiosk --size 320x240 --frames 5 >"$tmp/out" 2>"$tmp/err"; st=$?
  [ "$st" -eq 0 ] && grep -q 'using x11 (DISPLAY is set)' "$tmp/out" && grep -q '; x11 320x240;' "$tmp/out" && ok ||
    no "automatic x11: status $st: $(cat "$tmp/out" "$tmp/err")"
else
  echo "kiosk: /dev/dri exists: the no-DRM checks are skipped"
fi

# waits (up to $2 tenths of a second) for process $1 to end; kills it if it does not and
# returns 1
wait_gone() {
  for i in $(seq 1 "$2"); do kill -0 "$1" 2>/dev/null || return 0; sleep 0.1; done
  kill -9 "$1" 2>/dev/null
  return 1
}
# waits for the kiosk's start line in $tmp/out (the loop is running)
# The caller empties $tmp/out before it starts the kiosk: the shell truncates a background
# command's output only once the child runs, so an old run's start line could otherwise be
# read as this one's (seen in CI under AddressSanitizer, whose start is slow).
wait_started() {
  for i in $(seq 1 200); do grep -q '^lixel kiosk: GL_VENDOR' "$tmp/out" 2>/dev/null && return; sleep 0.1; done
  no "the kiosk printed no start line in 20 s: $(cat "$tmp/out" "$tmp/err" 2>/dev/null)"
}
helper=$(dirname "$lixel")/tests/destroy_window

# 8. N key presses sent at once (one xdotool call, no delay between them) make N method
#    changes: the loop reads every pending key each frame, not one per frame
presses=30
rm -f "$tmp/out" "$tmp/err"
"$lixel" kiosk --platform x11 --size 320x240 --frames 100000 --max-fps 30 >"$tmp/out" 2>&1 &
pid=$!
wid=$(find_window)
wait_started
if [ -n "$wid" ]; then
  # shellcheck disable=SC2046
  xdotool key --window "$wid" --delay 0 $(yes space | head -n "$presses") >/dev/null 2>&1
  sleep 0.5
  key q
fi
wait_gone "$pid" 100 || no "kiosk did not quit on q after $presses presses"
wait "$pid"; st=$?
changes=$(grep -c '^method: ' "$tmp/out")
[ "$st" -eq 0 ] && [ "$changes" -eq "$presses" ] && ok || no "$presses presses at once: status $st, $changes method changes: $(cat "$tmp/out")"
# each change starts where the one before ended, from plane, round the desktop's six methods
awk '/^method: /{ if (prev != "" && $2 != prev) bad = 1; prev = $4; if (first == "") first = $2 } END { exit !(first == "plane" && !bad) }' "$tmp/out" &&
  ok || no "the method changes do not follow each other: $(grep '^method: ' "$tmp/out" | head -n 8)"

# 9. the window destroyed by another client (XDestroyWindow): one line, status 0, and the
#    kiosk does not touch the window again (Xlib's default handler would end it with 1)
if [ -x "$helper" ]; then
  rm -f "$tmp/out" "$tmp/err"
  "$lixel" kiosk --platform x11 --size 320x240 --frames 100000 --max-fps 30 >"$tmp/out" 2>"$tmp/err" &
  pid=$!
  wid=$(find_window)
  wait_started
  sleep 0.3
  if [ -n "$wid" ] && "$helper" "$wid" 2>"$tmp/helper"; then
    wait_gone "$pid" 200 || no "kiosk still running 20 s after its window was destroyed"
    wait "$pid"; st=$?
    [ "$st" -eq 0 ] && [ "$(grep -c '^lixel kiosk: the window was closed (destroyed by another client); stopping$' "$tmp/out")" -eq 1 ] &&
      ok || no "window destroyed: status $st: $(cat "$tmp/out" "$tmp/err")"
    grep -q 'X Error\|BadWindow' "$tmp/out" "$tmp/err" && no "window destroyed: an X error was printed: $(cat "$tmp/err")" || ok
  else
    kill "$pid" 2>/dev/null; wait "$pid"
    no "could not destroy the kiosk's window '$wid': $(cat "$tmp/helper")"
  fi
  # the window manager's close (WM_DELETE_WINDOW): the same, in its own words
  rm -f "$tmp/out" "$tmp/err"
  "$lixel" kiosk --platform x11 --size 320x240 --frames 100000 --max-fps 30 >"$tmp/out" 2>&1 &
  pid=$!
  wid=$(find_window)
  wait_started
  if [ -n "$wid" ] && "$helper" --wm-delete "$wid" 2>"$tmp/helper"; then
    wait_gone "$pid" 200 || no "kiosk still running 20 s after WM_DELETE_WINDOW"
    wait "$pid"; st=$?
    [ "$st" -eq 0 ] && grep -q '^lixel kiosk: the window was closed (by the window manager); stopping$' "$tmp/out" &&
      ok || no "WM_DELETE_WINDOW: status $st: $(cat "$tmp/out")"
  else
    kill "$pid" 2>/dev/null; wait "$pid"
    no "could not send WM_DELETE_WINDOW to '$wid': $(cat "$tmp/helper")"
  fi
else
  no "the helper $helper is missing (make builds it)"
fi

# 10. the X server killed under the kiosk (its own Xvfb): no hang, one line, status 1 (the
#     display went away: a failure, which a supervisor may restart)
start_xvfb 81
xvfb2_pid=$started_pid
if [ -n "$started_display" ]; then
  rm -f "$tmp/out" "$tmp/err"
  DISPLAY=$started_display "$lixel" kiosk --platform x11 --size 320x240 --frames 100000 --max-fps 30 >"$tmp/out" 2>"$tmp/err" &
  pid=$!
  wait_started
  sleep 0.5
  # a write into the dead server's socket must not kill it by SIGPIPE (status 141, no line):
  # that depends on where the kiosk is when the server dies, so ask the kernel whether it
  # ignores SIGPIPE (signal 13, bit 12 of SigIgn) instead of hoping to hit the moment
  sigign=$(sed -n 's/^SigIgn:[[:space:]]*//p' "/proc/$pid/status" 2>/dev/null)
  [ -n "$sigign" ] && [ $(( 0x$sigign & 0x1000 )) -ne 0 ] && ok || no "kiosk on x11 does not ignore SIGPIPE (SigIgn '$sigign')"
  kill "$xvfb2_pid"; wait "$xvfb2_pid" 2>/dev/null
  xvfb2_pid=
  wait_gone "$pid" 200 || no "kiosk still running 20 s after its X server was killed"
  wait "$pid"; st=$?
  [ "$st" -eq 1 ] && grep -q "^lixel kiosk: lost the connection to the X server ($started_display); stopping\$" "$tmp/out" &&
    ok || no "X server killed: status $st: $(cat "$tmp/out" "$tmp/err")"
  [ ! -s "$tmp/err" ] && ok || no "X server killed: stderr is not empty: $(cat "$tmp/err")"
else
  no "no second Xvfb display could be started"
fi


# 9. the projector scene on x11: the slide through the projective light, the casters
#    cutting it; frame N read back into --snapshot (a PNG), and --snapshot needs --frames
"$lixel" kiosk --platform x11 --size 320x240 --scene projector --frames 20 --snapshot "$tmp/snap.png" >"$tmp/out" 2>&1
st=$?
[ "$st" -eq 0 ] && grep -q '; light projector$' "$tmp/out" && ok || no "kiosk --scene projector: exit status $st: $(cat "$tmp/out")"
[ "$(head -c 4 "$tmp/snap.png" 2>/dev/null | od -An -c | tr -d ' ')" = '211PNG' ] && ok || no "kiosk --snapshot wrote no PNG"
"$lixel" kiosk --platform x11 --scene projector --snapshot "$tmp/snap2.png" >"$tmp/out" 2>&1
st=$?
[ "$st" -eq 2 ] && [ ! -e "$tmp/snap2.png" ] && grep -q -- '--snapshot: expected --frames N' "$tmp/out" && ok ||
  no "kiosk --snapshot without --frames: exit status $st: $(cat "$tmp/out")"
# 10. two lights on x11, each with its own maps and pass: the start line names both, and
#     the run writes its snapshot (test_render checks the passes' sum against the reference)
"$lixel" kiosk --platform x11 --size 320x240 --scene twolights --frames 10 --snapshot "$tmp/two.png" >"$tmp/out" 2>&1
st=$?
[ "$st" -eq 0 ] && grep -q '; lights point, spot$' "$tmp/out" && [ -s "$tmp/two.png" ] && ok ||
  no "kiosk --scene twolights: exit status $st: $(cat "$tmp/out")"
echo "kiosk: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
