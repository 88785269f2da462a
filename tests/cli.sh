#!/bin/sh
# Command-line tests of lixel: help, bad input (exit 2, one line, nothing written),
# and good runs on both platforms with their JSON.
# Usage: tests/cli.sh path/to/lixel
set -u
lixel=${1:?usage: cli.sh path/to/lixel}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
ok() { pass=$((pass + 1)); }
no() { fail=$((fail + 1)); echo "FAIL: $*"; }

# expect_bad "what" ARGS...: exit status 2, exactly one line on stderr, no image.
expect_bad() {
  what=$1; shift
  rm -f "$tmp/out.png"
  "$lixel" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  st=$?
  lines=$(wc -l <"$tmp/stderr")
  if [ "$st" -ne 2 ]; then no "$what: exit status $st, expected 2"; return; fi
  if [ "$lines" -ne 1 ]; then no "$what: $lines lines on stderr, expected 1:"; cat "$tmp/stderr"; return; fi
  if [ -e "$tmp/out.png" ] || ls "$tmp"/out.png.tmp* >/dev/null 2>&1; then no "$what: an image was written"; return; fi
  ok
}

"$lixel" --help >"$tmp/help" 2>&1 && grep -q "render" "$tmp/help" && ok || no "lixel --help"
"$lixel" render --help >"$tmp/help" 2>&1 && ok || no "lixel render --help exit status"
for opt in --method --scene --config --size --eye --at --fov --light --light-dir --time --platform --out --measure --json \
    --plane-lixels --fallback-lixels --uniform-lixels --filter --light-size --lookup-region --caster-depth \
    --caster-maps --plane-density --depth-slots; do
  grep -q -- "$opt" "$tmp/help" && ok || no "render --help does not describe $opt"
done

out="--out $tmp/out.png"
expect_bad "no command"
expect_bad "unknown command" frobnicate
expect_bad "unknown method" render --method teapot $out
expect_bad "size 0x0" render --size 0x0 $out
expect_bad "size words" render --size wide $out
expect_bad "word for a number" render --fov wide $out
expect_bad "fov out of range" render --fov 180 $out
expect_bad "two numbers for a point" render --eye 1,2 $out
expect_bad "light and light-dir" render --light 1,2,3 --light-dir 0,-1,0 $out
expect_bad "zero light direction" render --light-dir 0,0,0 $out
expect_bad "eye equals at" render --eye 1,1,1 --at 1,1,1 $out
expect_bad "unknown platform" render --platform vulkan $out
expect_bad "unknown config" render --config sideways $out
expect_bad "missing value" render --size
expect_bad "unknown option" render --shadows $out
expect_bad "output into a missing directory" render --out "$tmp/no/such/dir/x.png"
expect_bad "second output into a missing directory" render $out --decision-out "$tmp/no/d.png"
expect_bad "reference output into a missing directory" render $out --reference-out "$tmp/no/r.png"
expect_bad "unreadable scene" render --scene "$tmp/none.scene" $out
printf 'light point 0 5 0\nsphere radius 0.5 at 0 0 colour 1 0 0\n' >"$tmp/bad.scene"
expect_bad "malformed scene" render --scene "$tmp/bad.scene" $out
grep -q "bad.scene:2: " "$tmp/stderr" && ok || no "malformed scene message lacks file:line: $(cat "$tmp/stderr")"

for platform in osmesa egl; do
  rm -f "$tmp/out.png"
  if "$lixel" render --platform $platform --method uniform --measure --json --size 96x64 --frames 2 \
      --out "$tmp/out.png" >"$tmp/json" 2>"$tmp/stderr"; then
    ok
    for key in '"method": "uniform"' "\"platform\": \"$platform\"" '"renderer"' '"size": \[96, 64\]' '"lixels": 262144' \
        '"maps": \[{"name": "uniform"' '"rendered": true' '"frame_ms"' '"setup_us"' '"warnings"' '"mismatch_pct"' \
        '"false_shadow_pct"' '"missing_shadow_pct"' '"compared_pixels"' '"planes": {"floor": {"map": "serving", "pixels"' \
        '"pixels_seen": [0-9]*, "pixels_no_lookup": [0-9]*, "lpp_median"' '"m_median"' '"m_max"' '"aniso_max"'; do
      grep -q "$key" "$tmp/json" && ok || no "$platform: JSON lacks $key"
    done
    grep -qiE 'nan|inf' "$tmp/json" && no "$platform: JSON holds NaN or Infinity" || ok
    # without a filter or --light-size, --measure skips the soft reference (seconds a frame at 1024^2)
    grep -q '"soft_error_pct"' "$tmp/json" && no "$platform: --measure computed the soft reference" || ok
    [ "$(wc -l <"$tmp/json")" -eq 1 ] && ok || no "$platform: JSON is not one line"
    # a PNG starts with \211PNG
    [ "$(head -c 4 "$tmp/out.png" | od -An -c | tr -d ' ')" = '211PNG' ] && ok || no "$platform: not a PNG"
  else
    no "$platform render failed: $(cat "$tmp/stderr")"
  fi
done

# The lixels of map NAME in the JSON of a render (w x h), or nothing.
map_lixels() {
  sed -n "s/.*\"name\": \"$1\", \"x\": [0-9]*, \"y\": [0-9]*, \"w\": \([0-9]*\), \"h\": \([0-9]*\).*/\1 \2/p" "$2" |
    awk '{ print $1 * $2 }'
}
# plane-optimal is the default: floor, wall and fallback maps, the plane maps shaped per
# frame within their budgets (350^2 lixels), the fallback 128x128; a plane no shadow
# reaches gets no map (the default view's wall: the casters' shadows all fall on the
# floor), the low light's long shadows reach the wall. With --plane-density budget the
# wall map spends its budget (many lixels a pixel at 160x120); by default it is only as
# dense as the casters reading it need: fewer lixels
"$lixel" render --config low --plane-density budget --json --size 160x120 --frames 1 --out "$tmp/p.png" >"$tmp/json" 2>"$tmp/stderr" &&
  n=$(map_lixels wall "$tmp/json") && [ -n "$n" ] && [ "$n" -gt 60000 ] && [ "$n" -le 122500 ] && ok ||
  no "low light, --plane-density budget: the wall map holds '$n' lixels, expected its 350^2 budget mostly used: $(cat "$tmp/json" "$tmp/stderr")"
"$lixel" render --config low --json --size 160x120 --frames 1 --out "$tmp/p.png" >"$tmp/json" 2>"$tmp/stderr" &&
  r=$(map_lixels wall "$tmp/json") && [ -n "$r" ] && [ "$r" -gt 0 ] && [ "$r" -lt "${n:-0}" ] && ok ||
  no "low light: the wall map holds '$r' lixels, expected fewer than the budget's '$n' (readers' density): $(cat "$tmp/json" "$tmp/stderr")"
if "$lixel" render --measure --json --size 160x120 --frames 1 --out "$tmp/p.png" >"$tmp/json" 2>"$tmp/stderr"; then
  # the fallback square, 128x128 or more: the wall, without a map, hands it lixels
  for key in '"method": "plane"' '"name": "fallback", "x": [0-9]*, "y": [0-9]*, "w": \(12[89]\|1[3-9][0-9]\|[23][0-9][0-9]\), "h": \1[,}]' \
      '"lixels": 261384' '"lpp_spread": 1[,}]' '"aniso_max": 1[,}]' '"atlas_fill": 0\.[0-9]'; do
    grep -q "$key" "$tmp/json" && ok || no "plane JSON lacks $key: $(cat "$tmp/json")"
  done
  n=$(map_lixels floor "$tmp/json")
  [ -n "$n" ] && [ "$n" -gt 60000 ] && [ "$n" -le 122500 ] && ok || no "plane map floor holds '$n' lixels, expected its 350^2 budget mostly used"
  [ "$(map_lixels wall "$tmp/json")" = 0 ] && ok || no "default view: a wall map, where no shadow falls: $(cat "$tmp/json")"
  # with --caster-maps fallback no caster reads the floor map (the ball did, which the
  # cylinder's shadow may reach): a lixel a pixel, far fewer lixels
  "$lixel" render --caster-maps fallback --json --size 160x120 --frames 1 --out "$tmp/p.png" >"$tmp/json2" 2>"$tmp/stderr" &&
    f=$(map_lixels floor "$tmp/json2") && [ -n "$f" ] && [ "$f" -gt 0 ] && [ "$f" -lt $((${n:-0} / 4)) ] && ok ||
    no "--caster-maps fallback: the floor map holds '$f' lixels, expected under a quarter of the default's '$n': $(cat "$tmp/json2" "$tmp/stderr")"
  grep -qiE 'nan|inf' "$tmp/json" && no "plane JSON holds NaN or Infinity" || ok
  # the depth path the self-test chose (llvmpipe: the depth texture)
  grep -q '"depth_path": "highp24-texture", "depth_selftest": "passed"' "$tmp/json" && ok || no "depth path: $(cat "$tmp/json")"
else
  no "default render failed: $(cat "$tmp/stderr")"
fi
# the miner's lamp (the light at the eye): every shadow lies behind what casts it, so no
# method draws a map or looks one up, and the image matches the reference; the text says why
for m in plane uniform lispsm; do
  if "$lixel" render --config miner --method $m --measure --json --size 160x120 --frames 1 --out "$tmp/m.png" \
      >"$tmp/json" 2>"$tmp/stderr"; then
    grep -q '"rendered": true' "$tmp/json" && no "miner's lamp, $m: a map drawn: $(cat "$tmp/json")" || ok
    for key in '"lookup_pct": 0[,}]' '"mismatch_pct": 0[,}]' '"warnings": \["light: the point light is at the eye'; do
      grep -q "$key" "$tmp/json" && ok || no "miner's lamp, $m: JSON lacks $key: $(cat "$tmp/json")"
    done
  else
    no "miner's lamp, $m: render failed: $(cat "$tmp/stderr")"
  fi
done
"$lixel" render --config miner --size 160x120 --frames 1 --out "$tmp/m.png" >"$tmp/text" 2>&1 &&
  grep -q '^warning: light: the point light is at the eye' "$tmp/text" && ok || no "miner's lamp: the text: $(cat "$tmp/text")"
# the paper's square maps on request
"$lixel" render --region-shape square --json --size 160x120 --frames 1 --out "$tmp/p.png" >"$tmp/json" 2>&1 &&
  grep -q '"name": "floor", "x": [0-9]*, "y": [0-9]*, "w": 350, "h": 350' "$tmp/json" && ok ||
  no "square maps: $(cat "$tmp/json")"
"$lixel" render --scene table --plane-lixels 200 --fallback-lixels 64 --json --size 96x64 --frames 1 --out "$tmp/t.png" >"$tmp/json" 2>&1 &&
  n=$(map_lixels table "$tmp/json") && [ -n "$n" ] && [ "$n" -le 40000 ] && grep -q '"lixels": 84096' "$tmp/json" && ok ||
  no "table scene with budgets: $(cat "$tmp/json")"
# the table's default view at 1024x1024: the floor's shadows in pieces, counted in the
# planes' JSON, their lixels together at least those used
"$lixel" render --scene table --size 1024x1024 --measure --json --frames 1 --out "$tmp/t.png" >"$tmp/json" 2>&1 &&
  floor=$(grep -o '"floor": {[^}]*}' "$tmp/json" | head -n 1) &&
  pieces=$(echo "$floor" | sed -n 's/.*"map_pieces": \([0-9]*\).*/\1/p') &&
  lixels=$(echo "$floor" | sed -n 's/.*"map_lixels": \([0-9]*\).*/\1/p') &&
  used=$(echo "$floor" | sed -n 's/.*"lixels_used": \([0-9.]*\).*/\1/p') &&
  [ "$pieces" -ge 2 ] && [ "$pieces" -le 4 ] && [ "$lixels" -le 122500 ] &&
  awk -v l="$lixels" -v u="$used" 'BEGIN { exit !(l >= u && u > 0) }' && ok ||
  no "table, 1024x1024: the floor's pieces '$pieces', lixels '$lixels', used '$used': $(cat "$tmp/json")"
# each two-word option's words both taken, to different effect: fixed budgets' atlas is
# smaller than shared ones' (which must hold a map grown by what the others leave)
for b in fixed shared; do
  "$lixel" render --budget-split $b --json --size 160x120 --frames 1 --out "$tmp/p.png" >"$tmp/b-$b.json" 2>&1 || no "--budget-split $b"
done
grep -q '"atlas": \[1982, 632\]' "$tmp/b-fixed.json" && grep -q '"atlas": \[2048, 785\]' "$tmp/b-shared.json" && ok ||
  no "--budget-split fixed and shared: $(grep -o '"atlas": [^]]*' "$tmp/b-fixed.json" "$tmp/b-shared.json")"
"$lixel" render --region-shape fitted --json --size 160x120 --frames 1 --out "$tmp/p.png" >"$tmp/json" 2>&1 &&
  ! grep -q '"name": "floor", "x": [0-9]*, "y": [0-9]*, "w": 350, "h": 350' "$tmp/json" && ok ||
  no "--region-shape fitted gave a square: $(cat "$tmp/json")"
expect_bad "region shape" render --region-shape round $out
expect_bad "budget split" render --budget-split half $out
expect_bad "plane density" render --plane-density most $out
expect_bad "caster maps" render --caster-maps nearest $out
expect_bad "caster maps in the bench" bench --caster-maps dense,fallback --configs default --frames 1
expect_bad "max lpp" render --plane-max-lpp 0 $out
expect_bad "removed method option" render --method plane/corner $out
expect_bad "method option" render --method plane/round $out
expect_bad "bench method option" bench --methods uniform,plane/lpp-1 --frames 1
expect_bad "zero budget" render --plane-lixels 0 $out
expect_bad "huge budget" render --uniform-lixels 100000 $out

# One strict number parser (src/base/number.c) behind every option, scene file and profile:
# decimal only, the whole token, the reason in the one line.
expect_says() {
  said=$1; shift
  expect_bad "$@"
  grep -q -- "$said" "$tmp/stderr" || no "$1: stderr does not say '$said':" "$(cat "$tmp/stderr")"
}
expect_says "not a decimal number" "leading space" render --fov " 60" $out
expect_says "not a decimal number" "hex float" render --fov 0x3Cp0 $out
expect_says "not a decimal number" "inf" render --time inf $out
expect_says "not a decimal number" "empty list item" render --eye 1,,2 $out
expect_says "not a decimal number" "trailing comma" render --light 1,2,3, $out
expect_says "too large to hold" "overflowing number" render --eye 1e400,2,3 $out
expect_says "option 'foo', expected square, fitted" "bench names the bad option and the good ones" bench --methods plane/foo --frames 1
expect_says "too small to hold" "subnormal number" render --fov 1e-320 $out
expect_says "too large to hold" "frames overflow" render --frames 99999999999999999999999 $out
expect_says "not a decimal number" "whole frames" render --frames 2.0 $out
expect_says "from -1e15 to 1e15" "coordinate beyond the scenes' range" render --eye 1e16,0,0 $out
expect_says "\\x0a" "line break shown escaped" render --fov "$(printf '5\nx')" $out
expect_bad "bench empty method" bench --methods uniform,,plane --frames 1
expect_bad "bench trailing comma" bench --methods uniform, --frames 1
# a name given twice would be two runs under one name (the ratios took one for the other)
expect_says "--methods: expected each method once, got 'plane/lpp1' twice" "bench method twice" bench --methods plane/lpp1,uniform,plane/lpp1 --frames 1
expect_says "--configs: expected each configuration once, got 'low' twice" "bench configuration twice" bench --methods uniform --configs low,default,low --frames 1
expect_says "--filters: expected each filter once, got 'pcf2x2' twice" "bench filter twice" bench --methods uniform --filters pcf2x2,none,pcf2x2 --frames 1
expect_bad "bench empty config" bench --configs default, --frames 1
expect_says "too large to hold" "bench frames overflow" bench --frames 99999999999999999999 --methods none
expect_bad "kiosk frames overflow" kiosk --frames 99999999999999999999999
expect_bad "kiosk frames hex" kiosk --frames 0x10
expect_bad "kiosk empty method" kiosk --methods plane,,uniform --frames 1
printf 'gpio-line 0x5\n' >"$tmp/hex.profile"
expect_says "hex.profile:1:" "hex in a profile" kiosk --board "$tmp/hex.profile" --frames 1
printf 'light point 0 0x5 0\n' >"$tmp/hex.scene"
expect_says "hex.scene:1:" "hex in a scene" render --scene "$tmp/hex.scene" $out
printf 'light point 0 1e999 0\n' >"$tmp/huge.scene"
expect_says "too large to hold" "overflow in a scene" render --scene "$tmp/huge.scene" $out
expect_bad "atlas too big for the GL" render --plane-lixels 8192 $out
grep -q "exceeds the maximum texture size\|do not fit" "$tmp/stderr" && ok || no "atlas error: $(cat "$tmp/stderr")"

# the scene file of the built-in scene and the text output
if "$lixel" render --scene tests/data/default.scene --config low --size 64x64 --frames 1 --out "$tmp/s.png" >"$tmp/text" 2>&1; then
  grep -q "wrote $tmp/s.png" "$tmp/text" && ok || no "text output does not name the image"
else
  no "render --scene tests/data/default.scene: $(cat "$tmp/text")"
fi
# method none allocates nothing and renders no map
"$lixel" render --method none --json --size 32x32 --frames 1 --out "$tmp/n.png" >"$tmp/json" 2>&1 &&
  grep -q '"lixels": 0' "$tmp/json" && grep -q '"maps": \[\]' "$tmp/json" && ok || no "method none: $(cat "$tmp/json")"

# lixel bench at a small size: every method over every configuration, all outputs
mkdir -p "$tmp/strips"
if "$lixel" bench --size 64x48 --frames 1 --warmup 0 --json --csv "$tmp/b.csv" --plot "$tmp/b.png" --strips "$tmp/strips" \
    >"$tmp/bench.json" 2>"$tmp/bench.err"; then
  ok
  for key in '"size": \[64, 48\]' '"configs": \["default", "overhead"' '"animation"\]' '"results": \[{"method": "none", "filter": "none", "config": "default", "frame_ms_median"' \
      '"frame_ms_min"' '"frame_ms_max"' '"shadow_ms_median"' '"main_ms_median"' '"setup_us"' \
      '"setup_again_us": [0-9.e+-]*, "lookup_pct"' '"mismatch_pct"' '"m_max": {' \
      '"summary": \[{"method": "none", "filter": "none", "frame_ms_median": [0-9.e-]*, "frame_ms_mean": [0-9.e-]*, "depth_slots": 8, "ratio_none": 1, "ratio_uniform"' \
      '"ratio_uniform_by_view_median"' '"ratio_uniform_by_view_most"' '"ratio_uniform_most_on": "' '"views_at_most_uniform": [0-9]' '"views_slower_every_round": [0-9]*, "views_faster_every_round": [0-9]' \
      '"mismatch_median"' '"mismatch_worst"' '"soft_error_pct"' '"soft_error_median"' '"light_size_deg": 0.5'; do
    grep -q "$key" "$tmp/bench.json" && ok || no "bench JSON lacks $key"
  done
  grep -qiE 'nan|inf' "$tmp/bench.json" && no "bench JSON holds NaN or Infinity" || ok
  # a line per method of the registry (the help's list) and configuration, and the header
  nm=$("$lixel" bench --help 2>&1 | sed -n 's/.*--methods LIST .*from \([a-z|]*\) .*/\1/p' | tr '|' '\n' | grep -c .)
  [ "$nm" -ge 6 ] && [ "$(wc -l <"$tmp/b.csv")" -eq $((nm * 11 + 1)) ] && ok ||
    no "bench CSV has $(wc -l <"$tmp/b.csv") lines, expected $((nm * 11 + 1)) ($nm methods)"
  head -1 "$tmp/b.csv" | grep -q ',shadow_ms_median,main_ms_median,' && ok || no "bench CSV header: $(head -1 "$tmp/b.csv")"
  # a result row's JSON keys are the CSV's columns, in their order (one list serves both)
  jkeys=$(sed -n 's/.*"results": \[{\([^{]*\)"m_max".*/\1/p' "$tmp/bench.json" | grep -o '"[a-z_]*":' | tr -d '":' | paste -sd, -)
  ckeys=$(head -1 "$tmp/b.csv" | sed 's/,m_max_.*//')
  [ -n "$jkeys" ] && [ "$jkeys" = "$ckeys" ] && ok || no "bench JSON row keys '$jkeys' are not the CSV's '$ckeys'"
  [ "$(head -c 4 "$tmp/b.png" | od -An -c | tr -d ' ')" = '211PNG' ] && ok || no "bench plot is not a PNG"
  [ "$(ls "$tmp/strips" | wc -l)" -eq 11 ] && ok || no "bench wrote $(ls "$tmp/strips" | wc -l) strips, expected 11"
  grep -q "configuration 11/11: animation" "$tmp/bench.err" && ok || no "bench shows no progress on stderr"
else
  no "bench failed: $(cat "$tmp/bench.err")"
fi
"$lixel" bench --size 48x32 --frames 2 --warmup 0 --methods uniform,plane,uniform/all,tsm/footprint --configs low >"$tmp/bench.txt" 2>&1 &&
  grep -q '^\[plane\] config=low: FrameTime: ' "$tmp/bench.txt" && grep -q '^uniform ' "$tmp/bench.txt" && ok ||
  no "bench text: $(cat "$tmp/bench.txt")"
# the shadow passes and the main pass apart, per method
grep -q '^method .*shadow ms *main ms' "$tmp/bench.txt" && grep -q '^\[uniform\] config=low: .* shadow: [0-9.]* ms main: [0-9.]* ms' "$tmp/bench.txt" && ok ||
  no "bench text lacks the pass columns: $(cat "$tmp/bench.txt")"
# the frame against uniform's view by view: the median ratio, its range, how many views at
# most uniform's, the view of the most, the views slower and faster in every round (four
# rounds of a frame each here) and the slower ones' names (uniform itself not listed)
"$lixel" bench --size 48x32 --frames 4 --warmup 0 --methods uniform,plane --configs low,overhead >"$tmp/bv.txt" 2>&1 &&
  sed -n "/^frame \/ uniform's, view by view/,\$p" "$tmp/bv.txt" >"$tmp/bv-table.txt" &&
  grep -q '^4 rounds, a difference the rounds resolve' "$tmp/bv-table.txt" &&
  grep -Eq '^plane +[0-9.]+ +\([0-9.]+-[0-9.]+\) +[0-2]/2  (low|overhead) +[0-2]/2 +[0-2]/2  (-|low|overhead|low,overhead)$' "$tmp/bv-table.txt" &&
  ! grep -q '^uniform ' "$tmp/bv-table.txt" && ok || no "bench text lacks the view-by-view ratios: $(cat "$tmp/bv.txt")"
# where the main pass looks the maps up: footprint (the default) or everywhere, the
# same decisions; a lookup share in the JSON, smaller for footprint
for lr in footprint all; do
  "$lixel" render --lookup-region $lr --json --size 160x120 --frames 1 --out "$tmp/l.png" --decision-out "$tmp/d-$lr.png" \
    >"$tmp/l-$lr.json" 2>&1 && grep -q '"lookup_pct": [0-9]' "$tmp/l-$lr.json" && ok || no "render --lookup-region $lr: $(cat "$tmp/l-$lr.json")"
done
cmp -s "$tmp/d-footprint.png" "$tmp/d-all.png" && ok || no "--lookup-region footprint and all decide differently"
# casters' faces compared along their planes (the default) or at their pixels' depth: the
# table with a thick top (in the maps, unlike the built-in slab) decides otherwise (a
# coarse map's acne on the casters: two pixels of false shadow at the point, none at the
# face; seen level with its top, the view this used, the box's lookup volumes ending at
# its lit faces left no lookup where they parted)
for cd in face point; do
  "$lixel" render --scene tests/data/thick-table.scene --caster-depth $cd --size 320x240 --frames 1 \
    --out "$tmp/l.png" --decision-out "$tmp/c-$cd.png" >"$tmp/c-$cd.txt" 2>&1 && ok ||
    no "render --caster-depth $cd: $(cat "$tmp/c-$cd.txt")"
done
! cmp -s "$tmp/c-face.png" "$tmp/c-point.png" && ok || no "--caster-depth face and point decide alike on the thick table"
# a GPU with fewer varyings than a caster reading every map needs with face, and than the
# legs under the table top and the slab's underside need for both fronts' tests: a line for
# each, and the frame still drawn
LIXEL_MAX_VARYINGS=7 "$lixel" render --scene table --caster-depth face --size 160x120 --frames 1 --out "$tmp/v.png" \
  >"$tmp/stdout" 2>"$tmp/stderr" && grep -q "needs 8 varying vectors, this GPU has 7" "$tmp/stderr" &&
  grep -q "only the first front's shadow is tested there" "$tmp/stderr" &&
  [ "$(wc -l <"$tmp/stderr")" -eq 2 ] && [ -s "$tmp/v.png" ] && ok || no "face with 7 varyings: $(cat "$tmp/stderr")"
# two lit shelves over the floor on a GPU that cannot hold the second shelf's test: one
# line, and the frame still drawn
LIXEL_MAX_VARYINGS=4 "$lixel" render --scene tests/data/two-shelves.scene --method uniform --size 160x120 --frames 1 \
  --out "$tmp/v.png" >"$tmp/stdout" 2>"$tmp/stderr" && grep -q "only the first front's shadow is tested there" "$tmp/stderr" &&
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] && [ -s "$tmp/v.png" ] && ok || no "two shelves with 4 varyings: $(cat "$tmp/stderr")"
fp=$(sed -n 's/.*"lookup_pct": \([0-9.]*\).*/\1/p' "$tmp/l-footprint.json"); al=$(sed -n 's/.*"lookup_pct": \([0-9.]*\).*/\1/p' "$tmp/l-all.json")
awk -v a="$fp" -v b="$al" 'BEGIN { exit !(a > 0 && a < b) }' && ok || no "lookup share footprint $fp, all $al"
grep -q '^\[uniform/all\] config=low: ' "$tmp/bench.txt" && grep -q '^\[tsm/footprint\] config=low: ' "$tmp/bench.txt" && ok ||
  no "bench with /all and /footprint methods: $(cat "$tmp/bench.txt")"
# the depth path: a forced one (the self-test's choice: the default render above), bad values
"$lixel" render --depth-precision mediump --json --size 96x64 --frames 1 --out "$tmp/d.png" >"$tmp/d.json" 2>&1 &&
  grep -q '"depth_path": "mediump11", "depth_selftest": "forced"' "$tmp/d.json" && ok || no "forced mediump: $(cat "$tmp/d.json")"
LIXEL_SIMULATE_LIMA=1 "$lixel" render --json --size 96x64 --frames 1 --out "$tmp/d.png" >"$tmp/d.json" 2>&1 &&
  grep -q '"depth_path": "mediump11", "depth_selftest": "fell-back"' "$tmp/d.json" && ok || no "simulated lima: $(cat "$tmp/d.json")"
LIXEL_SIMULATE_LIMA=1 "$lixel" render --depth-precision highp --json --size 96x64 --frames 1 --out "$tmp/d.png" >"$tmp/d.json" 2>"$tmp/d.err" &&
  grep -q 'fails its self-test' "$tmp/d.err" && grep -q '"warnings": \["the forced 24-bit highp depth path fails' "$tmp/d.json" && ok ||
  no "forced highp under the simulation: $(cat "$tmp/d.err" "$tmp/d.json")"
"$lixel" bench --size 48x32 --frames 1 --warmup 0 --methods uniform --configs default --json --mediump >"$tmp/d.json" 2>/dev/null &&
  grep -q '"depth_path": "mediump11", "depth_selftest": "forced"' "$tmp/d.json" && ok || no "bench --mediump: $(cat "$tmp/d.json")"
# the depth-texture path: its name in the JSON, no warning, the same decisions as highp's
# and an atlas image read back through its shader
"$lixel" render --depth-precision texture --measure --json --size 96x64 --frames 1 --out "$tmp/t.png" \
    --atlas-out "$tmp/t-atlas.png" --decision-out "$tmp/t-dec.png" >"$tmp/t.json" 2>"$tmp/t.err" &&
  grep -q '"depth_path": "highp24-texture", "depth_selftest": "forced"' "$tmp/t.json" &&
  grep -q '"warnings": \[\]' "$tmp/t.json" && [ ! -s "$tmp/t.err" ] && ok || no "depth texture: $(cat "$tmp/t.err" "$tmp/t.json")"
# depth slots: taken on the depth-texture path (llvmpipe is no tiler), said in the JSON
# and the text; 1 on the RGBA8 paths, or when asked
grep -q '"depth_slots": 8' "$tmp/t.json" && ok || no "depth texture's slots: $(cat "$tmp/t.json")"
"$lixel" render --depth-precision texture --depth-slots 3 --size 96x64 --frames 1 --out "$tmp/s.png" >"$tmp/s.txt" 2>&1 &&
  grep -q '^atlas: .*; cleared once every 3 frames (depth slots)$' "$tmp/s.txt" && ok || no "--depth-slots 3: $(cat "$tmp/s.txt")"
"$lixel" render --depth-precision texture --depth-slots 1 --json --size 96x64 --frames 1 --out "$tmp/s.png" >"$tmp/s.json" 2>&1 &&
  grep -q '"depth_slots": 1' "$tmp/s.json" && ok || no "render --depth-slots 1: $(cat "$tmp/s.json")"
expect_bad "depth slots 0" render --depth-slots 0 $out
expect_bad "depth slots 65" render --depth-slots 65 $out
expect_bad "depth slots in words" render --depth-slots eight $out
expect_bad "bench method option slots0" bench --methods plane/slots0
"$lixel" render --depth-precision highp --json --size 96x64 --frames 1 --out "$tmp/h.png" --atlas-out "$tmp/h-atlas.png" \
    --decision-out "$tmp/h-dec.png" >"$tmp/h.json" 2>&1 && cmp -s "$tmp/h-dec.png" "$tmp/t-dec.png" &&
  [ "$(head -c 4 "$tmp/t-atlas.png" | od -An -c | tr -d ' ')" = '211PNG' ] && ok ||
  no "the depth-texture path's decisions or atlas image differ from highp's"
grep -q '"depth_slots": 1' "$tmp/h.json" && ok || no "highp's depth slots: $(cat "$tmp/h.json")"
LIXEL_SIMULATE_NO_DEPTH_TEXTURE=1 "$lixel" render --depth-precision texture --json --size 96x64 --frames 1 \
    --out "$tmp/d.png" >"$tmp/d.json" 2>"$tmp/d.err" && grep -q '"depth_path": "highp24", "depth_selftest": "passed"' "$tmp/d.json" &&
  grep -q '"warnings": \["the depth-texture path cannot be taken (no GL_OES_depth_texture (simulated)): highp24 instead"' \
    "$tmp/d.json" && [ "$(wc -l <"$tmp/d.err")" -eq 1 ] && ok || no "depth texture missing: $(cat "$tmp/d.err" "$tmp/d.json")"
LIXEL_SIMULATE_LIMA=1 "$lixel" render --depth-precision texture --json --size 96x64 --frames 1 --out "$tmp/d.png" \
    >"$tmp/d.json" 2>"$tmp/d.err" && grep -q 'depth-texture depth path fails its self-test' "$tmp/d.err" && ok ||
  no "forced depth texture under the simulation: $(cat "$tmp/d.err" "$tmp/d.json")"
expect_bad "depth precision" render --depth-precision fp16 $out
expect_bad "bench depth precision" bench --depth-precision low
# output files: never over a device or through a symbolic link, checked before any work,
# concurrent writers each renaming a whole file into place, nothing left behind
if [ -c /dev/null ]; then
  "$lixel" render --size 64x48 --frames 1 --out /dev/null >"$tmp/stdout" 2>"$tmp/stderr"; st=$?
  [ "$st" -eq 2 ] && [ -c /dev/null ] && grep -q 'not a regular file' "$tmp/stderr" && ok || no "--out /dev/null: status $st: $(cat "$tmp/stderr")"
fi
echo keep >"$tmp/victim"
ln -s "$tmp/victim" "$tmp/link.png"
"$lixel" render --size 64x48 --frames 1 --out "$tmp/link.png" >"$tmp/stdout" 2>"$tmp/stderr"; st=$?
[ "$st" -eq 2 ] && [ "$(cat "$tmp/victim")" = keep ] && [ -L "$tmp/link.png" ] && ok || no "--out through a symlink: status $st: $(cat "$tmp/stderr")"
for i in 1 2 3 4; do "$lixel" render --size 96x64 --frames 1 --out "$tmp/same.png" >/dev/null 2>&1 & done
wait
[ "$(head -c 4 "$tmp/same.png" | od -An -c | tr -d ' ')" = '211PNG' ] && [ -z "$(ls -A "$tmp" | grep '^\.same')" ] && ok ||
  no "six writers of one --out: $(ls -la "$tmp")"
"$lixel" bench --size 48x32 --frames 1 --csv "$tmp/no/such/rows.csv" >"$tmp/stdout" 2>"$tmp/stderr"; st=$?
[ "$st" -eq 2 ] && ! grep -q 'configuration' "$tmp/stderr" && [ "$(wc -l <"$tmp/stderr")" -eq 1 ] && ok ||
  no "bench --csv into a missing folder: status $st: $(cat "$tmp/stderr")"
expect_bad "bench --strips ''" bench --strips ''
expect_bad "bench --plot onto a folder" bench --plot "$tmp"
expect_bad "time beyond a million seconds" render --time 1e308 $out
expect_bad "lookup region" render --lookup-region some $out
expect_bad "caster depth" render --caster-depth middle $out
expect_bad "method option pointdepth misspelt" render --method uniform/pointdepths $out
expect_bad "method option of a one-map method" render --method uniform/square $out
expect_bad "bench unknown method" bench --methods none,teapot
expect_bad "bench 17 methods" bench --methods none,uniform,psm,lispsm,tsm,xpsm,plane,plane/square,plane/shared,plane/lpp1,plane/twist,plane/onepiece,plane/similar,plane/pointdepth,uniform/pointdepth,tsm/all,psm/all
"$lixel" bench --methods none,uniform,psm,lispsm,tsm,xpsm,plane,plane/square,plane/shared,plane/lpp1,plane/twist,plane/onepiece,plane/similar,plane/pointdepth,uniform/pointdepth,tsm/all,psm/all \
  >/dev/null 2>"$tmp/stderr"; grep -q "at most 16 methods" "$tmp/stderr" && ok || no "17 methods: $(cat "$tmp/stderr")"
expect_bad "bench zero frames" bench --frames 0
expect_bad "bench unknown config" bench --configs sideways
expect_bad "bench strips into a missing directory" bench --strips "$tmp/no/such"

# Filtered shadows: --filter none|pcf2x2|pcf3x3; the soft-edge error against an area
# light of --light-size degrees with --measure; the bench's runs METHOD+FILTER
expect_bad "unknown filter" render --filter pcf4x4 $out
expect_bad "empty filter" render --filter '' $out
expect_bad "filter list for render" render --filter none,pcf2x2 $out
expect_bad "negative light size" render --light-size -1 $out
expect_bad "light size beyond 20 degrees" render --light-size 21 $out
expect_says "not a decimal number" "light size in words" render --light-size half $out
expect_bad "bench unknown filter" bench --filters none,pcf5
expect_bad "bench empty filter" bench --filters none,,pcf2x2
expect_bad "bench trailing comma in filters" bench --filters pcf2x2,
expect_bad "bench light size" bench --light-size 90
for f in none pcf2x2 pcf3x3; do
  "$lixel" render --method uniform --filter $f --light-size 0.5 --measure --json --size 96x64 --frames 1 --out "$tmp/f-$f.png" \
    >"$tmp/f.json" 2>"$tmp/stderr" && grep -q "\"filter\": \"$f\"" "$tmp/f.json" && grep -q '"soft_error_pct": [0-9]' "$tmp/f.json" &&
    grep -q '"light_size_deg": 0.5' "$tmp/f.json" && ok || no "render --filter $f: $(cat "$tmp/f.json" "$tmp/stderr")"
done
cmp -s "$tmp/f-none.png" "$tmp/f-pcf3x3.png" && no "--filter pcf3x3 drew the image none drew" || ok
"$lixel" render --filter pcf2x2 --measure --light-size 2 --size 96x64 --frames 1 --out "$tmp/f.png" >"$tmp/f.txt" 2>&1 &&
  grep -q '^soft edge: [0-9.]*% mean visibility error (filter pcf2x2) against a 2-degree area light$' "$tmp/f.txt" && ok ||
  no "render --filter text: $(cat "$tmp/f.txt")"
if "$lixel" bench --size 48x32 --frames 1 --warmup 0 --methods none,uniform --filters none,pcf3x3 --configs default \
    --csv "$tmp/f.csv" >"$tmp/f.txt" 2>&1; then
  grep -q '^\[uniform+pcf3x3\] config=default: FrameTime: .* soft: [0-9.]*%' "$tmp/f.txt" && grep -q '^uniform+pcf3x3 ' "$tmp/f.txt" &&
    ! grep -q 'none+' "$tmp/f.txt" && ok || no "bench --filters text: $(cat "$tmp/f.txt")"
  head -1 "$tmp/f.csv" | grep -q '^method,filter,config,.*,mismatch_worst,soft_error_pct' && grep -q '^uniform,pcf3x3,default,' "$tmp/f.csv" &&
    [ "$(wc -l <"$tmp/f.csv")" -eq 4 ] && ok || no "bench --filters CSV: $(cat "$tmp/f.csv")"
else
  no "bench --filters: $(cat "$tmp/f.txt")"
fi

# The extremes: a correct frame or a word about what was done (exit 0), from the JSON.
# json_num KEY FILE: the first number after "KEY":
json_num() { sed -n "s/.*\"$1\": \([-0-9.e+]*\).*/\1/p" "$2" | head -n 1; }
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 < b + 0) }'; }
ext() { "$lixel" render --size 160x120 --frames 1 --measure --json --out "$tmp/ext.png" "$@" >"$tmp/ext.json" 2>"$tmp/stderr"; }
ext --light 0,1e12,0 && grep -q 'taken as directional' "$tmp/ext.json" && below "$(json_num mismatch_pct "$tmp/ext.json")" 1 &&
  ok || no "a light 1e12 m away: $(cat "$tmp/ext.json" "$tmp/stderr")"
# (every method at these two extremes: test_extremes's named_extremes_match, in one context)
ext --method uniform --light 0,0,0 && below "$(json_num mismatch_pct "$tmp/ext.json")" 1 &&
  [ "$(json_num edge_on_pixels "$tmp/ext.json")" -gt 1000 ] && ok || no "uniform, the light on the floor: $(cat "$tmp/ext.json" "$tmp/stderr")"
ext --scene table --light 0,0.73,0 && grep -q 'inside the bounds of caster' "$tmp/ext.json" && ok ||
  no "the light inside the table's slab: $(cat "$tmp/ext.json" "$tmp/stderr")"
{ cat tests/data/default.scene; echo "box size 1 1 1 at 100000 0"; } >"$tmp/far.scene"
ext --method plane --scene "$tmp/far.scene" && below "$(json_num mismatch_pct "$tmp/ext.json")" 0.5 && ok ||
  no "plane, one caster 100 km away: $(cat "$tmp/ext.json" "$tmp/stderr")"
printf 'light point 0 5 0\nsphere radius 1e-300 at 0 0\n' >"$tmp/tiny.scene"
expect_says "at least 1e-30" "a radius below single precision" render --scene "$tmp/tiny.scene" $out

# Projective lights: the built-in scenes measure shadows and colour against the reference;
# a bad slide, beam or fov is one line and exit status 2, nothing written.
for sc in spotlight projector; do
  ext --scene $sc && below "$(json_num mismatch_pct "$tmp/ext.json")" 0.5 &&
    below "$(json_num colour_error "$tmp/ext.json")" 0.5 && [ "$(json_num unlit_pixels "$tmp/ext.json")" -gt 1000 ] &&
    ok || no "--scene $sc: $(cat "$tmp/ext.json" "$tmp/stderr")"
done
"$lixel" render --scene projector --size 96x64 --frames 1 --out "$tmp/p.png" --reference-out "$tmp/pref.png" >/dev/null 2>&1 &&
  [ "$(head -c 4 "$tmp/pref.png" | od -An -c | tr -d ' ')" = '211PNG' ] && ok || no "--reference-out wrote no PNG"
floor='plane floor corner -5 0 5 edge1 10 0 0 edge2 0 0 -10'
printf 'light projector 0 3 3 at 0 0 0 fov 40 slide none.png\n%s\n' "$floor" >"$tmp/noslide.scene"
expect_says "noslide.scene:1: slide '" "a missing slide" render --scene "$tmp/noslide.scene" $out
printf 'light projector 0 3 3 at 0 0 0 fov 40 slide noslide.scene\n%s\n' "$floor" >"$tmp/textslide.scene"
expect_says "expected a PNG file" "a slide that is not a PNG" render --scene "$tmp/textslide.scene" $out
head -c 60 tests/data/slide.png >"$tmp/trunc.png"
printf 'light projector 0 3 3 at 0 0 0 fov 40 slide trunc.png\n%s\n' "$floor" >"$tmp/trunc.scene"
expect_says "not a readable PNG" "a truncated slide" render --scene "$tmp/trunc.scene" $out
printf 'light spot 0 3 3 at 0 0 0 fov 40 beam trunc.png\n%s\n' "$floor" >"$tmp/truncbeam.scene"
expect_says "beam '" "a truncated beam" render --scene "$tmp/truncbeam.scene" $out
printf 'light spot 0 3 3 at 0 0 0 fov 0\n%s\n' "$floor" >"$tmp/fov0.scene"
expect_says "fov in (0, 150) degrees, got 0" "a zero fov" render --scene "$tmp/fov0.scene" $out
printf 'light spot 0 3 3 at 0 3 3 fov 40\n%s\n' "$floor" >"$tmp/at.scene"
expect_says "position differs from at" "a spotlight looking at itself" render --scene "$tmp/at.scene" $out
printf 'light spot 0 0.3 0 at 0 0 -3 fov 40\nsphere radius 0.5 at 0 0 bounce 0 0\n%s\n' "$floor" >"$tmp/inside.scene"
ext --scene "$tmp/inside.scene" && grep -q 'the light is inside the bounds of caster 1' "$tmp/ext.json" && ok ||
  no "a spotlight inside a caster: $(cat "$tmp/ext.json" "$tmp/stderr")"

# Several lights: each light's figures in the JSON, all measured against the reference;
# their bad input is one line and exit status 2, nothing written.
ext --scene twolights && below "$(json_num colour_error "$tmp/ext.json")" 0.5 &&
  grep -q '"lights": \[{"kind": "point".*{"kind": "spot"' "$tmp/ext.json" &&
  below "$(grep -o '"mismatch_pct": [-0-9.e+]*' "$tmp/ext.json" | head -n 1 | cut -d' ' -f2)" 0.5 && ok ||
  no "--scene twolights: $(cat "$tmp/ext.json" "$tmp/stderr")"
grep -q '"mismatch_pct"' "$tmp/ext.json" || no "twolights JSON has no mismatch"
{ for x in 1 2 3 4 5; do echo "light point $x 5 0"; done; echo "$floor"; } >"$tmp/five.scene"
expect_says "five.scene:5: expected at most 4 light lines" "five lights" render --scene "$tmp/five.scene" $out
{ for x in 1 2 3 4; do echo "light point $x 5 2 color 0.25 0.25 0.25"; done; grep -v '^light' tests/data/default.scene; } \
  >"$tmp/four.scene"
expect_says "give the lights less with --light-budget" "four plane lights at full budget" \
  render --scene "$tmp/four.scene" --method plane $out
ext --scene "$tmp/four.scene" --method plane --light-budget 1,0.5 && below "$(json_num mismatch_pct "$tmp/ext.json")" 0.5 &&
  [ "$(grep -o '"kind": "point"' "$tmp/ext.json" | wc -l)" -eq 4 ] && ok ||
  no "four plane lights with --light-budget 1,0.5: $(cat "$tmp/ext.json" "$tmp/stderr")"
for v in 0 1,2 half 1,,1 1,0.5,0.5,0.5,0.5 0.001; do
  expect_says "1 to 4 shares from 0.01 to 1" "--light-budget $v" render --scene twolights --light-budget "$v" $out
done
expect_says "1 to 4 shares" "bench --light-budget" bench --light-budget 2 --frames 1 --methods none
expect_says "light-budget" "kiosk --light-budget" kiosk --light-budget 0 --frames 1
expect_says "lightsN (1 <= N <= 4)" "a method spec of 5 lights" render --method uniform/lights5 $out
expect_says "lightsN (1 <= N <= 4)" "a method spec of 0 lights" render --method plane/lights0 $out

echo "cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
