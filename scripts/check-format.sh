#!/usr/bin/env bash
# Checks that every C++ source in the repository is laid out as .clang-format says (generated
# third-party code opts out through its own .clang-format). Prints the offending files and exits 1.
# Usage: scripts/check-format.sh [--fix]   (--fix rewrites the files in place instead)
set -euo pipefail
cd "$(dirname "$0")/.."
formatter="${STYK_CLANG_FORMAT:-clang-format-14}"
if ! command -v "$formatter" >/dev/null; then
  echo "check-format: $formatter not found (scripts/install-deps.sh --test installs it)" >&2
  exit 1
fi
mapfile -t sources < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc')
if [[ "${1:-}" == "--fix" ]]; then
  "$formatter" -i "${sources[@]}"
  exit 0
fi
# One formatter run over all files (a process per file takes minutes); its diagnostics name the
# files that differ.
mapfile -t unformatted < <("$formatter" --dry-run "${sources[@]}" 2>&1 |
                           sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: \(warning\|error\):.*/\1/p' | sort -u)
if (( ${#unformatted[@]} > 0 )); then
  printf 'check-format: not formatted as .clang-format says (fix: scripts/check-format.sh --fix):\n' >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "check-format: ${#sources[@]} files formatted"
