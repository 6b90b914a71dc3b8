#!/bin/sh
# Regenerates the builder decks of samples/ (docs/mesher.md): `styk mesh NAME --param value -o DECK`.
# Usage: samples/make_mesher_samples.sh [path/to/styk]   (default: build/cli/styk)
set -e
STYK=${1:-build/cli/styk}
cd "$(dirname "$0")"
case "$STYK" in /*) ;; *) STYK="../$STYK" ;; esac
m() { out=$1; shift; "$STYK" mesh "$@" -o "$out"; }
for mesh in 6x1 12x2 12x4 24x8; do
  m spec-2.1-cantilever-c3d8-$mesh.inp cantilever --element C3D8 --mesh $mesh
done
for e in c3d14 c3d21 c3d28; do m spec-2.4-single-$e.inp single-element --element $e; done
m spec-3.1.1-straight-beam-c3d21-tension.inp straight-beam --element C3D21 --load tension
m spec-3.1.1-straight-beam-c3d28-bending.inp straight-beam --element C3D28 --load bending
m spec-3.1.2-beam-distorted-c3d21-bending.inp beam-10x2x2 --element C3D21 --mesh distorted --load bending
m spec-3.1.3-curved-beam-c3d21.inp curved-beam --element C3D21
m spec-3.1.4-twisted-c3d21.inp twisted-beam --element C3D21
m spec-3.1.4-twisted-c3d28.inp twisted-beam --element C3D28
m spec-3.1.5-thick-plate-c3d21-6x6.inp thick-plate --element C3D21 --n 6
m spec-3.1.6-hemisphere-c3d21.inp hemisphere --element C3D21
m spec-3.1.7-thick-cylinder-c3d21.inp thick-cylinder --element C3D21 --poisson 0.49
m spec-3.1.8-patch-c3d28.inp patch-test --element C3D28
m spec-6.1-electric-plate-c3d28-slit.inp electric-plate --element C3D28 --slit yes
m spec-6.1-electric-plate-cps4.inp electric-plate --element CPS4
m spec-6.2-cylinder-wall-c3d28.inp cylinder-wall --element C3D28
# Contact models (SPEC §3.2, §4): two bodies with coincident interface nodes, *CONTACT PAIR.
m spec-3.2.1-punch-foundation-c3d21.inp punch-foundation --element C3D21
m spec-3.2.1-punch-foundation-c3d28.inp punch-foundation --element C3D28
for e in c3d14 c3d21 c3d28; do m spec-3.2.2-cylinders-$e.inp cylinders --element $e; done
m spec-3.2.2-cylinders-c3d20.inp cylinders --element C3D20
m spec-3.2.3-two-cantilevers-c3d21-mu0.2.inp two-cantilevers --element C3D21 --mu 0.2
m spec-3.2.3-two-cantilevers-c3d20-mu0.inp two-cantilevers --element C3D20 --mu 0
m spec-3.2.4-punch-halfspace-c3d21-mu0.04.inp punch-halfspace --element C3D21 --mu 0.04
m spec-3.2.4-punch-halfspace-c3d28-mu0.04.inp punch-halfspace --element C3D28 --mu 0.04
m spec-3.2.4-punch-halfspace-c3d21-aniso.inp punch-halfspace --element C3D21 --mu 0.04 --mu2 0.4
m spec-4.2-shrink-fit-A-c3d21-axial.inp shrink-fit --model A --element C3D21 --load-case axial
m spec-4.2-shrink-fit-B-sector-c3d21-rotation.inp shrink-fit --model B --sector yes --element C3D21 --load-case rotation
m spec-4.3-conical-fit-c3d21-mu0.2.inp conical-fit --element C3D21 --mu 0.2
m spec-4.4-spline-joint-c3d21.inp spline-joint --element C3D21
m spec-4.5-p3g-joint-c3d21.inp p3g-joint --element C3D21
# SPEC §2.4 two stacked elements; §4.6 bolted flange (the builder solves once to calibrate the
# preload: about 25 s).
for e in c3d14 c3d21 c3d28; do m spec-2.4-stacked-$e.inp stacked-elements --element $e; done
m spec-4.6-bolted-flange-c3d21.inp bolted-flange --element C3D21
