// fuzz_predicates: one propagation case of the Fig. 6 decision tree (propagateLocal) on a local
// configuration snapped to a lattice and nudged by multiples of the tolerances, so that G1–G5
// and their composites are common. Checks: the branch equals the tree evaluated exactly (GMP
// rationals) wherever every predicate on the path is clearly decided; the children's ranges lie
// in [0, 1] with t0 <= t1; every sampled ray of the wedge leaves the face inside a child
// (coverage) and every child point is seen from s through [b0, b1] (soundness), up to 100× the
// tolerances' angle.
// Format, check and seeds: verify/include/geodex/verify/cases/fuzz_predicates.h.
#include "decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geodex;
  const auto c = fuzz::decodeAs<verify::PredicateCase>(fuzz::FuzzTarget::Predicates, data, size);
  if (!c) return 0;
  fuzz::require(verify::checkPredicates(*c), fuzz::FuzzTarget::Predicates, data, size);
  return 0;
}
