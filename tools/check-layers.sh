#!/bin/sh
# Checks lixel's include rules (docs/lixel.md, "Layers"):
#  1. a file under src/LAYER/ includes only headers of its own layer or of a lower one
#     (the order below);
#  2. the GL-free files named on the command line (the Makefile's CORE_SRC) reach no GL,
#     EGL, X11, GBM or DRM header, directly or through lixel's own headers.
# Prints one line per broken rule (FILE: what it includes, and why that is refused) and
# exits 1 if there is any; silent and 0 otherwise.
# Usage: tools/check-layers.sh CORE_FILE...   (from the top of the repository)
set -u
order="base geom scene shadow measure gl platform kiosk app"
gl_headers='<(GLES2|GLES3|GL|EGL|X11)/|<gbm\.h>|<xf86drm|<drm'
bad=0

rank() { # the position of a layer in $order, or nothing
  i=0
  for l in $order; do
    [ "$l" = "$1" ] && { echo $i; return; }
    i=$((i + 1))
  done
}
layer_of() { echo "$1" | sed -n 's|^src/\([^/]*\)/.*|\1|p'; }
# lixel's own headers a file includes, as paths (a name no layer has is reported)
own_includes() { sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$1"; }
where() { ls src/*/"$1" 2>/dev/null | head -n 1; }

for f in src/*/*.c src/*/*.h; do
  l=$(layer_of "$f")
  r=$(rank "$l")
  if [ -z "$r" ]; then
    echo "$f: in src/$l/, which is no layer ($order)"
    bad=1
    continue
  fi
  for h in $(own_includes "$f"); do
    p=$(where "$h")
    [ -n "$p" ] || continue # generated in BUILD (none are included today)
    hl=$(layer_of "$p")
    hr=$(rank "$hl")
    if [ "$hr" -gt "$r" ]; then
      echo "$f: includes $p, of layer $hl, above its own ($l)"
      bad=1
    fi
  done
done

# Headers that reach a GL-side system header, found by repeating until nothing changes.
tainted=""
changed=1
while [ $changed -eq 1 ]; do
  changed=0
  for h in src/*/*.h; do
    case " $tainted " in *" $h "*) continue ;; esac
    hit=""
    grep -Eq "^[[:space:]]*#[[:space:]]*include[[:space:]]*($gl_headers)" "$h" && hit=1
    for i in $(own_includes "$h"); do
      p=$(where "$i")
      case " $tainted " in *" $p "*) hit=1 ;; esac
    done
    if [ -n "$hit" ]; then
      tainted="$tainted $h"
      changed=1
    fi
  done
done
for f in "$@"; do
  if grep -Eq "^[[:space:]]*#[[:space:]]*include[[:space:]]*($gl_headers)" "$f"; then
    echo "$f: GL-free (CORE_SRC), yet includes $(grep -Eo "($gl_headers)[^>]*>?" "$f" | head -n 1)"
    bad=1
  fi
  for i in $(own_includes "$f"); do
    p=$(where "$i")
    case " $tainted " in *" $p "*)
      echo "$f: GL-free (CORE_SRC), yet includes $p, which reaches a GL, EGL, X11 or DRM header"
      bad=1 ;;
    esac
  done
done
exit $bad
