#!/usr/bin/env bash
# geodex demo: installs the dependencies, builds the release preset, and computes exact geodesic
# distances from one vertex of a real mesh (CGAL's elephant, from Debian's libcgal-demo),
# printing distance statistics and the degeneracy table (Liu, Zhou & Hu 2007, Table 1).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

./scripts/install-deps.sh
cmake --preset release
cmake --build --preset release

MESH=build/release/data/meshes/elephant.off  # extracted from libcgal-demo at configure time
if [[ ! -f $MESH ]]; then
  echo "demo: $MESH is missing (libcgal-demo's data.tar.gz should provide it)" >&2
  exit 1
fi
mkdir -p build/demo

echo
echo "== geodex info $MESH"
build/release/bin/geodex info "$MESH"

echo
echo "== geodex distance $MESH --source v:0 --stats --out build/demo/distances.txt"
build/release/bin/geodex distance "$MESH" --source v:0 --stats --out build/demo/distances.txt
echo "distances (one line per vertex): build/demo/distances.txt"

# --- render the distance field, with the geodesic from v:0 to a hind foot -----------------------
echo
echo "== geodex render $MESH --source v:0 --target v:2000 --out build/demo/elephant.png"
build/release/bin/geodex render "$MESH" --source v:0 --target v:2000 --out build/demo/elephant.png
echo "picture (distance colours, isolines, source disc, path in red): build/demo/elephant.png"
