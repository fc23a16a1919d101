#!/usr/bin/env bash
# Mutation testing of solver/ and verify/: one planted bug at a time, in a git worktree of HEAD
# outside this checkout; writes docs/mutation.md. Not part of ./test.sh (hours, not minutes).
#   scripts/mutate.sh [--list] [--only ID,...] [--max N] [--seed S] [--no-debug] ...
# scripts/mutate.py --help lists the options; its docstring says how mutants are made and judged.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# Hours of rebuilds should yield to whatever else runs. `nice` alone does not when the run has a
# session of its own (setsid, nohup from another terminal): the kernel shares the CPU between
# sessions' autogroups first: a nice-19 compile of a run here got 47 % of a core beside a CI
# compile's 44 % (ps), and 6 % once its autogroup was set to 19. Where that can be set, it is.
echo 19 > /proc/self/autogroup 2>/dev/null || true
exec nice -n 19 python3 scripts/mutate.py "$@"
