#!/usr/bin/env bash
# Carries out the Dockerfile on a clean Debian 12 root without a Docker engine: what
# `docker build -t collide .` and `docker run --rm collide` would do, in a chroot (this project's
# machines have the Docker client but no daemon). Issue #31: "the Dockerfile builds and runs the
# tests".
#   usage: sudo scripts/dockerfile_check.sh [--build-only] [ROOT_DIR]
# The instructions are read from ./Dockerfile, not copied here, so the check follows the file:
#   FROM debian:12     a `debootstrap --variant=minbase bookworm` root (the same variant as the
#                      official image), made once in ROOT_DIR (default /var/tmp/collide-bookworm)
#                      and reused; every run works on a fresh copy of it;
#   ENV K=V, WORKDIR   as Docker does;
#   COPY . DEST        the build context: HEAD's files (`git archive`; .dockerignore leaves out
#                      only build outputs and .git, which a clean clone does not have);
#   RUN CMD            in the root, as root, with the ENV so far, in WORKDIR;
#   CMD ["a", ...]     the `docker run` step, after every RUN (left out with --build-only).
# Any other instruction is refused (exit 2), so the file cannot drift from what is checked.
# Exit status: that of the first failing step, 0 when all pass. Needs root and Debian's mirror.
set -euo pipefail

build_only=0
base=/var/tmp/collide-bookworm
for arg in "$@"; do
    case "$arg" in
        --build-only) build_only=1 ;;
        -*) echo "usage: $0 [--build-only] [ROOT_DIR]" >&2; exit 2 ;;
        *) base=$arg ;;
    esac
done
[[ "$(id -u)" -eq 0 ]] || { echo "$0: needs root (chroot, mount)" >&2; exit 2; }
repo=$(git rev-parse --show-toplevel)
dockerfile="$repo/Dockerfile"
[[ -f "$dockerfile" ]] || { echo "$0: no Dockerfile in $repo" >&2; exit 2; }

if [[ ! -x "$base/usr/bin/apt-get" ]]; then
    command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap
    debootstrap --variant=minbase bookworm "$base" http://deb.debian.org/debian
fi

root=$(mktemp -d "${base}.run.XXXXXX")
cleanup() {
    for m in dev/shm dev/pts dev proc; do umount "$root/$m" 2>/dev/null || true; done
    rm -rf --one-file-system "$root"
}
trap cleanup EXIT
cp -a "$base/." "$root/"
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
mount -t tmpfs tmpfs "$root/dev/shm"

env_args=(PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root)
workdir=/
run_in_root() {
    echo "== $1 (in $workdir): $2"
    chroot "$root" /usr/bin/env -i "${env_args[@]}" /bin/sh -c "mkdir -p '$workdir' && cd '$workdir' && $2"
}

cmd=""
line_no=0
while IFS= read -r line || [[ -n "$line" ]]; do
    line_no=$((line_no + 1))
    [[ "$line" =~ ^[[:space:]]*(#|$) ]] && continue
    instruction=${line%% *}
    rest=${line#* }
    case "$instruction" in
        FROM)
            [[ "$rest" == "debian:12" ]] ||
                { echo "Dockerfile:$line_no: FROM $rest: only debian:12 is checked here" >&2; exit 2; } ;;
        ENV) env_args+=("$rest") ;;
        WORKDIR) workdir=$rest ;;
        COPY)
            [[ "$rest" =~ ^\.\ +(/[^ ]*)$ ]] ||
                { echo "Dockerfile:$line_no: COPY $rest: only 'COPY . /DEST' is checked here" >&2; exit 2; }
            dest=${BASH_REMATCH[1]}
            mkdir -p "$root$dest"
            echo "== COPY . $dest (HEAD $(git -C "$repo" rev-parse --short HEAD))"
            git -C "$repo" archive HEAD | tar -x -C "$root$dest" ;;
        RUN) run_in_root RUN "$rest" ;;
        CMD) cmd=$rest ;;
        *) echo "Dockerfile:$line_no: $instruction: not an instruction this check knows" >&2; exit 2 ;;
    esac
done <"$dockerfile"

if [[ $build_only -eq 0 && -n "$cmd" ]]; then
    # The exec form, ["a", "b"]: its words joined for the shell (they hold no quotes here).
    words=$(python3 -c 'import json, shlex, sys; print(" ".join(map(shlex.quote, json.loads(sys.argv[1]))))' "$cmd")
    run_in_root CMD "$words"
fi
echo "== ok: the Dockerfile's steps passed in a clean Debian 12 root"
