#!/usr/bin/env bash
# What the observer hooks cost a release solve with no observer attached: the solver as shipped
# against the same sources compiled without the hooks (GEODEX_NO_OBSERVER_HOOKS), each a median
# of RUNS solves per process, the two processes alternated ROUNDS times per mesh; prints the
# ratio of the medians of the per-process medians (> 1: the hooks cost that much).
# With --mesh-units first, the same against the sources compiled without mesh units
# (GEODEX_NO_MESH_UNITS: what scale-independence costs a solve, docs/numerics.md).
#   scripts/hooks-overhead.sh [--mesh-units] [ROUNDS] [RUNS] [MESH...]
#   defaults: 7 rounds, 3 runs, fandisk, armadillo and bunny00 from libcgal-demo
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
other=geodex_nohooks_timing label="no hooks ms"
if [[ ${1:-} == --mesh-units ]]; then
  other=geodex_unscaled_timing label="unscaled ms"
  shift
fi
rounds=${1:-7}
runs=${2:-3}
shift $(( $# > 2 ? 2 : $# ))
meshes=("$@")
if [ ${#meshes[@]} -eq 0 ]; then
  d=build/release/data/meshes
  meshes=("$d/fandisk.off" "$d/armadillo.off" "$d/bunny00.off")
fi
cmake --preset release >/dev/null
cmake --build --preset release --target geodex_hooks_timing "$other" >/dev/null
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
printf '%-28s %12s %12s %8s\n' mesh "geodex ms" "$label" ratio
for mesh in "${meshes[@]}"; do
  with=() without=()
  for ((r = 0; r < rounds; ++r)); do
    with+=("$(build/release/bin/geodex_hooks_timing "$mesh" "$runs")")
    without+=("$(build/release/bin/$other "$mesh" "$runs")")
  done
  a=$(printf '%s\n' "${with[@]}" | median)
  b=$(printf '%s\n' "${without[@]}" | median)
  printf '%-28s %12s %12s %8.4f\n' "$(basename "$mesh")" "$a" "$b" "$(echo "$a / $b" | bc -l)"
done
