// Metamorphic properties of whole solves (DESIGN.md, "Oracles"): relations between two or more
// solves that hold for the exact geodesic distance, whatever it is — symmetry, invariance under
// rigid motions, uniform scaling, vertex relabelling, face reordering and coplanar refinement, and
// monotonicity in the set of sources. Each solve is watched by the full-tier invariant checker.
// Two solves that both meet the accuracy contract differ by at most kTwoSolves × diagonal.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numeric>
#include <sstream>

#include "exact_fig6.h"
#include "generators.h"
#include "geodex/propagate.h"
#include "solve_helpers.h"

namespace geodex::proptest {
namespace {

std::string mismatch(const char* what, std::span<const double> got, std::span<const double> want,
                     double diagonal) {
  const std::size_t v = worstIndex(got, want);
  std::ostringstream os;
  os.precision(17);
  os << what << ": distances differ by " << std::abs(got[v] - want[v]) / diagonal
     << " x diagonal at vertex " << v << " (" << got[v] << " vs " << want[v] << ")";
  return os.str();
}

// ===  Symmetry ===================================================================================

RC_GTEST_PROP(Metamorphic, DistanceIsSymmetricBetweenVertices, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const Index a = *gen::referencedVertex(mesh), b = *gen::referencedVertex(mesh);
  RC_TAG(mc.family, mesh.isBoundaryVertex(a) || mesh.isBoundaryVertex(b) ? "boundary vertex"
                                                                         : "interior vertices");
  const double ab = solveChecked(mesh, {SurfacePoint::atVertex(a)}).distances[b];
  const double ba = solveChecked(mesh, {SurfacePoint::atVertex(b)}).distances[a];
  recordAccuracy("symmetry d(a,b) vs d(b,a)", std::abs(ab - ba) / mesh.boundingBoxDiagonal());
  if (!(std::abs(ab - ba) <= kTwoSolves * mesh.boundingBoxDiagonal())) {
    std::ostringstream os;
    os.precision(17);
    os << "d(" << a << ", " << b << ") = " << ab << " but d(" << b << ", " << a << ") = " << ba;
    RC_FAIL(os.str());
  }
}

// ===  Rigid motion ===============================================================================

RC_GTEST_PROP(Metamorphic, RigidMotionsLeaveDistancesUnchanged, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  const double diag = mesh.boundingBoxDiagonal();
  const RigidMotion motion = *gen::rigidMotion(diag);
  RC_TAG(mc.family, src.kind);
  TriangleSoup moved = mc.soup;
  for (Vec3& p : moved.positions) p = motion.rotation * p + motion.translation;
  const Mesh movedMesh(moved);
  const Solved before = solveChecked(mesh, {src.point});
  const Solved after = solveChecked(movedMesh, {src.point});
  recordAccuracy("rigid motion", maxDifference(after.distances, before.distances) / diag);
  if (!(maxDifference(after.distances, before.distances) <= kTwoSolves * diag))
    RC_FAIL(mismatch("after a rigid motion", after.distances, before.distances, diag));
}

// ===  Uniform scaling ============================================================================
//
// Every tolerance is relative (tolerance.h), so scaling must give proportional distances and take
// the same decisions:
//  - by 1e-6 and 1e+6: distances proportional; and every propagation case the solve met, scaled by
//    the same factor, is decided by the same Fig. 6 leaf — unless exact predicates (exact_fig6.h)
//    decide the scaled case differently or ambiguously: rounding the scaled inputs can move a
//    case by an ulp, which for a needle is a different configuration.
//  - by 2^-20 and 2^+20 (≈ 1e∓6): every floating-point operation scales exactly, so the whole run
//    is the same run: the same degeneracy counts. (Not by 1e±6: rounding the scaled coordinates
//    reorders queue events whose keys tie in exact arithmetic — the same distance reached along two
//    routes — and a different but equally valid processing order meets other cases; e.g.
//    squareWithHoleMesh(3, 1, 0.65) from v:2 gives G1 1→0, D1 4→3, D4 0→1 at 1e-6 with distances
//    equal to 1.6e-16 × diagonal.)
struct RecordCases : SolverObserver {
  std::vector<std::pair<LocalWindow, Fig6Branch>> cases;
  void onPropagation(const PropagationEvent& e) override {
    if (cases.size() < 4096) cases.emplace_back(e.local, e.result.branch);
  }
};

LocalWindow scaled(const LocalWindow& w, double f) {
  LocalWindow s = w;
  s.edgeLength *= f;
  s.apex *= f;
  s.b0 *= f;
  s.b1 = std::min(w.b1 * f, s.edgeLength);
  s.source *= f;
  return s;
}

RC_GTEST_PROP(Metamorphic, UniformScalingScalesDistancesAndKeepsDecisions, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  RC_TAG(mc.family, src.kind);
  RecordCases recorded;
  const Solved base = solveChecked(mesh, {src.point}, nullptr, &recorded);
  const double diag = mesh.boundingBoxDiagonal();
  for (double factor : {1e-6, 1e6, std::ldexp(1.0, -20), std::ldexp(1.0, 20)}) {
    const bool exact = factor != 1e-6 && factor != 1e6;
    TriangleSoup scaledSoup = mc.soup;
    for (Vec3& p : scaledSoup.positions) p *= factor;
    const Mesh scaledMesh(scaledSoup);
    Solved s = solveChecked(scaledMesh, {src.point});
    for (double& d : s.distances) d /= factor;
    const std::string by = "scaled by " + std::to_string(factor);
    recordAccuracy("uniform scaling", maxDifference(s.distances, base.distances) / diag);
    if (!(maxDifference(s.distances, base.distances) <= kTwoSolves * diag))
      RC_FAIL(mismatch(by.c_str(), s.distances, base.distances, diag));
    if (exact && s.counters.count != base.counters.count) {
      RC_FAIL(by + " (exactly) the degeneracy counts changed: " + describeCounters(base.counters) +
              " became " + describeCounters(s.counters));
    }
    if (exact) continue;
    for (const auto& [w, branch] : recorded.cases) {
      const LocalWindow sw = scaled(w, factor);
      const Fig6Branch got = propagateLocal(sw).branch;
      if (got == branch) continue;
      // Rounding the scaled inputs may have moved the case itself (a needle's apex 1e-16 from v2
      // becomes exactly v2): the leaf must then follow exact geometry, not the unscaled leaf.
      const auto before = exactFig6Branches(w, ExactMode::Tolerance),
                 after = exactFig6Branches(sw, ExactMode::Tolerance);
      if (before.size() == 1 && before == after) {
        std::ostringstream os;
        os.precision(17);
        os << by << ", a case of this solve went from " << name(branch) << " to " << name(got)
           << " though exact predicates decide both as " << name(before[0]) << ": LocalWindow{"
           << w.edgeLength << ", Vec2(" << w.apex.x() << ", " << w.apex.y() << "), " << w.b0 << ", "
           << w.b1 << ", Vec2(" << w.source.x() << ", " << w.source.y() << ")}";
        RC_FAIL(os.str());
      }
    }
  }
}

// Across the whole range of doubles (docs/numerics.md): every generated mesh scaled by any power
// of two that keeps its coordinates normal numbers is the same run, bit for bit — distances and
// every counter; scaled by any power of ten a double holds, the same distances up to the input's
// rounding. (The 2^±20 case above is one point of this.)
RC_GTEST_PROP(Metamorphic, ScalingByAnyPowerOfTwoIsTheSameRunBitForBit, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  const int k = *rc::gen::inRange(-1000, 1001);
  TriangleSoup scaledSoup = mc.soup;
  for (Vec3& p : scaledSoup.positions)
    for (int i = 0; i < 3; ++i) {
      p[i] = std::ldexp(p[i], k);
      RC_PRE(p[i] == 0.0 || std::isnormal(p[i]));
    }
  RC_TAG(mc.family, k < -300 ? "2^k, k < -300" : (k > 300 ? "2^k, k > 300" : "2^k, |k| <= 300"));
  const Solved base = solveChecked(mesh, {src.point});
  const Solved s = solveChecked(Mesh(scaledSoup), {src.point});
  for (std::size_t v = 0; v < base.distances.size(); ++v) {
    if (s.distances[v] != std::ldexp(base.distances[v], k)) {
      std::ostringstream os;
      os.precision(17);
      os << "scaled by 2^" << k << ", vertex " << v << " has " << s.distances[v] << " instead of "
         << std::ldexp(base.distances[v], k) << " (" << base.distances[v] << " x 2^" << k << ")";
      RC_FAIL(os.str());
    }
  }
  if (s.counters.count != base.counters.count || s.counters.cases != base.counters.cases)
    RC_FAIL("scaled by 2^" + std::to_string(k) + " the counts changed: " + describeCounters(base.counters) +
            " became " + describeCounters(s.counters));
}

RC_GTEST_PROP(Metamorphic, ScalingByAnyPowerOfTenScalesDistances, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  const int k = *rc::gen::inRange(-250, 251);
  const double factor = std::pow(10.0, k);
  TriangleSoup scaledSoup = mc.soup;
  for (Vec3& p : scaledSoup.positions) p *= factor;
  RC_TAG(mc.family);
  const Solved base = solveChecked(mesh, {src.point});
  Solved s = solveChecked(Mesh(scaledSoup), {src.point});
  for (double& d : s.distances) d /= factor;
  const double diag = mesh.boundingBoxDiagonal();
  recordAccuracy("scaling by 10^k", maxDifference(s.distances, base.distances) / diag);
  if (!(maxDifference(s.distances, base.distances) <= kTwoSolves * diag))
    RC_FAIL(mismatch(("scaled by 1e" + std::to_string(k)).c_str(), s.distances, base.distances, diag));
}

// ===  Relabelling and reordering =================================================================

std::vector<Index> shuffled(std::size_t n, std::uint64_t seed) {
  std::vector<Index> p(n);
  std::iota(p.begin(), p.end(), Index{0});
  verify::SplitMix64 rng(seed);
  for (std::size_t i = n; i > 1; --i)
    std::swap(p[i - 1], p[static_cast<std::size_t>(rng.uniform() * i)]);
  return p;
}

RC_GTEST_PROP(Metamorphic, RelabellingVerticesAndReorderingFacesLeaveDistancesUnchanged, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  const int what = *gen::uniformInt(0, 3);  // 0: vertices, 1: faces (and their corners), 2: both
  const auto seed = *gen::uniformInt<std::uint64_t>(0, 1u << 20);
  RC_TAG(mc.family, what == 0 ? "relabel vertices" : what == 1 ? "reorder faces" : "both");
  const std::size_t nv = mc.soup.positions.size(), nf = mc.soup.faces.size();
  std::vector<Index> vmap(nv), fmap(nf);  // old index → new index
  std::iota(vmap.begin(), vmap.end(), Index{0});
  std::iota(fmap.begin(), fmap.end(), Index{0});
  if (what != 1) vmap = shuffled(nv, seed);
  if (what != 0) fmap = shuffled(nf, seed + 1);
  verify::SplitMix64 rng(seed + 2);
  std::vector<int> rotation(nf, 0);
  if (what != 0)
    for (int& r : rotation) r = static_cast<int>(rng.uniform() * 3);

  TriangleSoup relabelled;
  relabelled.positions.resize(nv);
  relabelled.faces.resize(nf);
  for (std::size_t v = 0; v < nv; ++v) relabelled.positions[vmap[v]] = mc.soup.positions[v];
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& c = mc.soup.faces[f];
    const int r = rotation[f];
    relabelled.faces[fmap[f]] = {vmap[c[r]], vmap[c[(r + 1) % 3]], vmap[c[(r + 2) % 3]]};
  }
  SurfacePoint mapped = src.point;
  switch (src.point.kind) {
    case SurfacePoint::Kind::Vertex: mapped.vertex = vmap[src.point.vertex]; break;
    case SurfacePoint::Kind::Edge:
      mapped.vertex = vmap[src.point.vertex];
      mapped.toVertex = vmap[src.point.toVertex];
      break;
    case SurfacePoint::Kind::Face: {
      const int r = rotation[src.point.face];
      mapped.face = fmap[src.point.face];
      mapped.bary = {src.point.bary[r], src.point.bary[(r + 1) % 3], src.point.bary[(r + 2) % 3]};
      break;
    }
  }
  const Mesh relabelledMesh(relabelled);
  const Solved before = solveChecked(mesh, {src.point});
  const Solved after = solveChecked(relabelledMesh, {mapped});
  std::vector<double> back(nv);
  for (std::size_t v = 0; v < nv; ++v) back[v] = after.distances[vmap[v]];
  const double diag = mesh.boundingBoxDiagonal();
  recordAccuracy("relabelling / reordering", maxDifference(back, before.distances) / diag);
  if (!(maxDifference(back, before.distances) <= kTwoSolves * diag))
    RC_FAIL(mismatch("after relabelling (original vertex numbers)", back, before.distances, diag));
}

// ===  Mirror image ===============================================================================
//
// Edges run from the smaller vertex number to the larger, so numbering the vertices backwards turns
// every edge around and every face frame into its mirror image (x → L − x): the solve is the
// mirror-image run of the same surface. Its distances are the same; and every propagation case of
// the first solve, mirrored, must be decided by the mirrored Fig. 6 leaf (G2 ↔ G3, G4 ↔ G5, left
// ↔ right of the wedge), so that the mirrored cases count the mirrored degeneracies — save cases
// the exact predicates call ambiguous, where rounding L − x may decide either way. The Fig. 6
// properties run generated cases mirrored too; this runs the cases real solves meet.
Fig6Branch mirrorOf(Fig6Branch b) {
  switch (b) {
    case Fig6Branch::G2: return Fig6Branch::G3;
    case Fig6Branch::G3: return Fig6Branch::G2;
    case Fig6Branch::G4: return Fig6Branch::G5;
    case Fig6Branch::G5: return Fig6Branch::G4;
    case Fig6Branch::LeftOfWedge: return Fig6Branch::RightOfWedge;
    case Fig6Branch::RightOfWedge: return Fig6Branch::LeftOfWedge;
    default: return b;
  }
}

RC_GTEST_PROP(Metamorphic, MirroringTheMeshMirrorsTheDecisionsAndKeepsTheDistances, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  RC_TAG(mc.family, src.kind);
  const std::size_t nv = mc.soup.positions.size();
  const auto backwards = [nv](Index v) { return static_cast<Index>(nv - 1 - v); };
  TriangleSoup mirror;
  mirror.positions.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) mirror.positions[backwards(static_cast<Index>(v))] = mc.soup.positions[v];
  for (const auto& c : mc.soup.faces) mirror.faces.push_back({backwards(c[0]), backwards(c[1]), backwards(c[2])});
  SurfacePoint mapped = src.point;
  if (src.point.kind != SurfacePoint::Kind::Face) mapped.vertex = backwards(src.point.vertex);
  if (src.point.kind == SurfacePoint::Kind::Edge) mapped.toVertex = backwards(src.point.toVertex);

  RecordCases recorded;
  const Solved base = solveChecked(mesh, {src.point}, nullptr, &recorded);
  const Solved mirrored = solveChecked(Mesh(mirror), {mapped});
  std::vector<double> back(nv);
  for (std::size_t v = 0; v < nv; ++v) back[v] = mirrored.distances[backwards(static_cast<Index>(v))];
  const double diag = mesh.boundingBoxDiagonal();
  recordAccuracy("mirror image", maxDifference(back, base.distances) / diag);
  if (!(maxDifference(back, base.distances) <= kTwoSolves * diag))
    RC_FAIL(mismatch("numbered backwards (original vertex numbers)", back, base.distances, diag));

  for (const auto& [w, branch] : recorded.cases) {
    const auto m = gen::detail::mirrored(w);
    if (!m) continue;
    const Fig6Branch got = propagateLocal(*m).branch;
    if (got == mirrorOf(branch)) continue;
    const auto exact = exactFig6Branches(w, ExactMode::Tolerance),
               exactMirror = exactFig6Branches(*m, ExactMode::Tolerance);
    if (exact.size() == 1 && exactMirror.size() == 1 && exactMirror[0] == mirrorOf(exact[0])) {
      std::ostringstream os;
      os.precision(17);
      os << "a case of this solve decided " << name(branch) << " has its mirror image decided "
         << name(got) << ", not " << name(mirrorOf(branch)) << ", though exact predicates decide the two as "
         << name(exact[0]) << " and " << name(exactMirror[0]) << ": LocalWindow{" << w.edgeLength
         << ", Vec2(" << w.apex.x() << ", " << w.apex.y() << "), " << w.b0 << ", " << w.b1
         << ", Vec2(" << w.source.x() << ", " << w.source.y() << ")}";
      RC_FAIL(os.str());
    }
  }
}

// ===  Coplanar refinement ========================================================================
//
// Splitting a face 1→3 at an interior point, or an edge (and its one or two faces) at a point
// along it, leaves the surface the same point set: the distances at the original vertices must
// not change. The new vertex (appended last) is flat (angle sum 2π) or on the boundary.

/// The refined soup, and the source to use on both meshes: the refined face or edge is the first
/// one from r.element on (cyclically) that the source is not given on (its index would change);
/// when there is none, the source moves to a vertex.
std::pair<TriangleSoup, SurfacePoint> refine(const TriangleSoup& soup, const Mesh& mesh,
                                             const Refinement& r, SurfacePoint source) {
  auto touches = [&](std::size_t i) {
    if (!r.splitEdge) return source.kind == SurfacePoint::Kind::Face && source.face == i;
    const Edge& E = mesh.edge(static_cast<Index>(i));
    if (source.kind == SurfacePoint::Kind::Edge)
      return (E.vertex[0] == source.vertex && E.vertex[1] == source.toVertex) ||
             (E.vertex[1] == source.vertex && E.vertex[0] == source.toVertex);
    if (source.kind == SurfacePoint::Kind::Face)
      return mesh.localEdgeIndex(source.face, static_cast<Index>(i)) >= 0;
    return false;
  };
  const std::size_t count = r.splitEdge ? mesh.numEdges() : mesh.numFaces();
  std::size_t chosen = count;
  for (std::size_t k = 0; k < count && chosen == count; ++k)
    if (!touches((r.element + k) % count)) chosen = (r.element + k) % count;
  if (chosen == count) {
    source = SurfacePoint::atVertex(soup.faces[0][0]);
    chosen = r.element;
  }
  TriangleSoup refined = soup;
  const Index p = static_cast<Index>(refined.positions.size());
  if (!r.splitEdge) {
    const auto corners = soup.faces[chosen];
    const double sum = r.bary[0] + r.bary[1] + r.bary[2];
    refined.positions.push_back((r.bary[0] * soup.positions[corners[0]] +
                                 r.bary[1] * soup.positions[corners[1]] +
                                 r.bary[2] * soup.positions[corners[2]]) /
                                sum);
    refined.faces[chosen] = {corners[0], corners[1], p};
    refined.faces.push_back({corners[1], corners[2], p});
    refined.faces.push_back({corners[2], corners[0], p});
  } else {
    const Edge& E = mesh.edge(static_cast<Index>(chosen));
    refined.positions.push_back((1.0 - r.t) * soup.positions[E.vertex[0]] +
                                r.t * soup.positions[E.vertex[1]]);
    const std::size_t nf = refined.faces.size();
    for (std::size_t f = 0; f < nf; ++f) {
      const auto c = refined.faces[f];
      for (int k = 0; k < 3; ++k) {
        const Index x = c[k], y = c[(k + 1) % 3], z = c[(k + 2) % 3];
        if ((x == E.vertex[0] && y == E.vertex[1]) || (x == E.vertex[1] && y == E.vertex[0])) {
          refined.faces[f] = {x, p, z};
          refined.faces.push_back({p, y, z});
          break;
        }
      }
    }
  }
  return {refined, source};
}

RC_GTEST_PROP(Metamorphic, CoplanarRefinementLeavesDistancesUnchanged, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase src = *gen::sourcePoint(mesh);
  const Refinement r = *gen::refinement(mesh.numFaces(), mesh.numEdges());
  RC_TAG(mc.family, r.splitEdge ? "edge split" : "1-to-3 face split");
  const auto [refined, source] = refine(mc.soup, mesh, r, src.point);
  const Mesh refinedMesh(refined);
  const Solved before = solveChecked(mesh, {source});
  const Solved after = solveChecked(refinedMesh, {source});
  const std::span<const double> original(after.distances.data(), mc.soup.positions.size());
  const double diag = mesh.boundingBoxDiagonal();
  recordAccuracy("coplanar refinement", maxDifference(original, before.distances) / diag);
  if (!(maxDifference(original, before.distances) <= kTwoSolves * diag))
    RC_FAIL(mismatch("after refining", original, before.distances, diag));
}

// ===  More sources ===============================================================================
//
// Adding a source never increases a distance; in fact the field is the minimum over the sources.
RC_GTEST_PROP(Metamorphic, AddingASourceNeverIncreasesADistance, ()) {
  const MeshCase mc = *gen::meshCase();
  const Mesh mesh(mc.soup);
  const SourceCase first = *gen::sourcePoint(mesh), second = *gen::sourcePoint(mesh);
  RC_TAG(mc.family, second.kind);
  const Solved one = solveChecked(mesh, {first.point});
  const Solved other = solveChecked(mesh, {second.point});
  const Solved both = solveChecked(mesh, {first.point, second.point});
  const double diag = mesh.boundingBoxDiagonal();
  std::vector<double> minimum(one.distances.size());
  for (std::size_t v = 0; v < minimum.size(); ++v) {
    if (!(both.distances[v] <= one.distances[v] + kTwoSolves * diag)) {
      std::ostringstream os;
      os.precision(17);
      os << "adding " << formatSurfacePoint(second.point) << " increased vertex " << v << " from "
         << one.distances[v] << " to " << both.distances[v];
      RC_FAIL(os.str());
    }
    minimum[v] = std::min(one.distances[v], other.distances[v]);
  }
  recordAccuracy("two sources vs min of one each", maxDifference(both.distances, minimum) / diag);
  if (!(maxDifference(both.distances, minimum) <= kTwoSolves * diag))
    RC_FAIL(mismatch("two sources vs the minimum of each alone", both.distances, minimum, diag));
}

}  // namespace
}  // namespace geodex::proptest
