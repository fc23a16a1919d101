// fuzz_edge_update: Algorithm 2 (EdgeIntervals::insert) on one edge, from a valid list of up to
// 8 intervals (sorted, contiguous or with gaps, near-equal ends and sources, large σ) and an
// incoming interval. Checks: the list after is well formed (the cheap step-6 invariants), equals
// the pointwise minimum of the list before and the incoming interval (InvariantChecker's full
// tier, the same contract as inside the solver), invents no pseudo-source, and rewrites only the
// slice the update reports. Text reproducers written by verify::writeReproducer
// ("geodex-edge-update 1") are read too.
// Format, check and seeds: verify/include/geodex/verify/cases/fuzz_edge_update.h.
#include "decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geodex;
  const auto c = fuzz::decodeAs<verify::EdgeUpdateCase>(fuzz::FuzzTarget::EdgeUpdate, data, size);
  if (!c) return 0;
  fuzz::require(verify::checkEdgeUpdate(*c), fuzz::FuzzTarget::EdgeUpdate, data, size);
  return 0;
}
