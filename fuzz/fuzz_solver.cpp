// fuzz_solver: a whole solve on a small mesh (≤ 64 faces: a height field on a grid with holes,
// moved vertices and steps, or a soup of lattice points; coplanar faces, 2π vertices, collinear
// rays, zero-area faces, several components are frequent) from 1–3 sources on vertices, edges
// or faces. Checks: the full invariant tier at every edge update and the unfolding of every
// propagated child; Euclidean ≤ d ≤ edge-graph Dijkstra; |d(u) − d(v)| ≤ |uv|; edge-midpoint
// queries within their ends' bounds; the traced path as long as the distance; on planar meshes
// d equals the Euclidean (rectangle) or planar-domain distance to 1e-9 × diagonal; optionally a
// stop distance keeps exactly the distances within it, a solve stopped by targets keeps theirs
// and every distance within its radius, and d(a, b) = d(b, a).
// Format, check and seeds: verify/include/geodex/verify/cases/fuzz_solver.h.
#include "decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geodex;
  const auto c = fuzz::decodeAs<verify::SolverCase>(fuzz::FuzzTarget::Solver, data, size);
  if (!c) return 0;
  fuzz::require(verify::checkSolver(*c), fuzz::FuzzTarget::Solver, data, size);
  return 0;
}
