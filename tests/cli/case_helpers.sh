# What the test scripts of the `geodex` binary share (sourced by tests/cli/run_cli_tests.sh and
# tests/crosscheck/run_crosscheck_tests.sh): the expectations on a run's exit code and output,
# and running the case the command line names. The sourcing script defines run(), which sets
# RC, LAST_CMD and writes stdout and stderr to $OUT and $ERR, and one case_NAME() per case.

fail() {
  echo "FAIL [$CASE]: $*" >&2
  echo "  command: ${LAST_CMD:-}" >&2
  echo "  exit code: ${RC:-}" >&2
  echo "  --- stdout (first 40 lines) ---" >&2
  head -n 40 "$OUT" >&2 || true
  echo "  --- stderr (last 40 lines) ---" >&2
  tail -n 40 "$ERR" >&2 || true
  exit 1
}

expect_rc() { [[ $RC -eq $1 ]] || fail "expected exit code $1"; }
# A crash (signal) shows as 128+N; bad input must never get there.
expect_err() { grep -Eq -- "$1" "$ERR" || fail "stderr should match /$1/"; }
expect_out() { grep -Eq -- "$1" "$OUT" || fail "stdout should match /$1/"; }

# run_named_case CASE: runs case_CASE, or with `all` every case (printing a pass/fail line each).
run_named_case() {
  local all
  all=$(declare -F | awk '{print $3}' | sed -n 's/^case_//p')
  if [[ $1 == all ]]; then
    local failed=0 c
    for c in $all; do
      if (CASE=$c; "case_$c"); then echo "pass: $c"; else failed=$((failed + 1)); fi
    done
    echo "$(($(wc -w <<<"$all") - failed)) passed, $failed failed"
    exit $((failed > 0))
  fi
  declare -F "case_$1" >/dev/null || { echo "unknown case '$1'; cases: $all" >&2; exit 2; }
  "case_$1"
}
