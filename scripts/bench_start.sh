#!/usr/bin/env bash
# Start-up time of commands that draw nothing (docs/benchmarks.md, "Start"): the median wall time
# of RUNS runs of each command with each program, the programs alternating run by run so that
# both see the same machine. Usage: scripts/bench_start.sh OLD_BIN NEW_BIN [RUNS [COMMAND...]]
# (each COMMAND one argument, e.g. "puzzle '1 2 3 4 0 6 7 5 8' --solve"; default: the set below).
set -euo pipefail
old=$(realpath "$1") new=$(realpath "$2") runs=${3:-20}  # absolute: the runs happen elsewhere
commands=("check gas" "scenes" "--version" "pq --ops 'P Q E * X'" "simulate gas --until 1")
if [[ $# -gt 3 ]]; then commands=("${@:4}"); fi
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
ms() {  # one run's wall time in milliseconds
    local start end
    start=$(date +%s%N)
    eval "\"$1\" $2" >/dev/null 2>&1 || true
    end=$(date +%s%N)
    echo $(((end - start) / 1000))  # microseconds
}
cd "$(mktemp -d)"
printf '%-42s %10s %10s %8s\n' command "old ms" "new ms" ratio
for command in "${commands[@]}"; do
    old_times=() new_times=()
    for ((i = 0; i < runs; ++i)); do
        old_times+=("$(ms "$old" "$command")")
        new_times+=("$(ms "$new" "$command")")
    done
    o=$(printf '%s\n' "${old_times[@]}" | median)
    n=$(printf '%s\n' "${new_times[@]}" | median)
    awk -v c="$command" -v o="$o" -v n="$n" \
        'BEGIN { printf "%-42s %10.1f %10.1f %8.2f\n", c, o / 1000, n / 1000, n / o }'
done
echo "NEEDED libraries (ldd): old $(ldd "$old" | wc -l), new $(ldd "$new" | wc -l)"
