#!/usr/bin/env bash
# Mutation testing of solver/ and verify/: one planted bug at a time, in a git worktree of HEAD
# outside this checkout; writes docs/mutation.md. Not part of ./test.sh (hours, not minutes).
#   scripts/mutate.sh [--list] [--only ID,...] [--max N] [--seed S] [--no-debug] ...
# scripts/mutate.py --help lists the options; its docstring says how mutants are made and judged.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
exec python3 scripts/mutate.py "$@"
