#!/usr/bin/env bash
# Benchmarks (docs/benchmarks.md): builds the release preset's geodex_bench and runs it, writing
#   build/bench/results.md    header (date, commit, machine) + the Markdown tables
#   build/bench/results.json  every figure, per-run times included
# then bench/anchors.py: geodex beside Kirsanov's MMP and VTP on issue 13's meshes, one run (their
# columns stay empty without --anchors DIR, the drivers ../shared/anchors/build.sh writes).
# Other arguments go to geodex_bench, e.g. `scripts/bench.sh --big` (adds the 871K-face dragon to
# both tables), `scripts/bench.sh --only flat-grid,fandisk --runs 5`. A full run takes ~15 min on 2
# cores; run it on an otherwise idle machine (the header records the load average before and after).
#   scripts/bench.sh [--anchors DIR] [geodex_bench arguments...]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

anchors=() big=() args=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --anchors) [[ $# -ge 2 ]] || { echo "bench.sh: --anchors needs a folder" >&2; exit 2; }
               anchors=(--anchors "$2"); shift 2; continue ;;
    --big) big=(--big) ;;
  esac
  args+=("$1")
  shift
done
set -- "${args[@]}"

cmake --preset release >/dev/null
cmake --build --preset release --target geodex_bench geodex_cli

out=build/bench
mkdir -p "$out"
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [[ -n $(git status --porcelain --untracked-files=no 2>/dev/null) ]]; then commit+=" (with uncommitted changes)"; fi
{
  echo "# geodex benchmarks"
  echo
  echo "Run $(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit, $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')."
  echo "Command: build/release/bin/geodex_bench --json $out/results.json $*"
  echo
} >"$out/results.md.tmp"
build/release/bin/geodex_bench --json "$out/results.json" "$@" >>"$out/results.md.tmp"
{
  echo
  echo "## Beside Kirsanov's MMP and VTP (bench/anchors.py ${anchors[*]} ${big[*]})"
  echo
  python3 bench/anchors.py --geodex build/release/bin/geodex "${anchors[@]}" "${big[@]}"
} >>"$out/results.md.tmp"
mv "$out/results.md.tmp" "$out/results.md"
cat "$out/results.md"
echo
echo "bench: wrote $out/results.md and $out/results.json"
