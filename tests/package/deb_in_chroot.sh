#!/usr/bin/env bash
# The Debian package's acceptance test: cpack in BUILD_DIR makes veduta_<version>_amd64.deb; a
# fresh Debian 12 root (debootstrap --variant=minbase bookworm) installs it with apt, which must
# find every library through the package's declared dependencies, and renders with it: the
# default scene with a display image (the plugin in /usr/lib/veduta) and a shipped scene (the
# rules in /usr/share/veduta). Not part of ctest: it needs root, the Debian mirror and a few
# minutes (docs/install.md). The root is made under PARENT (default /work/tmp-chroot) and
# deleted at the end, /proc unmounted first.
# Usage: deb_in_chroot.sh BUILD_DIR [PARENT]   (MIRROR=… to use another Debian mirror)
set -euo pipefail
usage="usage: deb_in_chroot.sh BUILD_DIR [PARENT]"
build=$(realpath "${1:?$usage}")
parent=${2:-/work/tmp-chroot}
mirror=${MIRROR:-http://deb.debian.org/debian}
[ "$(id -u)" = 0 ] || { echo "deb_in_chroot: needs root (debootstrap, chroot, mount)"; exit 2; }
[ -f "$build/CPackConfig.cmake" ] || { echo "deb_in_chroot: $build is not a configured veduta build folder"; exit 2; }
for tool in debootstrap cpack dpkg-shlibdeps; do
    command -v $tool >/dev/null || { echo "deb_in_chroot: $tool is missing (Debian: debootstrap, cmake, dpkg-dev)"; exit 2; }
done

echo "== cpack in $build"
cmake --build "$build" --target veduta veduta-diff veduta-images veduta_help_files -j2 >/dev/null
(cd "$build" && rm -f veduta_*.deb && cpack -G DEB >/dev/null)
deb=$(ls "$build"/veduta_*_amd64.deb)
echo "$(basename "$deb"): $(stat -c %s "$deb") bytes"
dpkg-deb --field "$deb" Package Version Architecture Section Maintainer Depends

mkdir -p "$parent"
root=$(mktemp -d "$parent/bookworm.XXXXXX")
chmod 755 "$root"  # apt downloads as the user _apt, who must reach its folders
cleanup() {
    if mountpoint -q "$root/proc"; then umount "$root/proc"; fi
    # Never delete through a mount that is still there.
    if mountpoint -q "$root/proc"; then echo "deb_in_chroot: $root/proc is still mounted; $root left"; return; fi
    rm -rf "$root"
}
trap cleanup EXIT

echo "== debootstrap bookworm into $root"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
    { tail -20 "$root.debootstrap.log"; exit 1; }
rm -f "$root.debootstrap.log"
# As an installed Debian 12: the release, its updates and its security fixes.
cat >"$root/etc/apt/sources.list" <<SOURCES
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
SOURCES
cp /etc/resolv.conf "$root/etc/resolv.conf"
cp "$deb" "$root/root/"
mount -t proc proc "$root/proc"

echo "== apt install ./$(basename "$deb") in the chroot"
chroot "$root" /usr/bin/env DEBIAN_FRONTEND=noninteractive bash -euo pipefail -c '
    cd /root
    apt-get update -q >/dev/null
    apt install -y -q ./veduta_*.deb >/root/apt.log 2>&1 || { tail -30 /root/apt.log; exit 1; }
    grep -E "^(Need to get|After this operation)" /root/apt.log
    dpkg -L veduta | grep -E "^/usr/(bin|lib/veduta)/|man1|completions/"
    cd /tmp
    time veduta render --spp 4 -o /tmp/default.exr --image /tmp/default.png
    time veduta render /usr/share/veduta/scenes/gruenderzeit-street.xml --spp 4 --res 480x270
    veduta diff /tmp/default.exr /tmp/default.exr | grep verdict
    stat -c "%n: %s bytes" /tmp/default.exr /tmp/default.png /tmp/renders/gruenderzeit-street.exr'
echo "deb_in_chroot: passed"
