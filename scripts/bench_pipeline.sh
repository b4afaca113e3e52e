#!/usr/bin/env bash
# Whole-pipeline frames per second of `collide render` (-q m, mode both, 2000 discs) against
# libx264 alone encoding exactly the same frames with the same preset and CRF (ffmpeg from raw
# RGBA). Prints both and their ratio.
# Usage: scripts/bench_pipeline.sh [collide] [seconds of video] [extra render options...]
# e.g. scripts/bench_pipeline.sh build/release/collide 5 --td-detect grid
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
seconds=${2:-5}
extra=("${@:3}")
scene=bench/scenes/pipeline-2000.toml
preset=veryfast   # collide's default H.264 preset and CRF (include/collide/video/video_writer.hpp)
crf=20
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. the frames themselves, dumped once (not timed: the dump adds disk writes)
"$collide" render "$scene" -q m --duration "$seconds" --progress none -o "$tmp/dump.mp4" "${extra[@]}" \
    --dump-rgba "$tmp/frames.rgba" >/dev/null 2>&1
frames=$(( $(stat -c %s "$tmp/frames.rgba") / (1280 * 720 * 4) ))

# 2. the whole pipeline: simulation + rendering + encoding
start=$(date +%s.%N)
"$collide" render "$scene" -q m --duration "$seconds" --progress none -o "$tmp/pipeline.mp4" "${extra[@]}" \
    >/dev/null 2>&1
pipeline_s=$(echo "$(date +%s.%N) - $start" | bc -l)

# 3. libx264 alone on the same frames
start=$(date +%s.%N)
ffmpeg -v error -y -f rawvideo -pix_fmt rgba -s 1280x720 -r 30 -i "$tmp/frames.rgba" \
    -c:v libx264 -preset "$preset" -crf "$crf" -pix_fmt yuv420p "$tmp/x264.mp4"
x264_s=$(echo "$(date +%s.%N) - $start" | bc -l)

printf 'frames %d  load %s\n' "$frames" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf 'pipeline      %6.2f s  %6.1f fps\n' "$pipeline_s" "$(echo "$frames / $pipeline_s" | bc -l)"
printf 'libx264 alone %6.2f s  %6.1f fps\n' "$x264_s" "$(echo "$frames / $x264_s" | bc -l)"
printf 'ratio pipeline/libx264 %.2f (target >= 0.9)\n' "$(echo "$x264_s / $pipeline_s" | bc -l)"
