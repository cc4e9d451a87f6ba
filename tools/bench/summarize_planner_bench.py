#!/usr/bin/env python3
"""Medians over objects of the planner benchmarks (tools/bench/planner_bench.cpp).

Usage: build/tools/cordgrasp-microbench --benchmark_filter='FirstFC|FingerStage' \
         --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
         --benchmark_format=json > plan_bench.json
       tools/bench/summarize_planner_bench.py plan_bench.json
"""
import json
import statistics
import sys


def main(path):
    with open(path) as f:
        runs = json.load(f)["benchmarks"]
    rows = {}
    for b in runs:
        if b.get("aggregate_name") != "median":
            continue
        kind, objset, obj = b["run_name"].split("/")
        rows.setdefault((kind, objset), []).append(b)
    for (kind, objset), bs in sorted(rows.items()):
        times = [b["real_time"] for b in bs]  # ms
        line = f"{kind:15s} {objset:4s} n={len(bs):2d} median over objects {statistics.median(times):8.1f} ms"
        if kind.endswith("FirstFC"):
            found = [b for b in bs if b.get("fc", 0) >= 0.5]
            line += f"  FC within 2 s: {len(found)}/{len(bs)}"
            slow = [b["run_name"].split('/')[-1] for b in bs if b.get("fc", 0) < 0.5]
            if slow:
                line += f" (missing: {', '.join(slow)})"
            regions = [b["finger_ms_per_region"] for b in bs if "finger_ms_per_region" in b]
            if regions:
                line += f"  finger stage median {statistics.median(regions):.1f} ms/region"
        if kind == "FingerStage":
            per = [b["ms_per_region"] for b in bs if "ms_per_region" in b]
            line += f"  finger stage median {statistics.median(per):.1f} ms/region"
        print(line)


if __name__ == "__main__":
    main(sys.argv[1])
