#!/usr/bin/env bash
# Whole-pipeline frames per second of `collide render` (-q m, mode both, 2000 discs) against
# libx264 alone encoding exactly the same frames with the same preset and CRF (ffmpeg from raw
# RGBA), in ROUNDS rounds (default 5). Prints both and their ratio per round, and the median ratio.
# Usage: [ROUNDS=n] scripts/bench_pipeline.sh [collide] [seconds of video] [extra render options...]
# e.g. scripts/bench_pipeline.sh build/release/collide 5 --td-detect grid
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${1:-build/release/collide}
seconds=${2:-5}
extra=("${@:3}")
rounds=${ROUNDS:-5}
scene=bench/scenes/pipeline-2000.toml
preset=veryfast   # collide's default H.264 preset and CRF (include/collide/video/video_writer.hpp)
crf=20
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. the frames themselves, dumped once (not timed: the dump adds disk writes)
"$collide" render "$scene" -q m --duration "$seconds" --progress none -o "$tmp/dump.mp4" "${extra[@]}" \
    --dump-rgba "$tmp/frames.rgba" >/dev/null 2>&1
frames=$(( $(stat -c %s "$tmp/frames.rgba") / (1280 * 720 * 4) ))

time_command() {  # prints the wall seconds the command took
    local start
    start=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    echo "$(date +%s.%N) - $start" | bc -l
}
pipeline() {  # 2. the whole pipeline: simulation + rendering + encoding
    "$collide" render "$scene" -q m --duration "$seconds" --progress none -o "$tmp/pipeline.mp4" \
        "${extra[@]}"
}
libx264_alone() {  # 3. libx264 alone on the same frames
    ffmpeg -v error -y -f rawvideo -pix_fmt rgba -s 1280x720 -r 30 -i "$tmp/frames.rgba" \
        -c:v libx264 -preset "$preset" -crf "$crf" -pix_fmt yuv420p "$tmp/x264.mp4"
}

# Both, ROUNDS times; the order alternates so that neither always runs first (right after the
# dump, or on caches warmed by the other). The ratio is taken per round; the median is reported.
printf 'frames %d  load %s\n' "$frames" "$(cut -d' ' -f1-3 /proc/loadavg)"
ratios=()
for ((round = 1; round <= rounds; ++round)); do
    if ((round % 2 == 1)); then
        pipeline_s=$(time_command pipeline)
        x264_s=$(time_command libx264_alone)
    else
        x264_s=$(time_command libx264_alone)
        pipeline_s=$(time_command pipeline)
    fi
    ratio=$(echo "$x264_s / $pipeline_s" | bc -l)
    ratios+=("$ratio")
    printf 'round %d: pipeline %5.2f s %6.1f fps   libx264 alone %5.2f s %6.1f fps   ratio %.3f\n' \
        "$round" "$pipeline_s" "$(echo "$frames / $pipeline_s" | bc -l)" "$x264_s" \
        "$(echo "$frames / $x264_s" | bc -l)" "$ratio"
done
median=$(printf '%s\n' "${ratios[@]}" | sort -g | awk '{v[NR] = $1} END {
    print (NR % 2 == 1) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
printf 'load %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
printf 'ratio pipeline/libx264, median of %d rounds: %.3f (target >= 0.9)\n' "$rounds" "$median"
