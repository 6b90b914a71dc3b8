#!/usr/bin/env bash
# Mises pictures of the SPEC §4.2 shrink fit after the frictionless heating (model A, the quarter,
# default mesh): the plain fit and the notched variants I and II (stand-ins for the thesis' lost
# Fig 4.21 / 4.23), one colour scale for all three, into docs/images/joints/ (docs/joints.md).
# Usage: scripts/render-shrink-fit-variants.sh [STYK] (default build/cli/styk)
set -euo pipefail
cd "$(dirname "$0")/.."
styk=${1:-build/cli/styk}
out=docs/images/joints
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
for notch in none I II; do
  name=shrink-fit-mises-$([[ $notch == none ]] && echo plain || echo "notch-$notch")
  "$styk" mesh shrink-fit --model A --load-case fit --mu 0 --notch "$notch" -o "$work/$name.inp"
  "$styk" solve "$work/$name.inp" -o "$work" > "$work/$name.log"
  "$styk" render "$work/$name.styk.h5" --field S.mises --deform none --range 0,400 \
    --zoom 1.5 --size 1200x900 -o "$out/$name.png"
done
