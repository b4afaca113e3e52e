#!/usr/bin/env bash
# Regenerates the README's gallery: one 480x270 thumbnail per built-in scene in docs/gallery/.
# Usage: scripts/gallery.sh [path/to/collide]   (default build/release/collide)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
mkdir -p docs/gallery
for scene in $("$collide" scenes | awk '{print $1}'); do
    "$collide" thumbnail "$scene" --at 1 --size 480x270 -o "docs/gallery/$scene.png" >/dev/null
    echo "docs/gallery/$scene.png"
done
