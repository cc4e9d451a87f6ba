#!/usr/bin/env bash
# Installs every Debian package cordgrasp needs (Debian 12). Idempotent: quiet when all present.
set -euo pipefail

PKGS=(
  build-essential cmake pkg-config git
  libbullet-dev libbullet-extras-dev     # Bullet incl. double-precision (bullet-float64) + HACD
  libmeshoptimizer-dev                    # HACD's input: a simplified copy of a large mesh
  libeigen3-dev
  liburdfdom-dev liburdfdom-headers-dev
  libassimp-dev
  libosmesa6-dev
  libqhull-dev                            # reentrant qhull_r + qhullcpp
  libglpk-dev                             # GLPK: the weight margin's linear program
  libcli11-dev
  libpolyclipping-dev                     # Clipper 6.4.2, for the XOR measure
  nlohmann-json3-dev
  libpng-dev
  libfreetype-dev fonts-dejavu-core      # render: caption text (FreeType + DejaVu Sans)
  libyaml-cpp-dev                         # hand description files
  libembree-dev                           # ray queries on large meshes
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev
  python3 python3-dev pybind11-dev       # the Python module (tools/python)
  python3-numpy python3-pytest            # its arrays and its test suite
  python3-matplotlib                      # tools/results.sh: the plots of docs/results.md
  libmujoco-dev                           # tests/export and mujoco_check: MuJoCo 2.2.2
  clang                                   # CORDGRASP_FUZZ=ON: the parsers' libFuzzer targets
  libclang-rt-14-dev                      # clang 14's libFuzzer, ASan and UBSan runtimes
  libwebp-dev                             # render: animated WebP of the physics (WebPAnimEncoder)
  libjs-three                             # report.html: three.js r111 for the 3D view (copied)
  chromium                                # the `browser` tests: report.html in headless Chromium
  parallel                                # GNU parallel: bench shards on many cores (tests/shard)
)

missing=()
for p in "${PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
