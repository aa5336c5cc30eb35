#!/usr/bin/env bash
# One formula, one place: each formula named below is written once in the product, in the file
# beside its name, and every other place calls that definition. Each is found by the
# characteristic expression it is written as (grep -E, one line); a second line that matches,
# anywhere in the product's rooms, fails, naming file and line, and so does a definition that is
# gone, since a pattern that finds nothing guards nothing. `--self-test` plants a second copy of
# each expression in a scratch tree and fails unless every one is caught.
#
# usage: tools/check_one_definition.sh [ROOT]   (default: this source tree)
#        tools/check_one_definition.sh --self-test
set -euo pipefail

names=()
homes=()
patterns=()
define() {
  names+=("$1")
  homes+=("$2")
  patterns+=("$3")
}
# The string tangent block k u u^T + q (I - u u^T): its outer product of a direction u u^T
# (a one-letter vector or a unit_ one; a least-squares row's outer product is not this).
define "string tangent block (u u^T)" core/tangent_blocks.h \
  '([a-z]|unit[A-Za-z_]*(\[[^]]*\])?) \* \1\.transpose\(\)'
# The mass breakdown: the members' masses by kind, and the structure from the kinds.
define "mass breakdown (members by kind)" design/design.cc \
  'strings\) *\+= *[A-Za-z_.]*mass\>'
define "mass breakdown (structure)" design/design.cc \
  'bars \+ [^;]*strings \+ [^;]*deck_strings'
# A member from its area: radius, mass, rest length and the two forms of a string's stiffness
# (an area: any name holding "area", or a one-letter a or da).
area='[A-Za-z_.]*(area[A-Za-z_]*|\<d?a)(\[[^]]*\])?'
modulus='(youngs_modulus|modulus|\<E)'
define "member from area (radius)" core/member_area.h \
  'sqrt\([^;]*/ *(std::numbers::pi|M_PI|kPi)\)'
define "member from area (mass rho A l)" core/member_area.h \
  "density \\* ${area} \\*"
define "member from area (stiffness E A / L0)" core/member_area.h \
  "${modulus} \\* ${area} / [A-Za-z_.]*(length|rest)"
define "member from area (stiffness (E A + T) / L)" core/member_area.h \
  "${modulus} \\* ${area} \\+ [^;]*\\) / "
define "member from area (rest length)" core/member_area.h \
  "/ \\(1(\\.0)? \\+ [^;]*${modulus}"

rooms=(core optim statics design truss dynamics bridge checks io sizing sweep export app tools python)

# Checks the tree at $1; names each formula written more than once or not at all, and returns 1
# when there is one.
check() {
  local root=$1 status=0 i hits count where
  for i in "${!names[@]}"; do
    hits=$(cd "$root" && for room in "${rooms[@]}"; do
      [ -d "$room" ] || continue
      find "$room" -name '*.cc' -o -name '*.h'
    done | sort | while IFS= read -r file; do
      # Comments may state a formula; only code defines one.
      sed 's://.*$::' "$file" | grep -nE -- "${patterns[$i]}" | sed "s|^|$file:|" || true
    done)
    count=$(printf '%s' "$hits" | grep -c . || true)
    where=${hits%%:*}
    if [ "$count" -eq 1 ] && [ "$where" = "${homes[$i]}" ]; then
      continue
    fi
    status=1
    if [ "$count" -eq 0 ]; then
      echo "check_one_definition: ${names[$i]}: no definition found (expected in ${homes[$i]})" >&2
    else
      echo "check_one_definition: ${names[$i]}: written $count times (its one place: ${homes[$i]}):" >&2
      printf '%s\n' "$hits" | sed 's/^/  /' >&2
    fi
  done
  return "$status"
}

# Plants, one formula at a time, a copy of its defining line in another room of a scratch tree
# that holds the definitions, and requires the check to fail naming that formula.
self_test() {
  local source=$1 scratch i line out failed=0
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' RETURN
  for i in "${!names[@]}"; do
    mkdir -p "$scratch/$(dirname "${homes[$i]}")"
    cp "$source/${homes[$i]}" "$scratch/${homes[$i]}"
  done
  if ! check "$scratch" 2> /dev/null; then
    echo "check_one_definition --self-test: the definitions alone do not pass" >&2
    return 1
  fi
  mkdir -p "$scratch/checks"
  for i in "${!names[@]}"; do
    line=$(sed 's://.*$::' "$source/${homes[$i]}" | grep -E -- "${patterns[$i]}" | sed -n 1p)
    printf '%s\n' "$line" > "$scratch/checks/planted.cc"
    if out=$(check "$scratch" 2>&1); then
      echo "check_one_definition --self-test: a second ${names[$i]} was not caught" >&2
      failed=1
    elif [[ "$out" != *"${names[$i]}: written 2 times"* ]]; then
      echo "check_one_definition --self-test: a second ${names[$i]} was reported as: $out" >&2
      failed=1
    fi
  done
  rm -f "$scratch/checks/planted.cc"
  [ "$failed" -eq 0 ] && echo "check_one_definition --self-test: each of ${#names[@]} second copies caught"
  return "$failed"
}

here=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "--self-test" ]; then
  self_test "$here"
  exit $?
fi
if check "${1:-$here}"; then
  echo "check_one_definition: each of ${#names[@]} formulas written once, in its one place"
else
  exit 1
fi
