#!/usr/bin/env bash
# Runs `geodex distance` from vertex 0 on every mesh of ../shared/meshes (the messy real-world
# ones) and prints one line per mesh and a summary. Each must either finish (exit 0) or be refused
# by name (exit 2 with an "error: …" line); a crash, a sanitizer report or any other exit is a
# failure. Meant for the asan preset (issue 2: "no crash under the asan preset"):
#   scripts/check-shared-meshes.sh [BUILD_DIR] [MESH_DIR]     defaults: build/asan ../shared/meshes
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build/asan}
meshes=${2:-$root/../shared/meshes}
geodex=$build/bin/geodex
[ -x "$geodex" ] || { echo "no $geodex: build that preset first" >&2; exit 2; }
[ -d "$meshes" ] || { echo "no $meshes" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0 refused=0 failed=0
printf '%-34s %-8s %8s  %s\n' mesh verdict seconds detail
for mesh in "$meshes"/*.obj "$meshes"/*.off "$meshes"/*.ply; do
  [ -e "$mesh" ] || continue
  name=$(basename "$mesh")
  start=$(date +%s.%N)
  "$geodex" distance "$mesh" --source v:0 --stats --quiet --out "$out/d.txt" > "$out/stdout" 2> "$out/stderr"
  code=$?
  secs=$(printf '%.1f' "$(echo "$(date +%s.%N) - $start" | bc)")
  if [ "$code" -eq 0 ] && ! grep -q 'Sanitizer\|runtime error' "$out/stderr"; then
    verdict=ok; passed=$((passed + 1))
    detail="$(grep -m1 '^reached:' "$out/stderr" | tr -s ' ')"
  elif [ "$code" -eq 2 ] && grep -q '^error:' "$out/stderr" && ! grep -q 'Sanitizer\|runtime error' "$out/stderr"; then
    verdict=refused; refused=$((refused + 1))
    detail=$(grep -m1 '^error:' "$out/stderr" | sed "s|$meshes/||" | cut -c1-100)
  else
    verdict=FAIL; failed=$((failed + 1))
    detail="exit $code: $(grep -m1 -E 'ERROR|error|Sanitizer' "$out/stderr" | cut -c1-100)"
  fi
  printf '%-34s %-8s %8s  %s\n' "$name" "$verdict" "$secs" "$detail"
done
echo "summary: $passed finished, $refused refused by name, $failed failed"
[ "$failed" -eq 0 ]
