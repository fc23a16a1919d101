#!/usr/bin/env bash
# Runs one test of `geodex crosscheck` against the programs in this directory, each wrong in a
# known way (edge_dijkstra.py: paths along edges; crash.py, hang.py, short_output.py), and
# against geodex's own `distance` command, which must pass.
#   run_crosscheck_tests.sh GEODEX GEODEX_CASES CASE
# GEODEX_CASES: how many generated cases the clean run of geodex's CLI takes (300 in CTest).
# Each case is one CTest test (tests/crosscheck/CMakeLists.txt); CASE `all` runs every case.
# Exit 0 = pass; anything else prints what was expected and got.
set -euo pipefail

GEODEX=$1
GEODEX_CASES=$2
CASE=$3
HERE=$(cd "$(dirname "$0")" && pwd)
DATA=$HERE/../data/cli

WORK=$(mktemp -d "${TMPDIR:-/tmp}/geodex-crosscheck-test.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
OUT=$WORK/stdout
ERR=$WORK/stderr
FINDINGS=$WORK/findings

# run ARGS…: runs `geodex crosscheck ARGS…`; sets RC, SECONDS_TAKEN, OUT and ERR.
run() {
  local start=$SECONDS
  set +e
  "$GEODEX" crosscheck "$@" >"$OUT" 2>"$ERR"
  RC=$?
  set -e
  SECONDS_TAKEN=$((SECONDS - start))
  LAST_CMD="geodex crosscheck $*"
}

# fail, expect_rc, expect_err, expect_out, run_named_case
source "$HERE/../cli/case_helpers.sh"

expect_usage_error() {
  expect_rc 2
  expect_err '^error: '
  [[ ! -e $FINDINGS ]] || [[ -z $(ls -A "$FINDINGS") ]] || fail "bad use must run no case"
}
# The finding directories of one kind.
findings_of() { find "$FINDINGS" -mindepth 1 -maxdepth 1 -type d -name "[0-9][0-9][0-9]-$1" | sort; }
expect_findings_only_of() {
  [[ -n $(findings_of "$1") ]] || fail "no $FINDINGS/NNN-$1"
  local others
  others=$(find "$FINDINGS" -mindepth 1 -maxdepth 1 -type d ! -name "[0-9][0-9][0-9]-$1")
  [[ -z $others ]] || fail "findings of another kind: $others"
}

DIJKSTRA="python3 $HERE/edge_dijkstra.py {mesh} {source} {out}"
# hang.py's child carries this marker, so that a test sees its own children only.
export HANG_MARKER=geodex-crosscheck-hang-child-$$

# ===  cases =====================================================================================

# Paths along edges are too long across every face: flagged, with small reproducers that still
# reproduce outside crosscheck (check_finding.py reruns the program and `geodex distance`).
case_edge_paths_flagged_and_minimized() {
  run --solver "$DIJKSTRA" --cases 28 --out "$FINDINGS" --max-findings 4
  expect_rc 1
  expect_out 'wrong-distance'
  expect_findings_only_of wrong-distance
  local n=0 shrank=0
  for dir in $(findings_of wrong-distance); do
    python3 "$HERE/check_finding.py" "$GEODEX" "$dir" 36 1e-9 "$DIJKSTRA" >>"$OUT" 2>>"$ERR" ||
      fail "$dir is not a reproducer"
    grep -q '^worst vertices' "$dir/report.txt" || fail "$dir/report.txt names no worst vertex"
    local before after
    before=$(awk 'NR == 2 {print $2}' "$dir/original.off")
    after=$(awk 'NR == 2 {print $2}' "$dir/mesh.off")
    ((after <= before)) || fail "$dir: minimizing grew the mesh"
    ((after < before)) && shrank=$((shrank + 1))
    n=$((n + 1))
  done
  ((n == 4)) || fail "expected 4 findings written (--max-findings 4), got $n"
  ((shrank >= 2)) || fail "only $shrank of the findings were minimized at all"
}

# geodex's own CLI, run as an outside program, agrees with geodex on every generated case.
case_geodex_cli_passes_clean() {
  run --solver "$GEODEX distance {mesh} --source v:{source} --out {out} --quiet" --cases "$GEODEX_CASES" \
    --out "$FINDINGS" --quiet
  expect_rc 0
  expect_out "^crosscheck: $GEODEX_CASES cases \(seed 1\): $GEODEX_CASES agree, 0 with findings, 0 not judged"
  [[ -z $(ls -A "$FINDINGS") ]] || fail "findings written for a clean run"
}

case_crash_reported_as_crash() {
  run --solver "python3 $HERE/crash.py {mesh} {source} {out}" --cases 3 --out "$FINDINGS"
  expect_rc 1
  expect_findings_only_of crash
  # One reproducer for the same crash on every mesh.
  [[ $(findings_of crash | wc -l) -eq 1 ]] || fail "the same crash written more than once"
  local report
  report=$(findings_of crash)/report.txt
  grep -q 'signal 6' "$report" || fail "the report does not say how it ended"
  grep -q 'crash.py: giving up' "$report" || fail "the report does not keep what it printed"
  [[ $(awk 'NR == 2 {print $2}' "$(findings_of crash)/mesh.off") -eq 1 ]] || fail "not minimized to one face"
}

# The program hangs and leaves a child behind: both are killed at the time limit, and the run
# ends in bounded time. A stall lasts the hour hang.py sleeps; the run takes 15 s and took 31 s
# beside two fuzzing campaigns (a false kill in the mutation job), so the bound is 120 s. The time
# limit leaves a loaded machine 2 s to start Python and print the line the report must keep (at
# 0.5 s the case failed once, in 6.4 s, beside a fuzz build).
case_hang_reported_as_timeout_without_stalling() {
  run --solver "python3 $HERE/hang.py {mesh} {source} {out}" --cases 2 --time-limit 2 --minimize-time 3 \
    --out "$FINDINGS"
  expect_rc 1
  expect_findings_only_of timeout
  ((SECONDS_TAKEN < 120)) || fail "took $SECONDS_TAKEN s"
  grep -q 'process group was killed' "$(findings_of timeout | head -n 1)/report.txt" || fail "report says no kill"
  grep -q 'hang.py: thinking' "$(findings_of timeout | head -n 1)/report.txt" || fail "output not kept"
  sleep 0.2
  if pgrep -f "$HANG_MARKER" >/dev/null; then fail "hang.py's child outlived its case"; fi
}

# Interrupted (Ctrl-C, a cancelled CI job), crosscheck takes the program's process group with it.
case_interrupt_kills_the_running_program() {
  "$GEODEX" crosscheck --solver "python3 $HERE/hang.py {mesh} {source} {out}" --cases 2 --out "$FINDINGS" \
    >"$OUT" 2>"$ERR" &
  local pid=$!
  sleep 1.5
  kill -INT "$pid"
  set +e
  wait "$pid"
  RC=$?
  set -e
  LAST_CMD="geodex crosscheck … (interrupted)"
  expect_rc 130
  sleep 0.2
  if pgrep -f "$HANG_MARKER" >/dev/null; then fail "hang.py's child outlived the interrupt"; fi
}

case_short_output_reported_as_line_count() {
  run --solver "python3 $HERE/short_output.py {mesh} {source} {out}" --cases 3 --out "$FINDINGS"
  expect_rc 1
  expect_findings_only_of line-count
  expect_out 'lines for [0-9]+ vertices'
}

case_missing_output_and_bad_values() {
  run --solver 'true {mesh} {source} {out}' --cases 1 --out "$FINDINGS"
  expect_rc 1
  expect_findings_only_of line-count
  expect_out 'no output file was written'
  rm -rf "$FINDINGS"
  run --solver 'yes distance | head -n 100 >{out} # {mesh} {source}' --cases 1 --out "$FINDINGS"
  expect_rc 1
  expect_findings_only_of bad-value
  expect_out "line 1 is not a number: 'distance'"
}

# A mesh of one's own runs first; with --cases 0 only it runs.
case_given_mesh() {
  run --solver "$DIJKSTRA" --mesh "$DATA/bent_grid.off" --source v:0 --source v:4 --cases 0 --out "$FINDINGS"
  expect_rc 1
  expect_out '^crosscheck: 2 cases'
  expect_out 'bent_grid\.off --source v:0'
  run --solver "$GEODEX distance {mesh} --source v:{source} --out {out} --quiet" --mesh "$DATA/two_components.off" \
    --source v:0 --source v:5 --cases 0 --out "$WORK/clean"
  expect_rc 0
  expect_out '^crosscheck: 2 cases \(seed 1\): 2 agree'
}

case_same_seed_same_findings() {
  run --solver "$DIJKSTRA" --cases 8 --seed 5 --out "$WORK/a" --max-findings 2 --quiet
  expect_rc 1
  run --solver "$DIJKSTRA" --cases 8 --seed 5 --out "$WORK/b" --max-findings 2 --quiet
  expect_rc 1
  diff -r -x report.txt -x picture.png "$WORK/a" "$WORK/b" >/dev/null || fail "two runs with --seed 5 differ"
  # A second run into the same directory numbers on.
  run --solver "$DIJKSTRA" --cases 8 --seed 5 --out "$WORK/a" --max-findings 2 --quiet
  [[ -d $WORK/a/003-wrong-distance && -d $WORK/a/004-wrong-distance ]] || fail "did not number on after 002"
}

case_bad_use_exits_2_with_a_clear_message() {
  run --solver 'prog {mesh} {source}' --out "$FINDINGS"
  expect_usage_error
  expect_err '\{out\}'
  run --solver 'prog {source} {out}' --out "$FINDINGS"
  expect_usage_error
  expect_err '\{mesh\}'
  run --out "$FINDINGS"
  expect_usage_error
  expect_err 'solver'
  run --solver "$DIJKSTRA" --mesh "$WORK/does_not_exist.off" --source v:0 --out "$FINDINGS"
  expect_usage_error
  expect_err 'does_not_exist\.off'
  run --solver "$DIJKSTRA" --mesh "$DATA/truncated.off" --source v:0 --out "$FINDINGS"
  expect_usage_error
  expect_err 'truncated\.off'
  run --solver "$DIJKSTRA" --mesh "$DATA/bent_grid.off" --source v:9 --out "$FINDINGS"
  expect_usage_error
  expect_err 'bent_grid\.off'
  expect_err 'v:9'
  run --solver "$DIJKSTRA" --mesh "$DATA/bent_grid.off" --source e:0,1,0.5 --out "$FINDINGS"
  expect_usage_error
  expect_err 'vertex sources'
  run --solver "$DIJKSTRA" --mesh "$DATA/bent_grid.off" --out "$FINDINGS"
  expect_usage_error
  expect_err 'source'
  run --solver "$DIJKSTRA" --source v:0 --out "$FINDINGS"
  expect_usage_error
  expect_err 'mesh'
  local option
  for option in '--time-limit 0' '--time-limit nan' '--time-limit -1' '--tolerance -1e-9' '--tolerance inf' \
    '--cases -3' '--cases many' '--seed x' '--max-findings 0' '--minimize-time 0'; do
    # shellcheck disable=SC2086  # the option and its value are two words
    run --solver "$DIJKSTRA" $option --out "$FINDINGS"
    expect_usage_error
    expect_err "${option%% *}"
  done
  run --solver "$DIJKSTRA" --cases 1 --out /proc/version/findings
  expect_usage_error
  expect_err '/proc/version/findings'
}

run_named_case "$CASE"
