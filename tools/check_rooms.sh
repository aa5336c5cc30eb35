#!/usr/bin/env bash
# The rooms include only downwards: each directory of the product is its own CMake library
# (CMakeLists.txt), and a file may include the headers of its own room and of the rooms its
# library links, never of a room above it. The linker would not catch an upward include between
# static libraries that one executable links, so this does. Lists each include that goes upwards
# and exits 1; exits 2 where a product directory is missing from the table below.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each room and the rooms it may include besides itself: what its library links, directly or
# through the libraries it links (CMakeLists.txt's target_link_libraries).
declare -A below=(
  [core]=""
  [optim]="core"
  [statics]="core"
  [design]="core optim statics"
  [truss]="core optim statics design"
  [dynamics]="core"
  [bridge]="core optim statics design dynamics"
  [checks]="core optim statics design dynamics bridge"
  [io]="core optim statics design dynamics bridge checks"
  [sizing]="core optim statics design dynamics bridge checks"
  [sweep]="core optim statics design dynamics bridge checks sizing"
  [export]="core optim statics design truss dynamics bridge"
  [app]="core optim statics design truss dynamics bridge checks io sizing sweep export"
  [tools]="core optim statics design truss dynamics bridge checks io sizing sweep export app"
  [python]="core optim statics design truss dynamics bridge checks io sizing sweep export app"
)

status=0
checked=0
for room in "${!below[@]}"; do
  if [ ! -d "$room" ]; then
    echo "check_rooms: $room/ is in the table but not in the tree" >&2
    exit 2
  fi
  allowed=" $room ${below[$room]} "
  while IFS= read -r line; do
    file=${line%%:*}
    target=$(printf '%s\n' "$line" | sed -n 's/.*#include "\([a-z_]*\)\/.*/\1/p')
    [ -z "$target" ] && continue
    checked=$((checked + 1))
    # An include of a directory that is not a room (e.g. a generated header) is not judged.
    [ -z "${below[$target]+x}" ] && continue
    if [[ "$allowed" != *" $target "* ]]; then
      echo "check_rooms: $file includes $target/, above $room/: ${line#*:}" >&2
      status=1
    fi
  done < <(grep -H '^#include "[a-z_]*/' "$room"/*.cc "$room"/*.h 2> /dev/null || true)
done
# Every product directory with C++ sources is in the table.
for dir in */; do
  dir=${dir%/}
  case "$dir" in build | tests | bench | docs | configs | examples) continue ;; esac
  if compgen -G "$dir/*.cc" > /dev/null && [ -z "${below[$dir]+x}" ]; then
    echo "check_rooms: $dir/ holds C++ sources but is not in the table" >&2
    status=2
  fi
done
[ "$status" -eq 0 ] && echo "check_rooms: $checked includes, each of its own room or one below"
exit "$status"
