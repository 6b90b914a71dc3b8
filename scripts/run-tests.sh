#!/usr/bin/env bash
# Every test: install what is missing (with the test peers, e.g. CalculiX), build everything, run
# the whole suite through ctest, then a short fuzzing run of the readers. Idempotent; safe to run
# again.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
scripts/build.sh
ctest --test-dir "${STYK_BUILD_DIR:-build}" --output-on-failure -j "${STYK_JOBS:-$(nproc)}"
# The readers under libFuzzer with ASan and UBSan (docs/fuzzing.md): a short, repeatable run of
# every harness (fixed seed and number of inputs); longer runs: scripts/fuzz.sh SECONDS.
STYK_FUZZ_RUNS="${STYK_FUZZ_RUNS:-4000}" scripts/fuzz.sh
