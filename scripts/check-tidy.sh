#!/usr/bin/env bash
# Runs clang-tidy (the checks of .clang-tidy) on Styk's C++ sources, with the compile commands of
# a configured build (build/compile_commands.json; scripts/build.sh writes it).
#   scripts/check-tidy.sh [BASE]     the .cpp files changed against BASE (default origin/main, else
#                                    main), plus the .cpp files beside a changed header
#   scripts/check-tidy.sh --all      every .cpp file in the compile commands (a pre-release check:
#                                    docs/fuzzing.md "Static checks" gives its time)
# Exits non-zero on any finding (WarningsAsErrors in .clang-tidy). STYK_JOBS sets the parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${STYK_BUILD_DIR:-build}
jobs=${STYK_JOBS:-$(nproc)}
tidy=$(command -v clang-tidy-14 || command -v clang-tidy || true)
if [[ -z "$tidy" ]]; then
  echo "check-tidy: clang-tidy not found (scripts/install-deps.sh --test installs clang-tidy-14)" >&2
  exit 1
fi
if [[ ! -f "$build/compile_commands.json" ]]; then
  echo "check-tidy: $build/compile_commands.json is missing: configure first (scripts/build.sh)" >&2
  exit 1
fi

# The project's own translation units in the compile commands (not the build tree's generated
# files, not the fuzz harnesses, which only the clang fuzz build compiles).
all_units() {
  python3 - "$build/compile_commands.json" "$PWD" <<'PY'
import json, os, sys
root = sys.argv[2]
for entry in json.load(open(sys.argv[1])):
    path = os.path.realpath(os.path.join(entry["directory"], entry["file"]))
    if path.startswith(root + "/") and "/build" not in path[len(root):]:
        print(os.path.relpath(path, root))
PY
}

if [[ "${1:-}" == "--all" ]]; then
  mapfile -t files < <(all_units | sort -u)
else
  base=${1:-$(git rev-parse --verify -q origin/main >/dev/null && echo origin/main || echo main)}
  mapfile -t changed < <(git diff --name-only --diff-filter=ACMR "$(git merge-base "$base" HEAD)" \
    -- '*.cpp' '*.hpp'; git ls-files --others --exclude-standard -- '*.cpp' '*.hpp')
  mapfile -t known < <(all_units | sort -u)
  declare -A wanted=()
  for f in "${changed[@]}"; do
    # A changed header is checked through the .cpp files of its directory and the one beside it.
    case "$f" in
      *.cpp) wanted["$f"]=1 ;;
      *.hpp) for k in "${known[@]}"; do
               [[ "$(dirname "$k")" == "$(dirname "$f")" || "$k" == "${f%.hpp}.cpp" ]] && wanted["$k"]=1
             done ;;
    esac
  done
  files=()
  for k in "${known[@]}"; do [[ -n "${wanted[$k]:-}" ]] && files+=("$k"); done
fi
if (( ${#files[@]} == 0 )); then
  echo "check-tidy: no C++ files to check" >&2
  exit 0
fi
echo "check-tidy: ${#files[@]} files, $jobs at a time" >&2
start=$(date +%s)
status=0
printf '%s\0' "${files[@]}" |
  xargs -0 -P "$jobs" -n 1 "$tidy" -p "$build" --quiet 2>/dev/null || status=$?
echo "check-tidy: $(( $(date +%s) - start )) s" >&2
exit $status
