#!/usr/bin/env bash
# run_build_type_test.sh CMAKE SOURCE_DIR WORK_DIR FIRST_CXX SECOND_CXX
# Configures SOURCE_DIR in WORK_DIR with FIRST_CXX, then with SECOND_CXX, both times with
# CMAKE_BUILD_TYPE=Release; the second configure deletes the cache (a compiler change) and runs
# without the build type. Fails unless the cache says Release at the end.
set -euo pipefail
(($# == 5)) || { echo "usage: $0 CMAKE SOURCE_DIR WORK_DIR FIRST_CXX SECOND_CXX" >&2; exit 2; }
cmake=$1 source=$2 work=$3 first=$4 second=$5

rm -rf "$work"
mkdir -p "$work"
options=(-G Ninja -DGEODEX_BUILD_TESTS=OFF -DGEODEX_BUILD_BENCH=OFF -DGEODEX_PYTHON=OFF
         -DCMAKE_BUILD_TYPE=Release)
for cxx in "$first" "$second"; do
  if ! "$cmake" -S "$source" -B "$work/build" "${options[@]}" -DCMAKE_CXX_COMPILER="$cxx" \
    >"$work/configure.log" 2>&1; then
    cat "$work/configure.log" >&2
    echo "FAIL: configure with $cxx" >&2
    exit 1
  fi
done
if ! grep -q "cache to be deleted" "$work/configure.log"; then
  echo "FAIL: the compiler change did not reset the cache; the test no longer sets the trap" >&2
  exit 1
fi
type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$work/build/CMakeCache.txt")
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$work/build/CMakeCache.txt")
echo "after $first then $second: CMAKE_BUILD_TYPE='$type', CMAKE_CXX_COMPILER=$compiler"
rm -rf "$work"
[[ $type == Release ]] || { echo "FAIL: the build type is '$type', not Release" >&2; exit 1; }
