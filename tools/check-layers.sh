#!/bin/sh
# Checks lixel's include rules (docs/lixel.md, "Layers"):
#  1. a file under src/LAYER/ includes only headers of its own layer or of a lower one
#     (the order below);
#  2. the GL-free files named on the command line (the Makefile's CORE_SRC) reach no GL,
#     EGL, X11, GBM or DRM header, directly or through lixel's own headers.
# Prints one line per broken rule (FILE: what it includes, and why that is refused) and
# exits 1 if there is any; silent and 0 otherwise. One awk pass reads every file once.
# Usage: tools/check-layers.sh CORE_FILE...   (from the top of the repository)
set -u
core=" $* "
# shellcheck disable=SC2046 # the file names have no spaces (src/LAYER/NAME)
exec awk -v order="base geom scene shadow measure gl platform kiosk app" -v core="$core" '
  function layer_of(p) { return (split(p, a, "/") >= 3 && a[1] == "src") ? a[2] : "" }
  BEGIN {
    n = split(order, o, " ")
    for (i = 1; i <= n; i++) rank[o[i]] = i
    gl = "^<(GLES2|GLES3|GL|EGL|X11)/|^<gbm\\.h>|^<xf86drm|^<drm"
  }
  FNR == 1 {
    files[++nf] = FILENAME
    k = split(FILENAME, parts, "/"); base = parts[k]
    if (!(base in where)) where[base] = FILENAME # the first of a name, as ls src/*/NAME gives
  }
  /^[ \t]*#[ \t]*include[ \t]*"/ {
    h = $0; sub(/^[^"]*"/, "", h); sub(/".*/, "", h)
    inc[FILENAME] = inc[FILENAME] " " h
  }
  /^[ \t]*#[ \t]*include[ \t]*</ {
    h = $0; sub(/^[^<]*/, "", h)
    if (h ~ gl) { sys_gl[FILENAME] = 1; if (!(FILENAME in first_gl)) { first_gl[FILENAME] = h } }
  }
  END {
    bad = 0
    for (i = 1; i <= nf; i++) {
      f = files[i]; l = layer_of(f)
      if (!(l in rank)) { printf "%s: in src/%s/, which is no layer (%s)\n", f, l, order; bad = 1; continue }
      m = split(inc[f], hs, " ")
      for (j = 1; j <= m; j++) {
        if (!(hs[j] in where)) continue # generated in BUILD (none are included today)
        p = where[hs[j]]; hl = layer_of(p)
        if (rank[hl] > rank[l]) { printf "%s: includes %s, of layer %s, above its own (%s)\n", f, p, hl, l; bad = 1 }
      }
    }
    # headers that reach a GL-side system header, repeated until nothing changes
    do {
      changed = 0
      for (i = 1; i <= nf; i++) {
        f = files[i]
        if (f !~ /\.h$/ || (f in tainted)) continue
        hit = (f in sys_gl)
        m = split(inc[f], hs, " ")
        for (j = 1; j <= m; j++) if ((hs[j] in where) && (where[hs[j]] in tainted)) hit = 1
        if (hit) { tainted[f] = 1; changed = 1 }
      }
    } while (changed)
    for (i = 1; i <= nf; i++) {
      f = files[i]
      if (index(core, " " f " ") == 0) continue
      if (f in sys_gl) {
        g = first_gl[f]; sub(/>.*/, ">", g)
        printf "%s: GL-free (CORE_SRC), yet includes %s\n", f, g; bad = 1
      }
      m = split(inc[f], hs, " ")
      for (j = 1; j <= m; j++)
        if ((hs[j] in where) && (where[hs[j]] in tainted)) {
          printf "%s: GL-free (CORE_SRC), yet includes %s, which reaches a GL, EGL, X11 or DRM header\n", f, where[hs[j]]
          bad = 1
        }
    }
    exit bad
  }
' src/*/*.c src/*/*.h
