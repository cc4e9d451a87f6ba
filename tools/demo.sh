#!/usr/bin/env bash
# Installs missing Debian packages, builds (Release, -j2) and runs the main job on the shipped
# default hand and object. Usage: tools/demo.sh [output dir, default ./demo-out]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CORDGRASP_BUILD_DIR:-$root/build}"
out="${1:-$PWD/demo-out}"
"$root/tools/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target cordgrasp
mkdir -p "$out"
"$build/tools/cordgrasp" info --hand cordgrasp_sah | tee "$out/hand-info.txt"
"$build/tools/cordgrasp" info --object "$root/assets/objects/mug.obj" | tee "$out/object-info.txt"
echo "demo: outputs in $out"
