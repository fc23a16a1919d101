#!/usr/bin/env bash
# Fuzzes every libFuzzer target (or the ones named) for SECONDS_PER_TARGET seconds each.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]      default: 60 s, all six targets
#
# Configures and builds the `fuzz` preset (clang, ASan + UBSan, libFuzzer; the fuzz targets only),
# then per target: fuzzes with 2 forked workers (GEODEX_FUZZ_WORKERS) on its corpus (build/fuzz-work/<target>/corpus,
# started from corpus/<target>/seed and the fixed-bug reproducers in regress/), merges the inputs
# that added coverage into that work corpus, minimizes every crash (-minimize_crash=1) into
# build/fuzz-findings/<target>/<check>-<hash> (one per failed check per run), and prints:
# executions, exec/s, coverage (cov/ft of libFuzzer's final stats), findings.
# Exit status 1 when any target has a finding. Reproduce one with
#   build/fuzz/bin/<target> FILE        or        geodex repro FILE
# Known open bugs (corpus/<target>/regress/open-*) are not seeded; to fuzz on past one, name its
# check in GEODEX_FUZZ_SKIP_CHECKS (comma-separated), e.g. GEODEX_FUZZ_SKIP_CHECKS=path-length.
# GEODEX_FUZZ_WORKERS (default 2) sets the forked workers per target, e.g. 1 to run two campaigns
# side by side on two cores.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

budget=60
if [[ $# -gt 0 && $1 =~ ^[0-9]+$ ]]; then
  budget=$1
  shift
fi
targets=("$@")
workers=${GEODEX_FUZZ_WORKERS:-2}
if [[ ${#targets[@]} -eq 0 ]]; then
  targets=(fuzz_mesh_io fuzz_predicates fuzz_edge_update fuzz_propagation fuzz_two_faces fuzz_solver)
fi

# Campaigns started side by side share build/fuzz: one configures and builds at a time (two
# ninjas in one build directory broke its CMake regeneration).
mkdir -p build
exec 9>build/fuzz.lock
flock 9
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target "${targets[@]}"
flock -u 9

status=0
summary=()
for target in "${targets[@]}"; do
  bin=build/fuzz/bin/$target
  work=build/fuzz-work/$target
  findings=build/fuzz-findings/$target
  rm -rf "$work/new" "$work/artifacts" "$work/minimize"
  mkdir -p "$work/corpus" "$work/new" "$work/artifacts" "$findings"
  # Seeds and reproducers of fixed bugs join the work corpus; open-* ones would only re-find
  # their known bug.
  for f in corpus/"$target"/seed/* corpus/"$target"/regress/*; do
    [[ -f $f ]] || continue
    case $(basename "$f") in open-*) continue ;; esac
    cp -n "$f" "$work/corpus/$(basename "$(dirname "$f")")-$(basename "$f")"
  done
  max_len=4096
  [[ $target == fuzz_mesh_io ]] && max_len=65536
  dict=()
  [[ -f fuzz/$target.dict ]] && dict=(-dict="fuzz/$target.dict")

  echo
  echo "=== $target: ${budget} s, $workers forked workers"
  # -fork with -ignore_crashes keeps fuzzing past a finding (the open bugs of regress/open-* are
  # found again within seconds; -jobs workers would stop at the first one).
  "$bin" -fork="$workers" -ignore_crashes=1 -max_total_time="$budget" -timeout=10 -rss_limit_mb=2048 \
    "${dict[@]}" -max_len="$max_len" -artifact_prefix="$work/artifacts/" -print_final_stats=1 \
    "$work/new" "$work/corpus" >"$work/fuzz.log" 2>&1 || true

  # Final stats: the last progress line of the fork-mode parent,
  # "#EXECS: cov: C ft: F corp: N exec/s E oom/timeout/crash: a/b/c time: Ts job: J ...".
  last=$(grep -E '^#[0-9]+: cov:' "$work/fuzz.log" | tail -1 || true)
  execs=$(sed -nE 's/^#([0-9]+):.*/\1/p' <<<"$last")
  cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
  ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")
  secs=$(sed -nE 's/.* time: ([0-9]+)s.*/\1/p' <<<"$last")
  execs=${execs:-0} cov=${cov:-?} ft=${ft:-?} secs=${secs:-$budget}
  rate=$((execs / (secs > 0 ? secs : 1)))

  # Keep what added coverage. An input of the work corpus that fails a check added since it was
  # kept makes the merge crash and restart: its artifact joins this run's findings (without the
  # prefix libFuzzer wrote it to the current directory, the checkout).
  "$bin" -merge=1 -max_len="$max_len" -artifact_prefix="$work/artifacts/" "$work/corpus" "$work/new" \
    >"$work/merge.log" 2>&1 || true
  corpus_size=$(find "$work/corpus" -type f | wc -l)

  # Findings: name each artifact after the check it fails (or the sanitizer's summary), minimize
  # the first of each kind into build/fuzz-findings/<target>/.
  declare -A seen=()
  crashes=0
  kinds=()
  for artifact in "$work"/artifacts/*; do
    [[ -f $artifact ]] || continue
    crashes=$((crashes + 1))
    out=$("$bin" "$artifact" 2>&1 || true)
    kind=$(grep -m1 -oE "check '[^']+' failed" <<<"$out" | sed -E "s/check '([^']+)' failed/\1/" || true)
    if [[ -z $kind ]]; then
      kind=$(grep -m1 -oE 'SUMMARY: [A-Za-z]+: [a-z-]+' <<<"$out" | awk '{print $3}' || true)
    fi
    kind=${kind:-$(basename "$artifact" | cut -d- -f1)}
    [[ -n ${seen[$kind]:-} ]] && continue
    seen[$kind]=1
    kinds+=("$kind")
    name="$kind-$(sha1sum "$artifact" | cut -c1-12)"
    if [[ $(basename "$artifact") == crash-* ]]; then
      # Only this check counts while minimizing, so the result still fails it.
      mkdir -p "$work/minimize"
      GEODEX_FUZZ_ONLY_CHECKS=$kind "$bin" -minimize_crash=1 -runs=20000 -max_total_time=30 -max_len="$max_len" \
        -artifact_prefix="$work/minimize/" -exact_artifact_path="$findings/$name" "$artifact" \
        >"$work/minimize-$name.log" 2>&1 || true
    fi
    [[ -f $findings/$name ]] || cp "$artifact" "$findings/$name"
    echo "  finding: $findings/$name"
  done
  unset seen

  line="$target: $execs executions in ${secs} s, $rate exec/s, cov $cov, ft $ft, corpus $corpus_size, findings $crashes"
  [[ ${#kinds[@]} -gt 0 ]] && line+=" (${kinds[*]})"
  echo "$line"
  summary+=("$line")
  [[ $crashes -eq 0 ]] || status=1
done

echo
echo "=== summary (work corpora in build/fuzz-work, findings in build/fuzz-findings)"
printf '%s\n' "${summary[@]}"
exit $status
