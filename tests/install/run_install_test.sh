#!/usr/bin/env bash
# Installs the build tree BUILD into a temporary prefix, then configures, builds, installs and
# runs the consumer project tests/install against it (only the installed package, headers and
# assets). Also runs the installed `cordgrasp` and imports the installed Python module.
# Usage: run_install_test.sh BUILD_DIR [PYTHON]
set -euo pipefail
build="$1"
python="${2:-}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"

cmake --install "$build" --prefix "$prefix" >/dev/null
unset CORDGRASP_ASSETS_DIR
cmake -S "$here" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
    >/dev/null
cmake --build "$tmp/consumer" -j2 >/dev/null
cmake --install "$tmp/consumer" --prefix "$prefix" >/dev/null
out="$("$prefix/bin/cordgrasp-consumer")"
echo "$out"
grep -qx "assets $prefix/share/cordgrasp" <<<"$out" || { echo "not the installed assets"; exit 1; }
grep -q '^grasp 0: epsilon' <<<"$out"

# The installed command finds the installed assets too.
"$prefix/bin/cordgrasp" info --hand cordgrasp_sah | grep -q "$prefix/share/cordgrasp"
if [ -n "$python" ] && [ -d "$prefix"/lib/python3*/dist-packages/cordgrasp ]; then
  PYTHONPATH="$(echo "$prefix"/lib/python3*/dist-packages)" "$python" -c "
import cordgrasp, sys
assert cordgrasp.assets_dir() == '$prefix/share/cordgrasp', cordgrasp.assets_dir()
print('python: assets', cordgrasp.assets_dir())"
fi
echo "install test: ok"
