#!/usr/bin/env bash
# Every C++ file of the project as .clang-format says, by clang-format-14 (the version
# tools/setup.sh installs: another version formats some constructs otherwise). Lists each file
# that differs and exits 1; fix with `clang-format-14 -i FILE`.
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=clang-format-14
if ! command -v "$formatter" > /dev/null 2>&1; then
  echo "check_format: $formatter not found; tools/setup.sh installs it" >&2
  exit 2
fi
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cc' '*.h')
else
  mapfile -t files < <(find . -path ./build -prune -o \( -name '*.cc' -o -name '*.h' \) -print)
fi
# One run over every file; its diagnostics ("FILE:LINE:COL: error: code should be
# clang-formatted") name the files that differ. Any other failure (a broken .clang-format) is
# shown as it is.
status=0
report=$("$formatter" --dry-run --Werror "${files[@]}" 2>&1) || status=$?
mapfile -t differ < <(printf '%s\n' "$report" |
  sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u)
if [ "$status" -ne 0 ] && [ "${#differ[@]}" -eq 0 ]; then
  echo "check_format: $formatter failed (exit $status):" >&2
  printf '%s\n' "$report" >&2
  exit 2
fi
if [ "${#differ[@]}" -gt 0 ]; then
  echo "check_format: ${#differ[@]} of ${#files[@]} files differ from .clang-format:" >&2
  printf '  %s\n' "${differ[@]}" >&2
  exit 1
fi
echo "check_format: all ${#files[@]} files as .clang-format says"
