// fuzz_two_faces: a source across two faces, against the exact two-face distance
// (fuzz_two_faces.h).
#include "geodex/verify/cases/fuzz_two_faces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "check_support.h"
#include "geodex/geodesic_solver.h"
#include "geodex/mesh.h"
#include "geodex/tolerance.h"
#include "geodex/verify/invariant_checker.h"
#include "geodex/verify/oracles.h"
#include "geodex/verify/repro.h"  // FuzzCase, which the seeds' expectations take
#include "mesh_case.h"
#include "svg.h"

namespace geodex::verify {

using namespace detail;

// ===  Format ====================================================================================

namespace {

TwoFaceSpec readTwoFaceSpec(ByteReader& r) {
  TwoFaceSpec s;
  s.unitExp = r.i8();
  for (auto& p : s.points)
    for (auto& c : p) c = r.quantity();
  s.winding = r.u8();
  s.source = readSourceSpec(r);
  return s;
}

}  // namespace

std::vector<std::uint8_t> encode(const TwoFaceSpec& s) {
  ByteWriter w;
  w.i8(s.unitExp);
  for (const auto& p : s.points)
    for (const auto& c : p) w.quantity(c);
  w.u8(s.winding);
  writeSourceSpec(w, s.source);
  return w.bytes();
}

// ===  Decoding ==================================================================================

namespace {

std::optional<TwoFaceCase> makeTwoFaceCase(const TwoFaceSpec& s) {
  const double unit = unitOf(s.unitExp);
  TwoFaceCase c;
  for (const auto& p : s.points) {
    Vec3 x;
    for (int k = 0; k < 3; ++k) x[k] = fieldValue(p[k], -16, 16, unit, 16 * unit);
    c.soup.positions.push_back(x);
  }
  // v0 = 0, v2 = 1, v1 = 2, w = 3.
  c.soup.faces.push_back((s.winding & 1) ? std::array<Index, 3>{0, 1, 2} : std::array<Index, 3>{0, 2, 1});
  c.soup.faces.push_back((s.winding & 2) ? std::array<Index, 3>{1, 0, 3} : std::array<Index, 3>{0, 1, 3});
  if (!soupValid(c.soup)) return std::nullopt;
  c.source = makeSource(s.source, c.soup);
  return c;
}

}  // namespace

std::optional<TwoFaceCase> decodeTwoFaces(std::span<const std::uint8_t> bytes) {
  if (bytes.size() > kMaxFuzzInputBytes) return std::nullopt;
  ByteReader r(bytes);
  return makeTwoFaceCase(readTwoFaceSpec(r));
}

// ===  Check: the exact two-face distance ========================================================

namespace {

/// Bit f set when the point lies in face f (by the elements it names, not by its position).
unsigned facesOf(const TriangleSoup& soup, const SurfacePoint& p) {
  unsigned mask = 0;
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    const auto& F = soup.faces[f];
    auto has = [&](Index v) { return F[0] == v || F[1] == v || F[2] == v; };
    bool in = false;
    switch (p.kind) {
      case SurfacePoint::Kind::Vertex: in = has(p.vertex); break;
      case SurfacePoint::Kind::Edge: in = has(p.vertex) && has(p.toVertex); break;
      case SurfacePoint::Kind::Face: in = p.face == f; break;
    }
    if (in) mask |= 1u << f;
  }
  return mask;
}

/// min over c on segment ab of |s − c| + |c − q|: convex in the segment parameter, minimised by
/// golden-section search (to rounding) and compared with both ends.
double viaSegment(const Vec3& s, const Vec3& q, const Vec3& a, const Vec3& b) {
  auto f = [&](double u) {
    const Vec3 c = a + u * (b - a);
    return (s - c).norm() + (c - q).norm();
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0, hi = 1.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 200 && hi - lo > 1e-17; ++it) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return std::min({f(0.0), f(1.0), f1, f2, f(0.5 * (lo + hi))});
}

}  // namespace

Verdict checkTwoFaces(const TwoFaceCase& c) {
  Verdict v;
  v.interesting = true;
  auto mesh = buildMesh(c.soup, v);
  if (!mesh) return v;
  GeodesicSolver solver(*mesh);
  InvariantChecker invariants(CheckLevel::Full, true);
  UnfoldingChecker unfolding(*mesh, &invariants);
  solver.setObserver(&unfolding);
  const std::vector<SurfacePoint> sources{c.source};
  auto where = [&] { return "\nmesh:\n" + describeSoup(c.soup) + "source " + formatSurfacePoint(c.source); };
  if (!solveChecked(solver, sources, {}, v)) {
    v.message += where();
    return v;
  }
  v.degeneracies = solver.counters();
  v.summary = std::to_string(solver.counters().cases) + " propagation cases, " +
              std::to_string(unfolding.checked) + " unfolded distances checked";

  const TriangleSoup soup = soupInMeshUnits(*mesh);
  const Vec3 S = surfacePointPosition(soup, c.source);
  const unsigned sourceFaces = facesOf(soup, c.source);
  const Vec3 a = soup.positions[0], b = soup.positions[1];  // the shared edge v0 v2
  const double diag = mesh->boundingBoxDiagonalInMeshUnits();
  double largestCoordinate = 0.0;
  for (const Vec3& x : soup.positions) largestCoordinate = std::max(largestCoordinate, x.cwiseAbs().maxCoeff());
  const double placing = 2.0 * tol::kPositionRoundingRel * largestCoordinate;  // S and Q placed in 3D
  std::vector<SurfacePoint> queries;
  for (Index x = 0; x < 4; ++x) queries.push_back(SurfacePoint::atVertex(x));
  for (const auto& F : soup.faces) {
    for (int k = 0; k < 3; ++k)
      for (double t : {0.25, 0.5, 0.75}) queries.push_back(SurfacePoint::onEdge(F[k], F[(k + 1) % 3], t));
  }
  queries.push_back(SurfacePoint::inFace(0, 1.0 / 3, 1.0 / 3, 1.0 / 3));
  queries.push_back(SurfacePoint::inFace(1, 1.0 / 3, 1.0 / 3, 1.0 / 3));
  queries.push_back(SurfacePoint::inFace(0, 0.6, 0.3, 0.1));
  queries.push_back(SurfacePoint::inFace(1, 0.1, 0.3, 0.6));
  for (const SurfacePoint& q : queries) {
    const Vec3 Q = surfacePointPosition(soup, q);
    const double truth = (facesOf(soup, q) & sourceFaces) != 0 ? (S - Q).norm() : viaSegment(S, Q, a, b);
    double got;
    try {
      got = solver.distanceInMeshUnits(q);
    } catch (const std::exception& e) {
      return fail(v, "unexpected-exception", std::string("query ") + formatSurfacePoint(q) + ": " + e.what() + where());
    }
    if (!(std::abs(got - truth) <= 1e-9 * diag + 1e-12 * truth + placing)) {
      return fail(v, "two-face-distance", "at " + formatSurfacePoint(q) + " the solver gives " + fmt(got) +
                                              ", the exact two-face distance is " + fmt(truth) + where());
    }
  }
  return v;
}

// ===  Description and picture ===================================================================

void describe(const TwoFaceCase& c, std::ostream& out) {
  out << std::setprecision(17);
  out << "# fuzz_two_faces: faces B (0) and A (1) share the edge 0-1\n"
      << describeSoup(c.soup) << "source " << formatSurfacePoint(c.source) << "\n";
}

void writeSvg(const TwoFaceCase& c, std::ostream& out) {
  const auto& P3 = c.soup.positions;
  // Unfold: v0 at the origin, v2 on +x, v1 (face B) above, w (face A) below.
  const Vec3 o = P3[0], dir = (P3[1] - o).normalized();
  auto unfold = [&](const Vec3& p, double sign) {
    const Vec3 rel = p - o;
    return Vec2(rel.dot(dir), sign * (rel - rel.dot(dir) * dir).norm());
  };
  const std::array<Vec2, 4> q{Vec2(0, 0), Vec2((P3[1] - o).norm(), 0), unfold(P3[2], 1), unfold(P3[3], -1)};
  auto at = [&](const SurfacePoint& p) -> Vec2 {
    switch (p.kind) {
      case SurfacePoint::Kind::Vertex: return q[p.vertex];
      case SurfacePoint::Kind::Edge: return (1 - p.t) * q[p.vertex] + p.t * q[p.toVertex];
      case SurfacePoint::Kind::Face: {
        const auto& F = c.soup.faces[p.face];
        return p.bary[0] * q[F[0]] + p.bary[1] * q[F[1]] + p.bary[2] * q[F[2]];
      }
    }
    return Vec2(0, 0);
  };
  Vec2 lo = q[0], hi = q[0];
  for (const Vec2& p : q) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  SvgDoc doc(900, 900);
  Panel G(20, 40, 860, 840, lo.x(), lo.y(), hi.x(), hi.y(), true);
  doc.polygon(G, {q[0], q[2], q[1]}, "#dde8f4", "#6b7f99");
  doc.polygon(G, {q[0], q[1], q[3]}, "#f4ecd0", "#99875b");
  std::string status;
  try {
    const Mesh mesh(c.soup);
    GeodesicSolver solver(mesh);
    const std::vector<SurfacePoint> sources{c.source};
    solver.solve(sources);
    SourceColours colour;
    const double px = 1.0 / G.sx;  // one pixel in world units
    for (Index e = 0; e < mesh.numEdges(); ++e) {
      const Edge& E = mesh.edge(e);
      const Vec2 a = q[E.vertex[0]], d2 = (q[E.vertex[1]] - a).normalized();
      for (const Interval& w : solver.edgeIntervals()[e].intervals()) {
        // The side the source is on: towards the third vertex of face[side] in the picture.
        const auto& F = mesh.face(E.face[w.side]);
        Index third = 0;
        for (Index x : F)
          if (x != E.vertex[0] && x != E.vertex[1]) third = x;
        Vec2 n(-d2.y(), d2.x());
        if (n.dot(q[third] - a) < 0) n = -n;
        const Vec2 off = 3 * px * n;
        const double u = mesh.unit();  // intervals are in mesh units, the picture in the file's
        doc.line(G, a + u * w.b0 * d2 + off, a + u * w.b1 * d2 + off, colour(w), 4);
        const Vec2 s = a + u * w.source.x() * d2 + u * w.source.y() * n;
        if ((s - 0.5 * (lo + hi)).norm() < 2 * (hi - lo).norm()) doc.dot(G, s, 3, colour(w));
      }
    }
    for (Index x = 0; x < 4; ++x) {
      const double dx = solver.vertexDistances()[x];
      doc.label(G, q[x], std::to_string(x) + ": " + (std::isfinite(dx) ? shortNum(dx) : std::string("inf")), 11);
    }
  } catch (const std::exception& e) {
    status = std::string("; the solve threw: ") + e.what();
  }
  doc.dot(G, at(c.source), 6, "#d62728");
  doc.labelPx(20, 22, "fuzz_two_faces: faces B (blue) and A (sand) unfolded, intervals and pseudo-sources by colour" + status, 13);
  doc.write(out);
}

// ===  Seeds =====================================================================================

namespace {

using Q = Quantity;
using K = DegeneracyKind;
Q n(int v) { return Q::lattice(v); }

/// A seed on the two faces with lattice positions `pts` (v0, v2, v1, w) that must hit every one
/// of `kinds` in the solve, and meet `extra`.
Seed twoFaces(const std::string& name, std::initializer_list<K> kinds, std::array<std::array<int, 3>, 4> pts,
              SourceSpec source, std::uint8_t winding = 0, int unitExp = 0,
              std::function<std::string(const Verdict&)> extra = {}) {
  TwoFaceSpec s;
  s.unitExp = static_cast<std::int8_t>(unitExp);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) s.points[i][k] = n(pts[i][k]);
  s.winding = winding;
  s.source = source;
  return {name, encode(s), [want = std::vector<K>(kinds), extra](const FuzzCase&, const Verdict& v) {
            if (std::string missing = kindsNotHit(v, want); !missing.empty()) return missing;
            return extra ? extra(v) : std::string();
          }};
}

/// An edge between distinct positions whose length underflows to 0 (denormal coordinates): a
/// zero-length edge gives its windows the range [0, 0] and breaks Algorithm 2's precondition, so
/// the validator refuses edges outside [tol::kMinEdgeLength, tol::kMaxEdgeLength] by name
/// ('edge-length-out-of-range') and the target skips these bytes.
Seed denormalEdgeRefused() {
  TwoFaceSpec p;
  const int pts[4][3] = {{0, 0, 0}, {0, 0, 0}, {4, 6, 0}, {4, -6, 0}};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) p.points[i][k] = n(pts[i][k]);
  p.points[1][0] = Q::exact(2.3715151000379834e-322);
  p.source = atVertex(3);
  return {.name = "internal-check-denormal-edge-length-underflows-to-zero",
          .bytes = encode(p),
          .expect = {},
          .dir = "regress",
          .refusedNow = true};
}

}  // namespace

std::vector<Seed> twoFaceSeeds() {
  return {
    // Points: v0, v2 (the shared edge), v1 (apex of face B), w (apex of face A). Vertex indices
    // 0 = v0, 1 = v2, 2 = v1, 3 = w; face 0 = B, face 1 = A.
    twoFaces("planar-quad-source-at-w", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {4, -6, 0}}}, atVertex(3)),
    twoFaces("bent-quad-source-in-face-A", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {4, -4, 5}}},
                inFace(1, n(4), n(6))),
    twoFaces("bent-quad-source-in-face-B", {}, {{{0, 0, 0}, {8, 0, 0}, {3, 5, -4}, {4, -4, 5}}},
                inFace(0, n(8), n(4))),
    twoFaces("source-on-shared-edge", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {4, -6, 3}}},
                onEdge(1, 0, n(8))),
    twoFaces("G4-source-w-v0-v1-collinear-unfolded", {K::G4}, {{{0, 0, 0}, {8, 0, 0}, {-4, 6, 0}, {4, -6, 0}}},
                atVertex(3)),
    twoFaces("G5-source-w-v2-v1-collinear-unfolded", {K::G5}, {{{0, 0, 0}, {8, 0, 0}, {12, 6, 0}, {4, -6, 0}}},
                atVertex(3)),
    twoFaces("G4-bent-collinear-after-unfolding", {K::G4}, {{{0, 0, 0}, {8, 0, 0}, {-3, 6, 0}, {3, 0, -6}}},
                atVertex(3)),
    twoFaces("boundary-vertex-source-v1", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {4, -4, 5}}}, atVertex(2)),
    twoFaces("G1-zero-area-face-A-source-on-e0-line", {K::G1}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {12, 0, 0}}},
                atVertex(3)),
    twoFaces("source-at-v0-on-shared-edge", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 2}, {4, -4, 5}}}, atVertex(0)),
    twoFaces("zero-area-face-B", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 0, 0}, {4, -6, 0}}}, atVertex(3),
                0, 0, [](const Verdict& v) { return v.degeneracies.zeroAreaFaces > 0 ? "" : "crosses no zero-area face"; }),
    twoFaces("zero-area-face-B-apex-beyond-edge", {}, {{{0, 0, 0}, {8, 0, 0}, {12, 0, 0}, {4, -6, 0}}},
                atVertex(3)),
    twoFaces("folded-faces-overlapping", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {5, 3, 0}}}, atVertex(3)),
    twoFaces("obtuse-faces-reflex-unfolding", {}, {{{0, 0, 0}, {8, 0, 0}, {-6, 2, 0}, {14, -2, 0}}}, atVertex(3)),
    twoFaces("source-on-edge-within-snap-of-vertex", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {4, -6, 2}}},
                onEdge(1, 1, n(0).nudged(8, Nudge::SnapParam, true))),
    twoFaces("face-source-near-shared-edge", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 1}, {4, -6, 2}}},
                inFace(1, n(8), n(8).nudged(-16, Nudge::Coincide))),
    twoFaces("inconsistent-winding", {}, {{{0, 0, 0}, {8, 0, 0}, {4, 6, 0}, {4, -4, 5}}}, atVertex(3), 1),
    twoFaces("scaled-1e-6-bent", {}, {{{0, 0, 0}, {8, 0, 0}, {3, 5, -4}, {4, -4, 5}}}, atVertex(3), 0, -20),
    twoFaces("scaled-1e+6-bent", {}, {{{0, 0, 0}, {8, 0, 0}, {3, 5, -4}, {4, -4, 5}}}, atVertex(3), 0, 20),
    denormalEdgeRefused(),
  };
}

}  // namespace geodex::verify
