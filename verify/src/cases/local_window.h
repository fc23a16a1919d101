#pragma once
// One window crossing one face in the frame of Fig. 3 (LocalWindow: v0 = (0, 0), v2 = (L, 0),
// the apex v1 above e0, the source s below it), as fuzz_predicates and fuzz_propagation judge
// propagateLocal on it: where the window's rays leave the face, whether the children cover the
// wedge, whether the tree decides the window alike at another scale, the window as text and as a
// picture. Private to verify/src/cases (hence namespace detail).

#include <ostream>
#include <span>
#include <string>

#include "geodex/propagate.h"

namespace geodex::verify::detail {

/// |sin| of the angle between a and b, or 2 when they point apart (or one is zero).
double sinAngle(const Vec2& a, const Vec2& b);

/// Whether the Fig. 6 tree must decide w and its unit-scale copy u (atUnitScale) bit for bit
/// alike: every value scales exactly, and each is zero or within 2^±100 of the face's size, so
/// that no product of four of them (sideOfRay) leaves the normal range at either scale. (A window
/// that much narrower than its edge is far below what the solver keeps, D1; its crossings round
/// in the subnormal range, differently at each scale.)
bool decidedAlikeAtUnitScale(const LocalWindow& w, const LocalWindow& u);

/// Whether two runs of the Fig. 6 tree ended alike, bit for bit: the leaf and every child.
bool sameDecision(const LocalPropagation& a, const LocalPropagation& b);

/// Where a ray leaves the face: on e1 (v0v1) or e2 (v1v2), at parameter t from the edge's first
/// vertex.
struct Exit {
  int edge = 0;  ///< 0: none found
  double t = 0.0;
  Vec2 point{0.0, 0.0};
};

/// Where the ray from s through p (p on e0, s below it) leaves the face v0 v1 v2.
Exit exitOf(const Vec2& s, const Vec2& p, const Vec2& v0, const Vec2& v1, const Vec2& v2);

/// The point at parameter t of e1 (edge 1, from v0) or e2 (edge 2, from v1).
Vec2 childPoint(const LocalWindow& w, int edge, double t);

/// "L=… apex=(…) window=[b0, b1] s=(…)" to 17 digits.
std::string describeLocal(const LocalWindow& w);
/// The branch and each child's edge and range, "G2 e2[0, 0.5]".
std::string describeResult(const LocalPropagation& r);

// === Coverage of the wedge =====================================================================

/// The angle by which an ε-decision of Fig. 6 may move a boundary ray of the wedge: the
/// collinearity angle, or a coincidence distance seen from s; 100× that is the slack of the
/// coverage and soundness checks (bugs move rays by far more).
double wedgeSlack(const LocalWindow& w);

/// What is wrong with propagateLocal's children (at most two, on e1 or e2, one per edge,
/// 0 <= t0 <= t1 <= 1), or nullptr.
const char* localChildrenProblem(const LocalPropagation& r);

struct Coverage {
  bool imageBelowEpsilon = false;  ///< nothing to cover: the wedge's image is below ε
  std::string uncovered;           ///< the first ray no child covers, or "" when all are covered
};

/// Coverage: every sampled ray from s through the window [b0, b1] that enters the face leaves it
/// through e1 or e2 inside one of `covering` (ranges in the local parameter of e1, e2), up to
/// 1e-12 in the parameter or wedgeSlack's angle from a covering range's end. Only for the
/// branches whose rays cross the face (not G1, not zero-area).
Coverage wedgeCoverage(const LocalWindow& w, std::span<const LocalChild> covering);

/// Draws the face in e0's frame, the window, the wedge from s to where its rays leave the face,
/// and propagateLocal's children on e1 (green) and e2 (purple); `extra` is a footer line.
void svgLocalWindow(const LocalWindow& w, std::ostream& out, const std::string& title = "fuzz_predicates",
                    const std::string& extra = "");

}  // namespace geodex::verify::detail
