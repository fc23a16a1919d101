#!/usr/bin/env bash
# Installs the geodex build tree into a scratch prefix and builds + runs tests/install/consumer
# against it (CTest test install.consumer; tests/install/CMakeLists.txt passes KEY=VALUE args):
#   CMAKE BUILD_DIR CONSUMER_DIR WORK_DIR GENERATOR MAKE_PROGRAM CXX CXX_FLAGS LINKER_FLAGS
#   BUILD_TYPE PYTHON (the interpreter, when the Python module was built; else empty)
# The consumer gets the same compiler and flags as the build (a sanitizer build's library needs
# the sanitizer runtime at link time too).
set -euo pipefail

for arg in "$@"; do
  case $arg in
    CMAKE=* | BUILD_DIR=* | CONSUMER_DIR=* | WORK_DIR=* | GENERATOR=* | MAKE_PROGRAM=* | CXX=* | \
      CXX_FLAGS=* | LINKER_FLAGS=* | BUILD_TYPE=* | PYTHON=*)
      declare "${arg%%=*}=${arg#*=}" ;;
    *) echo "run_install_test.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

fail() { echo "FAIL: $*" >&2; exit 1; }
PYTHON=${PYTHON:-}

PREFIX=$WORK_DIR/prefix
rm -rf "$WORK_DIR"
mkdir -p "$WORK_DIR"

echo "== cmake --install $BUILD_DIR --prefix $PREFIX"
"$CMAKE" --install "$BUILD_DIR" --prefix "$PREFIX" >"$WORK_DIR/install.log" ||
  { cat "$WORK_DIR/install.log" >&2; fail "cmake --install failed"; }
for header in geodesic_solver.h mesh.h mesh_io.h observer.h surface_point.h; do
  [[ -f $PREFIX/include/geodex/$header ]] || fail "include/geodex/$header not installed"
done
library=$(find "$PREFIX" -name libgeodex.a | head -n 1)
[[ -n $library ]] || fail "libgeodex.a not installed"
config=$(find "$PREFIX" -name geodexConfig.cmake | head -n 1)
[[ -n $config ]] || fail "geodexConfig.cmake not installed"
echo "installed: $library, $config"

echo "== configure, build and run the consumer"
# Only the scratch prefix may provide geodex: no package registries, no system prefixes first.
"$CMAKE" -S "$CONSUMER_DIR" -B "$WORK_DIR/build" -G "$GENERATOR" \
  -DCMAKE_MAKE_PROGRAM="$MAKE_PROGRAM" \
  -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_CXX_FLAGS="$CXX_FLAGS" \
  -DCMAKE_EXE_LINKER_FLAGS="$LINKER_FLAGS" \
  -DCMAKE_BUILD_TYPE="$BUILD_TYPE" \
  -DCMAKE_PREFIX_PATH="$PREFIX" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
  >"$WORK_DIR/configure.log" 2>&1 ||
  { cat "$WORK_DIR/configure.log" >&2; fail "configuring the consumer failed"; }
grep -F "geodex package: $PREFIX/" "$WORK_DIR/configure.log" ||
  { cat "$WORK_DIR/configure.log" >&2; fail "find_package(geodex) found another install"; }
"$CMAKE" --build "$WORK_DIR/build" >"$WORK_DIR/build.log" 2>&1 ||
  { cat "$WORK_DIR/build.log" >&2; fail "building the consumer failed"; }
"$WORK_DIR/build/consumer" || fail "the consumer's check failed (exit code $?)"

# The Python package, when the build made it (python/): installed under the prefix, it imports
# from there alone (no build tree on the path) and solves.
if [[ -n $PYTHON ]]; then
  echo "== the Python package"
  package=$(find "$PREFIX" -path '*/geodex/__init__.py' | head -n 1)
  [[ -n $package ]] || fail "the Python package geodex was built but not installed"
  site=$(dirname "$(dirname "$package")")
  (cd "$WORK_DIR" && PYTHONPATH=$site "$PYTHON" -c '
import sys, geodex
assert geodex.__file__.startswith(sys.argv[1]), geodex.__file__
d = geodex.distances([[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0]], [[0, 1, 2], [0, 2, 3]], 0)
assert abs(d[2] - 8 ** 0.5) < 1e-15, d
print("imported", geodex.__file__)' "$site") || fail "the installed Python package does not import and solve"
fi
echo "PASS"
