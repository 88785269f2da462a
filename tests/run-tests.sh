#!/bin/sh
# Runs every test program of a build directory and the command-line tests, then
# prints one closing line "N passed, N failed".
# Usage: tests/run-tests.sh BUILD_DIR
set -u
build=${1:-build}
passed=0
failed=0
failed_names=""
# The test programs run JOBS at a time (default: the CPUs), the long ones first, each
# into its own log, shown in name order when all are done; none asserts a time, so they
# may share the CPUs.
jobs=${JOBS:-$(nproc 2>/dev/null || echo 1)}
logs=$(mktemp -d "${TMPDIR:-/tmp}/lixel-tests.XXXXXX") || exit 1
for name in test_extremes test_render test_plane; do [ -x "$build/tests/$name" ] && echo "$name"; done >"$logs/order"
for t in "$build"/tests/test_*; do
  [ -x "$t" ] || continue
  grep -qx "$(basename "$t")" "$logs/order" || basename "$t" >>"$logs/order"
done
# Mesa's llvmpipe and OSMesa keep allocations of their own past exit (JIT code, context
# caches) that LeakSanitizer cannot attribute; GL-linked programs run under ASan and UBSan
# without the leak check, the GL-free ones with it.
xargs -P "$jobs" -I{} sh -c 'case {} in test_render|test_extremes) leaks=0 ;; *) leaks=1 ;; esac
  ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=$leaks" "$1/tests/{}" >"$2/{}.log" 2>&1; echo $? >"$2/{}.rc"' \
  sh "$build" "$logs" <"$logs/order"
for rc in "$logs"/*.rc; do
  [ -e "$rc" ] || continue
  name=$(basename "$rc" .rc)
  echo "== $name"
  cat "$logs/$name.log"
  if [ "$(cat "$rc")" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); failed_names="$failed_names $name"; fi
done
rm -rf "$logs"
echo "== cli"
if ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" sh tests/cli.sh "$build/lixel"; then passed=$((passed + 1)); else failed=$((failed + 1)); failed_names="$failed_names cli"; fi
echo "== kiosk (x11 under Xvfb)"
if ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" sh tests/kiosk_x11.sh "$build/lixel"; then passed=$((passed + 1)); else failed=$((failed + 1)); failed_names="$failed_names kiosk"; fi
[ -n "$failed_names" ] && echo "failed:$failed_names"
echo "tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
