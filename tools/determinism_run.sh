#!/usr/bin/env bash
# A fixed workload whose outputs must not depend on the machine's speed: three plans and a
# small bench with lift tests, seed 7. Run it twice (e.g. once under `nice` beside a parallel
# load, once idle) and compare the two folders with tools/compare_runs.py.
#
#   tools/determinism_run.sh OUT
#
# Environment: CORDGRASP (executable, default build/tools/cordgrasp), DATA (../shared/data).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
OUT="$1"
CG="${CORDGRASP:-$ROOT/build/tools/cordgrasp}"
DATA="${DATA:-$ROOT/../shared/data}"
mkdir -p "$OUT"
cat /proc/loadavg > "$OUT/load_start.txt"
start=$(date +%s.%N)
"$CG" plan --hand cordgrasp_sah --object mug --seed 7 --grasps 3 -q --out "$OUT/mug.plan.json"
echo "scale: 2" > "$OUT/scale2.yaml"  # the KIT mesh at about its real size
"$CG" plan --hand schunk_sah --object "$DATA/objects/kit/Pitcher.obj" --settings "$OUT/scale2.yaml" \
  --seed 7 --grasps 3 -q --out "$OUT/pitcher.plan.json"
"$CG" plan --hand cordgrasp_sah --object kettle --planner generic --seed 7 --grasps 2 -q \
  --out "$OUT/kettle_generic.plan.json"
objects=()
for o in mug box kettle bottle; do objects+=("$ROOT/assets/objects/$o.obj"); done
"$CG" bench --hands cordgrasp_sah,schunk_sah --objects "${objects[@]}" --planners cord,generic \
  --repeats 2 --tests lift --seed 7 --jobs 2 --no-sheets --overwrite --out-dir "$OUT/bench" \
  > "$OUT/bench.log" 2>&1
echo "$start $(date +%s.%N)" > "$OUT/wall.txt"
cat /proc/loadavg > "$OUT/load_end.txt"
