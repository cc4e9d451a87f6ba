#!/usr/bin/env bash
# Bullet (`cordgrasp validate --tests lift,shake`, protocol standard) against MuJoCo
# (cordgrasp-mujoco-check, the same protocol) on the same grasps: plans GRASPS grasps per object
# of the shipped objects and ../shared/data/objects for each hand, exports each plan as MJCF,
# runs both and prints per hand the grasps, held in each and how many verdicts agree. Files go
# to OUT_DIR.
#   tools/mujoco_check/agreement.sh OUT_DIR GRASPS HAND...
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
OUT="$1"; GRASPS="$2"; shift 2
CG="${CORDGRASP:-$ROOT/build/tools/cordgrasp}"
MJ="${MUJOCO_CHECK:-$ROOT/build/tools/mujoco_check/cordgrasp-mujoco-check}"
DATA="${DATA:-$ROOT/../shared/data}"
mkdir -p "$OUT"
objects=("$ROOT"/assets/objects/*.obj "$DATA"/objects/*/*.obj)
for hand in "$@"; do
  mkdir -p "$OUT/$hand"
  for obj in "${objects[@]}"; do
    name="$(basename "$(dirname "$obj")")_$(basename "$obj" .obj)"
    base="$OUT/$hand/$name"
    echo "time_limit_s: 10" > "$OUT/time_limit.yaml"
    "$CG" plan --hand "$hand" --object "$obj" --units auto -n "$GRASPS" --settings "$OUT/time_limit.yaml" \
      --out "$base.plan.json" >/dev/null 2>&1 || continue
    "$CG" validate --plan "$base.plan.json" --tests lift,shake --out "$base.sim.json" -q \
      >/dev/null 2>&1 || continue
    "$CG" export --plan "$base.plan.json" --format mjcf --out "$base.xml" >/dev/null 2>&1 ||
      continue
    "$MJ" --scene "$base.xml" --out "$base.mujoco.csv" >/dev/null ||
      continue
  done
  /usr/bin/python3 - "$OUT/$hand" "$hand" <<'PY'
import csv, glob, json, sys
d, hand = sys.argv[1], sys.argv[2]
n = bh = mh = agree = 0
for sim in sorted(glob.glob(d + "/*.sim.json")):
    csvf = sim.replace(".sim.json", ".mujoco.csv")
    try:
        rows = list(csv.DictReader(open(csvf)))
    except FileNotFoundError:
        continue
    grasps = json.load(open(sim))["grasps"]
    for g, r in zip(grasps, rows):
        b = g["outcome"] == "held"; m = r["held"] == "1"
        n += 1; bh += b; mh += m; agree += b == m
print(f"{hand}: {n} grasps, Bullet held {bh}, MuJoCo held {mh}, agree {agree} "
      f"({100.0 * agree / max(n, 1):.0f} %)")
PY
done
