// fuzz_propagation: one window across one face, against the 3-D geometry (fuzz_propagation.h).
#include "geodex/verify/cases/fuzz_propagation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <variant>

#include "check_support.h"
#include "fig6_exact.h"
#include "geodex/edge_intervals.h"
#include "geodex/mesh.h"
#include "geodex/predicates.h"
#include "geodex/tolerance.h"
#include "geodex/verify/repro.h"  // FuzzCase, which the seeds' expectations take
#include "local_window.h"

namespace geodex::verify {

using namespace detail;

// ===  Format ====================================================================================

namespace {

PropagationSpec readPropagationSpec(ByteReader& r) {
  PropagationSpec s;
  s.unitExp = r.i8();
  for (auto& p : s.points)
    for (auto& c : p) c = r.quantity();
  s.b0 = r.quantity();
  s.b1 = r.quantity();
  s.sourceMode = r.u8();
  s.sourceX = r.quantity();
  s.sourceY = r.quantity();
  s.sigma = r.quantity();
  s.childDirections = r.u8();
  return s;
}

}  // namespace

std::vector<std::uint8_t> encode(const PropagationSpec& s) {
  ByteWriter w;
  w.i8(s.unitExp);
  for (const auto& p : s.points)
    for (const auto& c : p) w.quantity(c);
  w.quantity(s.b0);
  w.quantity(s.b1);
  w.u8(s.sourceMode);
  w.quantity(s.sourceX);
  w.quantity(s.sourceY);
  w.quantity(s.sigma);
  w.u8(s.childDirections);
  return w.bytes();
}

// ===  Decoding ==================================================================================

LocalWindow localWindowOf(const PropagationCase& c) {
  // As Mesh builds the frame of a face on its edge (mesh.cpp) and GeodesicSolver::propagate the
  // window from an interval: x from v0 along e0, the apex's height by the cross product, the
  // source reflected below e0.
  const Vec3 origin = c.face[0];
  const double L = (c.face[1] - origin).norm();
  const Vec3 dir = (c.face[1] - origin) / L;
  const Vec3 rel = c.face[2] - origin;
  const Vec2 apex(rel.dot(dir), rel.cross(dir).norm());
  return {L, apex, c.window.b0, c.window.b1, Vec2(c.window.source.x(), -c.window.source.y())};
}

namespace {

/// A face the solver computes with: each edge's length, in the face's own mesh units, passes
/// Mesh's check (edgeLengthProblem).
bool faceInRange(const Vec3& a, const Vec3& b, const Vec3& c) {
  const MeshUnit unit = meshUnitOf(std::max({a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff()}));
  for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &c}, std::pair{&c, &a}}) {
    if (edgeLengthProblem(((*q - *p) * unit.inverse).norm(), unit) != EdgeLengthProblem::None) return false;
  }
  return true;
}

std::optional<PropagationCase> makePropagationCase(const PropagationSpec& s) {
  const double unit = unitOf(s.unitExp);
  PropagationCase c;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) c.face[i][k] = fieldValue(s.points[i][k], -16, 16, unit, 16 * unit);
  const Vec3 &v0 = c.face[0], &v2 = c.face[1], &v1 = c.face[2];
  // The face a mesh would accept: every edge in range (no zero-length edge, no underflow).
  if (!isFinite(v0) || !isFinite(v1) || !isFinite(v2) || !faceInRange(v0, v1, v2)) return std::nullopt;
  // e0's length as the solver has it, in the face's mesh units (checkPropagation works there),
  // scaled back by the power of two. Taken at the input's own scale, a face of 1e-159 squared its
  // sides into subnormals, and the window ending at that length reached 2.3e-7 of it beyond the
  // edge (regress/coverage-window-end-beyond-its-edge-by-a-subnormal-edge-length). Where the
  // length scaled back is not exact (subnormal itself), no window of this format ends at it.
  const MeshUnit faceUnit = meshUnitOf(std::max({v0.cwiseAbs().maxCoeff(), v1.cwiseAbs().maxCoeff(), v2.cwiseAbs().maxCoeff()}));
  const double lengthInUnits = ((v2 - v0) * faceUnit.inverse).norm();
  if (inFileUnitsRange(lengthInUnits, faceUnit) != ScaledRange::Normal) return std::nullopt;
  const double L = lengthInUnits * faceUnit.unit;
  Interval& w = c.window;
  double b0 = latticeValue(s.b0, 0, 16) / 16.0 * L + nudgeValue(s.b0, L);
  double b1 = latticeValue(s.b1, 0, 16) / 16.0 * L + nudgeValue(s.b1, L);
  if (b0 > b1) std::swap(b0, b1);
  w.b0 = std::max(b0, 0.0);
  w.b1 = std::min(b1, L);
  if (!(w.b0 < w.b1)) return std::nullopt;
  const double scale = 16 * unit;
  switch (s.sourceMode % 3) {
    case 0:
      w.source = Vec2(fieldValue(s.sourceX, -64, 80, unit, scale), std::abs(fieldValue(s.sourceY, 0, 64, unit, scale)));
      break;
    default: {
      // On the line from v1 through b (in e0's frame, v1 above e0, the source below), beyond b.
      const Vec2 apex = localWindowOf(c).apex;
      const Vec2 b(s.sourceMode % 3 == 1 ? w.b0 : w.b1, 0.0);
      const Vec2 away = b - apex;
      const double lambda = std::abs(fieldValue(s.sourceX, 0, 64, 0.125, 0.125));
      const Vec2 across = away.norm() > 0.0 ? Vec2(-away.y(), away.x()) / away.norm() : Vec2(0.0, 0.0);
      const Vec2 below = b + lambda * away + fieldValue(s.sourceY, -16, 16, unit, scale) * across;
      w.source = Vec2(below.x(), std::abs(below.y()));
    }
  }
  w.sigma = std::abs(fieldValue(s.sigma, 0, 64, unit, scale));
  w.origin = -1;
  if (!isFinite(w.source) || !std::isfinite(w.sigma)) return std::nullopt;
  // Only a window the solver can propagate: step 6 holds every interval of a list to at least its
  // D1 ε (tinyLength, relative to its source's distance) unless it is the whole edge (the last
  // one left on an edge shorter than ε); a narrower one is removed by Algorithm 2 step 3 before
  // it is ever propagated, so what its children lose is lost nowhere. Seen grazing from far away,
  // such a window's rounded ray directions smear over a long stretch of the edge it crosses, which
  // the coverage check would ask its children to cover
  // (regress/coverage-window-below-its-epsilon-seen-grazing-from-far).
  if (w.b1 - w.b0 < tinyLength(w, L) && !(w.b0 == 0.0 && w.b1 == L)) return std::nullopt;
  c.e1Forward = (s.childDirections & 1) == 0;
  c.e2Forward = (s.childDirections & 2) == 0;
  return c;
}

}  // namespace

std::optional<PropagationCase> decodePropagation(std::span<const std::uint8_t> bytes) {
  if (bytes.size() > kMaxFuzzInputBytes) return std::nullopt;
  ByteReader r(bytes);
  return makePropagationCase(readPropagationSpec(r));
}

// ===  Check =====================================================================================

namespace {

/// Coordinates of a point of the face's plane relative to e0: along e0 from v0, and across it
/// towards the apex. A point of the face (a child edge's point) is on the apex's side, so its
/// second coordinate is its distance from e0's line, taken without forming the plane's normal:
/// for a needle that normal is the direction of a tiny cross product and carries rounding
/// divided by the needle's height, which these coordinates do not.
/// Takes points as offsets from v0 (p − v0), never as positions: a point placed in absolute
/// coordinates is rounded to the ulp of its coordinates, which for a tiny face far from the
/// origin is a good part of the face, while an offset from v0 is rounded relative to itself
/// (regress/unfolding-sample-point-placed-at-1408-on-a-1e-12-face).
struct PlaneCoordinates {
  Vec3 along;  ///< e0's unit direction
  Vec2 operator()(const Vec3& fromV0) const { return {fromV0.dot(along), fromV0.cross(along).norm()}; }
};

/// The mesh edge a child of the case lands on (e1: v0v1, e2: v1v2), from its vertex[0] to its
/// vertex[1] as the case's directions say.
struct CaseChildEdge {
  Vec3 from, to;
  double length;  ///< |to − from|, as Mesh computes an edge's length
  bool forward;
};
CaseChildEdge childEdgeOf(const PropagationCase& c, int edge) {
  const Vec3 &v0 = c.face[0], &v2 = c.face[1], &v1 = c.face[2];
  const bool onE1 = edge == 1;
  const bool forward = onE1 ? c.e1Forward : c.e2Forward;
  const Vec3& segmentStart = onE1 ? v0 : v1;
  const Vec3& segmentEnd = onE1 ? v1 : v2;
  CaseChildEdge e{forward ? segmentStart : segmentEnd, forward ? segmentEnd : segmentStart, 0.0, forward};
  e.length = (e.to - e.from).norm();
  return e;
}

/// childInterval for one of the case's children, on its edge as childEdgeOf gives it.
ChildInterval childIntervalOf(const PropagationCase& c, const LocalWindow& w, const LocalChild& ch) {
  const CaseChildEdge e = childEdgeOf(c, ch.edge);
  return childInterval(w, ch, {e.length, e.forward}, childEdgesOnOneLine(w));
}

/// The case in its face's mesh units (MeshUnit), as the solver meets the face of a mesh; nullopt
/// when a value of the window is beyond the largest double there: no mesh the solver holds has
/// such a window (regress/unfolding-sigma-beyond-the-largest-double-in-mesh-units).
std::optional<PropagationCase> inMeshUnits(const PropagationCase& c, MeshUnit& unit) {
  double largest = 0.0;
  for (const Vec3& p : c.face) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  unit = meshUnitOf(largest);
  // (Tested by exponent before multiplying: debug test runs trap an overflow.)
  for (double x : {c.window.b0, c.window.b1, c.window.source.x(), c.window.source.y(), c.window.sigma})
    if (!std::isfinite(x) || inMeshUnitsRange(x, unit) == ScaledRange::Overflow) return std::nullopt;
  PropagationCase m = c;
  for (Vec3& p : m.face) p *= unit.inverse;
  m.window.b0 *= unit.inverse;
  m.window.b1 *= unit.inverse;
  m.window.source *= unit.inverse;
  m.window.sigma *= unit.inverse;
  return m;
}

using detail::scalesExactly;

/// Whether every value of w times k (a power of two) is exact: the Fig. 6 tree decides w and
/// w × k alike only then; a value far below its face's size may underflow to 0 at the input's
/// scale (regress/scale-invariance-apex-offset-underflows-at-the-inputs-scale).
bool scalesExactly(const LocalWindow& w, double k) {
  for (double x : {w.edgeLength, w.apex.x(), w.apex.y(), w.b0, w.b1, w.source.x(), w.source.y()})
    if (!scalesExactly(x, k)) return false;
  return true;
}

/// "the e1 child [b0, b1] s=… (edge length …)".
std::string describeChild(int edge, const Interval& n, double length) {
  std::ostringstream os;
  os << std::setprecision(17) << "the e" << edge << " child " << describeInterval(n) << " (edge length " << length
     << ")";
  return os.str();
}

/// The child's distance σ + |x − s'| at points of its range equals the parent's distance field
/// there, σ + |P − S3|, with S3 the parent's pseudo-source unfolded into the face's plane on the
/// far side of e0 from the apex: in the plane coordinates (along e0, towards the apex)
/// S3 = (s.x, −s.y) and a point P of the face is (a, b) with b >= 0, so
/// |P − S3| = hypot(a − s.x, b + s.y). P is placed from the mesh positions, x along the child
/// edge from its vertex[0]; nothing of the solver's frame or of the child's source is used.
/// Returns what differs at the first sample that is off, or "" when none is.
///
/// Tolerance: every length here is a difference of input positions or derived from such
/// differences (no point is placed in absolute coordinates: see PlaneCoordinates; a difference
/// of two doubles is rounded relative to itself, so the coordinates' magnitude does not enter).
/// The solver's frame, childInterval's re-expression of the source and this construction each
/// round by a few ulps of the largest length involved, σ + |s| + the face's longest edge:
/// kRoundingRel (45 ulps) of that. Plus one deliberate step of the solver: a source within the
/// drop band on the wrong side of the child edge's line (rounding, says childInterval) is put on
/// the line, which lowers the child's distances by at most its height there, `acrossLine`.
std::string unfoldingProblem(const PropagationCase& c, const LocalWindow& w, int edge, const CaseChildEdge& e,
                             const Interval& n) {
  const PlaneCoordinates plane{(c.face[1] - c.face[0]).normalized()};
  const double sx = c.window.source.x(), sy = c.window.source.y(), sigma = c.window.sigma;
  const double length = e.length;
  const Vec3 fromV0 = e.from - c.face[0];
  const Vec2 Q0 = plane(fromV0), Q1 = plane(e.to - c.face[0]), S(sx, -sy);
  const Vec2 u = (Q1 - Q0).normalized();
  // The face lies right of e1 (v0→v1) and e2 (v1→v2), both as Q1 − Q0 when forward: in these
  // coordinates v0 = (0, 0), v2 = (L, 0) and v1 has b >= 0, a clockwise turn. (Not the side of
  // the third vertex: for a needle seen from its far end that cross product is below its
  // rounding.)
  const double towardsFace = e.forward ? -1.0 : 1.0;
  const double acrossLine = std::max(0.0, -towardsFace * pred::cross(u, S - Q0));
  const double tolerance = tol::kRoundingRel * (sigma + Vec2(sx, sy).norm() + localScale(w)) + acrossLine;
  const Vec3 edgeDir = (e.to - e.from) / length;
  for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double x = f == 1.0 ? n.b1 : n.b0 + f * (n.b1 - n.b0);
    const Vec2 P = plane(fromV0 + x * edgeDir);
    const double truth = sigma + std::hypot(P.x() - sx, P.y() + sy);
    const double claim = sigma + std::hypot(x - n.source.x(), n.source.y());
    if (!(std::abs(claim - truth) <= tolerance)) {
      std::ostringstream os;
      os << std::setprecision(17) << "at x = " << x << " " << describeChild(edge, n, length) << " gives sigma + "
         << claim - sigma << " but the parent's pseudo-source unfolded in 3-D is " << truth - sigma
         << " away (tolerance " << tolerance << ")";
      return os.str();
    }
  }
  return "";
}

}  // namespace

Verdict checkPropagation(const PropagationCase& input) {
  Verdict v;
  // The solver propagates in mesh units; the checks below do too, so that their own arithmetic
  // holds at any scale the decoder reaches.
  MeshUnit unit;
  const auto inUnits = inMeshUnits(input, unit);
  if (!inUnits) return v.summary = "a value is beyond the largest double in mesh units: outside the solver's range", v;
  const PropagationCase& c = *inUnits;
  const LocalWindow w = localWindowOf(c);
  // A source farther than any mesh the solver accepts can put it (docs/numerics.md, step 2) is
  // outside propagateLocal's contract: its products of four lengths overflow, and everything reads
  // as collinear with it
  // (regress/exact-predicates-source-1e302-face-sizes-away-outside-the-solvers-range).
  const double faceSize = std::max({w.edgeLength, std::abs(w.apex.x()), std::abs(w.apex.y())});
  if (!(std::max(std::abs(w.source.x()), std::abs(w.source.y())) <= tol::kMaxSourceDistanceInFaceSizes * faceSize))
    return v.summary = "the source is farther from the face than any mesh can put it: outside the solver's range", v;
  v.interesting = true;
  LocalPropagation r;
  try {
    r = propagateLocal(w);
  } catch (const std::exception& e) {
    return fail(v, "unexpected-exception", std::string("propagateLocal threw: ") + e.what());
  }
  // The Fig. 6 tree decides the same configuration at the input's own scale identically, bit for
  // bit (the children are parameters): scaling by a power of two must change nothing.
  {
    const double k = unit.unit;
    const LocalWindow atScale{w.edgeLength * k, w.apex * k, w.b0 * k, w.b1 * k, w.source * k};
    if (scalesExactly(w, k) && decidedAlikeAtUnitScale(atScale, atUnitScale(w))) {
      const LocalPropagation scaled = propagateLocal(atScale);
      if (!sameDecision(scaled, r)) {
        std::ostringstream os;
        os << std::setprecision(17) << "at the input's scale (2^" << unit.exponent << ") the tree gives "
           << describeResult(scaled) << ", in mesh units " << describeResult(r);
        return fail(v, "scale-invariance", os.str());
      }
    }
  }
  ++v.degeneracies.cases;
  if (const auto k = degeneracyOf(r.branch)) ++v.degeneracies[*k];
  if (r.branch == Fig6Branch::ZeroAreaFace) ++v.degeneracies.zeroAreaFaces;
  if (r.branch == Fig6Branch::G1Outside) ++v.degeneracies.sourceOnEdgeLineOutside;
  v.summary = name(r.branch);
  auto where = [&] {
    std::ostringstream os;
    os << std::setprecision(17) << "\n  face v0 (" << c.face[0].transpose() << ") v2 ("
       << c.face[1].transpose() << ") v1 (" << c.face[2].transpose() << ")\n  window "
       << describeInterval(c.window) << "\n  local " << describeLocal(w) << " → " << describeResult(r)
       << "\n  e1 " << (c.e1Forward ? "v0→v1" : "v1→v0") << ", e2 " << (c.e2Forward ? "v1→v2" : "v2→v1");
    return os.str();
  };

  // (c) propagateLocal's children, then (d) its branch against the exact tree where every
  // predicate on the path is clearly decided (fuzz_predicates' checks, on this face's frame).
  if (const char* why = localChildrenProblem(r)) return fail(v, "child-range", why + where());
  const ExactFig6 exact = exactFig6(w);
  if (exact.branch && *exact.branch != r.branch) {
    return fail(v, "exact-predicates",
                "exactly evaluated the tree ends in " + std::string(name(*exact.branch)) + where());
  }

  // The children as the solver makes them (childInterval), each checked against the 3-D face.
  std::array<LocalChild, 2> made{};
  int numMade = 0;
  for (int i = 0; i < r.numChildren; ++i) {
    const LocalChild& ch = r.children[i];
    const CaseChildEdge e = childEdgeOf(c, ch.edge);
    const double length = e.length;
    const ChildInterval child = childIntervalOf(c, w, ch);
    if (child.outcome == ChildOutcome::SeenFromOutside) ++v.degeneracies.childEdgesSeenFromOutside;
    if (child.outcome != ChildOutcome::Made) continue;
    const Interval& n = child.interval;
    auto childText = [&] { return describeChild(ch.edge, n, length); };
    if (!(n.b0 >= 0.0 && n.b0 < n.b1 && n.b1 <= length))
      return fail(v, "child-range", childText() + " is not within 0 <= b0 < b1 <= its edge's length" + where());
    if (!(isFinite(n.source) && n.source.y() >= 0.0))
      return fail(v, "child-range", childText() + " has a source off its side or not finite" + where());
    if (numMade == 1 && made[0].edge == ch.edge)
      return fail(v, "child-range", "two children on e" + std::to_string(ch.edge) + where());
    // Back to the parameter along the directed segment e1 or e2, for the coverage check.
    made[numMade++] = e.forward ? LocalChild{ch.edge, n.b0 / length, n.b1 / length}
                              : LocalChild{ch.edge, 1.0 - n.b1 / length, 1.0 - n.b0 / length};

    // (a) The child against the parent's distance field in 3-D.
    if (const std::string why = unfoldingProblem(c, w, ch.edge, e, n); !why.empty())
      return fail(v, "unfolding", why + where());
  }

  // (b) Coverage by the children the solver keeps. Along e0 (G1) and through a zero-area face
  // the whole-edge children are the contract, nothing to sample (as in fuzz_predicates); a
  // grazing sliver given outside the window (G1 outside) is judged as any wedge's children.
  if (r.branch != Fig6Branch::ZeroAreaFace && r.branch != Fig6Branch::G1Inside &&
      !(r.branch == Fig6Branch::G1Outside && r.numChildren == 0)) {
    const Coverage coverage = wedgeCoverage(w, {made.data(), static_cast<std::size_t>(numMade)});
    if (!coverage.uncovered.empty()) return fail(v, "coverage", coverage.uncovered + where());
    if (coverage.imageBelowEpsilon) v.summary += " (image below epsilon)";
  }
  v.summary += ", " + std::to_string(numMade) + " of " + std::to_string(r.numChildren) + " children made";
  return v;
}

// ===  Description and picture ===================================================================

void describe(const PropagationCase& c, std::ostream& out) {
  out << std::setprecision(17);
  const Interval& w = c.window;
  out << "# fuzz_propagation: an interval on e0 = v0v2 propagated across the face v0 v1 v2\n"
      << "v0 " << c.face[0].transpose() << "\nv2 " << c.face[1].transpose() << "\nv1 "
      << c.face[2].transpose() << "\n"
      << "window " << w.b0 << " " << w.b1 << "\n"
      << "source " << w.source.x() << " " << w.source.y() << "   # in e0's frame, y on the far side from v1\n"
      << "sigma " << w.sigma << "\n"
      << "e1 " << (c.e1Forward ? "v0->v1" : "v1->v0") << "\ne2 " << (c.e2Forward ? "v1->v2" : "v2->v1") << "\n";
  // What the check computes: the case in its face's mesh units, as the solver meets it (at the
  // input's own scale a tiny face's squares are subnormal, and the frame comes out otherwise).
  MeshUnit unit;
  const std::optional<PropagationCase> inUnits = inMeshUnits(c, unit);
  if (!inUnits) {
    out << "# a value is beyond the largest double in mesh units: outside the solver's range\n";
    return;
  }
  const PropagationCase& m = *inUnits;
  const LocalWindow local = localWindowOf(m);
  out << "# local frame, in mesh units of 2^" << unit.exponent << ": " << describeLocal(local)
      << "; local scale " << localScale(local) << "\n";
  const LocalPropagation r = propagateLocal(local);
  out << "# propagateLocal: " << describeResult(r) << "\n";
  const ExactFig6 e = exactFig6(local);
  out << "# exact tree: " << (e.branch ? std::string(name(*e.branch)) : "undecided, near " + e.nearWhat) << "\n";
  for (int i = 0; i < r.numChildren; ++i) {
    const ChildInterval made = childIntervalOf(m, local, r.children[i]);
    out << "# childInterval e" << int(r.children[i].edge) << (childEdgeOf(m, r.children[i].edge).forward ? "" : " (backward)") << ": "
        << (made.outcome == ChildOutcome::Made ? describeInterval(made.interval)
            : made.outcome == ChildOutcome::Empty ? std::string("empty")
                                                  : std::string("dropped: the source is seen from outside the face"))
        << "\n";
  }
}

/// The face unfolded onto e0's frame with the window, its wedge and propagateLocal's ranges (as
/// fuzz_predicates draws them), and childInterval's intervals in the footer.
void writeSvg(const PropagationCase& c, std::ostream& out) {
  const LocalWindow w = localWindowOf(c);
  const LocalPropagation r = propagateLocal(w);
  std::ostringstream os;
  os << std::setprecision(6) << "sigma=" << c.window.sigma << "  children:";
  for (int i = 0; i < r.numChildren; ++i) {
    const LocalChild& ch = r.children[i];
    const ChildInterval made = childIntervalOf(c, w, ch);
    os << " e" << int(ch.edge) << (childEdgeOf(c, ch.edge).forward ? "" : " (backward)") << " ";
    if (made.outcome == ChildOutcome::Made)
      os << "[" << made.interval.b0 << ", " << made.interval.b1 << "] s'=(" << made.interval.source.x() << ", "
         << made.interval.source.y() << ")";
    else
      os << (made.outcome == ChildOutcome::Empty ? "empty" : "dropped (seen from outside)");
  }
  svgLocalWindow(w, out, "fuzz_propagation", os.str());
}

// ===  Seeds =====================================================================================
// One face v0, v2, v1 in 3-D and one interval on e0 = v0v2: b0, b1 in 16ths of |v0v2|, the source
// in e0's frame (x from v0, y its height on the far side from v1), or on the line from v1 through
// b0 (mode 1) or b1 (mode 2), λ × |b − v1| beyond b with λ = sourceX / 8.

namespace {

using Q = Quantity;
Q n(int v) { return Q::lattice(v); }

using FacePoints = std::array<std::array<Q, 3>, 3>;

FacePoints facePoints(std::array<std::array<int, 3>, 3> p) {
  FacePoints f;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) f[i][k] = n(p[i][k]);
  return f;
}

struct OneFace {
  FacePoints points;  ///< v0, v2, v1
  Q b0, b1;
  Q sourceX, sourceY;
  std::uint8_t sourceMode = 0;
  Q sigma = n(0);
  std::uint8_t childDirections = 0;  ///< bit 0: e1 runs v1→v0, bit 1: e2 runs v2→v1
  int unitExp = 0;
};

using PropagationExpect = std::function<std::string(const PropagationCase&, const Verdict&)>;

/// A seed whose window propagateLocal must decide as `expected`, and that meets `extra`.
Seed propagation(const std::string& name, Fig6Branch expected, const OneFace& f, PropagationExpect extra = {}) {
  PropagationSpec s;
  s.unitExp = static_cast<std::int8_t>(f.unitExp);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) s.points[i][k] = f.points[i][k];
  s.b0 = f.b0, s.b1 = f.b1;
  s.sourceMode = f.sourceMode;
  s.sourceX = f.sourceX, s.sourceY = f.sourceY;
  s.sigma = f.sigma;
  s.childDirections = f.childDirections;
  return {name, encode(s), [expected, extra](const FuzzCase& c, const Verdict& v) {
            const auto& pc = std::get<PropagationCase>(c);
            const auto r = propagateLocal(localWindowOf(pc));
            if (r.branch != expected)
              return "ends in " + std::string(geodex::name(r.branch)) + ", not " + std::string(geodex::name(expected));
            return extra ? extra(pc, v) : std::string();
          }};
}

/// The case makes `count` children (as the verdict's summary counts them).
PropagationExpect childrenMade(int count) {
  return [count](const PropagationCase&, const Verdict& v) {
    const std::string want = ", " + std::to_string(count) + " of ";
    return v.summary.find(want) != std::string::npos ? "" : "makes other than " + std::to_string(count) + " children: " + v.summary;
  };
}

}  // namespace

std::vector<Seed> propagationSeeds() {
  using B = Fig6Branch;
  // The face v0 = (0,0,0), v2 = (8,0,0), v1 = (4,4,0): e0's frame is the world's x-y plane, the
  // apex at (4, 4); lattice b = k means x = k/2. A source (x, y) lies at (x, −y) below e0.
  const FacePoints flat = facePoints({{{0, 0, 0}, {8, 0, 0}, {4, 4, 0}}});
  // A tilted face with no coordinate axis in its plane: collinear sources come from modes 1, 2.
  const FacePoints tilted = facePoints({{{1, 2, 3}, {9, -2, 5}, {3, 7, -4}}});
  // Needles: the flat face's apex moved onto e0 at x = 4 (or beyond v2, at 12), then lifted.
  const auto needle = [](int apexX, Q apexY) {
    FacePoints f = facePoints({{{0, 0, 0}, {8, 0, 0}, {apexX, 0, 0}}});
    f[2][1] = apexY;
    return f;
  };
  return {
    propagation("inside-wedge", B::InsideWedge, {flat, n(4), n(12), n(4), n(4)}, childrenMade(2)),
    propagation("left-of-wedge", B::LeftOfWedge, {facePoints({{{0, 0, 0}, {8, 0, 0}, {1, 4, 0}}}), n(8), n(12), n(5), n(4)},
                childrenMade(1)),
    propagation("right-of-wedge", B::RightOfWedge, {facePoints({{{0, 0, 0}, {8, 0, 0}, {7, 4, 0}}}), n(4), n(8), n(3), n(4)},
                childrenMade(1)),
    propagation("inside-wedge-window-whole-edge-sigma-5", B::InsideWedge, {flat, n(0), n(16), n(4), n(4), 0, n(5)}),
    propagation("inside-wedge-child-edges-backward", B::InsideWedge, {flat, n(4), n(12), n(4), n(4), 0, n(0), 3},
                childrenMade(2)),
    propagation("inside-wedge-e1-backward", B::InsideWedge, {flat, n(4), n(12), n(3), n(4), 0, n(0), 1}),
    propagation("inside-wedge-tilted-face", B::InsideWedge, {tilted, n(5), n(11), n(11), n(9)}),
    propagation("inside-wedge-far-source", B::InsideWedge, {flat, n(4), n(12), n(4), n(32).times8(6)}),
    propagation("inside-wedge-scaled-1e-6", B::InsideWedge, {flat, n(4), n(12), n(4), n(4), 0, n(3), 0, -20}),
    propagation("inside-wedge-scaled-1e+6", B::InsideWedge, {flat, n(4), n(12), n(4), n(4), 0, n(3), 0, 20}),
    // G1: the source on e0's line.
    propagation("G1-source-at-b0", B::G1Inside, {flat, n(4), n(12), n(2), n(0)}),
    propagation("G1-source-at-b1", B::G1Inside, {flat, n(4), n(12), n(6), n(0)}),
    propagation("G1-source-on-e0-line-outside-window", B::G1Outside, {flat, n(4), n(12), n(-3), n(0)}, childrenMade(0)),
    propagation("G1-G2-G4-source-at-b0-at-v0", B::G1Inside, {flat, n(0), n(12), n(0), n(0)}),
    propagation("G1-G3-G5-source-at-b1-at-v2", B::G1Inside, {flat, n(4), n(16), n(8), n(0)}),
    propagation("G1-source-half-tolerance-below-e0", B::G1Inside,
                {flat, n(4), n(12), n(2), n(0).nudged(4, Nudge::Coincide, true)}),
    // G2–G5: the source on the line through the apex and a window end.
    propagation("G2-source-b0-apex-collinear", B::G2, {flat, n(4), n(12), n(0), n(4)}),
    propagation("G3-source-b1-apex-collinear", B::G3, {flat, n(4), n(12), n(8), n(4)}),
    propagation("G4-source-v0-b0-collinear", B::G4, {flat, n(0), n(12), n(-4), n(4)}),
    propagation("G5-source-v2-b1-collinear", B::G5, {flat, n(4), n(16), n(12), n(4)}),
    propagation("G2-tilted-face-source-on-line-v1-b0", B::G2, {tilted, n(5), n(11), n(12), n(0), 1}),
    propagation("G3-tilted-face-source-on-line-v1-b1", B::G3, {tilted, n(5), n(11), n(12), n(0), 2}),
    propagation("G4-tilted-face-source-on-line-v1-v0", B::G4, {tilted, n(0), n(11), n(12), n(0), 1}),
    propagation("G5-tilted-face-source-on-line-v1-v2", B::G5, {tilted, n(5), n(16), n(12), n(0), 2}),
    propagation("G4-far-source-on-line-v1-v0", B::G4, {tilted, n(0), n(11), n(64).times8(5), n(0), 1}),
    propagation("G2-G3-both-rays-through-apex-G2-first", B::G2,
                {flat, n(8), n(8).nudged(4, Nudge::Coincide), n(4), n(4)}),
    // Zero-area faces and needles.
    propagation("zero-area-face-apex-on-e0", B::ZeroAreaFace, {needle(4, n(0)), n(4), n(12), n(4), n(4)},
                [](const PropagationCase&, const Verdict& v) {
                  return v.degeneracies.zeroAreaFaces > 0 ? "" : "crosses no zero-area face";
                }),
    propagation("zero-area-face-apex-beyond-v2", B::ZeroAreaFace,
                {needle(12, n(0)), n(4), n(12), n(4), n(4), 0, n(0), 2}),
    propagation("zero-area-face-apex-before-v0-tilted", B::ZeroAreaFace,
                {facePoints({{{1, 2, 3}, {9, -2, 7}, {-3, 4, 1}}}), n(4), n(12), n(4), n(4)}),
    // Apex heights relative to 16 lattice units: 2.5e-13 × 16 is below kFlatFaceRel × 8, 16 ε × 16
    // is a needle of relative height 3.2e-10.
    propagation("zero-area-needle-below-flat-tolerance", B::ZeroAreaFace,
                {needle(4, n(0).nudged(4, Nudge::FlatFace, true)), n(4), n(12), n(4), n(4)}),
    propagation("needle-apex-16eps-above-e0", B::InsideWedge,
                {needle(4, n(0).nudged(16, Nudge::Coincide)), n(4), n(12), n(4), n(4)}, childrenMade(2)),
    propagation("needle-beyond-v2-far-source-right-of-wedge", B::RightOfWedge,
                {needle(12, n(0).nudged(16, Nudge::Coincide)), n(4), n(12), n(4), n(32).times8(6)}),
  };
}

}  // namespace geodex::verify
