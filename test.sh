#!/usr/bin/env bash
# geodex tests: installs the dependencies, then for each preset configures, builds and runs CTest.
#   ./test.sh               the release, debug, asan, tsan and fuzz presets
#   ./test.sh debug [...]   the named presets only
# The fuzz preset builds only the libFuzzer targets and the corpus tools and runs the corpus
# replay plus a fixed-seed fuzz smoke per target (labels corpus, fuzz-smoke; scripts/fuzz.sh is the
# full fuzzing job).
# Every preset is run even when an earlier one fails; the exit code is non-zero if any configure,
# build or test step failed. One summary line per preset at the end, then "N passed, M failed".
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

if [[ $# -gt 0 ]]; then PRESETS=("$@"); else PRESETS=(release debug asan tsan fuzz); fi
FUZZ_TARGETS=(fuzz_mesh_io fuzz_predicates fuzz_edge_update fuzz_propagation fuzz_two_faces fuzz_solver
  geodex_corpus_open_findings geodex_corpus_degeneracy_coverage geodex_make_seeds)

./scripts/install-deps.sh

summary=()
total_passed=0
total_failed=0
status=0

for preset in "${PRESETS[@]}"; do
  echo
  echo "=== $preset ==="
  start=$SECONDS
  log=build/$preset.ctest.log
  if ! cmake --preset "$preset"; then
    summary+=("$preset: FAILED to configure ($((SECONDS - start)) s)")
    status=1
    continue
  fi
  targets=()
  labels=()
  if [[ $preset == fuzz ]]; then
    targets=(--target "${FUZZ_TARGETS[@]}")
    labels=(-L 'corpus|fuzz-smoke')
  fi
  if ! cmake --build --preset "$preset" "${targets[@]}"; then
    summary+=("$preset: FAILED to build ($((SECONDS - start)) s)")
    status=1
    continue
  fi
  build_seconds=$((SECONDS - start))
  mkdir -p build
  if ctest --preset "$preset" --no-tests=error "${labels[@]}" 2>&1 | tee "$log"; then result=passed; else
    result=FAILED
    status=1
  fi
  # "100% tests passed, 0 tests failed out of 42"
  counts=$(sed -n 's/.*tests passed, \([0-9]*\) tests\{0,1\} failed out of \([0-9]*\).*/\1 \2/p' "$log" | tail -n 1)
  failed=${counts% *}
  total=${counts#* }
  if [[ -z $counts ]]; then failed=0; total=0; fi
  total_passed=$((total_passed + total - failed))
  total_failed=$((total_failed + failed))
  summary+=("$preset: $result: $((total - failed)) of $total tests passed (build ${build_seconds} s, test $((SECONDS - start - build_seconds)) s)")
done

echo
echo "=== summary ==="
printf '%s\n' "${summary[@]}"
echo "$total_passed passed, $total_failed failed"
exit $status
