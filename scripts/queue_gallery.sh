#!/usr/bin/env bash
# Regenerates the README's event-queue gallery: `collide render gas --queue` with the classic
# loop and with the fast engine, one 960x540 still each (the strip's tree needs the width), taken
# with `collide thumbnail --at` (simulation time) in slow motion as a class would watch it.
# Usage: scripts/queue_gallery.sh [path/to/collide]   (default build/release/collide)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
mkdir -p docs/gallery
still() {  # name, simulation time, then the options
    local name=$1 at=$2
    shift 2
    "$collide" thumbnail gas --queue --slow-motion 4 "$@" --size 960x540 --at "$at" \
        -o "docs/gallery/$name.png" >/dev/null
    echo "docs/gallery/$name.png"
}
still queue-classic 3.05 --engine classic
still queue-fast 3.05 --engine fast
