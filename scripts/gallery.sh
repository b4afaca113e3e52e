#!/usr/bin/env bash
# Regenerates the README's gallery: one 640x360 thumbnail per built-in scene in docs/gallery/
# (the lesson layout; smaller frames switch to the compact form).
# Usage: scripts/gallery.sh [path/to/collide]   (default build/release/collide)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
mkdir -p docs/gallery
# --at is simulation time: 3 by default; where the story needs another moment, that one
# (maxwell-boltzmann: the speeds still spreading out, 6 s into its video; brownian: the tracer's
# path grown long enough to see, 15 s into its video).
at_of() {
    case $1 in
        maxwell-boltzmann) echo 0.3 ;;
        brownian) echo 45 ;;
        *) echo 3 ;;
    esac
}
for scene in $("$collide" scenes | awk '{print $1}'); do
    "$collide" thumbnail "$scene" --at "$(at_of "$scene")" --size 640x360 \
        -o "docs/gallery/$scene.png" >/dev/null
    echo "docs/gallery/$scene.png"
done
