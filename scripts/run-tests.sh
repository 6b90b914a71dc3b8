#!/usr/bin/env bash
# Every test: install what is missing (with the test peers, e.g. CalculiX), build everything and
# run the whole suite through ctest. Idempotent; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
scripts/build.sh
ctest --test-dir "${STYK_BUILD_DIR:-build}" --output-on-failure -j "${STYK_JOBS:-$(nproc)}"
