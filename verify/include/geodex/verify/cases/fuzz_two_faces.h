#pragma once
// fuzz_two_faces: two faces sharing an edge (any 3-D lattice positions: bent, flat, folded,
// zero-area) and a source point → a full solve with the full InvariantChecker and the unfolding
// check (every propagated child's distance equals σ + the 3-D distance to its parent's
// pseudo-source unfolded into the crossed face); distances at vertices, edge and face points
// equal the exact two-face distance (straight within a face, else the minimum over the shared
// edge). Its libFuzzer main is fuzz/fuzz_two_faces.cpp.

#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <vector>

#include "geodex/mesh.h"
#include "geodex/surface_point.h"
#include "geodex/verify/cases/byte_codec.h"
#include "geodex/verify/cases/fuzz_target.h"
#include "geodex/verify/cases/source_spec.h"

namespace geodex::verify {

/// The bytes: faces B = (v0, v1, v2) and A = (v0, v2, w) sharing the edge v0v2; windows from
/// the source cross into the other face.
struct TwoFaceSpec {
  std::int8_t unitExp = 0;
  std::array<std::array<Quantity, 3>, 4> points;  ///< v0, v2, v1, w: coordinates ∈ [−16, 16]
  std::uint8_t winding = 0;  ///< bit 0 flips B, bit 1 flips A
  SourceSpec source;
};

std::vector<std::uint8_t> encode(const TwoFaceSpec& s);

struct TwoFaceCase {
  TriangleSoup soup;  ///< vertices v0, v2, v1, w; face 0 = B, face 1 = A
  SurfacePoint source;
};

/// The case the bytes describe, or nullopt when the target skips them: too long, or two faces
/// the validator refuses.
std::optional<TwoFaceCase> decodeTwoFaces(std::span<const std::uint8_t> bytes);

Verdict checkTwoFaces(const TwoFaceCase& c);

/// The two faces as a tiny OFF file and the source.
void describe(const TwoFaceCase& c, std::ostream& out);
/// Both faces unfolded into one plane, the source, and the intervals after the solve coloured by
/// pseudo-source.
void writeSvg(const TwoFaceCase& c, std::ostream& out);

/// The committed corpus (corpus/fuzz_two_faces/): bent, flat, folded and zero-area pairs of
/// faces with sources on vertices, edges and faces, named after what they must hit, and the
/// regress files that can be described.
std::vector<Seed> twoFaceSeeds();

}  // namespace geodex::verify
