// fuzz_propagation: one face (3-D lattice positions nudged by the tolerances: needles, zero-area
// faces and collinear sources are common) and one interval on its edge v0v2 → the solver's one
// propagation step: the LocalWindow as GeodesicSolver::propagate builds it, propagateLocal, and
// childInterval for each child. Checks: each child's distance σ + |x − s'| equals the parent's
// distance field σ + |P − S3| at points of its range, S3 the pseudo-source unfolded across v0v2 in
// 3-D; every sampled ray of the window leaves the face inside a child; children lie within their
// edges, at most one per edge; the Fig. 6 branch equals the exact tree off ε-ambiguity. No mesh,
// no solver.
// Format, check and seeds: verify/include/geodex/verify/cases/fuzz_propagation.h.
#include "decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geodex;
  const auto c = fuzz::decodeAs<verify::PropagationCase>(fuzz::FuzzTarget::Propagation, data, size);
  if (!c) return 0;
  fuzz::require(verify::checkPropagation(*c), fuzz::FuzzTarget::Propagation, data, size);
  return 0;
}
