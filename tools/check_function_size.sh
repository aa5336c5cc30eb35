#!/usr/bin/env bash
# No product function over 100 lines: clang-tidy-14's readability-function-size (LineThreshold
# 100, nothing else) over every .cc file of the product (not tests/ or bench/), compiled as
# BUILD_DIR/compile_commands.json says (the first argument, else build). Prints each function
# over the limit and exits 1; exits 2 if clang-tidy-14 or the compile database is missing, or a
# file does not parse. A long function is split into short helpers. About 5 min on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
tidy=clang-tidy-14
build=${1:-build}
if ! command -v "$tidy" > /dev/null 2>&1; then
  echo "check_function_size: $tidy not found; tools/setup.sh installs it" >&2
  exit 2
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "check_function_size: $build/compile_commands.json not found; configure the build first" >&2
  exit 2
fi

dirs=(core optim statics design truss dynamics bridge checks io sizing sweep export app tools python)
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files "${dirs[@]/%//*.cc}")
else
  mapfile -t files < <(find "${dirs[@]}" -name '*.cc')
fi

# Two files at a time: the check parses each file in full, and CI has two cores. The
# compiler's warnings are left to the build (-w): under -Werror clang would stop a file on a
# warning g++ does not give (-Wshadow of a field), and the file would go unchecked.
config='{Checks: "-*,readability-function-size",
         CheckOptions: [{key: readability-function-size.LineThreshold, value: 100}]}'
status=0
report=$(printf '%s\n' "${files[@]}" |
  xargs -P2 -n1 "$tidy" -p "$build" --quiet --extra-arg=-w --config="$config" 2>&1) || status=$?

# "FILE:LINE:COL: warning: function 'NAME' exceeds ..." then "FILE:LINE:COL: note: N lines
# including whitespace and comments (threshold 100)": one line per function, "FILE FUNCTION
# LINE N".
mapfile -t long < <(printf '%s\n' "$report" | awk -v root="$PWD/" '
  / warning: function .* exceeds recommended size/ {
    split($0, at, ":"); file = at[1]; line = at[2]; sub("^" root, "", file)
    name = $0; sub(/^.* warning: function \047/, "", name); sub(/\047 exceeds.*$/, "", name)
  }
  / note: [0-9]+ lines including whitespace/ && name != "" {
    n = $0; sub(/^.* note: /, "", n); sub(/ lines.*$/, "", n)
    print file " " name " " line " " n; name = ""
  }' | sort -u)
# A file clang-tidy cannot parse is not checked: that fails as a missing tool does.
if [ "$status" -ne 0 ]; then
  echo "check_function_size: $tidy failed (exit $status):" >&2
  printf '%s\n' "$report" | grep -E 'error:|Error' >&2 || printf '%s\n' "$report" >&2
  exit 2
fi

for f in "${long[@]}"; do
  read -r file name line n <<< "$f"
  echo "check_function_size: $file:$line: $name is $n lines (limit 100)" >&2
done
if [ "${#long[@]}" -gt 0 ]; then
  exit 1
fi
echo "check_function_size: no function over 100 lines in ${#files[@]} files"
