#!/usr/bin/env bash
# Regenerates the README's gallery: one 640x360 thumbnail per built-in scene in docs/gallery/
# (the lesson layout; smaller frames switch to the compact form).
# Usage: scripts/gallery.sh [path/to/collide]   (default build/release/collide)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
mkdir -p docs/gallery
for scene in $("$collide" scenes | awk '{print $1}'); do
    "$collide" thumbnail "$scene" --at 3 --size 640x360 -o "docs/gallery/$scene.png" >/dev/null
    echo "docs/gallery/$scene.png"
done
