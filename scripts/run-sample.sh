#!/usr/bin/env bash
# The main job: install what is missing, build, solve the sample cantilever, render its Mises
# stress headless to a PNG and say where the results went. Idempotent; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh --target styk
out=${STYK_OUT:-out/sample}
mkdir -p "$out"
build/cli/styk solve samples/cantilever-c3d20.inp -o "$out"
build/cli/styk export "$out/cantilever-c3d20.styk.h5" --vtu -o "$out/cantilever-c3d20.vtu"
build/cli/styk render "$out/cantilever-c3d20.styk.h5" --field S.mises --averaging I --bands 12 \
  --deform auto --view iso --size 1600x1200 -o "$out/cantilever-c3d20-mises.png"
echo "sample solved: results in $out/ (cantilever-c3d20.styk.h5, .dat, .vtu, -mises.png)"
