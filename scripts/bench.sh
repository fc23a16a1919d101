#!/usr/bin/env bash
# Benchmarks (docs/benchmarks.md): builds the release preset's geodex_bench and runs it, writing
#   build/bench/results.md    header (date, commit, machine) + the Markdown tables
#   build/bench/results.json  every figure, per-run times included
# Extra arguments go to geodex_bench, e.g. `scripts/bench.sh --big` (adds the 871K-face dragon),
# `scripts/bench.sh --only flat-grid,fandisk --runs 5`. A full run takes ~15 min on 2 cores; run it
# on an otherwise idle machine (the header records the load average before and after).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

cmake --preset release >/dev/null
cmake --build --preset release --target geodex_bench

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
mv "$out/results.md.tmp" "$out/results.md"
cat "$out/results.md"
echo
echo "bench: wrote $out/results.md and $out/results.json"
