#pragma once
// The degenerate cases of Liu, Zhou & Hu 2007, named as in the paper and DESIGN.md, and the
// counters the solver keeps of them: geometric-intersection cases G1–G5 over all propagation
// cases is the Fig. 6 rate `--stats` reports (not the paper's Table 1 rate: README, Degeneracies).

#include <array>
#include <cstdint>
#include <string_view>

namespace geodex {

enum class DegeneracyKind : std::uint8_t {
  // Geometric intersection (Sect. 3.1, Fig. 4), decided in the order of Fig. 6.
  G1,  ///< s coincides with b0 or b1: the pseudo-source lies on the line of e0
  G2,  ///< s, b0, v1 collinear (b0 ≠ v0)
  G3,  ///< s, b1, v1 collinear (b1 ≠ v2)
  G4,  ///< s, v0 = b0, v1 collinear
  G5,  ///< s, v2 = b1, v1 collinear
  // Geodesic discontinuities (Sect. 3.2), repaired by Algorithm 2 steps 3–5.
  D1,  ///< tiny interval (step 3 removes it)
  D2,  ///< consecutive intervals overlap (resolved at the midpoint)
  D3,  ///< consecutive intervals separated by a tiny gap (step 4 sews it)
  D4,  ///< distances differ at a shared endpoint after an Eq. 1 split (root polished)
  kCount
};
inline constexpr std::size_t kNumDegeneracyKinds = static_cast<std::size_t>(DegeneracyKind::kCount);

constexpr std::string_view name(DegeneracyKind k) {
  constexpr std::array<std::string_view, kNumDegeneracyKinds> names{"G1", "G2", "G3", "G4", "G5",
                                                                   "D1", "D2", "D3", "D4"};
  return names[static_cast<std::size_t>(k)];
}
constexpr bool isGeometric(DegeneracyKind k) { return k <= DegeneracyKind::G5; }

struct DegeneracyCounters {
  std::array<std::uint64_t, kNumDegeneracyKinds> count{};
  /// All propagation cases (one window propagated across one face), degenerate or not: the
  /// denominator of the Fig. 6 degeneracy rate.
  std::uint64_t cases = 0;
  /// Cases in which anything degenerate happened: a G1–G5 leaf of Fig. 6, or a D1–D4 repair at
  /// one of the case's children in the update of its batch's run on that edge
  /// (forEachRepairedIncoming, edge_intervals.h). The paper's Sect. 5 rate ("degenerate cases over
  /// all the cases") read this way is the closest we measure to its Table 1 (docs/paper.md).
  std::uint64_t degenerateCases = 0;
  /// Mesh-level cases the paper leaves out: windows passed through a zero-area face, and
  /// windows whose source lies on their own edge's line outside the window (their rays run
  /// along the edge; only those a hair off it enter the face, at a grazing angle).
  std::uint64_t zeroAreaFaces = 0;
  std::uint64_t sourceOnEdgeLineOutside = 0;
  /// Children dropped because their source lies clearly outside the face across their edge
  /// (the rays cannot leave through it; see GeodesicSolver::propagate).
  std::uint64_t childEdgesSeenFromOutside = 0;
  /// D1 slivers removed at an edge's vertex into a neighbour of another pseudo-source, or lost
  /// there outright to one (edge_intervals.cpp, reportFanOfALostSliver), whose vertex then relays
  /// the fan they would have made (GeodesicSolver::relayFanThroughVertex): the vertices made
  /// pseudo-sources this way.
  std::uint64_t d1FansRelayed = 0;
  /// Windows whose edge ray runs through the apex of the face they cross (G2–G5), whose apex
  /// then relays the fan beyond it (GeodesicSolver::propagate): the vertices made pseudo-sources
  /// this way.
  std::uint64_t apexFansRelayed = 0;
  /// Strips of an edge that the incoming window won by Algorithm 2's tie rule only, inside
  /// another window that goes on on both sides, left to that window (step 2) or given back to the
  /// incoming one around them (before steps 3–5): see edge_intervals.cpp, keepTieStripsInsideOld.
  std::uint64_t tieStripsKept = 0;

  std::uint64_t& operator[](DegeneracyKind k) { return count[static_cast<std::size_t>(k)]; }
  std::uint64_t operator[](DegeneracyKind k) const { return count[static_cast<std::size_t>(k)]; }
  std::uint64_t geometricTotal() const { return count[0] + count[1] + count[2] + count[3] + count[4]; }
  std::uint64_t discontinuityTotal() const { return count[5] + count[6] + count[7] + count[8]; }
  DegeneracyCounters& operator+=(const DegeneracyCounters& o) {
    for (std::size_t i = 0; i < kNumDegeneracyKinds; ++i) count[i] += o.count[i];
    cases += o.cases;
    degenerateCases += o.degenerateCases;
    zeroAreaFaces += o.zeroAreaFaces;
    sourceOnEdgeLineOutside += o.sourceOnEdgeLineOutside;
    childEdgesSeenFromOutside += o.childEdgesSeenFromOutside;
    d1FansRelayed += o.d1FansRelayed;
    apexFansRelayed += o.apexFansRelayed;
    tieStripsKept += o.tieStripsKept;
    return *this;
  }
};

}  // namespace geodex
