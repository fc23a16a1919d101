#!/bin/bash -eu
# Builds geodex's fuzz targets into $OUT and zips each one's seed corpus (corpus/<target>/seed and
# the fixed-bug reproducers in regress/) as $OUT/<target>_seed_corpus.zip, as ClusterFuzzLite and
# OSS-Fuzz expect. Runs inside their image ($CXX, $CXXFLAGS, $LIB_FUZZING_ENGINE set there) or
# here: `OUT=/tmp/out .clusterfuzzlite/build.sh` with clang++ and libFuzzer defaults.
# (The shebang's -eu is lost when the script is run as `bash build.sh`, as ClusterFuzzLite does.)
set -euo pipefail
SRC_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
: "${OUT:?set OUT to the output directory}"
: "${CXX:=clang++}"
: "${CXXFLAGS:=-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined,fuzzer-no-link}"
: "${LIB_FUZZING_ENGINE:=-fsanitize=fuzzer}"
BUILD=${WORK:-/tmp}/geodex-fuzz-build
TARGETS=(fuzz_mesh_io fuzz_predicates fuzz_edge_update fuzz_propagation fuzz_two_faces fuzz_solver)

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$SRC_DIR" -B "$BUILD" "${generator[@]}" \
  -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGEODEX_FUZZING=ON -DGEODEX_FUZZING_ENGINE="$LIB_FUZZING_ENGINE" -DGEODEX_CHECKS=ON \
  -DGEODEX_BUILD_TESTS=OFF -DGEODEX_BUILD_BENCH=OFF
cmake --build "$BUILD" --parallel "${NPROC:-2}" --target "${TARGETS[@]}"

mkdir -p "$OUT"
for target in "${TARGETS[@]}"; do
  cp "$BUILD/bin/$target" "$OUT/"
  # A dictionary where the input is text (fuzz/<target>.dict), and libFuzzer options for all:
  # the input cap the target itself enforces.
  if [[ -f $SRC_DIR/fuzz/$target.dict ]]; then cp "$SRC_DIR/fuzz/$target.dict" "$OUT/"; fi
  max_len=4096
  [[ $target == fuzz_mesh_io ]] && max_len=65536
  printf '[libfuzzer]\nmax_len = %s\n' "$max_len" > "$OUT/$target.options"
  inputs=()
  for f in "$SRC_DIR"/corpus/"$target"/seed/* "$SRC_DIR"/corpus/"$target"/regress/*; do
    [[ -f $f ]] || continue
    case $(basename "$f") in open-*) continue ;; esac  # known open bugs: not seeds
    inputs+=("$f")
  done
  rm -f "$OUT/${target}_seed_corpus.zip"
  zip -q -j "$OUT/${target}_seed_corpus.zip" "${inputs[@]}"
  echo "$target: $OUT/$target, ${#inputs[@]} seeds in $OUT/${target}_seed_corpus.zip"
done
