// fuzz_two_faces: a face and its neighbour across the window's edge (any 3-D lattice positions:
// bent, flat, folded, zero-area) and a source point in either → a full solve. Checks: every
// interval a propagation creates has the distance σ + |P − s| of its parent's pseudo-source s
// unfolded into the crossed face, computed independently from the 3-D positions; the full
// invariant tier holds at every edge update; distances at the vertices, at edge points and at
// face points equal the exact two-face distance (straight within a face, else the minimum over
// the shared edge).
// Format, check and seeds: verify/include/geodex/verify/cases/fuzz_two_faces.h.
#include "decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geodex;
  const auto c = fuzz::decodeAs<verify::TwoFaceCase>(fuzz::FuzzTarget::TwoFaces, data, size);
  if (!c) return 0;
  fuzz::require(verify::checkTwoFaces(*c), fuzz::FuzzTarget::TwoFaces,
                data, size);
  return 0;
}
