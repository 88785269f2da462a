#!/bin/sh
# Fails on any function in src/ longer than MAX lines (default 80), from its opening to
# its closing brace (lixel's style puts both at the start of a line). One line each:
# FILE:LINE: NAME is N lines.
# Usage: tools/check-function-length.sh [MAX]   (from the top of the repository)
max=${1:-80}
awk -v max="$max" '
  FNR == 1 { prev = ""; start = 0 }
  /^\{/ { start = FNR; name = prev; next }
  /^\}/ && start {
    n = FNR - start + 1
    if (n > max) {
      sub(/\(.*/, "", name); k = split(name, w, /[ *]+/)
      printf "%s:%d: %s is %d lines (at most %d)\n", FILENAME, start, w[k], n, max
      bad = 1
    }
    start = 0
  }
  # the signature: the last line before "{" that starts a declaration (not its
  # continuation, which is indented)
  /^[A-Za-z]/ { prev = $0 }
  END { exit bad }
' src/*/*.c
