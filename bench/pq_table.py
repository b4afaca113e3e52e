#!/usr/bin/env python3
"""Turns `bench_pq --benchmark_format=json` output into the Markdown tables of docs/benchmarks.md.

Cells are median CPU ns per step and, in parentheses, the ratio to std::priority_queue (hold) or
to indexed:2 (decrease) at the same N, all from the one run. Usage: pq_table.py results.json
"""
import json
import sys
from collections import defaultdict


def medians(path):
    with open(path) as f:
        data = json.load(f)
    out = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name", "median") != "median":
            continue
        family, queue, n = b["run_name"].rsplit("/", 2) if b["run_name"].count("/") >= 2 else (None, None, None)
        if family is None:
            continue
        out[(family, queue, int(n))] = b["cpu_time"]
    return out


def table(results, family, baseline):
    cells = {(q, n): t for (f, q, n), t in results.items() if f == family}
    sizes = sorted({n for _, n in cells})
    queues = []
    for q, _ in cells:
        if q not in queues:
            queues.append(q)
    queues.sort(key=lambda q: (q != baseline, q))
    lines = ["| queue | " + " | ".join(f"N = {n:.0e}".replace("e+0", "e") for n in sizes) + " |",
             "| --- |" + " ---: |" * len(sizes)]
    for q in queues:
        row = []
        for n in sizes:
            if (q, n) not in cells:
                row.append("")
                continue
            t = cells[(q, n)]
            base = cells.get((baseline, n))
            row.append(f"{t:.0f} ns ({t / base:.2f})" if base else f"{t:.0f} ns")
        lines.append(f"| {q} | " + " | ".join(row) + " |")
    return "\n".join(lines)


def main():
    results = medians(sys.argv[1])
    print("Hold model (pop the earliest, push it back later), ns per pop+push, ratio to std::priority_queue:\n")
    print(table(results, "hold", "std::priority_queue"))
    print("\nDecrease-key mix on the indexed heap (3/4 decrease_key, 1/4 hold step), ns per step, ratio to indexed:2:\n")
    print(table(results, "decrease", "indexed:2"))


if __name__ == "__main__":
    main()
