#!/usr/bin/env bash
# The README's first command: install what is missing, build a Release build, render the demo:
# the `tunnelling` scene side by side (time-driven left, event-driven right) to out/demo.mp4,
# and its last frame to out/demo.png.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
echo "==> configuring and building build/release"
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_BUILD_TESTS=OFF \
      -DCOLLIDE_BUILD_BENCH=OFF >/dev/null
cmake --build build/release --target collide
mkdir -p out
echo "==> rendering the demo (tunnelling, 720p30, 35.5 s with its questions)"
build/release/collide render tunnelling -o out/demo.mp4
build/release/collide render tunnelling --last-frame -o out/demo.png
