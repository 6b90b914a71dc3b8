#!/usr/bin/env bash
# Every test: install what is missing (with the test peers, e.g. CalculiX), check the source layout
# (scripts/check-format.sh), build everything, run the whole suite through ctest, then a short
# fuzzing run of the readers. Idempotent; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
scripts/check-format.sh
scripts/build.sh
ctest --test-dir "${STYK_BUILD_DIR:-build}" --output-on-failure -j "${STYK_JOBS:-$(nproc)}"
# The readers under libFuzzer with ASan and UBSan (docs/fuzzing.md): a short, repeatable run
# (fixed seed and number of inputs) of every harness; the results-file harness is seeded with
# sealed files only, so its mutations stay within what Styk controls (the seal is verified before
# HDF5 reads a byte).
STYK_FUZZ_RUNS="${STYK_FUZZ_RUNS:-4000}" scripts/fuzz.sh 0 inp_reader dat_reader results_reader \
  msh_reader
