#!/bin/sh
# Runs libFuzzer harnesses for a while each, in a fresh temporary folder: the seeds of
# fuzz/corpus/NAME are copied there (the repository's corpus is never changed) and crash,
# leak and timeout files go there too, never into the tree. Prints one line per harness
# (seconds, runs, coverage) and, when one fails, where its findings are kept.
# Usage: tools/fuzz.sh FUZZ_BIN_DIR SECONDS NAME...   (from the top of the repository)
set -u
bindir=$1
seconds=$2
shift 2
failed=""
for name in "$@"; do
  bin=$bindir/$name
  if [ ! -x "$bin" ]; then
    echo "fuzz: $bin is missing (make fuzz builds it)" >&2
    failed="$failed $name"
    continue
  fi
  # The longest input worth trying: a few lines of a scene or profile (each parser
  # refuses a line past 1023 or 511 characters), a spec or mode a little past the
  # 63 characters they take.
  case $name in
    fuzz_scene) max_len=4096 ;;
    fuzz_board) max_len=2048 ;;
    *) max_len=128 ;;
  esac
  work=$(mktemp -d "${TMPDIR:-/tmp}/lixel-$name.XXXXXX") || exit 1
  mkdir "$work/corpus" "$work/artifacts"
  cp fuzz/corpus/"$name"/* "$work/corpus/"
  dict=""
  [ -f "fuzz/$name.dict" ] && dict="-dict=$(pwd)/fuzz/$name.dict"
  abs_bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
  # -timeout: one input taking over 10 s is a finding; leaks are one too (detect_leaks).
  # libFuzzer counts whole seconds and stops only once more than -max_total_time have
  # passed (2 ran 3 s): one less runs for SECONDS.
  start=$(date +%s)
  (cd "$work" && ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=1" UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1" \
    "$abs_bin" -max_total_time="$((seconds > 1 ? seconds - 1 : 1))" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$work/artifacts/" $dict corpus) >"$work/log" 2>&1
  rc=$?
  secs=$(($(date +%s) - start))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log")
  cov=$(grep '^#[0-9]' "$work/log" | tail -n 1 | sed -n 's/.* cov: \([0-9]*\) ft: \([0-9]*\) corp: \([0-9]*\).*/cov \1, features \2, corpus \3/p')
  if [ "$rc" -eq 0 ] && ! ls "$work/artifacts" | grep -q .; then
    echo "fuzz: $name: ok, $secs s, ${runs:-?} runs, ${cov:-?}"
    rm -rf "$work"
  else
    echo "fuzz: $name: FAILED (exit $rc) after ${runs:-?} runs; findings in $work/artifacts, log in $work/log"
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*invariant failed|.*runtime error|artifact_prefix|Test unit written)' "$work/log" | head -n 20
    failed="$failed $name"
  fi
done
[ -z "$failed" ] || { echo "fuzz: failed:$failed"; exit 1; }
