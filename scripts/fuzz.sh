#!/usr/bin/env bash
# Fuzzes the readers of untrusted files (docs/fuzzing.md): builds fuzz/ with clang, ASan and UBSan
# into build-fuzz/ (STYK_FUZZ=ON: the readers and the harnesses only), seeds one corpus per harness
# from samples/ and tests/inputs/, and runs each harness for SECONDS (default 60).
#   scripts/fuzz.sh [SECONDS] [HARNESS...]     harnesses: inp_reader dat_reader results_reader
# The corpora grow in build-fuzz/corpus/ from run to run. A finding (crash, sanitizer report,
# timeout, memory blow-up) stops with a non-zero exit and its input in build-fuzz/findings/; it
# becomes a regression input under tests/inputs/fuzz/ with the fix.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
harnesses=("$@")
if (( ${#harnesses[@]} == 0 )); then harnesses=(inp_reader dat_reader results_reader); fi
build=${STYK_FUZZ_BUILD_DIR:-build-fuzz}

scripts/install-deps.sh --fuzz
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DSTYK_FUZZ=ON -DSTYK_GUI=OFF \
  -DSTYK_OSMESA=OFF -DSTYK_TESTS=OFF -DSTYK_PETSC=OFF -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" >/dev/null
cmake --build "$build" -j "${STYK_JOBS:-$(nproc)}" --target "${harnesses[@]/#/fuzz_}"

# Seeds: the inputs the tests use, small enough to mutate quickly (<= 64 KiB), plus decks that
# *INCLUDE a part (the harness writes what follows "**FUZZ-INCLUDE" to part.inp).
seed() {  # harness, find pattern
  local dir="$build/corpus/$1"
  mkdir -p "$dir"
  find samples tests/inputs -type f -name "$2" -size -64k -print0 |
    while IFS= read -r -d '' f; do cp -n "$f" "$dir/$(echo "$f" | tr '/' '_')"; done
}
seed inp_reader '*.inp'
seed dat_reader '*.dat'
seed results_reader '*.styk.h5'
for f in samples/spec-2.1-cantilever-c3d8-6x1.inp samples/cantilever-c3d20.inp; do
  [[ -f "$f" ]] || continue
  include_seed="$build/corpus/inp_reader/include_$(basename "$f")"
  { echo "*INCLUDE, INPUT=part.inp"; sed -n '/^\*STEP/,$p' "$f"; echo "**FUZZ-INCLUDE";
    sed '/^\*STEP/,$d' "$f"; } > "$include_seed"
done

mkdir -p "$build/findings"
status=0
for h in "${harnesses[@]}"; do
  echo "fuzz: $h for ${seconds} s" >&2
  if ! "$build/fuzz/fuzz_$h" "$build/corpus/$h" -max_total_time="$seconds" -timeout=20 \
      -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
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
