#!/usr/bin/env python3
"""A bench run in shards and merged gives the unsharded results.csv (ctest label `shard`).

Runs a small bench of shipped objects once unsharded, then as 4 shards, either through GNU
parallel (--mode parallel: `parallel cordgrasp bench ... --shard {}/4 ::: 1 2 3 4`) or through
the Slurm array script tools/bench_array.sh run locally once per task index with
SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT set (--mode slurm), merges the shards with
`cordgrasp merge` and compares the merged results.csv with the unsharded one cell by cell,
except the wall-clock columns (bench_timing_columns() in bench_job.h). Exit 0: passed,
1: failed, 77: skipped (--mode parallel without GNU parallel; the reason printed).
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import time

SKIP = 77
SHARDS = 4
OBJECTS = ["box", "sphere", "bottle"]
# Cheap and machine-independent: lift only, a time limit far above what these objects need.
BENCH_ARGS = ["--hands", "cordgrasp_sah", "--planners", "cord", "--repeats", "3",
              "--tests", "lift", "--time-limit", "60", "--no-sheets"]
TIMING_COLUMNS = {"first_fc_s", "exploration_s", "finger_s", "quality_s", "total_s",
                  "sim_wall_s", "validated_first_accepted_cpu_s", "validated_cpu_s"}


def run(command, env=None):
    """Runs a command; raises with its output when it fails."""
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} exited with {done.returncode}:\n"
                           f"{done.stdout}{done.stderr}")
    return done


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.reader(f))


def differences(reference, merged):
    """What differs between two results.csv files, wall-clock columns aside."""
    ref, got = read_csv(reference), read_csv(merged)
    if not ref or not got:
        return [f"empty results.csv ({reference}: {len(ref)} lines, {merged}: {len(got)})"]
    if ref[0] != got[0]:
        return [f"headers differ: {ref[0]} vs {got[0]}"]
    header = ref[0]
    out = []
    if len(ref) != len(got):
        out.append(f"{len(ref) - 1} rows unsharded, {len(got) - 1} merged")
    compared = [i for i, name in enumerate(header) if name not in TIMING_COLUMNS]
    missing_timing = TIMING_COLUMNS - set(header)
    if missing_timing:
        out.append(f"no column(s) {sorted(missing_timing)}: the timing list is out of date")
    for row, (a, b) in enumerate(zip(ref[1:], got[1:]), start=1):
        for i in compared:
            if a[i] != b[i]:
                out.append(f"row {row} (attempt {a[0]}), column {header[i]}: "
                           f"'{a[i]}' unsharded, '{b[i]}' merged")
    timed_out = header.index("timed_out")
    if any(r[timed_out] == "1" for r in ref[1:] + got[1:]):
        out.append("an attempt hit --time-limit: its row depends on the machine's load")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cordgrasp", required=True, help="the cordgrasp executable")
    ap.add_argument("--source-dir", required=True, help="the source tree (assets/, tools/)")
    ap.add_argument("--mode", choices=["parallel", "slurm"], required=True)
    ap.add_argument("--out-dir", required=True, help="folder for the benches (emptied first)")
    args = ap.parse_args()
    parallel = shutil.which("parallel")
    if args.mode == "parallel" and not parallel:
        print("SKIP: GNU parallel not found on PATH; install Debian's parallel "
              "(tools/install-deps.sh) to run this test")
        return SKIP
    start = time.monotonic()
    cordgrasp = os.path.abspath(args.cordgrasp)
    out = os.path.abspath(args.out_dir)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    objects = [os.path.join(args.source_dir, "assets", "objects", o + ".obj") for o in OBJECTS]
    bench = ["bench", "--objects", *objects, *BENCH_ARGS]
    failures = []
    try:
        run([cordgrasp, *bench, "--jobs", "2", "--quiet", "--out-dir", out + "/unsharded"])
        if args.mode == "parallel":
            # -q: each argument stays one word; --halt: a failed shard fails the run at once.
            run([parallel, "--will-cite", "-q", "-j", "2", "--halt", "now,fail=1", cordgrasp,
                 *bench, "--jobs", "1", "--quiet", "--shard", "{}/%d" % SHARDS,
                 "--out-dir", out + "/shard-{}", ":::", *map(str, range(1, SHARDS + 1))])
        else:
            script = os.path.join(args.source_dir, "tools", "bench_array.sh")
            env = dict(os.environ, CORDGRASP=cordgrasp, SLURM_CPUS_PER_TASK="1")
            for name in ("SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT"):
                env.pop(name, None)
            usage = subprocess.run(["bash", script, out, *bench[1:]], capture_output=True,
                                   text=True, env=env)
            if usage.returncode == 0 or "usage:" not in usage.stderr:
                failures.append("bench_array.sh without SLURM_ARRAY_TASK_ID ran or said no "
                                f"usage (exit {usage.returncode}): {usage.stderr}")
            for k in range(1, SHARDS + 1):
                task = dict(env, SLURM_ARRAY_TASK_ID=str(k), SLURM_ARRAY_TASK_COUNT=str(SHARDS))
                run(["bash", script, out, *bench[1:]], env=task)
        shards = [f"{out}/shard-{k}" for k in range(1, SHARDS + 1)]
        for shard in shards:
            if not os.path.isfile(shard + "/results.csv"):
                failures.append(f"{shard}/results.csv was not written")
        run([cordgrasp, "merge", *shards, "--out-dir", out + "/merged"])
    except RuntimeError as e:
        print(f"FAIL: {e}")
        return 1
    failures += differences(out + "/unsharded/results.csv", out + "/merged/results.csv")
    rows = len(read_csv(out + "/unsharded/results.csv")) - 1
    if rows != len(OBJECTS) * 3:
        failures.append(f"{rows} rows unsharded, expected {len(OBJECTS) * 3}")
    if not os.path.isfile(out + "/merged/report.html"):
        failures.append("merge wrote no report.html")
    print(f"{args.mode}: {SHARDS} shards of {rows} attempts merged in {out}/merged; "
          f"{time.monotonic() - start:.1f} s")
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
