#!/usr/bin/env bash
# collide's sphere engine against the anchor code (docs/benchmarks.md, issue 47's 3D target): the
# public EDMD code's Single/mdSingle.c (https://github.com/FSmallenburg/EDMD), run the way
# docs/benchmarks-history.md ("The 3D engine against the anchor code") describes, interleaved with
# one or two collide binaries, rounds alternating which program runs first.
#   usage: scripts/bench_anchor.sh EDMD_SINGLE_DIR NEW_COLLIDE [OLD_COLLIDE] [ROUNDS] [SIZES]
# EDMD_SINGLE_DIR is a checkout's Single/ directory; its files are copied and edited in a temporary
# directory (N, packing 0.45, an FCC start, maxtime, line-buffered output), never in place, so this
# repository carries none of that code. ROUNDS defaults to 5 (3 at 10^6, which takes ~40 s a run);
# SIZES to "4000 108000 1048576". Prints one line per run and the ratio to the anchor per round:
# collisions per wall second, the anchor's from its simtime-0 line to its last.
set -euo pipefail
src=$(realpath "$1") new=$(realpath "$2")
old=${3:+$(realpath "$3")}
rounds=${4:-5} sizes=${5:-4000 108000 1048576}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
maxtime() { case $1 in 4000) echo 19 ;; 108000) echo 3 ;; *) echo 1 ;; esac; }
build_anchor() {  # N: the anchor code for N spheres, built for this machine
    local dir=$work/anchor_$1
    mkdir -p "$dir"
    cp "$src"/mdSingle.c "$src"/mdSingle.h "$src"/mt19937ar.c "$dir"/
    sed -i -e "s/^double maxtime = [0-9.]*;/double maxtime = $(maxtime "$1");/" \
        -e 's/^int initialconfig = 0;/int initialconfig = 1;/' \
        -e 's/^double packfrac = [0-9.]*;/double packfrac = 0.45;/' \
        -e "s/^int N = [0-9]*;/int N = $1;/" \
        -e 's/^    init();/    setvbuf(stdout, NULL, _IOLBF, 0); init();/' "$dir"/mdSingle.c
    if ! grep -q "int N = $1;" "$dir"/mdSingle.c || ! grep -q '_IOLBF' "$dir"/mdSingle.c; then
        echo "bench_anchor: $src/mdSingle.c is not the layout this script edits" >&2
        exit 2
    fi
    gcc -Ofast -funroll-loops -march=native -o "$dir"/anchor "$dir"/mdSingle.c -lm
}
anchor_rate() {  # N: M collisions per second, timed from the simtime-0 line to the last
    (cd "$work/anchor_$1" && ./anchor | python3 -u -c "
import sys, time
rows = [(time.perf_counter(), l.split()) for l in sys.stdin if 'Simtime:' in l]
(t0, r0), (t1, r1) = rows[0], rows[-1]
c0, c1 = int(r0[3].rstrip(',')), int(r1[3].rstrip(','))
print(f'{(c1 - c0) / (t1 - t0) / 1e6:.4f}')")
}
collide_rate() {  # BINARY N: M collisions per wall second
    local extra=(--collisions 3e6)
    [[ $2 == 4000 ]] || extra+=(--warmup 1e6)
    [[ $2 -lt 1000000 ]] || extra=(--collisions 4e6 --warmup 1e6)
    "$1" bench engine --dim 3 --n "$2" --eta 0.45 --json "${extra[@]}" |
        python3 -c "import json, sys; print(f\"{json.load(sys.stdin)['collisions_per_second'] / 1e6:.4f}\")"
}
for n in $sizes; do build_anchor "$n"; done
echo "load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%T) UTC"
for ((r = 1; r <= rounds; ++r)); do
    for n in $sizes; do
        if [[ $n -ge 1000000 && $r -gt 3 ]]; then continue; fi
        if ((r % 2)); then
            a=$(anchor_rate "$n"); c=$(collide_rate "$new" "$n"); o=${old:+$(collide_rate "$old" "$n")}
        else
            o=${old:+$(collide_rate "$old" "$n")}; c=$(collide_rate "$new" "$n"); a=$(anchor_rate "$n")
        fi
        awk -v r="$r" -v n="$n" -v a="$a" -v c="$c" -v o="$o" 'BEGIN {
            printf "round %d N=%d anchor %.4f new %.4f (%.2fx)", r, n, a, c, c / a
            if (o != "") printf " old %.4f (%.2fx)", o, o / a
            printf "\n" }'
    done
done
echo "load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%T) UTC"
