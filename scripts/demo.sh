#!/usr/bin/env bash
# The README's first command: install what is missing, build a Release build, render the demo.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
echo "==> configuring and building build/release"
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_BUILD_TESTS=OFF >/dev/null
cmake --build build/release --target collide
echo "==> collide"
build/release/collide --version
