#!/usr/bin/env bash
# Draws the six regions the cord planner tries first on an object, in two orders: by χ alone
# and by (missed side cords, χ), the order of the `fallback` side-cord default
# (docs/algorithm.md §4 and §10). One PNG, the two contact sheets one above the other.
#
#   tools/region_order_sheet.sh OBJECT SCALE SEED OUT.png   (hand: schunk_sah)
#
# Environment: CORDGRASP (default build/tools/cordgrasp), PYTHON (default /usr/bin/python3,
# with python3-matplotlib).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
CG="${CORDGRASP:-$ROOT/build/tools/cordgrasp}"
PY="${PYTHON:-/usr/bin/python3}"
OBJ="$1"; SCALE="$2"; SEED="$3"; OUT="$4"
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
"$CG" explore --hand schunk_sah --object "$OBJ" --scale "$SCALE" --seed "$SEED" \
  --json "$TMP/regions.json" --top 0 > /dev/null
"$PY" - "$TMP" <<'PY'
import json, sys
d = sys.argv[1]
j = json.load(open(f"{d}/regions.json"))
missed = lambda r: sum(1 for c in r["front_cords"] if not c)
for name, key in (("chi", lambda r: r["chi_m2"]), ("missed", lambda r: (missed(r), r["chi_m2"]))):
    regions = sorted(j["regions"], key=key)
    json.dump(dict(j, regions=regions), open(f"{d}/{name}.json", "w"))
    with open(f"{d}/{name}.txt", "w") as f:
        f.write(", ".join(f"{missed(r)}/{len(r['front_cords'])}" for r in regions[:6]))
PY
for o in chi missed; do
  "$CG" render --regions "$TMP/$o.json" --scale "$SCALE" --sheet 6 --size 260x200 \
    --out "$TMP/$o.png" > /dev/null
done
"$PY" - "$TMP" "$OUT" "$(basename "$OBJ" .obj)" "$SCALE" "$SEED" <<'PY'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mi
import matplotlib.pyplot as plt
d, out, name, scale, seed = sys.argv[1:6]
titles = {"chi": "by χ alone",
          "missed": "by missed side cords, then χ (the fallback default)"}
fig, axes = plt.subplots(2, 1, figsize=(8.6, 11))
for ax, o in zip(axes, ("chi", "missed")):
    img = mi.imread(f"{d}/{o}.png")
    ax.imshow(img[int(img.shape[0] * 0.09):])   # drop the sheet's own title line
    ax.axis("off")
    missed = open(f"{d}/{o}.txt").read()
    ax.set_title(f"{name} ×{scale}, seed {seed}: first six regions {titles[o]}\n"
                 f"missed cords / cords: {missed}", fontsize=10)
fig.tight_layout()
fig.savefig(out, dpi=80)
PY
echo "wrote $OUT" >&2
