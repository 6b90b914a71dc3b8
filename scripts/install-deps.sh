#!/usr/bin/env bash
# Installs the Debian 12 packages Styk needs. Idempotent: apt-get skips what is present, and the
# package index is refreshed only when a package is missing.
# Usage: scripts/install-deps.sh [--test] [--fuzz]   (--test adds the test-only peers: calculix-ccx
# and its test suite, time, gmsh (meshes for the import tests), clang-format and clang-tidy
# (scripts/check-format.sh, scripts/check-tidy.sh); --fuzz adds clang and its libFuzzer /
# sanitizer runtimes: scripts/fuzz.sh; --memcheck adds valgrind: docs/fuzzing.md)
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config ccache make
  libeigen3-dev libsuitesparse-dev libopenblas-dev libmetis-dev
  petsc-dev openmpi-bin
  libhdf5-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev
  libosmesa6-dev libgl-dev libglx-dev libpng-dev libstb-dev zlib1g-dev qt6-base-dev libqt6opengl6-dev qt6-charts-dev
  libfreetype-dev fonts-dejavu-core
)
for option in "$@"; do
  case "$option" in
    --test) packages+=(calculix-ccx calculix-ccx-test time python3 xvfb xauth python3-meshio clang-format-14 clang-tidy-14
                       python3-h5py gmsh) ;;
    --fuzz) packages+=(clang libclang-rt-14-dev) ;;
    --memcheck) packages+=(valgrind) ;;
    *) echo "install-deps: unknown option $option (use --test, --fuzz, --memcheck)" >&2; exit 1 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if (( ${#missing[@]} == 0 )); then
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
