#pragma once
// A source point as the bytes of fuzz_two_faces and fuzz_solver give it: a vertex, a point on an
// edge of a face, or a point inside a face, each found by index modulo the soup's size so that
// every byte means some point of the mesh.

#include <cstdint>

#include "geodex/mesh.h"
#include "geodex/surface_point.h"
#include "geodex/verify/cases/byte_codec.h"

namespace geodex::verify {

struct SourceSpec {
  std::uint8_t kind = 0;     ///< mod 3: vertex, edge point, face point
  std::uint8_t element = 0;  ///< vertex: index mod #V (an unreferenced one moves to a face's
                             ///< corner); edge and face point: face index mod #F
  std::uint8_t corner = 0;   ///< edge point: the edge from corner k mod 3 to corner k + 1
  Quantity t;                ///< edge point: t ∈ [0, 16] / 16; nudges relative to 1
  Quantity a, b;             ///< face point: barycentrics a, b ∈ [0, 16] / 16, c = 1 − a − b
                             ///< (reflected when a + b > 1)
};

// Builders for readable seeds (the mesh targets' seeds()).
/// Vertex v.
SourceSpec atVertex(int v);
/// On the edge from corner k to corner k + 1 of face f, at t (lattice 0..16 over 16).
SourceSpec onEdge(int f, int k, Quantity t);
/// In face f with barycentrics a, b (lattice 0..16 over 16) and 1 − a − b.
SourceSpec inFace(int f, Quantity a, Quantity b);

SourceSpec readSourceSpec(ByteReader& r);
void writeSourceSpec(ByteWriter& w, const SourceSpec& s);

/// The point s stands for on the soup (which has at least one face).
SurfacePoint makeSource(const SourceSpec& s, const TriangleSoup& soup);

}  // namespace geodex::verify
