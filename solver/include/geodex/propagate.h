#pragma once
// One-face propagation (Surazhsky et al. Fig. 3 a/b/c) with the Fig. 6 decision tree of Liu, Zhou
// & Hu 2007 for the five geometric-intersection degeneracies G1–G5, on a *local configuration*:
// the face unfolded onto the window's edge e0 = v0v2, v0 at the origin, v2 at (L, 0), the apex v1
// above the x-axis, the pseudo-source s below it (y <= 0).
//
//   decision order (DESIGN.md):
//   (1) s on the line of e0 (s = b0 or s = b1)      G1: inside [b0,b1] → e1 and e2 whole;
//                                                      outside → nothing enters the face
//   (2) s, b0, v1 collinear                           e2; and if b0 = v0 also e1 whole (G4), else G2
//   (3) s, b1, v1 collinear                           e1; and if b1 = v2 also e2 whole (G5), else G3
//   (4) v1 left of ray s→b0                           e2 only  (if b0 = v0: Fig. 3c, see below)
//   (5) v1 right of ray s→b1                          e1 only  (if b1 = v2: mirror of Fig. 3c)
//   (6) otherwise, v1 strictly inside the wedge       e1 and e2 (Fig. 3b)
//
// Fig. 3c's "additional intervals" from v0 (or v2) as a pseudo-source are not made here: the
// window's value at v0 updates v0's distance, and when v0 is a saddle or boundary vertex the
// solver's pseudo-source event for v0 creates exactly those intervals (and the same ones for every
// other face around v0), once per improvement of v0's distance.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "geodex/degeneracy.h"
#include "geodex/interval.h"
#include "geodex/mesh.h"

namespace geodex {

/// The leaf of the Fig. 6 tree a propagation ended in.
enum class Fig6Branch : std::uint8_t {
  ZeroAreaFace,   ///< apex on the line of e0: the window passes straight through (not in the paper)
  G1Inside,       ///< (1) s on e0's line, within [b0, b1]
  G1Outside,      ///< (1) s on e0's line, outside [b0, b1]: only rays a hair off it enter the face
  G2,             ///< (2) s, b0, v1 collinear, b0 ≠ v0
  G4,             ///< (2) s, b0 = v0, v1 collinear
  G3,             ///< (3) s, b1, v1 collinear, b1 ≠ v2
  G5,             ///< (3) s, b1 = v2, v1 collinear
  LeftOfWedge,    ///< (4) Fig. 3a, interval on e2
  RightOfWedge,   ///< (5) Fig. 3a mirrored, interval on e1
  InsideWedge,    ///< (6) Fig. 3b
};
std::string_view name(Fig6Branch b);
/// The degeneracy counter a branch increments, if any.
std::optional<DegeneracyKind> degeneracyOf(Fig6Branch b);

/// The local configuration of one propagation case.
struct LocalWindow {
  double edgeLength;  ///< L = |v0 v2|
  Vec2 apex;          ///< v1, y >= 0
  double b0, b1;      ///< window range on e0, 0 <= b0 < b1 <= L
  Vec2 source;        ///< unfolded pseudo-source, y <= 0 (below e0, away from the apex)
};

/// A new interval on e1 (v0→v1) or e2 (v1→v2), as parameters along that directed segment.
struct LocalChild {
  std::uint8_t edge;  ///< 1 for e1, 2 for e2
  double t0, t1;      ///< 0 <= t0 <= t1 <= 1 along the directed segment
};

struct LocalPropagation {
  Fig6Branch branch;
  std::uint8_t numChildren = 0;
  std::array<LocalChild, 2> children{};
};

/// Runs the Fig. 6 decision tree and computes the new intervals' ranges. Pure function. At any
/// scale, for a configuration a mesh can have: the source within
/// tol::kMaxSourceDistanceInFaceSizes of the face's size (a window of a solve always is).
LocalPropagation propagateLocal(const LocalWindow& w);

/// The local length scale the predicates of one case are relative to: the face's longest edge.
double localScale(const LocalWindow& w);

/// The same configuration scaled by a power of two so that its face's largest coordinate lies in
/// [1, 2): exact while nothing leaves the normal range, and the children (parameters along e1
/// and e2) are the same. What propagateLocal decides a face far from unit size on, and what a
/// check computes its own geometry on at any scale. (A zero or non-finite size: w as it is.)
LocalWindow atUnitScale(const LocalWindow& w);

// ===  From a LocalChild to an Interval on the child edge =======================================

/// Whether the children of a propagation across this face lie on one line with e0: the apex is
/// within kFlatFaceRel of e0's line, relative to max(L, |v1|). (Relative to the two edges at v0,
/// not to localScale as propagateLocal's zero-area branch is: the two are separate decisions,
/// and making them one would change the solver's results, not only its code.)
bool childEdgesOnOneLine(const LocalWindow& w);

/// The mesh edge a LocalChild lies on: e1 (v0→v1) or e2 (v1→v2) of the local frame.
struct ChildEdge {
  double length;  ///< the edge's length as the mesh has it (the child's ends are t × length)
  /// The edge's vertex[0] is the start of the directed segment (v0 for e1, v1 for e2); false: the
  /// edge runs the other way and the child's range and source are mirrored along it.
  bool forward;
};

/// What became of a LocalChild.
enum class ChildOutcome : std::uint8_t {
  Made,             ///< an interval with b0 < b1
  Empty,            ///< its range is empty once scaled and clamped to the edge
  SeenFromOutside,  ///< the source lies clearly outside the face across the child edge: the rays
                    ///< cannot leave through it (counted: childEdgesSeenFromOutside)
};

struct ChildInterval {
  ChildOutcome outcome = ChildOutcome::Empty;
  /// When Made: b0 < b1 in [0, edge length] along the edge's own direction, and the source in the
  /// edge's frame (x from its vertex[0], y >= 0 on the crossed face's side). σ, side, origin and
  /// flags are left at their defaults for the caller: they belong to the mesh, not the frame.
  Interval interval;
};

/// The interval a propagation's child puts on its edge (Surazhsky et al. Sect. 3.3: the new
/// interval keeps its parent's pseudo-source, re-expressed in the child edge's frame). Pure.
///   w        the parent's local configuration (source below e0, as propagateLocal takes it)
///   c        one of propagateLocal(w)'s children
///   e        the mesh edge it lies on
///   oneLine  childEdgesOnOneLine(w), computed once per propagation
ChildInterval childInterval(const LocalWindow& w, const LocalChild& c, const ChildEdge& e, bool oneLine);

}  // namespace geodex
