#!/usr/bin/env bash
# Proves a refactoring changed nothing a class sees: renders a fixed set of outputs with two
# `collide` binaries and compares them byte for byte.
#   usage: scripts/check_identical.sh OLD_COLLIDE NEW_COLLIDE [WORK_DIR] [--quick]
# The set (issue #27's "done when"): thumbnails of every built-in scene at 320x180, 854x480 and
# 1280x720 (plus the full and none overlay levels, the light theme, the event-only mode and the
# queue strip), `-q l` videos of three scenes, the heap trace, heapsort, five implementations side
# by side, the indexed heap's increase-key, the puzzle (video and --solve text), `render --queue`,
# `--layout-json` at every level (compared as JSON values), the collision lesson's modes, code,
# --dt lists, replays and 3D scenes, and the text outputs of `pq`, `check` and `scenes`.
# --quick leaves out the videos (a few seconds instead of a few minutes).
# Exit 0 when every output is identical, 1 when one differs (each difference is listed).
set -euo pipefail

if [[ $# -lt 2 ]]; then
    echo "usage: $0 OLD_COLLIDE NEW_COLLIDE [WORK_DIR] [--quick]" >&2
    exit 2
fi
old=$(realpath "$1")
new=$(realpath "$2")
shift 2
work=""
quick=0
for arg in "$@"; do
    case "$arg" in
        --quick) quick=1 ;;
        *) work=$arg ;;
    esac
done
[[ -n "$work" ]] || work=$(mktemp -d)
mkdir -p "$work/old" "$work/new"

# Each case: a name (the output file's stem) and the arguments; OUT stands for the output path.
cases=()
add() { cases+=("$*"); }

scenes=(gas brownian diffusion billiards newtons-cradle maxwell-boltzmann tunnelling dense-fluid)
for s in "${scenes[@]}"; do
    for size in 320x180 854x480 1280x720; do
        add "thumb-$s-$size.png|thumbnail $s --at 3 --size $size -o OUT"
    done
done
add "thumb-gas-full.png|thumbnail gas --at 3 --size 1280x720 --overlays full -o OUT"
add "thumb-billiards-none.png|thumbnail billiards --at 1 --size 854x480 --overlays none -o OUT"
add "thumb-tunnelling-light.png|thumbnail tunnelling --at 2 --size 1280x720 --theme light -o OUT"
add "thumb-dense-light-full.png|thumbnail dense-fluid --at 2 --size 1280x720 --theme light --overlays full -o OUT"
add "thumb-gas-event-full.png|thumbnail gas --at 2 --size 854x480 --mode event --overlays full -o OUT"
add "thumb-brownian-speed.png|thumbnail brownian --at 4 --size 854x480 --color speed -o OUT"
add "thumb-queue-classic.png|thumbnail gas --queue --engine classic --slow-motion 4 --size 960x540 --at 3.05 -o OUT"
add "thumb-queue-fast.png|thumbnail gas --queue --slow-motion 4 --size 960x540 --at 3.05 -o OUT"
add "thumb-queue-light.png|thumbnail gas --queue --engine classic --size 1280x720 --at 2 --theme light -o OUT"
add "last-tunnelling.png|render tunnelling --last-frame -q l -o OUT"
# The collision lesson's choices (issue #43): both modes alone, the code beside the queue, a --dt
# list, a replay's frame, 3D scenes (fixed and orbiting), a time-driven step longer than a frame.
add "thumb-gas-time.png|thumbnail gas --at 2 --size 854x480 --mode time -o OUT"
add "thumb-gas-event.png|thumbnail gas --at 2 --size 854x480 --mode event -o OUT"
add "thumb-queue-code.png|thumbnail gas --queue --code --size 1280x720 --at 3.05 -o OUT"
add "thumb-dt-list.png|thumbnail tunnelling --dt 0.01,0.02,0.04 --at 2 --size 1280x720 -o OUT"
add "thumb-dt-long.png|thumbnail gas --dt 0.2 --at 2 --size 854x480 -o OUT"
add "thumb-gas-3d.png|thumbnail gas-3d --at 1 --size 854x480 -o OUT"
add "thumb-alder-orbit.png|thumbnail alder-wainwright --at 1 --size 854x480 --camera orbit -o OUT"
add "thumb-freeze-slab.png|thumbnail spheres-freeze --at 1 --size 854x480 --slab 0.2 --projection perspective -o OUT"
add "timeline-tunnelling.json|render tunnelling -q l --duration 6 --timeline-json OUT -o $work/scratch.mp4"
add "layout-code.json|render gas -q l --duration 1 --queue --code --layout-json OUT -o $work/scratch.mp4"
add "layout-dt-list.json|render tunnelling -q l --duration 1 --dt 0.01,0.02,0.04 --layout-json OUT -o $work/scratch.mp4"
for level in lesson full none; do
    add "layout-$level.json|render gas -q l --duration 1 --overlays $level --layout-json OUT -o $work/scratch.mp4"
done
add "layout-queue.json|render gas -q l --duration 1 --queue --engine classic --layout-json OUT -o $work/scratch.mp4"
add "heap-trace.png|heap --ops P_Q_E_*_X_A_M_*_P_L_E_* --at 18 --size 854x480 -o OUT"
add "heap-five.png|heap --ops P_Q_E_*_X_A_M_* --impl unordered,ordered,binary,dary:3,indexed --at 9 --size 1280x720 -o OUT"
add "heap-sort.png|heap --sort S_O_R_T_E_X_A_M_P_L_E --at 30 --size 854x480 -o OUT"
add "heap-indexed.png|heap --ops 5_9_3_7_*_3^12 --impl indexed:2 --at 18 --size 854x480 -o OUT"
add "heap-dary-min-light.png|heap --ops P_Q_E_*_X_A_M_* --impl dary:3 --min --at 12 --size 854x480 --theme light -o OUT"
add "puzzle.png|puzzle 8_1_3_4_0_2_7_6_5 --at 6 --size 1280x720 -o OUT"
add "puzzle-big.png|puzzle 8_6_7_2_5_4_3_0_1 --at 12 --size 854x480 -o OUT"
if [[ $quick -eq 0 ]]; then
    for s in tunnelling gas billiards; do
        add "video-$s.mp4|render $s -q l -o OUT"
    done
    add "video-queue.mp4|render gas --queue --engine classic --slow-motion 4 -q l --duration 4 -o OUT"
    add "video-heap-trace.mp4|heap --ops P_Q_E_*_X_A_M_*_P_L_E_* -q l -o OUT"
    add "video-heapsort.mp4|heap --sort S_O_R_T_E_X_A_M_P_L_E -q l -o OUT"
    add "video-heap-five.mp4|heap --ops P_Q_E_*_X_A_M_* --impl unordered,ordered,binary,dary:3,indexed -q l -o OUT"
    add "video-puzzle.mp4|puzzle 8_1_3_4_0_2_7_6_5 -q l -o OUT"
    add "video-event.mp4|render billiards -q l --mode event --duration 4 -o OUT"
    add "video-time.mp4|render newtons-cradle -q l --mode time --duration 4 -o OUT"
    add "video-code.mp4|render gas --queue --code -q l --duration 3 -o OUT"
    add "video-dt-list.mp4|render tunnelling -q l --duration 4 --dt 0.01,0.02,0.04 -o OUT"
    add "video-gas-3d.mp4|render gas-3d -q l --duration 3 --camera orbit -o OUT"
fi
# Text outputs (stdout): OUT unused, the stdout is the output.
add "pq-trace.txt|pq --ops P_Q_E_*_X_A_M_*_P_L_E_*"
add "pq-markdown.txt|pq --ops P_Q_E_*_X_A_M_* --format markdown --impl binary,indexed"
add "puzzle-solve.txt|puzzle 8_1_3_4_0_2_7_6_5 --solve"
add "check-gas.txt|check gas"
add "scenes.txt|scenes"
# Messages of bad input (stderr and exit code): the fields the simulation library names, spelled
# as the options the user typed.
add "err-pq-empty.txt|pq --ops P_*_*"
add "err-pq-impl.txt|pq --ops P --impl dary:65"
add "err-heap-token.txt|heap --ops P_?"
add "err-heap-increase.txt|heap --ops 5_3_3^12"
add "err-heap-absent.txt|heap --ops 5_3_4^12 --impl indexed"
add "err-heap-sort.txt|heap --sort S_*"
add "err-heap-pace.txt|heap --ops P --pace 0"
add "err-simulate-dt.txt|simulate gas --until 1 --engine time --dt 0"
add "err-simulate-engine.txt|simulate gas --until 1 --engine warp"
add "err-simulate-detect.txt|simulate gas --until 1 --engine time --td-detect octree"
add "err-thumb-pq.txt|thumbnail gas --engine classic --pq x"
add "err-puzzle-moves.txt|puzzle random --moves -1"
add "err-puzzle-heuristic.txt|puzzle 1_2_3_4_0_6_7_5_8 --solve --heuristic euclid"

run_case() {  # binary, dir, case
    local bin=$1 dir=$2 spec=$3
    local name=${spec%%|*} args=${spec#*|}
    local out="$dir/$name"
    local -a argv=()
    local a
    for a in $args; do
        a=${a//_/ }          # operations and boards are written with _ for spaces
        a=${a//OUT/$out}
        argv+=("$a")
    done
    if [[ $name == *.txt ]]; then
        "$bin" "${argv[@]}" >"$out" 2>"$out.stderr" || echo "exit $?" >>"$out"
    else
        "$bin" "${argv[@]}" --progress none >/dev/null 2>"$out.stderr" || echo "exit $?" >"$out.exit"
    fi
}

# JSON files (--layout-json, --timeline-json) are compared as values: a change of writer may
# change their spacing, never what they say.
same_json() {
    python3 -c 'import json, sys; sys.exit(json.load(open(sys.argv[1])) != json.load(open(sys.argv[2])))' "$1" "$2" 2>/dev/null
}

differ=0
for spec in "${cases[@]}"; do
    name=${spec%%|*}
    run_case "$old" "$work/old" "$spec"
    run_case "$new" "$work/new" "$spec"
    for f in "$name" "$name.exit"; do
        if [[ -e "$work/old/$f" || -e "$work/new/$f" ]]; then
            if [[ $f == *.json ]] && same_json "$work/old/$f" "$work/new/$f"; then
                continue  # the same values, whatever the writer's spacing
            fi
            if ! cmp -s "$work/old/$f" "$work/new/$f"; then
                echo "DIFFERS: $f"
                differ=1
            fi
        fi
    done
    # Messages too, with the two output folders' names made equal.
    if ! cmp -s <(sed "s#$work/old#WORK#g" "$work/old/$name.stderr") \
                <(sed "s#$work/new#WORK#g" "$work/new/$name.stderr"); then
        echo "DIFFERS: $name.stderr"
        differ=1
    fi
done
echo "compared ${#cases[@]} outputs in $work (old/ and new/)"
if [[ $differ -ne 0 ]]; then
    echo "check_identical: outputs differ" >&2
    exit 1
fi
echo "check_identical: all identical"
