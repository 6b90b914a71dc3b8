#!/usr/bin/env bash
# Configures (once) and builds Styk into build/ with Ninja. Extra arguments go to `cmake --build`.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STYK_BUILD_DIR:-build}
if [[ ! -f "$build_dir/build.ninja" ]]; then
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release ${STYK_CMAKE_ARGS:-}
fi
cmake --build "$build_dir" -j "${STYK_JOBS:-$(nproc)}" "$@"
