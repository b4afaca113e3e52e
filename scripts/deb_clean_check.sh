#!/usr/bin/env bash
# Installs a collide .deb on a clean Debian 12 root (no docker engine needed) and runs it there:
# the check issue #31 asks for ("the .deb installs on a clean Debian 12 and `collide render gas`
# works from it"). Needs root and Debian's mirror; makes the root with debootstrap when missing.
#   usage: sudo scripts/deb_clean_check.sh PACKAGE.deb [ROOT_DIR]
# ROOT_DIR (default /var/tmp/collide-bookworm) is created with `debootstrap --variant=minbase
# bookworm` and reused; each run installs the package into a fresh copy, so runs do not mix.
set -euo pipefail

if [[ $# -lt 1 || ! -f "$1" ]]; then
    echo "usage: $0 PACKAGE.deb [ROOT_DIR]" >&2
    exit 2
fi
deb=$(realpath "$1")
base=${2:-/var/tmp/collide-bookworm}
[[ "$(id -u)" -eq 0 ]] || { echo "$0: needs root (chroot, mount)" >&2; exit 2; }

if [[ ! -x "$base/usr/bin/apt-get" ]]; then
    command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap
    debootstrap --variant=minbase bookworm "$base" http://deb.debian.org/debian
fi

root=$(mktemp -d "${base}.run.XXXXXX")
cleanup() {
    for m in proc dev/pts dev; do umount "$root/$m" 2>/dev/null || true; done
    rm -rf --one-file-system "$root"
}
trap cleanup EXIT
cp -a "$base/." "$root/"
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
cp "$deb" "$root/tmp/collide.deb"

chroot "$root" /bin/bash -euo pipefail -c '
    export DEBIAN_FRONTEND=noninteractive LC_ALL=C.UTF-8
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends /tmp/collide.deb >/dev/null
    echo "== installed: $(dpkg-query -W -f="\${Package} \${Version}" collide)"
    cd /tmp
    collide --version
    collide scenes | head -3
    collide check gas
    collide thumbnail gas --at 2 -o gas.png
    collide render gas -q l --duration 2 -o gas.mp4
    collide heap --help >/dev/null
    ls -l gas.png gas.mp4
    echo "== ok: the package installs on a clean Debian 12 and renders"
'
