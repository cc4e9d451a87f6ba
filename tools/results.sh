#!/usr/bin/env bash
# Regenerates docs/results.md: the evaluation of Li et al. (T-RO 2015), Fig. 11-14 and 17 and
# physics hold rates, reproduced with `cordgrasp bench` on ../shared/data.
#
#   tools/results.sh [--full] [OUT_DIR]
#
# The KIT meshes in ../shared/data are the Dex-Net copies (median extent 4.5 cm, about half
# their real size): every KIT experiment (Fig. 12, 13-14, KIT physics) runs at --scale 2, an
# approximation of real size, and at --scale 1 (Dex-Net scale) beside it. The cylinder of
# Fig. 11, the YCB and the shipped objects are real size and run at --scale 1 only.
#
# Without --full it runs the reduced protocol that fits a small shared machine (about 6 min CPU,
# 20 min wall on a loaded 2-core machine; what is reduced is listed in docs/results.md); --full runs the paper's counts
# (100 runs per Fig. 11 setting, physics on 10 attempts per object and two hands: hours on
# 2 cores). Raw outputs (results.csv, summary.md, bench.json, contact sheets per experiment)
# go to OUT_DIR (default /tmp/cordgrasp_results); the page to docs/results.md
# (RESULTS_MD to override), its plots to docs/img/results/ (matplotlib from Debian's
# /usr/bin/python3, python3-matplotlib; tools/install-deps.sh installs it).
#
# Environment: CORDGRASP (executable, default build/tools/cordgrasp), DATA (default
# ../shared/data), JOBS (threads per bench, default nproc), PYTHON (default /usr/bin/python3).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MODE=reduced
if [ "${1:-}" = "--full" ]; then MODE=full; shift; fi
OUT="${1:-/tmp/cordgrasp_results}"
CG="${CORDGRASP:-$ROOT/build/tools/cordgrasp}"
DATA="${DATA:-$ROOT/../shared/data}"
JOBS="${JOBS:-$(nproc)}"
MD="${RESULTS_MD:-$ROOT/docs/results.md}"
PY="${PYTHON:-/usr/bin/python3}"
IMG="$(dirname "$MD")/img/results"
KIT="$DATA/objects/kit"
YCB="$DATA/objects/ycb"
SHIPPED="$ROOT/assets/objects"

if [ "$MODE" = full ]; then
  FIG11_RUNS=100; PHYS_REPEATS=10; PHYS_HANDS=schunk_sah,cordgrasp_sah
else
  FIG11_RUNS=30; PHYS_REPEATS=1; PHYS_HANDS=schunk_sah
fi
FIG12_OBJECTS=(CoffeeFilters CokePlasticLarge KoalaCandy Pitcher Wineglass)
GENERIC_BUDGETS=(0.25 1 4)   # Fig. 12: the paper does not state its three budgets
KIT_SCALES=(1 2)             # Dex-Net scale and about real size (see above)
FIG17_OBJECTS=("$YCB/025_mug.obj" "$YCB/019_pitcher_base.obj" "$YCB/051_large_clamp.obj"
               "$YCB/035_power_drill.obj" "$YCB/037_scissors.obj"
               "$SHIPPED/pliers.obj" "$SHIPPED/kettle.obj")

mkdir -p "$OUT"
: > "$OUT/commands.txt"
bench() {  # bench NAME ARGS...: one cordgrasp bench into OUT/NAME, command logged
  local name="$1"; shift
  echo "cordgrasp bench $* --jobs $JOBS --out-dir \$OUT/$name" >> "$OUT/commands.txt"
  echo "== $name" >&2
  "$CG" bench "$@" --jobs "$JOBS" --overwrite --out-dir "$OUT/$name"
}
start=$(date +%s)

# Each setting is a planner settings file (docs/algorithm.md §10c) in OUT/settings. Every
# cord run is the paper's planner: no sampled surface points after its regions
# (fallback_attempts 0, docs/algorithm.md §10).
mkdir -p "$OUT/settings"
paper="$OUT/settings/paper.yaml"
echo "fallback_attempts: 0" > "$paper"

# Fig. 11: alpha and exploration time against the number of sets, with / without local
# improvement, on the long cylinder (the shipped one: 35 mm x 250 mm), Schunk SAH.
for sets in 5 10 20 40; do
  echo "{fallback_attempts: 0, cord: {sets: $sets}}" > "$OUT/settings/sets${sets}_li.yaml"
  echo "{fallback_attempts: 0, cord: {sets: $sets, local_improvement: false}}" \
    > "$OUT/settings/sets${sets}_noli.yaml"
  for li in li noli; do
    bench "fig11_sets${sets}_$li" --hands schunk_sah --objects "$SHIPPED/long_cylinder.obj" \
      --planners cord --repeats "$FIG11_RUNS" --settings "$OUT/settings/sets${sets}_$li.yaml" \
      --tests none --no-sheets
  done
done

# Fig. 12: cord (10 attempts) vs generic (10 attempts at each of three time budgets), and
# Fig. 13-14: all 26 KIT objects x 10 attempts, Schunk SAH, cord planner; at each KIT scale
# (experiment names get _x2 at --scale 2).
fig12=()
for o in "${FIG12_OBJECTS[@]}"; do fig12+=("$KIT/$o.obj"); done
for sc in "${KIT_SCALES[@]}"; do
  tag=""; [ "$sc" = 1 ] || tag="_x$sc"
  bench "fig12_cord$tag" --hands schunk_sah --objects "${fig12[@]}" --planners cord \
    --repeats 10 --scale "$sc" --tests none --settings "$paper"
  for b in "${GENERIC_BUDGETS[@]}"; do
    bench "fig12_generic_${b}s$tag" --hands schunk_sah --objects "${fig12[@]}" \
      --planners generic --repeats 10 --time-limit "$b" --scale "$sc" --tests none --no-sheets
  done
  bench "fig13$tag" --hands schunk_sah --objects "$KIT" --planners cord --repeats 10 \
    --scale "$sc" --tests none --settings "$paper"
done

# Fig. 17 stand-in: complex objects, cord then generic with the paper's protocol (generic
# timeout = the cord planner's largest time on that object).
bench fig17_cord --hands schunk_sah --objects "${FIG17_OBJECTS[@]}" --planners cord \
  --repeats 10 --tests none --settings "$paper"
for obj in "${FIG17_OBJECTS[@]}"; do
  name="$(basename "$obj" .obj)"
  limit="$(awk -F, -v o="$name" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
             $c["object"] == o && $c["total_s"] > m { m = $c["total_s"] }
             END { printf "%.3f", (m > 0 ? m : 10) }' "$OUT/fig17_cord/results.csv")"
  bench "fig17_generic_$name" --hands schunk_sah --objects "$obj" --planners generic \
    --repeats 10 --time-limit "$limit" --tests none --no-sheets
done

# Physics: the first grasp of each attempt through lift + shake in Bullet, both planners,
# per object set and hand (KIT at both scales).
for set in shipped kit kit_x2 ycb; do
  sc=1
  case $set in shipped) dir="$SHIPPED" ;; kit) dir="$KIT" ;; kit_x2) dir="$KIT"; sc=2 ;;
               ycb) dir="$YCB" ;; esac
  bench "physics_$set" --hands "$PHYS_HANDS" --objects "$dir" --planners cord,generic \
    --repeats "$PHYS_REPEATS" --scale "$sc" --tests lift,shake --no-sheets --settings "$paper"
done

end=$(date +%s)
load="$(cut -d' ' -f1-3 /proc/loadavg)"
mkdir -p "$IMG"
"$PY" "$ROOT/tools/results_report.py" --in-dir "$OUT" --mode "$MODE" --img-dir "$IMG" \
  --fig11-runs "$FIG11_RUNS" --phys-repeats "$PHYS_REPEATS" --phys-hands "$PHYS_HANDS" \
  --wall-s $((end - start)) --jobs "$JOBS" --load "$load" \
  --commit "$(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown)" \
  --notes "$ROOT/docs/results-notes.md" --out "$MD"
echo "wrote $MD (raw outputs in $OUT)" >&2
