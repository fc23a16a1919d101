#include "geodex/verify/check.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <ostream>
#include <sstream>

#include "geodex/error.h"
#include "geodex/verify/exact_predicates.h"
#include "geodex/verify/oracles.h"

namespace geodex::verify {
namespace {

// ===  Tolerances of the oracles (relative, and why) ============================================
// Distances agree with an independent exact answer to this × the bounding-box diagonal: the
// solver's accuracy contract (docs/properties.md). Metamorphic re-solves use it too: a rigid
// motion or a scale changes rounding, which may flip an ε decision, moving a distance by O(ε).
constexpr double kAgreeRel = 1e-9;
// Bounds (Euclidean, Dijkstra, Lipschitz) hold exactly in real arithmetic; allow rounding only.
constexpr double kBoundRel = 1e-12;
// Exact-predicate comparisons are made only this many ε away from every decision boundary.
constexpr double kExactMargin = 10.0;

std::string fmt(double x) {
  std::ostringstream os;
  os << std::setprecision(17) << x;
  return os.str();
}

OracleResult fromReport(const std::string& name, const CheckReport& r) {
  OracleResult o(name);
  o.checked = r.checked;
  o.failed = r.failed;
  o.maxError = r.maxError;
  o.firstFailure = r.firstFailure;
  return o;
}

// Watches every Fig. 6 decision and re-evaluates it exactly.
class ExactPredicateObserver : public SolverObserver {
 public:
  OracleResult result{std::string("exact-predicates")};
  void onPropagation(const PropagationEvent& e) override {
    bool agrees = false;
    if (!judgeFig6(e.local, e.result.branch, agrees)) return;
    ++result.checked;
    if (agrees) return;
    const ExactFig6 exact = exactFig6(e.local);
    ++result.failed;
    result.maxError = 1.0;
    if (result.firstFailure.empty()) {
      std::ostringstream os;
      os << std::setprecision(17) << "face " << e.face << ", edge " << e.edge << ": decided "
         << name(e.result.branch) << " but exactly " << name(exact.branch) << " (margin "
         << exact.margin << " ε): L=" << e.local.edgeLength << " apex=(" << e.local.apex.x()
         << ", " << e.local.apex.y() << ") b0=" << e.local.b0 << " b1=" << e.local.b1 << " s=("
         << e.local.source.x() << ", " << e.local.source.y() << ")";
      result.firstFailure = os.str();
    }
  }
};

class ObserverPair : public SolverObserver {
 public:
  ObserverPair(SolverObserver& a, SolverObserver& b) : a_(a), b_(b) {}
  void onPropagation(const PropagationEvent& e) override { a_.onPropagation(e); b_.onPropagation(e); }
  void onEdgeUpdate(const EdgeUpdateEvent& e) override { a_.onEdgeUpdate(e); b_.onEdgeUpdate(e); }
  void onWindowDropped(const WindowDroppedEvent& e) override { a_.onWindowDropped(e); b_.onWindowDropped(e); }
  void onFinish(const GeodesicSolver& s) override { a_.onFinish(s); b_.onFinish(s); }

 private:
  SolverObserver& a_;
  SolverObserver& b_;
};

std::vector<double> solveOn(const TriangleSoup& soup, const std::vector<SurfacePoint>& sources) {
  const Mesh mesh(soup);
  return exactGeodesicDistance(mesh, sources);
}

// Compares a re-solve of the mesh scaled by 2^k with the original: equal × 2^k, bit for bit.
void compareBitForBit(OracleResult& r, const std::string& what, std::span<const double> original,
                      std::span<const double> other, int k) {
  for (std::size_t v = 0; v < original.size(); ++v) {
    const double want = std::ldexp(original[v], k), got = other[v];
    ++r.checked;
    if (got == want) continue;
    ++r.failed;
    r.maxError = std::max(r.maxError, std::isfinite(want) && want != 0.0 ? std::abs(got / want - 1.0) : INFINITY);
    if (r.firstFailure.empty())
      r.firstFailure = what + ": vertex " + std::to_string(v) + " has " + fmt(got) + " instead of " + fmt(want) +
                       " (bit for bit)";
  }
}

// Compares a re-solve's per-vertex distances (already mapped back) with the original.
void compareFields(OracleResult& r, const std::string& what, std::span<const double> original,
                   std::span<const double> other, double factor, double diag) {
  for (std::size_t v = 0; v < original.size(); ++v) {
    const double a = original[v] * factor, b = other[v];
    if (std::isinf(a) && std::isinf(b)) continue;
    ++r.checked;
    const double err = std::abs(a - b) / (diag * factor);
    if (!(err <= r.maxError)) r.maxError = std::isnan(err) ? INFINITY : err;
    if (!(err <= kAgreeRel)) {
      ++r.failed;
      if (r.firstFailure.empty())
        r.firstFailure = what + ": vertex " + std::to_string(v) + " has " + fmt(b) + " instead of " + fmt(a);
    }
  }
}

// ===  Oracles ====================================================================================

void metamorphicInto(OracleResult& r, const Mesh& mesh, const std::vector<SurfacePoint>& sources,
                     std::span<const double> d) {
  const TriangleSoup& soup = mesh.soup();
  const double diag = mesh.boundingBoxDiagonal();
  // Rigid motion: a rotation about a skew axis and a translation.
  {
    TriangleSoup moved = soup;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 t(0.3 * diag, -1.7 * diag, 2.1 * diag);
    for (Vec3& p : moved.positions) p = R * p + t;
    compareFields(r, "rigid motion", d, solveOn(moved, sources), 1.0, diag);
  }
  for (double factor : {1e-6, 1e6}) {
    TriangleSoup scaled = soup;
    for (Vec3& p : scaled.positions) p *= factor;
    compareFields(r, "scale " + fmt(factor), d, solveOn(scaled, sources), factor, diag);
  }
  // Across the whole range of doubles (docs/numerics.md): by powers of two the same distances bit
  // for bit, wherever every scaled coordinate is still a normal number (or zero); by powers of
  // ten (rounded) the same up to the input's rounding. (`mesh` comes in mesh units, its largest
  // coordinate in [1, 2), so 2^±1000 is inside the range.)
  for (const int k : {-1000, -600, -100, 100, 600, 1000}) {
    TriangleSoup scaled = soup;
    bool normal = true;
    for (Vec3& p : scaled.positions)
      for (int i = 0; i < 3; ++i) {
        p[i] = std::ldexp(p[i], k);
        normal = normal && (p[i] == 0.0 || std::isnormal(p[i]));
      }
    if (normal) compareBitForBit(r, "scale 2^" + std::to_string(k), d, solveOn(scaled, sources), k);
  }
  for (const int k : {-250, -80, 80, 250}) {
    const double factor = std::pow(10.0, k);
    TriangleSoup scaled = soup;
    for (Vec3& p : scaled.positions) p *= factor;
    compareFields(r, "scale 1e" + std::to_string(k), d, solveOn(scaled, sources), factor, diag);
  }
  // Vertex relabelling (reversed order) and face reordering (reversed order).
  {
    const std::size_t n = soup.positions.size();
    TriangleSoup relabelled;
    relabelled.positions.assign(soup.positions.rbegin(), soup.positions.rend());
    auto map = [n](Index v) { return static_cast<Index>(n - 1 - v); };
    for (auto f : soup.faces) relabelled.faces.push_back({map(f[0]), map(f[1]), map(f[2])});
    std::reverse(relabelled.faces.begin(), relabelled.faces.end());
    std::vector<SurfacePoint> mapped;
    for (SurfacePoint s : sources) {
      if (s.kind != SurfacePoint::Kind::Face) {
        s.vertex = map(s.vertex);
        if (s.kind == SurfacePoint::Kind::Edge) s.toVertex = map(s.toVertex);
      } else {
        s.face = static_cast<Index>(soup.faces.size() - 1 - s.face);
      }
      mapped.push_back(s);
    }
    const std::vector<double> other = solveOn(relabelled, mapped);
    std::vector<double> back(n);
    for (std::size_t v = 0; v < n; ++v) back[v] = other[map(static_cast<Index>(v))];
    compareFields(r, "relabelling and face reordering", d, back, 1.0, diag);
  }
  // Coplanar refinement: every face not holding a source split 1→3 at its centroid. A face of
  // zero area stays whole: its centroid lies on its line, at one of its corners when two of them
  // are mirror images about the third, and splitting there would make a zero-length edge, which
  // the solver refuses (the check would blame the user's mesh).
  {
    TriangleSoup refined = soup;
    refined.faces.clear();
    std::vector<char> keep(soup.faces.size(), 0);
    for (const SurfacePoint& s : sources)
      if (s.kind == SurfacePoint::Kind::Face && s.face < keep.size()) keep[s.face] = 1;
    std::vector<Index> newFaceOf(soup.faces.size(), kNoIndex);
    for (Index f = 0; f < soup.faces.size(); ++f) {
      const auto t = soup.faces[f];
      const Vec3 &p0 = soup.positions[t[0]], &p1 = soup.positions[t[1]], &p2 = soup.positions[t[2]];
      if (keep[f] || (p1 - p0).cross(p2 - p0) == Vec3::Zero()) {
        newFaceOf[f] = static_cast<Index>(refined.faces.size());
        refined.faces.push_back(t);
        continue;
      }
      const Index c = static_cast<Index>(refined.positions.size());
      refined.positions.push_back((p0 + p1 + p2) / 3.0);
      refined.faces.push_back({t[0], t[1], c});
      refined.faces.push_back({t[1], t[2], c});
      refined.faces.push_back({t[2], t[0], c});
    }
    std::vector<SurfacePoint> mapped = sources;
    for (SurfacePoint& s : mapped)
      if (s.kind == SurfacePoint::Kind::Face) s.face = newFaceOf[s.face];
    const std::vector<double> other = solveOn(refined, mapped);
    compareFields(r, "1-to-3 coplanar refinement", d, std::span<const double>(other).first(d.size()), 1.0, diag);
  }
}

void symmetryInto(OracleResult& r, const Mesh& mesh, const SurfacePoint& a, std::span<const double> d) {
  // From the farthest reachable vertex b and two more spread over the mesh, back to a.
  std::vector<Index> bs;
  Index far = kNoIndex;
  for (Index v = 0; v < d.size(); ++v)
    if (std::isfinite(d[v]) && (far == kNoIndex || d[v] > d[far])) far = v;
  if (far == kNoIndex) return;
  bs.push_back(far);
  for (Index v = static_cast<Index>(d.size() / 3); v < d.size() && bs.size() < 3; v += static_cast<Index>(d.size() / 3 + 1))
    if (std::isfinite(d[v])) bs.push_back(v);
  for (Index b : bs) {
    GeodesicSolver back(mesh);
    back.solve(std::vector<SurfacePoint>{SurfacePoint::atVertex(b)});
    const double dba = back.distance(a);
    ++r.checked;
    const double err = std::abs(dba - d[b]) / mesh.boundingBoxDiagonal();
    r.maxError = std::max(r.maxError, err);
    if (!(err <= kAgreeRel)) {
      ++r.failed;
      if (r.firstFailure.empty())
        r.firstFailure = "d(source, v" + std::to_string(b) + ") = " + fmt(d[b]) + " but d(v" + std::to_string(b) + ", source) = " + fmt(dba);
    }
  }
}

// Rotates a planar soup into the z = 0 plane; false if it is not planar.
bool flattenIfPlanar(const TriangleSoup& soup, double diag, TriangleSoup& flat) {
  if (soup.faces.empty()) return false;
  // Sum of face normals, each turned to agree with the first: winding may be inconsistent
  // (Kirsanov's flat mesh alternates), which must not cancel the sum.
  Vec3 n = Vec3::Zero();
  for (const auto& f : soup.faces) {
    const Vec3 fn = (soup.positions[f[1]] - soup.positions[f[0]]).cross(soup.positions[f[2]] - soup.positions[f[0]]);
    n += n.dot(fn) < 0.0 ? Vec3(-fn) : fn;
  }
  if (n.norm() == 0.0) return false;
  n.normalize();
  const Vec3 o = soup.positions[soup.faces[0][0]];
  std::vector<char> used(soup.positions.size(), 0);
  for (const auto& f : soup.faces) used[f[0]] = used[f[1]] = used[f[2]] = 1;
  for (Index v = 0; v < soup.positions.size(); ++v)
    if (used[v] && std::abs((soup.positions[v] - o).dot(n)) > 1e-12 * diag) return false;
  const Eigen::Matrix3d R = Eigen::Quaterniond::FromTwoVectors(n, Vec3::UnitZ()).toRotationMatrix();
  flat = soup;
  for (Vec3& p : flat.positions) {
    p = R * (p - o);
    p.z() = 0.0;
  }
  return true;
}

void planarInto(OracleResult& r, const Mesh& mesh, const std::vector<SurfacePoint>& sources, std::span<const double> d) {
  TriangleSoup flat;
  const double diag = mesh.boundingBoxDiagonal();
  if (mesh.numComponents() != 1 || !flattenIfPlanar(mesh.soup(), diag, flat)) return;
  std::vector<Polygon2> boundary;
  try {
    boundary = planarBoundaryPolygons(flat);
  } catch (const std::exception&) {
    return;  // a pinched boundary: the visibility-graph oracle does not apply
  }
  // Nor to a mesh folded over itself: flat, but its geodesics are not the domain's shortest paths
  // (CheckRegression.ThePlanarOracleLeavesAFlatMeshFoldedOntoItselfAlone).
  if (!coversItsDomainOnce(flat, boundary)) return;
  // Only the vertices of faces are queried: an unreferenced one may lie outside the domain (its
  // distance is +inf anyway), and the oracle refuses such a query.
  const std::vector<Vec2> positions = planarPositions(flat);
  std::vector<Index> referenced;
  std::vector<Vec2> queries;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    if (!mesh.isReferenced(static_cast<Index>(v))) continue;
    referenced.push_back(static_cast<Index>(v));
    queries.push_back(positions[v]);
  }
  std::vector<double> exact(d.size(), INFINITY);
  for (const SurfacePoint& s : sources) {
    // A source on a vertex no face uses is not in the domain: 0 there, and it reaches nothing.
    if (s.kind == SurfacePoint::Kind::Vertex && !mesh.isReferenced(s.vertex)) {
      exact[s.vertex] = 0.0;
      continue;
    }
    const Vec3 p = surfacePointPosition(flat, s);
    const auto one = planarDomainDistances(boundary, Vec2(p.x(), p.y()), queries);
    for (std::size_t k = 0; k < referenced.size(); ++k)
      exact[referenced[k]] = std::min(exact[referenced[k]], one[k]);
  }
  compareFields(r, "planar shortest path", exact, d, 1.0, diag);
}

// d in mesh units; the paths are brought into them too.
void pathsInto(OracleResult& r, const GeodesicSolver& solver, std::span<const double> d) {
  const Mesh& mesh = solver.mesh();
  const double diag = mesh.boundingBoxDiagonalInMeshUnits();
  const std::size_t n = d.size();
  const std::size_t step = std::max<std::size_t>(1, n / 16);
  for (std::size_t v = 0; v < n; v += step) {
    if (!std::isfinite(d[v])) continue;
    GeodesicPath p = solver.path(SurfacePoint::atVertex(static_cast<Index>(v)));
    p.length *= mesh.meshUnit().inverse;
    for (PathPoint& q : p.points) q.position *= mesh.meshUnit().inverse;
    ++r.checked;
    std::string why;
    double err = std::abs(p.length - d[v]) / (d[v] + diag);
    if (!(err <= kAgreeRel)) why = "length " + fmt(p.length) + " but distance " + fmt(d[v]);
    // Bends only at pseudo-source vertices (or sources): at an edge point the two segments are
    // straight in the unfolding, |a − p| + |p − b| = |a' − b| with a' a rotated about the edge.
    for (std::size_t k = 1; why.empty() && k + 1 < p.points.size(); ++k) {
      const SurfacePoint& w = p.points[k].where;
      if (w.kind == SurfacePoint::Kind::Vertex) {
        const bool allowed = mesh.isPseudoSourceVertex(w.vertex) ||
                             std::any_of(solver.sources().begin(), solver.sources().end(), [&](const ResolvedPoint& s) {
                               return s.kind == SurfacePoint::Kind::Vertex && s.element == w.vertex;
                             });
        if (!allowed) {
          // Passing straight through a flat or convex vertex is allowed only without bending.
          const Vec3 a = p.points[k - 1].position, q = p.points[k].position, b = p.points[k + 1].position;
          const double bend = (a - q).norm() + (q - b).norm() - (a - b).norm();
          if (bend > 1e-9 * diag && mesh.angleSum(w.vertex) < 2 * std::numbers::pi - 1e-9)
            why = "bends at vertex " + std::to_string(w.vertex) + ", which is neither a saddle nor on the boundary";
        }
        continue;
      }
      if (w.kind != SurfacePoint::Kind::Edge) continue;
      const Vec3 e0 = mesh.positionInMeshUnits(w.vertex), e1 = mesh.positionInMeshUnits(w.toVertex);
      const Vec3 u = (e1 - e0).normalized();
      const Vec3 a = p.points[k - 1].position, q = p.points[k].position, b = p.points[k + 1].position;
      auto along = [&](const Vec3& x) { return (x - e0).dot(u); };
      auto off = [&](const Vec3& x) { return ((x - e0) - along(x) * u).norm(); };
      // In the unfolding a and b lie on opposite sides of the edge line.
      const double ua = along(a), ub = along(b), ha = off(a), hb = off(b);
      const double unfolded = std::hypot(ua - ub, ha + hb);
      const double bend = (a - q).norm() + (q - b).norm() - unfolded;
      err = std::max(err, std::abs(bend) / diag);
      if (std::abs(bend) > kAgreeRel * diag)
        why = "not straight across edge " + std::to_string(w.vertex) + "-" + std::to_string(w.toVertex) + " (bend " + fmt(bend) + ")";
      (void)q;
    }
    r.maxError = std::max(r.maxError, err);
    if (!why.empty()) {
      ++r.failed;
      if (r.firstFailure.empty()) r.firstFailure = "path to vertex " + std::to_string(v) + ": " + why;
    }
  }
}

bool wanted(const CheckOptions& o, const std::string& name) {
  if (o.oracles.empty()) return name != "cgal";
  return std::find(o.oracles.begin(), o.oracles.end(), name) != o.oracles.end();
}

void writeReproducerFile(const std::string& path, const CheckOptions& o, const std::vector<SurfacePoint>& sources,
                         const std::string& what) {
  std::ofstream out(path);
  out << "# geodex check reproducer: " << what << "\n";
  out << "geodex-check 1\n";
  out << "mesh " << o.meshPath << "\n";
  for (const SurfacePoint& s : sources) out << "source " << formatSurfacePoint(s) << "\n";
}

}  // namespace

OracleResult planarOracle(const Mesh& mesh, const std::vector<SurfacePoint>& sources, std::span<const double> d) {
  OracleResult r("planar");
  planarInto(r, mesh, sources, d);
  return r;
}
OracleResult metamorphicOracle(const Mesh& mesh, const std::vector<SurfacePoint>& sources, std::span<const double> d) {
  OracleResult r("metamorphic");
  metamorphicInto(r, mesh, sources, d);
  return r;
}
OracleResult symmetryOracle(const Mesh& mesh, const SurfacePoint& a, std::span<const double> dFromA) {
  OracleResult r("symmetry");
  symmetryInto(r, mesh, a, dFromA);
  return r;
}
OracleResult pathOracle(const GeodesicSolver& solver, std::span<const double> d) {
  OracleResult r("paths");
  pathsInto(r, solver, d);
  return r;
}
bool judgeFig6(const LocalWindow& w, Fig6Branch decided, bool& agrees) {
  const ExactFig6 exact = exactFig6(w);
  if (!(exact.margin > kExactMargin)) return false;
  agrees = exact.branch == decided;
  return true;
}

const std::vector<std::string>& oracleNames() {
  static const std::vector<std::string> names{"bounds", "lipschitz", "planar", "symmetry", "metamorphic",
                                              "paths", "exact-predicates", "cgal"};
  return names;
}

CheckResult runChecks(const Mesh& mesh, const std::vector<SurfacePoint>& sources, const CheckOptions& options) {
  for (const std::string& o : options.oracles)
    if (std::find(oracleNames().begin(), oracleNames().end(), o) == oracleNames().end())
      throw InputError("bad-oracle", "unknown oracle '" + o + "'");
  if (wanted(options, "cgal") && !options.cgal)
    throw InputError("bad-oracle", "the cgal oracle is not available in this build");

  CheckResult result;
  GeodesicSolver solver(mesh);
  InvariantChecker checker(options.level, /*throwOnViolation=*/false);
  ExactPredicateObserver exact;
  ObserverPair both(checker, exact);
  solver.setObserver(wanted(options, "exact-predicates") ? static_cast<SolverObserver*>(&both) : &checker);
  solver.solve(sources);
  solver.setObserver(nullptr);
  result.counters = solver.counters();
  result.stats = solver.stats();
  result.invariants = checker.tallies();
  // The oracles work on the mesh in its mesh units (exact), with the distances in mesh units:
  // their own arithmetic (squares of coordinates) then holds at any scale the solver accepts.
  const Mesh unitMesh(soupInMeshUnits(mesh));
  const auto d = solver.vertexDistancesInMeshUnits();
  if (const InvariantViolation* v = checker.firstViolation()) {
    result.violations.push_back(v->what());
    if (!options.reproducerPath.empty()) {
      writeReproducer(*v, options.reproducerPath);
      result.reproducer = options.reproducerPath;
    }
  }

  const TriangleSoup& soup = unitMesh.soup();
  auto add = [&](OracleResult r) {
    if (r.failed > 0 && !r.advisory) result.violations.push_back("oracle '" + r.name + "': " + r.firstFailure);
    result.oracles.push_back(std::move(r));
  };
  if (wanted(options, "bounds")) {
    std::vector<Vec3> points;
    for (const SurfacePoint& s : sources) points.push_back(surfacePointPosition(soup, s));
    // The solver snaps a source a hair from a vertex or an edge onto it: tetrahedron.off from
    // e:0,1,5e-11 has d = 0 at vertex 0, 5e-11 below the straight line from where it was given
    // (CheckRegression.GeodexCheckAllowsTheSnapOfASourceAHairFromAVertex).
    const double placing = sourcePlacementSlack(soup, sources);
    add(fromReport("bounds-euclidean",
                   checkEuclideanLowerBound(d, euclideanDistances(soup.positions, points),
                                            kBoundRel, placing)));
    add(fromReport("bounds-dijkstra",
                   checkUpperBound(d, edgeGraphDijkstra(unitMesh, sources), kBoundRel, placing)));
  }
  if (wanted(options, "lipschitz")) add(fromReport("lipschitz", checkLipschitz(unitMesh, d, kBoundRel)));
  if (wanted(options, "planar")) add(planarOracle(unitMesh, sources, d));
  if (wanted(options, "symmetry") && !sources.empty()) {
    // d(a, ·) from the first source alone: the checked field may have several sources.
    const SurfacePoint& a = sources.front();
    add(symmetryOracle(unitMesh, a, exactGeodesicDistance(unitMesh, std::vector<SurfacePoint>{a})));
  }
  if (wanted(options, "metamorphic")) add(metamorphicOracle(unitMesh, sources, d));
  if (wanted(options, "paths")) add(pathOracle(solver, d));
  if (wanted(options, "exact-predicates")) add(exact.result);
  if (wanted(options, "cgal")) {
    OracleResult r = fromReport("cgal", checkAgreement(d, options.cgal(soup, sources), kAgreeRel));
    r.advisory = true;
    add(r);
  }
  if (!result.violations.empty() && result.reproducer.empty() && !options.reproducerPath.empty()) {
    writeReproducerFile(options.reproducerPath, options, sources, result.violations.front());
    result.reproducer = options.reproducerPath;
  }
  return result;
}

void writeCheckText(std::ostream& out, const CheckResult& r) {
  out << "invariant              checked    violated  worst\n";
  for (const InvariantTally& t : r.invariants) {
    if (t.checked == 0) continue;
    out << std::left << std::setw(22) << t.name << std::right << std::setw(10) << t.checked << std::setw(10)
        << t.violated << "  " << std::setprecision(3) << t.worst << "\n";
  }
  out << "oracle                 checked    failed    max error\n";
  for (const OracleResult& o : r.oracles) {
    out << std::left << std::setw(22) << o.name << std::right << std::setw(10) << o.checked << std::setw(10)
        << o.failed << "  " << std::setprecision(3) << o.maxError << (o.advisory ? "  (advisory)" : "") << "\n";
  }
  if (!r.violations.empty()) out << "first violation: " << r.violations.front() << "\n";
  if (!r.reproducer.empty()) out << "reproducer written to " << r.reproducer << "\n";
}

namespace {
std::string jsonString(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      o += buf;
    } else o += c;
  }
  return o + "\"";
}
std::string jsonNumber(double x) { return std::isfinite(x) ? fmt(x) : (x > 0 ? "1e308" : "-1e308"); }
}  // namespace

void writeCheckJson(std::ostream& out, const CheckResult& r) {
  out << "{\"ok\": " << (r.ok() ? "true" : "false") << ", \"cases\": " << r.counters.cases << ", \"degeneracies\": {";
  for (std::size_t k = 0; k < kNumDegeneracyKinds; ++k)
    out << (k ? ", " : "") << "\"" << name(static_cast<DegeneracyKind>(k)) << "\": " << r.counters.count[k];
  out << "}, \"violations\": [";
  for (std::size_t i = 0; i < r.violations.size(); ++i) out << (i ? ", " : "") << jsonString(r.violations[i]);
  out << "], \"invariants\": {";
  bool first = true;
  for (const InvariantTally& t : r.invariants) {
    out << (first ? "" : ", ") << jsonString(t.name) << ": {\"checked\": " << t.checked << ", \"violated\": " << t.violated
        << ", \"worst\": " << jsonNumber(t.worst) << "}";
    first = false;
  }
  out << "}, \"oracles\": {";
  first = true;
  for (const OracleResult& o : r.oracles) {
    out << (first ? "" : ", ") << jsonString(o.name) << ": {\"checked\": " << o.checked << ", \"failed\": " << o.failed
        << ", \"max_error\": " << jsonNumber(o.maxError) << ", \"advisory\": " << (o.advisory ? "true" : "false") << "}";
    first = false;
  }
  out << "}, \"reproducer\": " << jsonString(r.reproducer) << "}\n";
}

}  // namespace geodex::verify
