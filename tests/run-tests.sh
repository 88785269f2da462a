#!/bin/sh
# Runs every test program of a build directory and the command-line tests, then
# prints one closing line "N passed, N failed".
# Usage: tests/run-tests.sh BUILD_DIR
set -u
build=${1:-build}
passed=0
failed=0
failed_names=""
for t in "$build"/tests/test_*; do
  [ -x "$t" ] || continue
  name=$(basename "$t")
  echo "== $name"
  if "$t"; then passed=$((passed + 1)); else failed=$((failed + 1)); failed_names="$failed_names $name"; fi
done
echo "== cli"
if sh tests/cli.sh "$build/lixel"; then passed=$((passed + 1)); else failed=$((failed + 1)); failed_names="$failed_names cli"; fi
[ -n "$failed_names" ] && echo "failed:$failed_names"
echo "tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
