#!/usr/bin/env bash
# One fuzz target's smoke run (CTest label `fuzz-smoke`, `fuzz` preset): RUNS inputs (at most
# SECONDS) with a fixed seed, in one process — so the run is the same sequence of inputs on every
# machine, and a slower machine that hits the time cap runs a prefix of it — from the target's seeds and the reproducers of fixed
# bugs (regress/open-* would only find their known bug again). Inputs that add coverage go to the
# scratch directory, never into corpus/. A finding fails the run; libFuzzer prints the file it
# wrote (SCRATCH/crash-…), which `geodex repro` or the target itself replays.
#
#   fuzz_smoke.sh FUZZER CORPUS_DIR SCRATCH MAX_LEN SECONDS RUNS
set -euo pipefail
fuzzer=$1 corpus=$2 scratch=$3 max_len=$4 seconds=$5 runs=$6
rm -rf "$scratch"
mkdir -p "$scratch/new" "$scratch/start"
for f in "$corpus"/seed/* "$corpus"/regress/*; do
  [[ -f $f ]] || continue
  case $(basename "$f") in open-*) continue ;; esac
  cp "$f" "$scratch/start/$(basename "$(dirname "$f")")-$(basename "$f")"
done
exec "$fuzzer" -seed=1 -runs="$runs" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
  -print_final_stats=1 -artifact_prefix="$scratch/" "$scratch/new" "$scratch/start"
