#!/usr/bin/env bash
# Regenerates the README's puzzle still: a hardest 8-puzzle (31 moves) mid-search, BFS against
# A*, with `collide puzzle --at` (docs/puzzle.md explains the picture).
# Usage: scripts/puzzle_gallery.sh [path/to/collide]   (default build/release/collide)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
mkdir -p docs/gallery
"$collide" puzzle "8 6 7 2 5 4 3 0 1" --size 854x480 --at 12 -o docs/gallery/puzzle.png >/dev/null
echo docs/gallery/puzzle.png
