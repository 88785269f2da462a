#!/bin/sh
# Installs the Debian packages lixel needs for a make target, only those missing.
# Usage: tools/install-deps.sh build|check|fuzz
# As root it runs apt-get; otherwise it prints one line naming what to install.
set -eu
build_pkgs="gcc make pkg-config libegl-dev libgles-dev libosmesa6-dev libpng-dev libegl-mesa0 libgl1-mesa-dri libgpiod-dev libx11-dev libdrm-dev libgbm-dev"
check_pkgs="libcmocka-dev xvfb xdotool xauth glslang-tools"
# the libFuzzer harnesses: clang and its fuzzer and sanitizer runtimes (not pulled in
# without recommends)
fuzz_pkgs="make clang libclang-rt-dev"
case "${1:-build}" in
  build) want="$build_pkgs" ;;
  check) want="$build_pkgs $check_pkgs $fuzz_pkgs" ;;
  fuzz) want="$fuzz_pkgs" ;;
  *) echo "install-deps.sh: unknown set '$1' (expected build, check or fuzz)" >&2; exit 2 ;;
esac
missing=""
for p in $want; do
  # dpkg -s exits 0 for removed-but-configured packages too; check the status line.
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$'; then
    missing="$missing $p"
  fi
done
[ -z "$missing" ] && exit 0
if ! command -v apt-get >/dev/null 2>&1; then
  echo "lixel: missing packages:$missing (no apt-get here: install them with your package manager)" >&2
  exit 1
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "lixel: missing Debian packages:$missing -- run: sudo apt-get install$missing" >&2
  exit 1
fi
echo "lixel: installing Debian packages:$missing" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >&2
apt-get install -y -qq --no-install-recommends $missing >&2
