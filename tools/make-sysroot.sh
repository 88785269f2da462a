#!/bin/sh
# shellcheck disable=SC2086,SC2116  # package lists are split on purpose
# Makes a Debian 12 sysroot for cross-building lixel and running it under qemu-user.
# Usage: tools/make-sysroot.sh arm64|armhf DIR
#
# It downloads (apt-get download) the target architecture's -dev packages lixel builds
# against, Mesa's runtime and every package they depend on, and unpacks each one into
# DIR with dpkg-deb -x; nothing is installed on this machine. Multiarch installs
# (apt-get install libfoo-dev:arm64) fail on Debian 12 on version skew between the
# architectures, so apt here runs with a private state (DIR/.apt) that knows only the
# target architecture, fed by this machine's Debian sources. Absolute symlinks inside
# DIR are made relative so they resolve inside DIR, and the pkg-config files are
# checked to use prefix=/usr (pkg-config's PKG_CONFIG_SYSROOT_DIR then adds DIR).
# Rerunnable: the package lists are refreshed, the .deb files kept, DIR re-extracted.
set -eu

me=make-sysroot.sh
if [ $# -ne 2 ] || [ -z "$2" ]; then
  echo "$me: usage: $me arm64|armhf DIR" >&2
  exit 2
fi
arch=$1
case $arch in
  arm64) triplet=aarch64-linux-gnu ;;
  armhf) triplet=arm-linux-gnueabihf ;;
  *) echo "$me: unknown architecture '$arch' (expected arm64 or armhf)" >&2; exit 2 ;;
esac
for tool in apt-get apt-cache dpkg-deb; do
  command -v "$tool" >/dev/null 2>&1 || { echo "$me: $tool not found (this needs Debian's apt and dpkg)" >&2; exit 1; }
done
if [ -e "$2" ] && [ ! -d "$2" ]; then
  echo "$me: '$2' exists and is not a directory" >&2
  exit 2
fi
mkdir -p "$2"
dir=$(cd "$2" && pwd -P)
[ "$dir" != / ] || { echo "$me: refusing to use / as the sysroot" >&2; exit 2; }

# What lixel builds against (tools/install-deps.sh's build set, :ARCH), its tests'
# cmocka, the C library, and the Mesa drivers it loads at run time.
want="libc6-dev libegl-dev libgles-dev libosmesa6-dev libpng-dev libgpiod-dev libx11-dev
libdrm-dev libgbm-dev libcmocka-dev libegl-mesa0 libgl1-mesa-dri libosmesa6 libgbm1
libglapi-mesa libgles2 libegl1 libglvnd0 libstdc++6 libgcc-s1"
# Tools and maintainer-script helpers that dependencies pull in: never needed in a
# sysroot, they only make it bigger.
skip=" debconf debconf-2.0 dpkg perl-base perl install-info sensible-utils ucf
lsb-base init-system-helpers libc-bin tzdata readline-common libc-dev-bin
linux-libc-dev-bin rpcsvc-proto"
skip=" $(echo $skip) "

t0=$(date +%s)
apt_dir=$dir/.apt
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/debs" "$apt_dir/prefs.d"
: > "$apt_dir/status"
set -- -o "APT::Architecture=$arch" -o "APT::Architectures::=$arch" \
  -o "Dir::State=$apt_dir" -o "Dir::State::Lists=$apt_dir/lists" \
  -o "Dir::State::status=$apt_dir/status" -o "Dir::Cache=$apt_dir/cache" \
  -o "Dir::Etc::Preferences=/dev/null" -o "Dir::Etc::PreferencesParts=$apt_dir/prefs.d" \
  -o "Debug::NoLocking=1" -o "APT::Get::List-Cleanup=0"
# As root apt downloads as the _apt user, which cannot write into DIR.
[ "$(id -u)" -ne 0 ] || set -- "$@" -o "APT::Sandbox::User=root"

echo "$me: updating the $arch package lists (private apt state in $apt_dir)"
# apt-get update fails when any one index fails (a mirror mid-sync, a suite such as
# bookworm-security broken for one architecture); go on with the indexes that came
# (their packages are consistent among themselves), if the main one is among them.
if ! apt-get "$@" -qq update; then
  if ls "$apt_dir/lists/"*_main_binary-"${arch}"_Packages* >/dev/null 2>&1; then
    echo "$me: warning: some $arch package indexes failed to download (above); going on with those that did" >&2
  else
    echo "$me: apt-get update for $arch failed (is the Debian mirror reachable?)" >&2
    exit 1
  fi
fi

# Every real package in the closure; apt-cache prints virtual ones as <name>.
pkgs=$(apt-cache "$@" depends --recurse --no-recommends --no-suggests --no-conflicts \
  --no-breaks --no-replaces --no-enhances $want | grep -v '^[ <]' | sed 's/:.*//' | sort -u)
list=""
n_skip=0
for p in $pkgs; do
  case $skip in *" $p "*) n_skip=$((n_skip + 1)); continue ;; esac
  case "$p" in *-doc|*-doc-*) n_skip=$((n_skip + 1)); continue ;; esac
  list="$list $p"
done
n=$(echo $list | wc -w)
echo "$me: $n packages to unpack ($n_skip tool packages left out)"

# Download only the .deb files not already here (file names carry the version).
# (--print-uris prints nothing for a file already in the current directory: ask in
# $apt_dir, download into $apt_dir/debs.)
cd "$apt_dir"
apt-get "$@" download --print-uris $list > "$apt_dir/uris" \
  || { echo "$me: apt-get could not locate every $arch package" >&2; exit 1; }
awk '{print $2}' "$apt_dir/uris" > "$apt_dir/files"
need=""
while IFS= read -r f; do
  [ -s "debs/$f" ] || need="$need ${f%%_*}"
done < "$apt_dir/files"
[ -s "$apt_dir/files" ] || { echo "$me: apt-get listed no $arch packages to download" >&2; exit 1; }
cd "$apt_dir/debs"
if [ -n "$need" ]; then
  echo "$me: downloading $(echo $need | wc -w) .deb files"
  apt-get "$@" -qq download $need
else
  echo "$me: every .deb file is already downloaded"
fi

# Unpack exactly the .deb files of this closure (older versions are left alone).
echo "$me: unpacking into $dir"
while IFS= read -r f; do
  [ -s "$f" ] || { echo "$me: $f is missing after the download" >&2; exit 1; }
  dpkg-deb -x "$f" "$dir"
done < "$apt_dir/files"
cd "$dir"

# Absolute symlinks (lib*.so -> /lib/aarch64-linux-gnu/libfoo.so.1) would point at this
# machine's files; make each relative to its own directory so it resolves inside DIR.
fixed=0
find . -path ./.apt -prune -o -type l -print > "$apt_dir/links"
while IFS= read -r l; do
  target=$(readlink "$l")
  case $target in /*) ;; *) continue ;; esac
  up=$(dirname "${l#./}" | sed -e 's|[^/][^/]*|..|g')
  [ "$(dirname "${l#./}")" = . ] && up=.
  ln -sfn "$up$target" "$l"
  fixed=$((fixed + 1))
done < "$apt_dir/links"
echo "$me: made $fixed absolute symlinks relative"

# pkg-config files: Debian's use prefix=/usr, which PKG_CONFIG_SYSROOT_DIR maps into
# DIR; rewrite any that name DIR itself (from an older run) back to /usr.
pc_fixed=0
for pc in usr/lib/$triplet/pkgconfig/*.pc usr/share/pkgconfig/*.pc usr/lib/pkgconfig/*.pc; do
  [ -f "$pc" ] || continue
  if grep -q "$dir" "$pc"; then
    sed -i "s|$dir||g" "$pc"
    pc_fixed=$((pc_fixed + 1))
  fi
done
n_pc=$(ls usr/lib/$triplet/pkgconfig/*.pc usr/share/pkgconfig/*.pc 2>/dev/null | wc -l)
echo "$me: $n_pc pkg-config files, $pc_fixed rewritten"

# The loader qemu runs and the libraries the build links against must be there.
case $arch in
  arm64) ld_so=lib/ld-linux-aarch64.so.1 ;;
  armhf) ld_so=lib/ld-linux-armhf.so.3 ;;
esac
for f in "$ld_so" usr/lib/$triplet/libc.so usr/lib/$triplet/libOSMesa.so \
  usr/lib/$triplet/libEGL.so usr/lib/$triplet/libpng.so usr/lib/$triplet/libcmocka.so \
  usr/lib/$triplet/dri/swrast_dri.so usr/include/GLES2/gl2.h; do
  [ -e "$f" ] || { echo "$me: $f is missing from the sysroot" >&2; exit 1; }
done

t1=$(date +%s)
mb=$(du -sm --exclude=.apt . | awk '{print $1}')
debs_mb=$(du -sm .apt | awk '{print $1}')
echo "$me: $arch sysroot ready in $dir: $n packages, $mb MB (+$debs_mb MB of .deb files and apt lists in .apt), $((t1 - t0)) s"
