#!/usr/bin/env bash
# Regenerates the README's lesson stills in docs/gallery/: the instant replay (a frame from the
# middle of tunnelling's replay), a caption in another language (a Polish scene with Greek and
# mathematical characters: its title card and a still) and the slide player's first page
# (headless Chromium's screenshot of index.html from `render --slides`), the code on screen
# (`heap --code`, `--queue --code`, `puzzle --code`) and the perspective camera on spheres.
# Usage: scripts/lesson_gallery.sh [path/to/collide]   (default build/release/collide)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=$(realpath "${1:-build/release/collide}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p docs/gallery

# The replay: 4.5 s after its segment starts (both checks and the unseen hit drawn), as
# --timeline-json says.
"$collide" render tunnelling --size 640x360 --progress none -o "$tmp/t.mp4" \
    --timeline-json "$tmp/t.json" >/dev/null 2>&1
at=$(python3 -c 'import json,sys
s=[x for x in json.load(open(sys.argv[1]))["segments"] if x["kind"]=="replay"][0]
print(s["start"]+4.5)' "$tmp/t.json")
ffmpeg -v error -y -ss "$at" -i "$tmp/t.mp4" -frames:v 1 docs/gallery/replay-tunnelling.png
echo "docs/gallery/replay-tunnelling.png (t = $at s)"

# A caption in Polish, with Greek and mathematical characters.
cat >"$tmp/gaz.toml" <<'TOML'
title = "Gaz w pudełku: Δt ≈ 0,04 s"
description = "Zderzenia sprężyste: 20 kul, energia E = ½mv² zachowana"

[box]
width = 1.0
height = 1.0
boundary = "walls"

[[generate]]
count = 20
radius = 0.03
mass = 1.0
temperature = 0.02
color = "#e0a030"
seed = 10

[render]
duration = 8.0
dt = 0.04
caption = "Lewa: kroki Δt = 0,04 s; prawa: kolejka zdarzeń, σ → η"
TOML
"$collide" render "$tmp/gaz.toml" --size 640x360 --progress none --lang pl \
    -o "$tmp/gaz.mp4" >/dev/null 2>&1
ffmpeg -v error -y -ss 1 -i "$tmp/gaz.mp4" -frames:v 1 docs/gallery/language-card.png
"$collide" thumbnail "$tmp/gaz.toml" --at 3 --size 640x360 -o docs/gallery/language-still.png \
    >/dev/null 2>&1
echo "docs/gallery/language-card.png docs/gallery/language-still.png"

# The slide player's first page, as a browser shows it before the first key press.
"$collide" render billiards -q m --progress none -o "$tmp/b.mp4" --slides "$tmp/slides" \
    >/dev/null
timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --window-size=1280,800 --virtual-time-budget=4000 \
    --screenshot="$tmp/slides.png" "file://$tmp/slides/index.html" >/dev/null 2>&1
ffmpeg -v error -y -i "$tmp/slides.png" -vf scale=800:-2 docs/gallery/slide-player.png
echo "docs/gallery/slide-player.png"

# Code on screen: the heap's sink with its line under way; the event-driven loop beside its queue.
"$collide" heap --ops "P Q E * X A M * P L E *" --code --size 960x540 --at 9.5 \
    -o docs/gallery/heap-code.png >/dev/null
"$collide" thumbnail gas --queue --code --engine classic --mode event --size 960x540 --at 0.1 \
    -o docs/gallery/queue-code.png >/dev/null
"$collide" puzzle "5 2 8 1 0 4 7 6 3" --code --size 960x540 --at 7.5 --progress none \
    -o docs/gallery/puzzle-code.png >/dev/null
echo "docs/gallery/heap-code.png docs/gallery/queue-code.png docs/gallery/puzzle-code.png"

# Spheres through the perspective camera.
"$collide" thumbnail alder-wainwright --at 2 --projection perspective --size 640x360 \
    -o docs/gallery/alder-wainwright-perspective.png >/dev/null
echo "docs/gallery/alder-wainwright-perspective.png"
