#!/usr/bin/env bash
# Builds Styk with AddressSanitizer and UndefinedBehaviorSanitizer (STYK_SANITIZE=ON) into
# build-asan/ and runs the tests there through ctest (docs/fuzzing.md "Sanitized test runs").
#   scripts/sanitize.sh                  every test (long: the whole tree instrumented)
#   scripts/sanitize.sh -L unit          one CTest label (unit, verification, cli, ccx, ...)
#   scripts/sanitize.sh -R 'Seal|Inp'    any other ctest selection
# The arguments go to ctest. STYK_ASAN_TARGETS="a b" builds only those targets (the suites the
# selection runs and what they call, e.g. "styk styk_io_tests"); otherwise everything is built.
# A sanitizer report fails the test that caused it (halt_on_error), and ctest's exit code is the
# script's.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${STYK_ASAN_BUILD_DIR:-build-asan}
jobs=${STYK_JOBS:-$(nproc)}

scripts/install-deps.sh --test
# Configured every time (a few seconds), so that a build directory made before the GUI was
# included gets it too. RelWithDebInfo: -O2 keeps the suites' run time reasonable, -g names the
# lines in reports.
generator=()
[[ -f "$build/CMakeCache.txt" ]] || generator=(-G Ninja)
cmake -S . -B "$build" "${generator[@]}" -DSTYK_SANITIZE=ON -DSTYK_GUI=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo ${STYK_CMAKE_ARGS:-} >/dev/null
targets=()
for target in ${STYK_ASAN_TARGETS:-}; do targets+=(--target "$target"); done
cmake --build "$build" -j "$jobs" "${targets[@]}"

# As in the fuzzing runs (docs/fuzzing.md): HDF5 asks malloc for whatever size a damaged file
# declares and reports the file unreadable when malloc returns NULL (the regression file of
# FuzzRegressions.EveryFoundInputIsRefusedByName does this), so ASan returns NULL too instead of
# stopping; HDF5's own leaks on those error paths are suppressed, Styk's are reported.
export ASAN_OPTIONS="halt_on_error=1:allocator_may_return_null=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
# print_suppressions=0: the suppressed leaks' summary would land in the stderr of the child
# `styk` processes whose output the command-line tests compare.
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
# Open MPI's libraries are built without frame pointers, and its plug-ins are unloaded at
# MPI_Finalize: with the fast unwinder a leak they hold until exit shows one unnamed frame, which
# no suppression can match. The slow unwinder walks through libmpi and names it. (Suites that draw
# through Mesa go back to the fast unwinder: tests/CMakeLists.txt, styk_sanitize_environment.)
export ASAN_OPTIONS="$ASAN_OPTIONS:fast_unwind_on_malloc=0"
ctest --test-dir "$build" --output-on-failure -j "$jobs" "$@"
