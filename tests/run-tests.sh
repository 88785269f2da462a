#!/bin/sh
# Runs every test of a build directory in one pool, JOBS at a time (default: the CPUs),
# the long ones first, with the kiosk test beside the pool, each into its own log, shown
# in a fixed order when all are done, then prints one closing line "tests: N passed,
# N failed". None asserts a time, so they may share the CPUs. The tests are
#   - every test program BUILD/tests/test_*;
#   - cli (tests/cli.sh) and kiosk (tests/kiosk_x11.sh, under Xvfb);
#   - with SOAK_SECONDS=N, a kiosk soak of N seconds (tests/kiosk_soak.sh);
#   - with FUZZ_SECONDS=N, N seconds of each libFuzzer harness FUZZ_NAMES lists, from
#     FUZZ_DIR (default BUILD/fuzz), by tools/fuzz.sh.
# Usage: tests/run-tests.sh BUILD_DIR   (from the top of the repository)
set -u
build=${1:-build}
passed=0
failed=0
failed_names=""
jobs=${JOBS:-$(nproc 2>/dev/null || echo 1)}
# The pool keeps every CPU busy: llvmpipe's own rasterizer threads would only add their
# hand-offs (5 of the pool's 90 CPU-seconds here), so it rasterizes in the calling thread
# unless the caller says otherwise. What the tests check does not depend on it.
export LP_NUM_THREADS=${LP_NUM_THREADS:-0}
logs=$(mktemp -d "${TMPDIR:-/tmp}/lixel-tests.XXXXXX") || exit 1
trap 'rm -rf "$logs"' EXIT

# The job list, "KIND NAME" a line, longest first (as measured on two cores), except that
# test_render starts after test_filter: on a fresh machine Mesa's shader cache is empty, and
# most of test_render's shader variants are test_filter's, compiled once that way instead of
# twice at the same time. The kiosk test is not in the list (below).
{
  echo "script cli"
  [ -x "$build/tests/test_filter" ] && echo "program test_filter"
  for name in test_render test_extremes; do [ -x "$build/tests/$name" ] && echo "program $name"; done
  [ -n "${SOAK_SECONDS:-}" ] && echo "script soak"
  for name in ${FUZZ_SECONDS:+${FUZZ_NAMES:-}}; do echo "fuzz $name"; done
  for t in "$build"/tests/test_*; do
    [ -x "$t" ] || continue
    case $(basename "$t") in test_extremes | test_render | test_filter) ;; *) echo "program $(basename "$t")" ;; esac
  done
} >"$logs/jobs"

# One job: its output into NAME.log, its exit status into NAME.rc.
# Mesa's llvmpipe and OSMesa keep allocations of their own past exit (JIT code, context
# caches) that LeakSanitizer cannot attribute: GL-linked programs run under ASan and UBSan
# without the leak check, the GL-free ones with it.
run_one='kind=$1 name=$2 build=$RUN_BUILD logs=$RUN_LOGS start=$(date +%s)
  case $kind:$name in
    program:test_render | program:test_extremes | program:test_filter) ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" "$build/tests/$name" ;;
    program:*) ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=1" "$build/tests/$name" ;;
    script:cli) ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" sh tests/cli.sh "$build/lixel" ;;
    script:kiosk) ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" sh tests/kiosk_x11.sh "$build/lixel" ;;
    script:soak) ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" sh tests/kiosk_soak.sh "$build/lixel" ;;
    fuzz:*) sh tools/fuzz.sh "${FUZZ_DIR:-$build/fuzz}" "$FUZZ_SECONDS" "$name" ;;
  esac >"$logs/$name.log" 2>&1
  echo $? >"$logs/$name.rc"
  echo $(($(date +%s) - start)) >"$logs/$name.secs"'
export RUN_BUILD=$build RUN_LOGS=$logs FUZZ_SECONDS=${FUZZ_SECONDS:-}
# The kiosk test waits on key presses and windows most of its time: it runs beside the
# pool, not in one of its slots (2-3 s less in all on two cores, cold shader cache).
sh -c "$run_one" sh script kiosk &
kiosk_pid=$!
xargs -P "$jobs" -L 1 sh -c "$run_one" sh <"$logs/jobs"
wait "$kiosk_pid"
echo "script kiosk" >>"$logs/jobs"

while read -r kind name; do
  echo "== $name ($(cat "$logs/$name.secs" 2>/dev/null) s)"
  cat "$logs/$name.log"
  if [ "$(cat "$logs/$name.rc" 2>/dev/null)" = 0 ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    failed_names="$failed_names $name"
  fi
done <"$logs/jobs"
[ -n "$failed_names" ] && echo "failed:$failed_names"
echo "tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
