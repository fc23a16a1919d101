#!/usr/bin/env bash
# Runs `geodex check --level full` on every mesh of Debian's libcgal-demo with three sources each
# (a vertex, an edge point, a face point) and prints one line per mesh plus a summary. Meshes the
# solver refuses must be refused by name (exit 2 with "error: … kind"); anything else is a failure.
#   scripts/check-cgal-meshes.sh [BUILD_DIR] [OUT_DIR]
set -uo pipefail
build=${1:-build/release}
out=${2:-build/check-cgal}
geodex=$build/bin/geodex
meshes=$build/data/meshes
[ -x "$geodex" ] || { echo "no $geodex: build the release preset first" >&2; exit 2; }
[ -d "$meshes" ] || { echo "no $meshes: install libcgal-demo and re-run cmake" >&2; exit 2; }
mkdir -p "$out"
passed=0 refused=0 failed=0
printf '%-34s %-8s %8s %10s %s\n' mesh verdict seconds cases detail
for mesh in "$meshes"/*.off "$meshes"/*.ply "$meshes"/*.obj; do
  [ -e "$mesh" ] || continue
  name=$(basename "$mesh")
  start=$(date +%s.%N)
  "$geodex" check "$mesh" --sample-sources --level full --json --repro "$out/$name.repro" \
    > "$out/$name.json" 2> "$out/$name.err"
  code=$?
  secs=$(printf '%.1f' "$(echo "$(date +%s.%N) - $start" | bc)")
  cases=$(grep -o '"cases": [0-9]*' "$out/$name.json" 2>/dev/null | grep -o '[0-9]*$' || true)
  case $code in
    0) verdict=pass; passed=$((passed + 1)); detail="" ;;
    2) verdict=refused; refused=$((refused + 1)); detail=$(grep -m1 '^error:' "$out/$name.err" | cut -c1-90) ;;
    *) verdict=FAIL; failed=$((failed + 1)); detail=$(grep -o '"violations": \["[^"]*' "$out/$name.json" | cut -c17-120; grep -m1 -i 'error' "$out/$name.err" | cut -c1-90) ;;
  esac
  printf '%-34s %-8s %8s %10s %s\n' "$name" "$verdict" "$secs" "${cases:--}" "$detail"
done
echo "summary: $passed passed, $refused refused by name, $failed failed"
[ "$failed" -eq 0 ]
