#!/usr/bin/env bash
# Long property-test run: the RapidCheck suite (tests/property) again and again, each pass with a
# fresh random seed and a large max_success, for as long as asked. Stops at the first failing pass
# and prints how to replay it. See docs/properties.md.
#
#   scripts/properties-long.sh [MINUTES]        default 10
#
# Environment:
#   GEODEX_PROPERTY_BIN   the executable (default: build/release/bin/geodex_property_tests if
#                         built, else build/debug/bin/geodex_property_tests)
#   MAX_SUCCESS           cases per property and pass (default 2000; the local properties run
#                         10 × that, see tests/property/weighted_prop.h)
#   GTEST_FILTER          which properties (default: every property suite, minus the known bugs
#                         listed in tests/property/CMakeLists.txt (GEODEX_KNOWN_BUGS), which would
#                         stop every pass; the deterministic regression and oracle self-tests do
#                         not depend on the seed and are left to CTest)
#   INCLUDE_KNOWN_BUGS=1  keep the known-bug properties in the default filter
#
# Exit status: 0 if every pass succeeded, 1 at the first failure, 2 on bad usage.
set -euo pipefail

minutes=${1:-10}
if ! [[ $minutes =~ ^[0-9]+$ ]] || (( minutes < 1 )); then
  echo "usage: $0 [MINUTES]   (a positive whole number, default 10)" >&2
  exit 2
fi

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${GEODEX_PROPERTY_BIN:-}
if [[ -z $bin ]]; then
  for candidate in "$root/build/release/bin/geodex_property_tests" \
                   "$root/build/debug/bin/geodex_property_tests"; do
    if [[ -x $candidate ]]; then bin=$candidate; break; fi
  done
fi
if [[ -z $bin || ! -x $bin ]]; then
  echo "properties-long: no property executable; build it first:" >&2
  echo "  cmake --preset release" >&2
  echo "  cmake --build --preset release --target geodex_property_tests" >&2
  exit 2
fi
bin=$(realpath "$bin")  # the passes run in a scratch directory
max_success=${MAX_SUCCESS:-2000}
suites="Fig6.*:Algorithm2.*:WholeSolve.*:Metamorphic.*"
# The known bugs, from the one list CTest uses.
known=$(sed -n '/^set(GEODEX_KNOWN_BUGS/,/)/p' "$root/tests/property/CMakeLists.txt" |
          grep -o '"[^"]*"' | tr -d '"' | paste -sd: || true)
if [[ -n ${GTEST_FILTER:-} ]]; then
  filter=$GTEST_FILTER
elif [[ -n $known && ${INCLUDE_KNOWN_BUGS:-0} != 1 ]]; then
  filter="$suites-$known"
else
  filter=$suites
fi

# Failing passes leave reproducer files (property-failure*.{off,txt}) in the working directory:
# run in a scratch one, printed at a failure, so the checkout stays clean.
work=$(mktemp -d "${TMPDIR:-/tmp}/geodex-properties.XXXXXX")
log=$work/output.log
keep_work=0
trap '[[ $keep_work == 1 ]] || rm -rf "$work"' EXIT

deadline=$(( $(date +%s) + 60 * minutes ))
pass=0
echo "properties-long: $bin, max_success=$max_success, filter $filter, for $minutes min"
while (( $(date +%s) < deadline )); do
  pass=$((pass + 1))
  # A 63-bit seed from the kernel's generator (RapidCheck takes any unsigned 64-bit number).
  seed=$(( $(od -An -N8 -tu8 /dev/urandom | tr -d ' ') & 0x7fffffffffffffff ))
  params="seed=$seed max_success=$max_success"
  start=$(date +%s)
  printf 'pass %d: RC_PARAMS="%s" ... ' "$pass" "$params"
  # The coverage gate judges each pass (it is skipped under a filter unless forced).
  if (cd "$work" && RC_PARAMS="$params" GEODEX_COVERAGE_GATE=force "$bin" \
        --gtest_filter="$filter" >"$log" 2>&1); then
    echo "ok ($(( $(date +%s) - start )) s)"
    continue
  fi
  echo "FAILED ($(( $(date +%s) - start )) s)"
  echo
  grep -E '^\[  FAILED  \]|Falsifiable|CoverageGate' "$log" | sort -u || true
  echo
  echo "---- last 60 lines of the output ----"
  tail -n 60 "$log"
  echo "-------------------------------------"
  echo
  echo "seed: $seed"
  keep_work=1
  if compgen -G "$work/property-failure*" >/dev/null; then
    echo "reproducer files (shrunk case): $(echo "$work"/property-failure*)"
  fi
  reproduce=$(grep -o 'RC_PARAMS="reproduce=[^"]*"' "$log" | tail -n 1 || true)
  if [[ -n $reproduce ]]; then
    echo "replay the failing case(s), already shrunk, with:"
    echo "  $reproduce $bin"
  else
    echo "replay the whole pass with:"
    echo "  RC_PARAMS=\"$params\" GEODEX_COVERAGE_GATE=force $bin --gtest_filter='$filter'"
  fi
  exit 1
done
echo "properties-long: $pass passes, no failure"
