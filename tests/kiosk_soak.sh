#!/bin/sh
# Soak test of the kiosk (make soak): `lixel kiosk --platform x11 --overlay` under Xvfb for
# SOAK_SECONDS (default 600) with a space key press every 50 ms (xdotool: 20 presses a
# second, sent in one batch per second), its own resident memory sampled every 5 seconds
# (every second in runs shorter than 2 minutes): RssAnon + RssShmem in /proc/PID/status,
# what a leak grows. The mapped libraries' pages (RssFile, 64 MB of VmRSS's 116 here) grow
# by themselves the first time a code path runs, and are reported apart.
#
# It fails when
#   - memory grows: the baseline is the largest sample of the warm-up (the first minute,
#     or the first half of a run shorter than 2 minutes: shaders compiled, buffers and
#     caches filled, the animation's casters through most of their positions); any later
#     sample above the baseline plus the tolerance (2% of it, at least 2048 kB) fails;
#   - the method changes the kiosk logs ('method: A -> B') are not exactly the presses sent;
#   - the kiosk dies, or does not quit with status 0 on q at the end.
# Prints the figures: presses sent, changes counted, its own memory first/baseline/last/max.
# Usage: tests/kiosk_soak.sh path/to/lixel   (SOAK_SECONDS=20 for a short run; SOAK_SAMPLES=FILE
# keeps every sample there, one "seconds own-kB file-kB" a line)
set -u
lixel=${1:?usage: kiosk_soak.sh path/to/lixel}
seconds=${SOAK_SECONDS:-600}
case $seconds in '' | *[!0-9]*) echo "kiosk_soak: SOAK_SECONDS must be a whole number of seconds" >&2; exit 2 ;; esac
[ "$seconds" -ge 5 ] || { echo "kiosk_soak: SOAK_SECONDS must be at least 5" >&2; exit 2; }
per_second=20 # one press every 50 ms
if [ "$seconds" -ge 120 ]; then warmup=60; else warmup=$((seconds / 2)); fi
if [ "$seconds" -ge 120 ]; then every=5; else every=1; fi
tmp=$(mktemp -d)
xvfb_pid=
pid=
cleanup() {
  [ -n "$pid" ] && kill "$pid" 2>/dev/null && wait "$pid" 2>/dev/null
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "soak: FAIL: $*"; exit 1; }
now_ns() { date +%s%N; }

. "$(dirname "$0")/xvfb.sh"
start_xvfb 71
xvfb_pid=$started_pid
[ -n "$started_display" ] || fail "no Xvfb display could be started"
export DISPLAY=$started_display

"$lixel" kiosk --platform x11 --size 800x600 --overlay >"$tmp/out" 2>"$tmp/err" &
pid=$!
wid=
for i in $(seq 1 200); do
  grep -q '^lixel kiosk: GL_VENDOR' "$tmp/out" 2>/dev/null && wid=$(xdotool search --name '^lixel$' 2>/dev/null | head -n 1)
  [ -n "$wid" ] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
[ -n "$wid" ] || fail "the kiosk did not start: $(cat "$tmp/out" "$tmp/err")"
echo "soak: $seconds s, $per_second presses a second, RSS every $every s, warm-up $warmup s"

# "OWN FILE": RssAnon + RssShmem, RssFile (kB)
rss() { awk '/^RssAnon:/ { a = $2 } /^RssShmem:/ { s = $2 } /^RssFile:/ { f = $2 } END { if (a != "") print a + s, f }' "/proc/$pid/status" 2>/dev/null; }
keys=$(yes space | head -n "$per_second" | tr '\n' ' ')
sent=0
start=$(now_ns)
next_sample=0
second=0
: >"$tmp/rss"
while [ "$second" -lt "$seconds" ]; do
  kill -0 "$pid" 2>/dev/null || fail "the kiosk died after $second s: $(tail -n 5 "$tmp/out") $(cat "$tmp/err")"
  if [ "$second" -ge "$next_sample" ]; then
    r=$(rss)
    [ -n "$r" ] && echo "$second $r" >>"$tmp/rss"
    next_sample=$((next_sample + every))
  fi
  # one second's presses, 50 ms apart; then wait for the start of the next second
  # shellcheck disable=SC2086
  xdotool key --window "$wid" --delay 40 $keys >/dev/null 2>&1 || fail "xdotool could not send keys after $sent presses"
  sent=$((sent + per_second))
  second=$((second + 1))
  left=$((start + second * 1000000000 - $(now_ns)))
  [ "$left" -gt 0 ] && sleep "$(awk -v ns="$left" 'BEGIN { printf "%.3f", ns / 1e9 }')"
done
elapsed=$(( ($(now_ns) - start) / 1000000 ))
r=$(rss)
[ -n "$r" ] && echo "$second $r" >>"$tmp/rss"
# every press reaches the kiosk before q, which it reads after them
sleep 1
xdotool key --window "$wid" q >/dev/null 2>&1
for i in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$pid" 2>/dev/null && fail "the kiosk did not quit on q"
wait "$pid"; st=$?
pid=
changes=$(grep -c '^method: ' "$tmp/out")

# the memory rule (see the top of this file)
figures=$(awk -v warmup="$warmup" '
  { t = $1; r = $2; if (NR == 1) { first = r; flo = $3 } last = r; if (r > max) max = r; if ($3 > fhi) fhi = $3
    if (t <= warmup) { if (r > base) base = r } else { after++; if (r > worst) worst = r } }
  END {
    tol = base * 0.02; if (tol < 2048) tol = 2048
    printf "%d %d %d %d %d %d %d %d %d\n", first, base, last, max, base + tol, worst, after, flo, fhi
  }' "$tmp/rss")
set -- $figures
first=$1 base=$2 last=$3 max=$4 limit=$5 worst=$6 after=$7 file_first=$8 file_max=$9
echo "soak: presses sent $sent in $((elapsed / 1000)).$(printf %03d $((elapsed % 1000))) s (one every $((elapsed / (sent > 0 ? sent : 1))) ms), method changes $changes"
echo "soak: own memory (RssAnon + RssShmem) kB: first $first, warm-up max (baseline) $base, last $last, max $max; limit after the warm-up $limit ($after samples, largest $worst)"
echo "soak: libraries' pages (RssFile) kB: first $file_first, max $file_max"
echo "soak: own memory samples (s kB): $(awk '{ if ((NR - 1) % 12 == 0) printf "%s:%s ", $1, $2; l = $1 ":" $2 } END { print l }' "$tmp/rss")"
[ -n "${SOAK_SAMPLES:-}" ] && cp "$tmp/rss" "$SOAK_SAMPLES"
result=0
[ "$st" -eq 0 ] || { echo "soak: FAIL: the kiosk's exit status $st: $(cat "$tmp/err")"; result=1; }
[ "$changes" -eq "$sent" ] || { echo "soak: FAIL: $sent presses sent, $changes method changes logged"; result=1; }
[ "$after" -ge 1 ] || { echo "soak: FAIL: no RSS sample after the warm-up"; result=1; }
[ "$worst" -le "$limit" ] || { echo "soak: FAIL: its own memory grew after the warm-up: $worst kB > $limit kB"; result=1; }
[ "$result" -eq 0 ] && echo "soak: passed"
exit "$result"
