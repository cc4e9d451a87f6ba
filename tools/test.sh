#!/usr/bin/env bash
# Installs missing Debian packages, configures, builds (Release, -j2) and runs the whole ctest
# suite, then the sanitizer pass: an ASan + UBSan build (RelWithDebInfo, build-asan/) running
# the labels unit, physics and robustness but not dataset. With clang (install-deps installs
# it) that build is clang's, with the parsers' libFuzzer targets (CORDGRASP_FUZZ), and also runs
# the label fuzz: each target fuzzes from its seed corpus for a fixed number of inputs. Without
# clang it is GCC's, without fuzzing. A sanitizer report or a fuzzing finding fails the run.
# Usage: tools/test.sh [--sanitize | --no-sanitize] [extra ctest args, e.g. -L unit]
#   --sanitize      only the sanitizer pass
#   --no-sanitize   only the Release suite (a quick local run)
#   extra ctest args apply to the pass(es) run; with them the sanitizer pass is skipped unless
#   asked for (--sanitize)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CORDGRASP_BUILD_DIR:-$root/build}"
asan_build="${CORDGRASP_ASAN_BUILD_DIR:-$root/build-asan}"

sanitize_only=0
sanitize=1
if [[ "${1:-}" == "--sanitize" ]]; then
  sanitize_only=1
  shift
elif [[ "${1:-}" == "--no-sanitize" ]]; then
  sanitize=0
  shift
fi

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

sanitizer_pass() {
  local compiler=() labels='unit|physics|robustness' what="GCC's"
  if command -v clang++ >/dev/null; then
    # clang compiles the sanitized build in about half GCC's CPU time and brings libFuzzer.
    compiler=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCORDGRASP_FUZZ=ON)
    labels='unit|physics|robustness|fuzz'
    what="clang's, with the fuzz targets"
  fi
  echo "test.sh: sanitizer pass (ASan + UBSan, $what, $asan_build): labels $labels" \
       "without dataset (the shipped hands and objects run the same code)" >&2
  if [[ -f "$asan_build/CMakeCache.txt" ]] &&
     ! grep -q "CORDGRASP_FUZZ:BOOL=$([[ ${#compiler[@]} -gt 0 ]] && echo ON || echo OFF)" \
          "$asan_build/CMakeCache.txt"; then
    rm -rf "$asan_build"  # configured with the other compiler: start again
  fi
  # -g1: line tables only, enough for the sanitizers' stack traces (file:line) and cheaper to
  # compile and link than -g's full debug information.
  cmake -S "$root" -B "$asan_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCORDGRASP_SANITIZE=ON \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
      -DCORDGRASP_BUILD_BENCH=OFF -DCORDGRASP_BUILD_PYTHON=OFF "${compiler[@]}" "${launcher[@]}" \
      >/dev/null
  cmake --build "$asan_build" -j2
  # Leaks are not checked: Bullet's and OSMesa's process-lifetime allocations would drown them
  # (the fuzz tests check them, with tests/fuzz/lsan.supp).
  (cd "$asan_build" &&
   ASAN_OPTIONS="detect_leaks=0:abort_on_error=0:halt_on_error=1" \
   UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
   ctest --output-on-failure -j2 -L "$labels" -LE dataset "$@")
}

"$root/tools/install-deps.sh"
if [[ $sanitize_only == 1 ]]; then
  sanitizer_pass "$@"
  exit
fi
echo "test.sh: Release build ($build): the whole suite" >&2
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build "$build" -j2
(cd "$build" && ctest --output-on-failure -j2 "$@")
if [[ $sanitize == 1 && $# == 0 ]]; then
  sanitizer_pass
else
  echo "test.sh: sanitizer pass skipped (--no-sanitize or ctest arguments given)" >&2
fi
