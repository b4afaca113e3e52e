#!/usr/bin/env bash
# Regenerates the README's heap gallery: one 640x360 still per slide of a heap lesson, taken
# with `collide heap --at` inside an operation, at the rest after a step (the keys have landed,
# the step still lit: nothing half-way over the labels), so every one is readable
# (docs/heap.md explains each command).
# Usage: scripts/heap_gallery.sh [path/to/collide]   (default build/release/collide)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
mkdir -p docs/gallery
lecture="P Q E * X A M * P L E *"
still() {  # name, seconds into the video, then the lesson's options
    local name=$1 at=$2
    shift 2
    "$collide" heap "$@" --size 640x360 --at "$at" -o "docs/gallery/$name.png" >/dev/null
    echo "docs/gallery/$name.png"
}
still heap-binary 23.65 --ops "$lecture"
still heap-side-by-side 30 --ops "$lecture" --impl unordered,ordered,binary
still heap-dary-min 21.5 --ops "$lecture" --impl dary:3 --min
still heap-indexed 18.72 --ops "5 9 3 7 * 3^12" --impl indexed:2
still heap-heapsort 40.35 --sort "S O R T E X A M P L E"
