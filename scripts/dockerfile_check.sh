#!/usr/bin/env bash
# Carries out the Dockerfile on clean Debian 12 roots without a Docker engine: what
# `docker build -t collide .` and `docker run --rm collide` would do, in chroots (this project's
# machines have the Docker client but no daemon). Issue #46: a multi-stage runtime image.
#   usage: sudo scripts/dockerfile_check.sh [--build-only] [ROOT_DIR]
#          scripts/dockerfile_check.sh --dry-run     (no root: reads the file, prints the steps)
# The instructions are read from ./Dockerfile, not copied here, so the check follows the file:
#   FROM debian:12 [AS NAME]  a new stage: a fresh copy of a `debootstrap --variant=minbase
#                      bookworm` root (the same variant as the official image), made once in
#                      ROOT_DIR (default /var/tmp/collide-bookworm) and reused;
#   ENV K=V, ARG K=V, WORKDIR   as Docker does (an ARG takes the caller's $K when set, as
#                      --build-arg would);
#   COPY . DEST, COPY PATH DEST   from the build context: HEAD's files (`git archive`;
#                      .dockerignore leaves out only build outputs and .git);
#   COPY --from=NAME SRC DEST     from an earlier stage's root;
#   RUN CMD            in the stage's root, with the ENV and ARGs so far, in WORKDIR, as USER;
#   USER NAME          later RUNs and the run step as that user (its uid in that root);
#   ENTRYPOINT [..], CMD [..]   the `docker run` step in the last stage, after every RUN (left
#                      out with --build-only), as USER: the entrypoint's words, then CMD's.
# Any other instruction is refused (exit 2), so the file cannot drift from what is checked.
# Exit status: that of the first failing step, 0 when all pass. Needs root and Debian's mirror.
set -euo pipefail

build_only=0
dry_run=0
base=/var/tmp/collide-bookworm
for arg in "$@"; do
    case "$arg" in
        --build-only) build_only=1 ;;
        --dry-run) dry_run=1 ;;
        -*) echo "usage: $0 [--build-only | --dry-run] [ROOT_DIR]" >&2; exit 2 ;;
        *) base=$arg ;;
    esac
done
[[ $dry_run -eq 1 || "$(id -u)" -eq 0 ]] || { echo "$0: needs root (chroot, mount)" >&2; exit 2; }
repo=$(git rev-parse --show-toplevel)
dockerfile="$repo/Dockerfile"
[[ -f "$dockerfile" ]] || { echo "$0: no Dockerfile in $repo" >&2; exit 2; }

if [[ $dry_run -eq 0 && ! -x "$base/usr/bin/apt-get" ]]; then
    command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap
    debootstrap --variant=minbase bookworm "$base" http://deb.debian.org/debian
fi

declare -A stage_roots=()
roots=()
cleanup() {
    for r in "${roots[@]}"; do
        for m in dev/shm dev/pts dev proc; do umount "$r/$m" 2>/dev/null || true; done
        rm -rf --one-file-system "$r"
    done
}
trap cleanup EXIT

root=""
# A fresh stage: a copy of the clean root with /proc, /dev and a /dev/shm of its own.
new_stage() {
    if [[ $dry_run -eq 1 ]]; then root="/stage-$1"; return; fi
    root=$(mktemp -d "${base}.run.XXXXXX")
    roots+=("$root")
    cp -a "$base/." "$root/"
    cp /etc/resolv.conf "$root/etc/resolv.conf"
    mount -t proc proc "$root/proc"
    mount --bind /dev "$root/dev"
    mount --bind /dev/pts "$root/dev/pts"
    mount -t tmpfs tmpfs "$root/dev/shm"
}

env_args=()
workdir=/
user=root
run_in_root() {
    echo "== $1 (in $workdir, as $user): $2"
    [[ $dry_run -eq 1 ]] && return 0
    local spec=0:0
    if [[ $user != root ]]; then
        spec="$(chroot "$root" id -u "$user"):$(chroot "$root" id -g "$user")"
    fi
    chroot --userspec="$spec" "$root" /usr/bin/env -i "${env_args[@]}" /bin/sh -c \
        "mkdir -p '$workdir' 2>/dev/null; cd '$workdir' && $2"
}
# The exec form, ["a", "b"]: its words quoted for the shell.
exec_words() {
    python3 -c 'import json, shlex, sys; print(" ".join(map(shlex.quote, json.loads(sys.argv[1]))))' "$1"
}

cmd=""
entrypoint=""
stage=0
line_no=0
while IFS= read -r line || [[ -n "$line" ]]; do
    line_no=$((line_no + 1))
    [[ "$line" =~ ^[[:space:]]*(#|$) ]] && continue
    instruction=${line%% *}
    rest=${line#* }
    case "$instruction" in
        FROM)
            [[ "$rest" =~ ^debian:12(\ +AS\ +([A-Za-z0-9_-]+))?$ ]] ||
                { echo "Dockerfile:$line_no: FROM $rest: only debian:12 [AS NAME] is checked here" >&2; exit 2; }
            stage=$((stage + 1))
            new_stage "$stage"
            [[ -n "${BASH_REMATCH[2]}" ]] && stage_roots[${BASH_REMATCH[2]}]=$root
            echo "== FROM debian:12: stage $stage${BASH_REMATCH[2]:+ (${BASH_REMATCH[2]})}"
            env_args=(PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root)
            workdir=/ user=root cmd="" entrypoint="" ;;
        ENV) env_args+=("$rest") ;;
        ARG)
            name=${rest%%=*}
            value=${rest#*=}
            [[ -n "${!name:-}" ]] && value=${!name}
            env_args+=("$name=$value") ;;
        WORKDIR) workdir=$rest ;;
        USER) user=$rest ;;
        COPY)
            if [[ "$rest" =~ ^--from=([A-Za-z0-9_-]+)\ +(/[^ ]*)\ +(/[^ ]*)$ ]]; then
                from=${stage_roots[${BASH_REMATCH[1]}]:-}
                [[ -n "$from" ]] || { echo "Dockerfile:$line_no: no stage ${BASH_REMATCH[1]}" >&2; exit 2; }
                echo "== COPY --from=${BASH_REMATCH[1]} ${BASH_REMATCH[2]} ${BASH_REMATCH[3]}"
                [[ $dry_run -eq 1 ]] || cp -a "$from${BASH_REMATCH[2]}" "$root${BASH_REMATCH[3]}"
            elif [[ "$rest" =~ ^([^-/ ][^ ]*)\ +(/[^ ]*)$ ]]; then
                src=${BASH_REMATCH[1]} dest=${BASH_REMATCH[2]}
                echo "== COPY $src $dest (HEAD $(git -C "$repo" rev-parse --short HEAD))"
                [[ $dry_run -eq 1 ]] && continue
                if [[ $src == . ]]; then
                    mkdir -p "$root$dest"
                    git -C "$repo" archive HEAD | tar -x -C "$root$dest"
                else
                    mkdir -p "$(dirname "$root$dest")"
                    git -C "$repo" show "HEAD:$src" >"$root$dest"
                fi
            else
                echo "Dockerfile:$line_no: COPY $rest: not a form checked here" >&2; exit 2
            fi ;;
        RUN) run_in_root RUN "$rest" ;;
        CMD) cmd=$(exec_words "$rest") ;;
        ENTRYPOINT) entrypoint=$(exec_words "$rest") ;;
        *) echo "Dockerfile:$line_no: $instruction: not an instruction this check knows" >&2; exit 2 ;;
    esac
done <"$dockerfile"

if [[ $build_only -eq 0 && -n "$entrypoint$cmd" ]]; then
    run_in_root "docker run" "$entrypoint $cmd"
    [[ $user != root ]] || { echo "the image runs as root" >&2; exit 1; }
    run_in_root "docker run" "$entrypoint --version"
fi
echo "== ok: the Dockerfile's steps passed in clean Debian 12 roots"
