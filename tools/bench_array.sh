#!/usr/bin/env bash
#SBATCH --job-name=cordgrasp-bench
#SBATCH --cpus-per-task=4
#SBATCH --output=bench-%A_%a.log
# One task of a Slurm job array running a bench in shards (docs/bench.md, "Shards"):
# array task K of N runs `cordgrasp bench BENCH_ARGS --shard K/N --out-dir OUT_DIR/shard-K`
# with --jobs $SLURM_CPUS_PER_TASK threads (so BENCH_ARGS must not hold --jobs, --shard or
# --out-dir). Join the shards afterwards with
# `cordgrasp merge OUT_DIR/shard-* --out-dir OUT_DIR/all`.
#
#   sbatch --array=1-16 tools/bench_array.sh OUT_DIR BENCH_ARGS...
#
# --array must be 1..N (Slurm sets SLURM_ARRAY_TASK_COUNT to N only for a contiguous 1-based
# range). Run locally, one task at a time, by setting the variables:
#   SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_COUNT=4 tools/bench_array.sh OUT_DIR BENCH_ARGS...
# Environment: CORDGRASP (the executable, default `cordgrasp` on PATH), SLURM_CPUS_PER_TASK
# (threads, default 1).
set -euo pipefail

usage() {
  echo "usage: sbatch --array=1-N $0 OUT_DIR BENCH_ARGS...  (or locally with" \
       "SLURM_ARRAY_TASK_ID=K SLURM_ARRAY_TASK_COUNT=N set)" >&2
  echo "bench_array.sh: $1" >&2
  exit 2
}

[ $# -ge 2 ] || usage "expected OUT_DIR and the bench's arguments"
k="${SLURM_ARRAY_TASK_ID:-}"
n="${SLURM_ARRAY_TASK_COUNT:-}"
[[ "$k" =~ ^[0-9]+$ && "$n" =~ ^[0-9]+$ ]] ||
  usage "SLURM_ARRAY_TASK_ID ('$k') and SLURM_ARRAY_TASK_COUNT ('$n') must be set to numbers"
(( k >= 1 && k <= n )) ||
  usage "task $k of $n: --array must run 1..N (SLURM_ARRAY_TASK_ID from 1 to the count)"
out="$1"
shift
exec "${CORDGRASP:-cordgrasp}" bench "$@" --jobs "${SLURM_CPUS_PER_TASK:-1}" --shard "$k/$n" \
  --quiet --out-dir "$out/shard-$k"
