#!/usr/bin/env bash
# Fuzzes the readers of untrusted files (docs/fuzzing.md): builds fuzz/ with clang, ASan and UBSan
# into build-fuzz/ (STYK_FUZZ=ON: the readers and the harnesses only), seeds one corpus per harness
# from samples/ and tests/inputs/, and runs each harness for SECONDS (default 60).
#   scripts/fuzz.sh [SECONDS] [HARNESS...]     harnesses: inp_reader dat_reader results_reader
#                                              msh_reader
# With STYK_FUZZ_RUNS=N each harness runs N inputs from a fixed random seed instead (the test
# command's short, repeatable run: scripts/run-tests.sh). STYK_FUZZ_RESEAL=1 makes the results
# harness seal each mutated file again, so mutations reach HDF5 behind the seal (docs/fuzzing.md).
# The corpora grow in build-fuzz/corpus/ from run to run. A finding (crash, sanitizer report,
# timeout, memory blow-up) stops with a non-zero exit and its input in build-fuzz/findings/; it
# becomes a regression input under tests/inputs/fuzz/ with the fix.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
harnesses=("$@")
if (( ${#harnesses[@]} == 0 )); then harnesses=(inp_reader dat_reader results_reader msh_reader); fi
build=${STYK_FUZZ_BUILD_DIR:-build-fuzz}

scripts/install-deps.sh --fuzz
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DSTYK_FUZZ=ON -DSTYK_GUI=OFF \
  -DSTYK_OSMESA=OFF -DSTYK_TESTS=OFF -DSTYK_PETSC=OFF -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" >/dev/null
cmake --build "$build" -j "${STYK_JOBS:-$(nproc)}" --target "${harnesses[@]/#/fuzz_}"

# Seeds: the inputs the tests use, small enough to mutate quickly (<= 64 KiB; results files, which
# are larger, <= 128 KiB), plus decks that
# *INCLUDE a part (the harness writes what follows "**FUZZ-INCLUDE" to part.inp).
seed() {  # harness, find pattern, largest size
  local dir="$build/corpus/$1"
  mkdir -p "$dir"
  find samples tests/inputs -type f -name "$2" -size "-$3" -print0 |
    while IFS= read -r -d '' f; do cp -n "$f" "$dir/$(echo "$f" | tr '/' '_')"; done
}
seed inp_reader '*.inp' 64k
seed dat_reader '*.dat' 64k
seed msh_reader '*.msh' 64k
# Results files: sealed ones only (docs/fuzzing.md). An unsealed seed (written before the seal) is
# parsed by HDF5 itself, and its mutations reach memory errors inside HDF5 that Styk cannot
# prevent; a sealed seed's mutations are refused by the seal before HDF5 reads a byte (unless
# STYK_FUZZ_RESEAL=1 seals them again: the harness' measurement mode).
mkdir -p "$build/corpus/results_reader"
find samples tests/inputs -type f -name '*.styk.h5' -size -128k -print0 |   # smallest ~75 KB
  while IFS= read -r -d '' f; do
    [[ "$(head -c 18 "$f" | tr -d '\0')" == "styk-results-seal " ]] || continue
    cp -n "$f" "$build/corpus/results_reader/$(echo "$f" | tr '/' '_')"
  done
for f in samples/spec-2.1-cantilever-c3d8-6x1.inp samples/cantilever-c3d20.inp; do
  [[ -f "$f" ]] || continue
  include_seed="$build/corpus/inp_reader/include_$(basename "$f")"
  { echo "*INCLUDE, INPUT=part.inp"; sed -n '/^\*STEP/,$p' "$f"; echo "**FUZZ-INCLUDE";
    sed '/^\*STEP/,$d' "$f"; } > "$include_seed"
done

mkdir -p "$build/findings"
# HDF5 asks malloc for whatever size a damaged file declares; in a normal build malloc returns
# NULL and HDF5 reports the file as unreadable (tests/inputs/fuzz/), so ASan must return NULL too
# instead of stopping on "allocation-size-too-big".
export ASAN_OPTIONS="allocator_may_return_null=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
# HDF5's own leaks on those error paths are not Styk's (fuzz/lsan.supp).
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
for h in "${harnesses[@]}"; do
  if [[ -n "${STYK_FUZZ_RUNS:-}" ]]; then echo "fuzz: $h, $STYK_FUZZ_RUNS runs" >&2
  else echo "fuzz: $h for $seconds s" >&2; fi
  max_len=65536
  if [[ "$h" == results_reader ]]; then max_len=131072; fi
  budget=(-max_total_time="$seconds")
  if [[ -n "${STYK_FUZZ_RUNS:-}" ]]; then budget=(-runs="$STYK_FUZZ_RUNS" -seed=1); fi
  if ! "$build/fuzz/fuzz_$h" "$build/corpus/$h" "${budget[@]}" -timeout=20 \
      -rss_limit_mb=4096 -max_len="$max_len" -print_final_stats=1 \
      -artifact_prefix="$build/findings/$h-" 2> "$build/findings/$h.log"; then
    echo "fuzz: $h found a problem; see $build/findings/$h.log and the input beside it" >&2
    tail -40 "$build/findings/$h.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/findings/$h.log" |
      sed "s/^/fuzz: $h: /" >&2
  fi
done
exit $status
