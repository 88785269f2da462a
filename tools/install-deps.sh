#!/bin/sh
# Installs what lixel needs for a make target, only what is missing. Libraries are asked
# of pkg-config and programs of the shell (so a library installed another way counts);
# the Mesa drivers, which have neither, of dpkg where there is one.
# Usage: tools/install-deps.sh build|check|asan|fuzz [--verify]
#   --verify: install nothing; list what is missing and fail (the Makefile's check
#   before it compiles anything).
# As root it runs apt-get; otherwise it prints one line naming what to install.
set -eu
# KIND NAME DEBIAN-PACKAGE: pc = a pkg-config module, cmd = a program, deb = a Debian
# package with no pkg-config file or program, fuzzer = clang's libFuzzer runtime
build_reqs="
cmd gcc gcc
cmd make make
cmd pkg-config pkg-config
pc egl libegl-dev
pc glesv2 libgles-dev
pc osmesa libosmesa6-dev
pc libpng libpng-dev
pc libgpiod libgpiod-dev
pc x11 libx11-dev
pc libdrm libdrm-dev
pc gbm libgbm-dev
deb libegl-mesa0 libegl-mesa0
deb libgl1-mesa-dri libgl1-mesa-dri
"
check_reqs="
pc cmocka libcmocka-dev
cmd Xvfb xvfb
cmd xdotool xdotool
cmd xauth xauth
cmd glslangValidator glslang-tools
"
# the libFuzzer harnesses: clang and its fuzzer and sanitizer runtimes (not pulled in
# without recommends)
fuzz_reqs="
cmd make make
cmd clang clang
fuzzer clang libclang-rt-dev
"
case "${1:-build}" in
  build) reqs="$build_reqs" ;;
  check) reqs="$build_reqs $check_reqs" ;;
  asan) reqs="$build_reqs $check_reqs $fuzz_reqs" ;;
  fuzz) reqs="$fuzz_reqs" ;;
  *) echo "install-deps.sh: unknown set '$1' (expected build, check, asan or fuzz)" >&2; exit 2 ;;
esac
verify=false
[ "${2:-}" = --verify ] && verify=true

# Whether clang links a libFuzzer harness (its runtime is a package of its own).
fuzzer_links() {
  command -v clang >/dev/null 2>&1 || return 1
  d=$(mktemp -d "${TMPDIR:-/tmp}/lixel-deps.XXXXXX") || return 1
  printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' >"$d/f.c"
  clang -fsanitize=fuzzer "$d/f.c" -o "$d/f" >/dev/null 2>&1
  st=$?
  rm -rf "$d"
  return $st
}

missing=""
echo "$reqs" | {
  while read -r kind name pkg; do
    [ -n "$kind" ] || continue
    case $kind in
      pc) command -v pkg-config >/dev/null 2>&1 && pkg-config --exists "$name" && continue ;;
      cmd) command -v "$name" >/dev/null 2>&1 && continue ;;
      # no dpkg: not a Debian system, nothing to ask; the driver is looked for at run time
      deb) { ! command -v dpkg-query >/dev/null 2>&1 ||
             dpkg-query -W -f='${Status}' "$name" 2>/dev/null | grep -q '^install ok installed$'; } && continue ;;
      fuzzer) fuzzer_links && continue ;;
    esac
    case " $missing " in *" $pkg "*) ;; *) missing="$missing $pkg" ;; esac
  done
  echo "$missing"
} >"${TMPDIR:-/tmp}/lixel-missing.$$"
missing=$(cat "${TMPDIR:-/tmp}/lixel-missing.$$")
rm -f "${TMPDIR:-/tmp}/lixel-missing.$$"
missing=$(echo $missing)
[ -z "$missing" ] && exit 0
if $verify; then
  echo "lixel: missing (Debian packages): $missing -- as root: sh tools/install-deps.sh ${1:-build}, or apt-get install $missing" >&2
  exit 1
fi
if ! command -v apt-get >/dev/null 2>&1; then
  echo "lixel: missing: $missing (Debian's names; no apt-get here: install them with your package manager)" >&2
  exit 1
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "lixel: missing Debian packages: $missing -- run: sudo apt-get install $missing" >&2
  exit 1
fi
echo "lixel: installing Debian packages: $missing" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >&2
apt-get install -y -qq --no-install-recommends $missing >&2
