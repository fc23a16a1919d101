#pragma once
// fuzz_propagation: the solver's one propagation step alone (propagateLocal, childInterval), on
// one 3-D face (lattice positions nudged by the tolerances: needles, zero-area faces, collinear
// sources are common) and one interval on its edge v0v2. Checks: each child's distance function
// equals σ + the 3-D distance to the parent's pseudo-source unfolded across v0v2; every sampled
// ray of the window leaves the face inside a child; children within their edges, at most one per
// edge; the branch equals the exactly evaluated Fig. 6 tree off ε-ambiguity, and the same at the
// input's own scale. No mesh, no solver. Its libFuzzer main is fuzz/fuzz_propagation.cpp.

#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <vector>

#include "geodex/interval.h"
#include "geodex/propagate.h"
#include "geodex/verify/cases/byte_codec.h"
#include "geodex/verify/cases/fuzz_target.h"

namespace geodex::verify {

/// The bytes: one face and one interval on its edge e0 = v0v2. The source is given in the
/// interval's frame on e0 (x from v0, y >= 0 its height on the far side of e0 from v1).
struct PropagationSpec {
  std::int8_t unitExp = 0;
  std::array<std::array<Quantity, 3>, 3> points;  ///< v0, v2, v1: coordinates ∈ [−16, 16];
                                                  ///< nudges relative to 16 lattice units
  Quantity b0, b1;  ///< along e0 in 16ths of its length L: ∈ [0, 16], swapped if reversed,
                    ///< clamped to [0, L]; nudges relative to L
  /// mod 3: 0 the source at (sourceX, sourceY); 1 (2) on the line from v1 through b0 (b1),
  /// beyond it: at b + λ (b − v1) with λ = sourceX / 8, then moved by sourceY across that line
  /// (G2–G5 in any face, not only in axis-aligned ones).
  std::uint8_t sourceMode = 0;
  Quantity sourceX;  ///< mode 0: x ∈ [−64, 80]; modes 1, 2: λ × 8 ∈ [0, 64] (|·| taken)
  Quantity sourceY;  ///< mode 0: y ∈ [0, 64] (|y| taken); modes 1, 2: an offset ∈ [−16, 16]
  Quantity sigma;    ///< σ ∈ [0, 64] (|σ| taken)
  /// bit 0: the mesh edge e1 runs v1 → v0; bit 1: e2 runs v2 → v1 (a child edge may run either
  /// way in a mesh, and the child interval is then mirrored along it).
  std::uint8_t childDirections = 0;
  // Nudges of b0, b1 are relative to L; of the source and σ to 16 lattice units.
};

std::vector<std::uint8_t> encode(const PropagationSpec& s);

struct PropagationCase {
  std::array<Vec3, 3> face;  ///< v0, v2, v1: the window's edge e0 = v0v2 and the apex
  /// On e0 (x from v0): b0 < b1 within [0, |v0v2|], the pseudo-source with y >= 0 on the far
  /// side of e0 from v1, σ >= 0.
  Interval window;
  bool e1Forward = true;  ///< the mesh edge e1 runs v0 → v1 (else v1 → v0)
  bool e2Forward = true;  ///< the mesh edge e2 runs v1 → v2 (else v2 → v1)
};
/// The LocalWindow GeodesicSolver::propagate builds for the case: e0's frame from the 3-D
/// positions as Mesh builds a face frame, the source reflected below e0.
LocalWindow localWindowOf(const PropagationCase& c);

/// The case the bytes describe, or nullopt when the target skips them: too long, a face a mesh
/// would refuse (an edge out of range), an empty window, a value not finite, or a window
/// narrower than its D1 ε that Algorithm 2 would have removed before propagating it.
std::optional<PropagationCase> decodePropagation(std::span<const std::uint8_t> bytes);

Verdict checkPropagation(const PropagationCase& c);

/// The face, the window, the local frame, propagateLocal's result, the exact tree's branch and
/// what childInterval makes of each child.
void describe(const PropagationCase& c, std::ostream& out);
/// The face in e0's frame with the window, its wedge and the children, as fuzz_predicates draws
/// them, and childInterval's intervals in the footer.
void writeSvg(const PropagationCase& c, std::ostream& out);

/// The committed corpus (corpus/fuzz_propagation/): seeds per Fig. 6 branch on flat, tilted and
/// needle faces, with child edges either way round, each named after the branch it must end in.
std::vector<Seed> propagationSeeds();

}  // namespace geodex::verify
