#!/usr/bin/env bash
# Fraction of the cord planner's force-closure grasps that hold through lift + shake in Bullet
# per object set and hand. Plans and sim.json files go to OUT_DIR; one summary line
# per (set, hand) at the end.
#
#   tools/hold_rates.sh [OUT_DIR] [GRASPS_PER_OBJECT] [HANDS...]
#   e.g. tools/hold_rates.sh /tmp/holds 3 cordgrasp_sah schunk_sah panda_hand
#
# HANDS are shipped hand names or hand description files (a variant's results then go to
# OUT_DIR/<file name without .yaml>/).
#
# Environment: CORDGRASP (the executable, default build/tools/cordgrasp), DATA (shared data,
# default ../shared/data), TIME_LIMIT (plan time limit per object, default 10 s),
# SOFT_FINGER (soft-finger radius for two-finger grippers, default 0.005 m: two point
# contacts are never force closure), TRIALS (validate --trials: each grasp also simulated with
# the hand nudged; held / not-held of marginal grasps is chaotic, docs/physics.md; default 1),
# YCB_MASSES (1: the YCB objects get their measured masses, table below; 0: density × volume
# like the other sets; default 1), VALIDATE_ARGS (more `cordgrasp validate` options, split at
# spaces, e.g. "--protocol thorough --physics levers.yaml"; default none).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
OUT="${1:-/tmp/cordgrasp_hold_rates}"
GRASPS="${2:-3}"
shift $(( $# > 2 ? 2 : $# ))
HANDS=("$@")
[ ${#HANDS[@]} -eq 0 ] && HANDS=(cordgrasp_sah schunk_sah panda_hand)
CG="${CORDGRASP:-$ROOT/build/tools/cordgrasp}"
DATA="${DATA:-$ROOT/../shared/data}"
TIME_LIMIT="${TIME_LIMIT:-10}"
SOFT_FINGER="${SOFT_FINGER:-0.005}"
TRIALS="${TRIALS:-1}"
YCB_MASSES="${YCB_MASSES:-1}"
read -r -a VALIDATE_EXTRA <<< "${VALIDATE_ARGS:-}"
# Measured masses of the YCB objects [kg], from the YCB object and model set (Calli et al.,
# IEEE Robotics & Automation Magazine 2015). The default density × closed volume gets these
# wrong by up to 7×: the pitcher's mesh is closed over its 2.5 l inside (1.27 kg at 500 kg/m³).
declare -A YCB_MASS=(
  [003_cracker_box]=0.411 [005_tomato_soup_can]=0.349 [006_mustard_bottle]=0.603
  [019_pitcher_base]=0.178 [025_mug]=0.118 [035_power_drill]=0.895 [037_scissors]=0.082
  [051_large_clamp]=0.125)
mkdir -p "$OUT"

declare -A SETS
SETS[shipped]="$(ls "$ROOT"/assets/objects/*.obj)"
SETS[kit]="$(ls "$DATA"/objects/kit/*.obj)"
SETS[ycb]="$(ls "$DATA"/objects/ycb/*.obj)"

summary=()
for hand in "${HANDS[@]}"; do
  label="$(basename "$hand" .yaml)"
  settings="$OUT/$label.settings.yaml"  # the plan's settings (docs/algorithm.md §10c)
  echo "time_limit_s: $TIME_LIMIT" > "$settings"
  case "$label" in panda_hand|parallel_gripper)
    echo "quality: {contact: {soft_finger_radius_m: $SOFT_FINGER}}" >> "$settings" ;;
  esac
  for set in shipped kit ycb; do
    held=0; total=0; no_plan=0; trials_held=0; trials_total=0
    failed=(0 0 0 0 0 0)   # not held in settle, close, lift, shake, gravity6; preshape overlaps
    for obj in ${SETS[$set]}; do
      name="$(basename "$obj" .obj)"
      base="$OUT/$label/$set/$name"
      mkdir -p "$(dirname "$base")"
      if ! "$CG" plan --hand "$hand" --object "$obj" --grasps "$GRASPS" \
          --settings "$settings" --seed 1 --out "$base.plan.json" \
          > "$base.plan.txt" 2>&1; then
        no_plan=$((no_plan + 1)); continue
      fi
      mass=()
      if [ "$set" = ycb ] && [ "$YCB_MASSES" = 1 ]; then
        [ -n "${YCB_MASS[$name]:-}" ] || { echo "hold_rates.sh: no measured mass for YCB object $name" >&2; exit 1; }
        mass=(--mass "${YCB_MASS[$name]}")
      fi
      "$CG" validate --plan "$base.plan.json" --tests lift,shake --trials "$TRIALS" --quiet "${mass[@]}" \
          ${VALIDATE_EXTRA[@]+"${VALIDATE_EXTRA[@]}"} \
          --out "$base.sim.json" > "$base.sim.txt" 2>&1 || { echo "validate failed: $base"; continue; }
      line="$(grep '^held [0-9]* / ' "$base.sim.txt")"   # "held k / n (...)"
      k="$(echo "$line" | awk '{print $2}')"; n="$(echo "$line" | awk '{print $4}')"
      held=$((held + k)); total=$((total + n))
      # "not held by phase: settle 0, close 2, lift 1, shake 0, gravity6 0; preshape overlaps 1"
      mapfile -t counts < <(grep '^not held by phase:' "$base.sim.txt" |
          grep -oE '(settle|close|lift|shake|gravity6|overlaps) [0-9]+' | awk '{print $2}')
      for i in "${!counts[@]}"; do failed[i]=$((failed[i] + counts[i])); done
      if [ "$TRIALS" -gt 1 ]; then   # "held in k / n trials of all grasps"
        t="$(tail -n 1 "$base.sim.txt")"
        trials_held=$((trials_held + $(echo "$t" | awk '{print $3}')))
        trials_total=$((trials_total + $(echo "$t" | awk '{print $5}')))
      fi
      echo "$label $set $name: $line"
    done
    trials_text=""
    [ "$TRIALS" -gt 1 ] && trials_text=", held in $trials_held / $trials_total trials"
    summary+=("$label $set: held $held / $total force-closure grasps$trials_text ($no_plan objects without a plan); not held in close ${failed[1]}, lift ${failed[2]}, shake ${failed[3]}, settle ${failed[0]}; preshape overlaps ${failed[5]}")
  done
done
printf '%s\n' "${summary[@]}" | tee "$OUT/summary.txt"
