#!/usr/bin/env bash
# Installs missing Debian packages, configures, builds (Release, -j2) and runs the whole
# ctest suite (the sanitizer pass on request, below).
# Usage: tools/test.sh [--sanitize] [extra ctest args, e.g. -L unit]
#   --sanitize               only the sanitizer pass: builds with CORDGRASP_SANITIZE (ASan +
#                            UBSan) in build-asan/ and runs the labels unit, physics, robustness
#   CORDGRASP_SANITIZE_PASS=1  also run the sanitizer pass after the normal suite (off in CI:
#                            ~50 CPU-minutes of ASan build and tests on 2 cores would take
#                            the CI to about 40 of its 45 minutes)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CORDGRASP_BUILD_DIR:-$root/build}"
asan_build="${CORDGRASP_ASAN_BUILD_DIR:-$root/build-asan}"

sanitize_only=0
if [[ "${1:-}" == "--sanitize" ]]; then
  sanitize_only=1
  shift
fi

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

sanitizer_pass() {
  cmake -S "$root" -B "$asan_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCORDGRASP_SANITIZE=ON \
      -DCORDGRASP_BUILD_BENCH=OFF -DCORDGRASP_BUILD_PYTHON=OFF "${launcher[@]}" >/dev/null
  cmake --build "$asan_build" -j2
  # Leaks are not checked: Bullet's and OSMesa's process-lifetime allocations would drown them.
  (cd "$asan_build" &&
   ASAN_OPTIONS="detect_leaks=0:abort_on_error=0:halt_on_error=1" \
   UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
   ctest --output-on-failure -j2 -L 'unit|physics|robustness' "$@")
}

"$root/tools/install-deps.sh"
if [[ $sanitize_only == 1 ]]; then
  sanitizer_pass "$@"
  exit
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build "$build" -j2
(cd "$build" && ctest --output-on-failure -j2 "$@")
if [[ "${CORDGRASP_SANITIZE_PASS:-0}" == 1 && $# == 0 ]]; then
  sanitizer_pass
fi
