#!/usr/bin/env bash
# Installs missing Debian packages, builds (Release, -j2) and runs the main job on the shipped
# default hand (cordgrasp_sah) and object (mug): plan three grasps with the cord planner that
# hold in Bullet (validated planning: held through lift and shake in >= 2 of 3 trials, pairwise
# different), render them with their physics frames. Usage: tools/demo.sh [output dir, default ./demo-out]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CORDGRASP_BUILD_DIR:-$root/build}"
out="${1:-$PWD/demo-out}"
"$root/tools/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target cordgrasp
"$build/tools/cordgrasp" run --out-dir "$out"
echo "demo: outputs in $out (open $out/report.html in a browser, or $out/report.md)"
