// fuzz_solver: a whole solve on a small mesh, against the distance oracles (fuzz_solver.h).
#include "geodex/verify/cases/fuzz_solver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "check_support.h"
#include "geodex/error.h"
#include "geodex/geodesic_solver.h"
#include "geodex/mesh.h"
#include "geodex/tolerance.h"
#include "geodex/verify/invariant_checker.h"
#include "geodex/verify/oracles.h"
#include "geodex/verify/repro.h"  // FuzzCase, which the seeds' expectations take
#include "geodex/verify/same_solve.h"
#include "mesh_case.h"
#include "svg.h"

namespace geodex::verify {

using namespace detail;

// ===  Format ====================================================================================

namespace {

/// The grid size a spec's nx, ny bytes stand for.
std::pair<int, int> gridSize(std::uint8_t nxByte, std::uint8_t nyByte) {
  const int nx = 1 + nxByte % 8;
  const int ny = std::min(1 + nyByte % 8, kMaxFuzzGridCells / nx);
  return {nx, ny};
}

SolverSpec readSolverSpec(ByteReader& r) {
  SolverSpec s;
  s.unitExp = r.i8();
  s.mode = r.u8();
  if (s.mode % 2 == 0) {
    s.nx = r.u8();
    s.ny = r.u8();
    s.levels = r.u8();
    s.zStep = r.u8();
    const auto [nx, ny] = gridSize(s.nx, s.ny);
    for (int i = 0; i < (nx + 1) * (ny + 1); ++i) s.vertexBytes.push_back(r.u8());
    for (int i = 0; i < nx * ny; ++i) s.cellBytes.push_back(r.u8());
  } else {
    const int np = 3 + r.u8() % (kMaxFuzzSoupPoints - 2);
    for (int i = 0; i < np; ++i) s.points.push_back({r.i8(), r.i8(), r.i8()});
    const int nf = 1 + r.u8() % kMaxFuzzFaces;
    for (int i = 0; i < nf; ++i) s.faces.push_back({r.u8(), r.u8(), r.u8()});
  }
  const int ns = 1 + r.u8() % kMaxFuzzSources;
  for (int i = 0; i < ns; ++i) s.sources.push_back(readSourceSpec(r));
  s.flags = r.u8();
  s.stop = r.quantity();
  return s;
}

}  // namespace

std::vector<std::uint8_t> encode(const SolverSpec& s) {
  ByteWriter w;
  w.i8(s.unitExp);
  w.u8(s.mode);
  if (s.mode % 2 == 0) {
    w.u8(s.nx);
    w.u8(s.ny);
    w.u8(s.levels);
    w.u8(s.zStep);
    const auto [nx, ny] = gridSize(s.nx, s.ny);
    for (int i = 0; i < (nx + 1) * (ny + 1); ++i)
      w.u8(i < static_cast<int>(s.vertexBytes.size()) ? s.vertexBytes[i] : 0);
    for (int i = 0; i < nx * ny; ++i)
      w.u8(i < static_cast<int>(s.cellBytes.size()) ? s.cellBytes[i] : 0);
  } else {
    GEODEX_REQUIRE(s.points.size() >= 3 && s.points.size() <= kMaxFuzzSoupPoints,
                   "3 to " << kMaxFuzzSoupPoints << " soup points");
    GEODEX_REQUIRE(!s.faces.empty() && s.faces.size() <= kMaxFuzzFaces,
                   "1 to " << kMaxFuzzFaces << " soup faces");
    w.u8(static_cast<std::uint8_t>(s.points.size() - 3));
    for (const auto& p : s.points)
      for (std::int8_t c : p) w.i8(c);
    w.u8(static_cast<std::uint8_t>(s.faces.size() - 1));
    for (const auto& f : s.faces)
      for (std::uint8_t c : f) w.u8(c);
  }
  GEODEX_REQUIRE(!s.sources.empty() && s.sources.size() <= kMaxFuzzSources,
                 "1 to " << kMaxFuzzSources << " sources");
  w.u8(static_cast<std::uint8_t>(s.sources.size() - 1));
  for (const SourceSpec& src : s.sources) writeSourceSpec(w, src);
  w.u8(s.flags);
  w.quantity(s.stop);
  return w.bytes();
}

// ===  Decoding ==================================================================================

namespace {

std::optional<SolverCase> makeSolverCase(const SolverSpec& s) {
  const double unit = unitOf(s.unitExp);
  SolverCase c;
  TriangleSoup& soup = c.soup;
  if (s.mode % 2 == 0) {
    const auto [nx, ny] = gridSize(s.nx, s.ny);
    const int levels = std::max(1, s.levels % 5);
    static constexpr double kZSteps[] = {1.0, 0.5, 2.0, 0.25};
    static constexpr double kJitter[] = {0.0, 0.5, -0.5, 0.0};
    const double zUnit = kZSteps[s.zStep % 4] * unit;
    bool jittered = false, flat = true, removed = false;
    double z0 = 0.0;
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        const std::size_t k = static_cast<std::size_t>(j * (nx + 1) + i);
        const std::uint8_t b = k < s.vertexBytes.size() ? s.vertexBytes[k] : 0;
        const double dx = kJitter[(b >> 4) & 3], dy = kJitter[(b >> 6) & 3];
        const double z = ((b & 15) % levels) * zUnit;
        if (k == 0) z0 = z;
        flat = flat && z == z0;
        jittered = jittered || dx != 0.0 || dy != 0.0;
        soup.positions.emplace_back((i + dx) * unit, (j + dy) * unit, z);
      }
    }
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const std::size_t k = static_cast<std::size_t>(j * nx + i);
        const std::uint8_t b = k < s.cellBytes.size() ? s.cellBytes[k] : 0;
        if ((b & 2) != 0) {
          removed = true;
          continue;
        }
        const Index v00 = j * (nx + 1) + i, v10 = v00 + 1, v01 = v00 + (nx + 1), v11 = v01 + 1;
        if ((b & 1) == 0) {
          soup.faces.push_back({v00, v10, v11});
          soup.faces.push_back({v00, v11, v01});
        } else {
          soup.faces.push_back({v00, v10, v01});
          soup.faces.push_back({v10, v11, v01});
        }
      }
    }
    c.planar = flat && !jittered;
    c.rectangle = c.planar && !removed;
  } else {
    for (const auto& p : s.points) {
      soup.positions.emplace_back(wrapInt(p[0], -8, 8) * unit, wrapInt(p[1], -8, 8) * unit,
                                  wrapInt(p[2], -8, 8) * unit);
    }
    const auto np = static_cast<Index>(soup.positions.size());
    for (const auto& f : s.faces) soup.faces.push_back({f[0] % np, f[1] % np, f[2] % np});
  }
  if (soup.faces.empty() || soup.faces.size() > static_cast<std::size_t>(kMaxFuzzFaces)) return std::nullopt;
  if (!soupValid(soup)) return std::nullopt;
  for (const SourceSpec& src : s.sources) c.sources.push_back(makeSource(src, soup));
  if ((s.flags & 1) != 0) c.stopDistance = std::abs(fieldValue(s.stop, 0, 64, unit, unit));
  c.checkSymmetry = (s.flags & 2) != 0;
  if ((s.flags & 4) != 0) {
    const auto k = static_cast<Index>(s.flags >> 3);
    const double third = 1.0 / 3.0;
    c.targets = {SurfacePoint::atVertex(k % static_cast<Index>(soup.positions.size())),
                 SurfacePoint::inFace(k % static_cast<Index>(soup.faces.size()), third, third, third)};
  }
  return c;
}

}  // namespace

std::optional<SolverCase> decodeSolver(std::span<const std::uint8_t> bytes) {
  if (bytes.size() > kMaxFuzzInputBytes) return std::nullopt;
  ByteReader r(bytes);
  return makeSolverCase(readSolverSpec(r));
}

// ===  Check =====================================================================================

namespace {

/// The distances within the planar domain the mesh covers (PlanarDomain, oracles.h) from the
/// nearest source to each vertex, or nullopt when the mesh is not one the oracle can describe
/// (pinched boundary, several components).
std::optional<std::vector<double>> planarReference(const Mesh& mesh, const TriangleSoup& soup,
                                                   const std::vector<Vec3>& sources) {
  if (mesh.numComponents() != 1) return std::nullopt;
  try {
    std::vector<Polygon2> loops = planarBoundaryPolygons(soup);
    if (!coversItsDomainOnce(soup, loops)) return std::nullopt;
    PlanarDomain domain(std::move(loops));
    std::vector<Vec2> queries;
    std::vector<Index> which;
    for (Index x = 0; x < mesh.numVertices(); ++x) {
      if (!mesh.isReferenced(x)) continue;
      queries.emplace_back(soup.positions[x].x(), soup.positions[x].y());
      which.push_back(x);
    }
    std::vector<double> ref(mesh.numVertices(), INFINITY);
    for (const Vec3& s : sources) {
      const auto d = domain.distances(Vec2(s.x(), s.y()), queries);
      for (std::size_t i = 0; i < which.size(); ++i) ref[which[i]] = std::min(ref[which[i]], d[i]);
    }
    return ref;
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

constexpr double kRel = 1e-9;  // DESIGN.md's accuracy target, × the distances or diagonal

/// A case after its first solve, as each step of checkSolver reads it. Every oracle works in
/// mesh units, as the solver does, so that its own arithmetic holds at any scale; the messages
/// show the mesh as given.
struct SolvedCase {
  const SolverCase& c;
  const Mesh& mesh;
  const GeodesicSolver& solver;
  TriangleSoup soup;                 ///< the mesh in mesh units
  std::vector<double> d;             ///< the vertex distances, in mesh units
  std::vector<Vec3> sourcePositions;  ///< in mesh units
  double diag = 0.0;                 ///< the bounding box diagonal, in mesh units

  /// The mesh as given and its sources, to follow a failure's message.
  std::string where() const {
    std::string w = "\nmesh:\n" + describeSoup(mesh.soup());
    for (const SurfacePoint& s : c.sources) w += "source " + formatSurfacePoint(s) + "\n";
    return w;
  }
};

/// An oracle's report as the verdict: false, with the check failed in v, when it is not ok.
bool report(Verdict& v, const char* check, const CheckReport& r, const SolvedCase& s) {
  if (!r.ok()) fail(v, check, r.summary() + s.where());
  return r.ok();
}

/// No distance is NaN or negative.
bool checkDistanceValues(const SolvedCase& s, Verdict& v) {
  for (Index x = 0; x < s.d.size(); ++x) {
    if (std::isnan(s.d[x]) || s.d[x] < 0.0)
      return fail(v, "distance-values", "vertex " + std::to_string(x) + " has distance " + fmt(s.d[x]) + s.where()), false;
  }
  return true;
}

/// How far the oracles' sources may be from the solver's (sourcePlacementSlack).
double sourcePlacement(const SolvedCase& s) { return sourcePlacementSlack(s.soup, s.c.sources); }

/// Euclidean ≤ d ≤ edge-graph Dijkstra, Lipschitz along edges, and on planar meshes the
/// Euclidean (rectangle) or planar-domain distance.
bool checkDistanceOracles(const SolvedCase& s, Verdict& v) {
  const std::vector<double>& d = s.d;
  const std::vector<double> euclid = euclideanDistances(s.soup.positions, s.sourcePositions);
  const double placing = sourcePlacement(s);
  if (!report(v, "euclidean-lower-bound", checkEuclideanLowerBound(d, euclid, kRel, placing), s)) return false;
  if (!report(v, "upper-bound", checkUpperBound(d, edgeGraphDijkstra(s.soup, s.c.sources), kRel, placing), s))
    return false;
  if (!report(v, "lipschitz", checkLipschitz(s.soup, d, kRel), s)) return false;
  if (s.c.rectangle) {
    if (!report(v, "planar-agreement", checkAgreement(d, euclid, kRel, placing), s)) return false;
  } else if (s.c.planar) {
    if (const auto ref = planarReference(s.mesh, s.soup, s.sourcePositions))
      if (!report(v, "planar-agreement", checkAgreement(d, *ref, kRel, placing), s)) return false;
  }
  return true;
}

/// Queries at edge midpoints lie within what their edge's ends allow.
bool checkEdgeMidpoints(const SolvedCase& s, Verdict& v) {
  for (Index e = 0; e < s.mesh.numEdges(); ++e) {
    const Edge& E = s.mesh.edge(e);
    const double du = s.d[E.vertex[0]], dv = s.d[E.vertex[1]];
    const double got = s.solver.distanceInMeshUnits(SurfacePoint::onEdge(E.vertex[0], E.vertex[1], 0.5));
    const Vec3 mid = 0.5 * (s.soup.positions[E.vertex[0]] + s.soup.positions[E.vertex[1]]);
    if (!std::isfinite(du)) {
      if (std::isfinite(got))
        return fail(v, "edge-query", "edge " + std::to_string(e) + " has unreachable ends but its midpoint is at " + fmt(got) + s.where()), false;
      continue;
    }
    double lower = std::max(du, dv) - 0.5 * E.length;
    double nearest = INFINITY;
    for (const Vec3& p : s.sourcePositions) nearest = std::min(nearest, (p - mid).norm());
    // The midpoint and the sources are placed in 3-D, to the rounding of the coordinates: far
    // from the origin that is more than kRel × a small mesh's distances
    // (CheckRegression.AFlatGridFarFromTheOriginPassesTheMidpointCheckThoughPlacingItsMidpointsRounds).
    lower = std::max(lower, nearest - sourcePlacement(s));
    const double upper = std::min(du, dv) + 0.5 * E.length;
    const double slack = kRel * (upper + s.diag);
    if (!(got >= lower - slack && got <= upper + slack)) {
      std::ostringstream os;
      os << std::setprecision(17) << "the midpoint of edge " << e << " (" << E.vertex[0] << "-"
         << E.vertex[1] << ", ends at " << du << " and " << dv << ", length " << E.length
         << ") is at " << got << ", outside [" << lower << ", " << upper << "]";
      return fail(v, "edge-query", os.str() + s.where()), false;
    }
  }
  return true;
}

/// The reachable vertex farthest from the sources, or kNoIndex when none is reachable.
Index farthestVertex(const std::vector<double>& d) {
  Index farthest = kNoIndex;
  for (Index x = 0; x < d.size(); ++x)
    if (std::isfinite(d[x]) && (farthest == kNoIndex || d[x] > d[farthest])) farthest = x;
  return farthest;
}

/// A path traced from the farthest vertex ends at a source and is as long as its distance.
bool checkTracedPath(const SolvedCase& s, Index farthest, Verdict& v) {
  const std::vector<double>& d = s.d;
  if (farthest == kNoIndex || !(d[farthest] > 0.0)) return true;
  const double inverse = s.mesh.meshUnit().inverse;
  try {
    GeodesicPath p = s.solver.path(SurfacePoint::atVertex(farthest));
    p.length *= inverse;
    for (PathPoint& q : p.points) q.position *= inverse;
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < p.points.size(); ++i) sum += (p.points[i + 1].position - p.points[i].position).norm();
    double toSource = INFINITY;
    if (!p.points.empty())
      for (const Vec3& src : s.sourcePositions) toSource = std::min(toSource, (p.points.back().position - src).norm());
    const double tolerance = kRel * (d[farthest] + s.diag);
    if (p.points.empty() || !(std::abs(p.length - d[farthest]) <= tolerance) ||
        !(std::abs(sum - p.length) <= tolerance) || !(toSource <= tolerance)) {
      std::ostringstream os;
      os << std::setprecision(17) << "the path from vertex " << farthest << " (distance " << d[farthest]
         << ") has length " << p.length << ", " << p.points.size() << " points summing to " << sum
         << ", ending " << toSource << " from the nearest source:";
      for (const PathPoint& q : p.points)
        os << "\n  " << formatSurfacePoint(q.where) << " at (" << q.position.x() << ", " << q.position.y()
           << ", " << q.position.z() << ")";
      return fail(v, "path-length", os.str() + s.where()), false;
    }
  } catch (const InputError& e) {
    // Its length is in file units: refused, rightly, when the distance it must equal overflows.
    const double longest = d[farthest] + kRel * (d[farthest] + s.diag);
    if (!(e.kind() == "distance-overflow" && inFileUnitsRange(longest, s.mesh.meshUnit()) == ScaledRange::Overflow))
      return fail(v, "unexpected-exception", std::string("path: ") + e.what() + s.where()), false;
  } catch (const std::exception& e) {
    return fail(v, "unexpected-exception", std::string("path: ") + e.what() + s.where()), false;
  }
  return true;
}

/// With a stop distance, a second solve keeps every distance within it and drops every one
/// beyond.
bool checkStopDistance(const SolvedCase& s, Verdict& v) {
  if (!s.c.stopDistance) return true;
  GeodesicSolver stopped(s.mesh);
  SolveOptions options;
  options.stopDistance = *s.c.stopDistance;
  if (!solveChecked(stopped, s.c.sources, options, v)) return v.message += s.where(), false;
  const auto ds = stopped.vertexDistancesInMeshUnits();
  const double stop = *s.c.stopDistance * s.mesh.meshUnit().inverse;
  // Distances are good to kRel × diagonal: a vertex that close to the stop may go either way.
  const double band = kRel * (stop + s.diag);
  for (Index x = 0; x < s.d.size(); ++x) {
    const bool within = s.d[x] <= stop - band;
    const bool beyond = s.d[x] > stop + band;
    if ((within && !(std::abs(ds[x] - s.d[x]) <= band)) || (beyond && ds[x] != INFINITY)) {
      return fail(v, "stop-distance", "vertex " + std::to_string(x) + " at " + fmt(s.d[x]) + " gets " +
                                          fmt(ds[x]) + " with stop distance " + fmt(stop) + s.where()),
             false;
    }
  }
  return true;
}

/// With targets, a second solve that stops once they are final gives them the distances the
/// whole solve gives them, and every vertex distance it keeps (final up to its radius) too.
bool checkTargets(const SolvedCase& s, Verdict& v) {
  if (s.c.targets.empty()) return true;
  GeodesicSolver targeted(s.mesh);
  SolveOptions options;
  options.targets = s.c.targets;
  if (!solveChecked(targeted, s.c.sources, options, v)) return v.message += s.where(), false;
  // (Both finite, or the same infinity: a finite distance where the whole solve has none is wrong.)
  const auto agree = [&](double got, double whole) {
    return got == whole || (std::isfinite(got) && std::isfinite(whole) && std::abs(got - whole) <= kRel * (whole + s.diag));
  };
  for (const SurfacePoint& t : s.c.targets) {
    const double got = targeted.distanceInMeshUnits(t), whole = s.solver.distanceInMeshUnits(t);
    if (!agree(got, whole))
      return fail(v, "targets", "target " + formatSurfacePoint(t) + " is at " + fmt(got) +
                                    " when it stops the solve, " + fmt(whole) + " after the whole solve" + s.where()),
             false;
  }
  const double radius = targeted.stats().radius * s.mesh.meshUnit().inverse;
  const auto ds = targeted.vertexDistancesInMeshUnits();
  for (Index x = 0; x < s.d.size(); ++x) {
    const bool final = s.d[x] <= radius - kRel * (radius + s.diag);
    if ((std::isfinite(ds[x]) || final) && !agree(ds[x], s.d[x]))
      return fail(v, "targets", "vertex " + std::to_string(x) + " at " + fmt(s.d[x]) + " gets " + fmt(ds[x]) +
                                    " from the solve the targets stopped at radius " + fmt(radius) + s.where()),
             false;
  }
  return true;
}

/// A solve for vertex distances only, which releases the lists behind the wavefront (and starts
/// again keeping them should a window reach a released one), gives the vertex distances of the
/// solve that keeps them, to the bit (SolveOptions::vertexDistancesOnly).
bool checkVertexDistancesOnly(const SolvedCase& s, Verdict& v) {
  GeodesicSolver released(s.mesh);  // no observer: one that reads the lists would keep them
  SolveOptions options;
  options.vertexDistancesOnly = true;
  try {
    released.solve(s.c.sources, options);
  } catch (const std::exception& e) {
    return fail(v, "vertex-distances-only",
                std::string("the solve threw: ") + e.what() + s.where()),
           false;
  }
  const auto kept = s.solver.vertexDistancesInMeshUnits();
  const auto got = released.vertexDistancesInMeshUnits();
  for (Index x = 0; x < kept.size(); ++x) {
    if (!(got[x] == kept[x] || (std::isnan(got[x]) && std::isnan(kept[x]))))
      return fail(v, "vertex-distances-only",
                  "vertex " + std::to_string(x) + " at " + fmt(kept[x]) + " gets " + fmt(got[x]) +
                      " from the solve that released " +
                      std::to_string(released.stats().edgesReleased) + " lists" +
                      (released.stats().releaseUndone ? " (and started again)" : "") + s.where()),
             false;
  }
  return true;
}

/// A solve whose rounds of batches run on two threads (SolveOptions::threads) gives what the
/// checked solve, on one, gave, to the bit: the rounds are the same, so every vertex distance,
/// every interval of every edge and every count must be.
bool checkTwoThreads(const SolvedCase& s, Verdict& v) {
  GeodesicSolver two(s.mesh);
  SolveOptions options;
  options.threads = 2;
  try {
    two.solve(s.c.sources, options);
  } catch (const std::exception& e) {
    return fail(v, "two-threads", std::string("the solve threw: ") + e.what() + s.where()), false;
  }
  if (const std::string where = firstDifference(s.solver, two, /*lists=*/true); !where.empty())
    return fail(v, "two-threads", "the " + where + " differs with two threads" + s.where()), false;
  return true;
}

/// When asked, d(a, b) = d(b, a) for a single vertex source a and the farthest vertex b.
bool checkSymmetricDistance(const SolvedCase& s, Index farthest, Verdict& v) {
  const SolverCase& c = s.c;
  if (!(c.checkSymmetry && c.sources.size() == 1 && c.sources[0].kind == SurfacePoint::Kind::Vertex &&
        farthest != kNoIndex && farthest != c.sources[0].vertex))
    return true;
  GeodesicSolver back(s.mesh);
  const std::vector<SurfacePoint> from{SurfacePoint::atVertex(farthest)};
  if (!solveChecked(back, from, {}, v)) return v.message += s.where(), false;
  return report(v, "symmetry", checkSymmetry(s.d[farthest], back.vertexDistancesInMeshUnits()[c.sources[0].vertex], kRel),
                s);
}

}  // namespace

namespace {

struct PlantedError {
  Index vertex;
  double amount;  ///< in mesh units
};

Verdict checkSolverWith(const SolverCase& c, const PlantedError* planted) {
  Verdict v;
  v.interesting = true;
  auto mesh = buildMesh(c.soup, v);
  if (!mesh) return v;
  GeodesicSolver solver(*mesh);
  SolvedCase s{c, *mesh, solver, soupInMeshUnits(*mesh), {}, {}, 0.0};

  // The solve, with the full invariant tier and the unfolding check at every edge update.
  InvariantChecker invariants(CheckLevel::Full, true);
  UnfoldingChecker unfolding(*mesh, &invariants);
  solver.setObserver(&unfolding);
  if (!solveChecked(solver, c.sources, {}, v)) return v.message += s.where(), v;
  v.degeneracies = solver.counters();
  const auto meshUnitDistances = solver.vertexDistancesInMeshUnits();
  s.d.assign(meshUnitDistances.begin(), meshUnitDistances.end());
  if (planted != nullptr) s.d.at(planted->vertex) += planted->amount;
  {
    std::ostringstream os;
    os << mesh->numFaces() << " faces, " << c.sources.size() << " source(s), "
       << solver.counters().cases << " propagation cases, " << solver.stats().intervalsAtEnd
       << " intervals at the end";
    v.summary = os.str();
  }
  s.diag = mesh->boundingBoxDiagonalInMeshUnits();

  // Then the distances it gave, against the oracles; the first check to fail ends the case.
  if (!checkDistanceValues(s, v)) return v;
  for (const SurfacePoint& p : c.sources) s.sourcePositions.push_back(surfacePointPosition(s.soup, p));
  const Index farthest = farthestVertex(s.d);
  if (!checkDistanceOracles(s, v)) return v;
  if (!checkEdgeMidpoints(s, v)) return v;
  if (!checkTracedPath(s, farthest, v)) return v;
  if (!checkStopDistance(s, v)) return v;
  if (!checkTargets(s, v)) return v;
  if (!checkVertexDistancesOnly(s, v)) return v;
  if (!checkTwoThreads(s, v)) return v;
  checkSymmetricDistance(s, farthest, v);
  return v;
}

}  // namespace

Verdict checkSolver(const SolverCase& c) { return checkSolverWith(c, nullptr); }

Verdict checkSolverWithPlantedError(const SolverCase& c, Index vertex, double errorInMeshUnits) {
  const PlantedError planted{vertex, errorInMeshUnits};
  return checkSolverWith(c, &planted);
}

// ===  Description and picture ===================================================================

void describe(const SolverCase& c, std::ostream& out) {
  out << std::setprecision(17);
  out << "# fuzz_solver: " << c.soup.faces.size() << " faces"
      << (c.rectangle ? ", planar rectangle" : c.planar ? ", planar" : "") << "\n"
      << describeSoup(c.soup);
  for (const SurfacePoint& s : c.sources) out << "source " << formatSurfacePoint(s) << "\n";
  if (c.stopDistance) out << "stop-distance " << *c.stopDistance << "\n";
  for (const SurfacePoint& t : c.targets) out << "target " << formatSurfacePoint(t) << "\n";
  if (c.checkSymmetry) out << "check-symmetry\n";
}

void writeSvg(const SolverCase& c, std::ostream& out) {
  std::vector<Vec3> sources;
  for (const SurfacePoint& s : c.sources) sources.push_back(surfacePointPosition(c.soup, s));
  std::vector<double> d;
  try {
    const Mesh mesh(c.soup);
    d = exactGeodesicDistance(mesh, c.sources);
  } catch (const std::exception&) {
  }
  svgMesh(c.soup, sources, d, "fuzz_solver: vertex: distance", out);
}

// ===  Seeds =====================================================================================

namespace {

using Q = Quantity;
Q n(int v) { return Q::lattice(v); }

/// A grid of nx × ny cells: `levels` heights, a byte per vertex and per cell as SolverSpec says.
SolverSpec grid(int nx, int ny, int levels, std::vector<std::uint8_t> vertexBytes, std::vector<std::uint8_t> cells,
                std::vector<SourceSpec> sources, std::uint8_t flags = 0, Q stop = {}, int unitExp = 0) {
  SolverSpec s;
  s.unitExp = static_cast<std::int8_t>(unitExp);
  s.mode = 0;
  s.nx = static_cast<std::uint8_t>(nx - 1);
  s.ny = static_cast<std::uint8_t>(ny - 1);
  s.levels = static_cast<std::uint8_t>(levels);
  s.vertexBytes = std::move(vertexBytes);
  s.cellBytes = std::move(cells);
  s.sources = std::move(sources);
  s.flags = flags;
  s.stop = stop;
  return s;
}

/// A soup of lattice points and faces.
SolverSpec soup(std::vector<std::array<std::int8_t, 3>> points, std::vector<std::array<std::uint8_t, 3>> faces,
                std::vector<SourceSpec> sources, std::uint8_t flags = 0) {
  SolverSpec s;
  s.mode = 1;
  s.points = std::move(points);
  s.faces = std::move(faces);
  s.sources = std::move(sources);
  s.flags = flags;
  return s;
}

using SolverExpect = std::function<std::string(const SolverCase&, const Verdict&)>;

/// A seed that must meet `extra`.
Seed solver(const std::string& name, const SolverSpec& s, SolverExpect extra = {}) {
  return {name, encode(s), [extra](const FuzzCase& c, const Verdict& v) {
            return extra ? extra(std::get<SolverCase>(c), v) : std::string();
          }};
}

/// Some vertex is unreachable from the sources.
SolverExpect someUnreachable() {
  return [](const SolverCase& c, const Verdict&) {
    const Mesh mesh(c.soup);
    for (double d : exactGeodesicDistance(mesh, c.sources))
      if (!std::isfinite(d)) return std::string();
    return std::string("every vertex is reachable");
  };
}

}  // namespace

std::vector<Seed> solverSeeds() {
  const std::uint8_t kRemoved = 2, kOtherDiagonal = 1;
  auto is = [](bool rectangle, bool planar) -> SolverExpect {
    return [=](const SolverCase& c, const Verdict&) {
      return c.rectangle == rectangle && c.planar == planar ? "" : "planar/rectangle flags differ";
    };
  };
  return {
    // Flat grids: every interior vertex has angle sum exactly 2π; rays along the diagonals run
    // exactly through vertices (collinear rays); distances are Euclidean.
    solver("flat-grid-2pi-vertices-source-at-corner", grid(4, 4, 0, {}, {}, {atVertex(0)}), is(true, true)),
    solver("flat-grid-source-at-2pi-interior-vertex", grid(4, 4, 0, {}, {}, {atVertex(12)}), is(true, true)),
    solver("flat-grid-alternating-diagonals-two-sources",
           grid(4, 4, 0, {}, std::vector<std::uint8_t>(16, kOtherDiagonal), {atVertex(0), atVertex(24)}), is(true, true)),
    solver("boundary-vertex-source-mid-side", grid(4, 4, 0, {}, {}, {atVertex(2)}), is(true, true)),
    solver("source-on-an-edge-midpoint", grid(4, 4, 0, {}, {}, {onEdge(10, 0, n(8))})),
    solver("source-on-an-edge-within-snap-of-vertex", grid(4, 4, 0, {}, {}, {onEdge(10, 0, n(0).nudged(8, Nudge::SnapParam, true))})),
    solver("source-inside-a-face", grid(4, 4, 0, {}, {}, {inFace(9, n(3), n(5))})),
    solver("three-sources-vertex-edge-face", grid(8, 4, 0, {}, {}, {atVertex(0), onEdge(20, 1, n(4)), inFace(50, n(5), n(5))})),
    // Mesh-level cases.
    solver("disconnected-part-unreachable", grid(4, 1, 0, {}, {0, kRemoved, 0, 0}, {atVertex(0)}), someUnreachable()),
    solver("unreferenced-vertex-corner-cell-removed", grid(3, 3, 0, {}, {kRemoved}, {atVertex(5)})),
    solver("l-shape-planar-nonconvex-reflex-corner",
           grid(4, 4, 0, {}, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, kRemoved, kRemoved, 0, 0, kRemoved, kRemoved}, {atVertex(0)}),
           is(false, true)),
    solver("square-with-hole-planar",
           grid(4, 4, 0, {}, {0, 0, 0, 0, 0, kRemoved, kRemoved, 0, 0, kRemoved, kRemoved, 0, 0, 0, 0, 0}, {atVertex(0)}),
           is(false, true)),
    // Height fields: the centre of a 2 × 2 grid (vertex 4) as a saddle (angle sum > 2π) and a cone.
    solver("saddle-vertex-height-field", grid(2, 2, 3, {1, 0, 1, 2, 1, 2, 1, 0, 1}, {}, {atVertex(0)})),
    solver("saddle-vertex-as-source", grid(2, 2, 3, {1, 0, 1, 2, 1, 2, 1, 0, 1}, {}, {atVertex(4)})),
    solver("cone-vertex-peak", grid(2, 2, 4, {0, 0, 0, 0, 3, 0, 0, 0, 0}, {}, {atVertex(0)})),
    solver("terraced-steps-height-field",
           grid(4, 4, 4, {0, 0, 1, 1, 2, 0, 1, 1, 2, 2, 1, 1, 2, 3, 3, 1, 2, 2, 3, 3, 2, 2, 3, 3, 3}, {}, {atVertex(0)})),
    solver("terraced-steps-scaled-1e-6",
           grid(4, 4, 4, {0, 0, 1, 1, 2, 0, 1, 1, 2, 2, 1, 1, 2, 3, 3, 1, 2, 2, 3, 3, 2, 2, 3, 3, 3}, {}, {atVertex(0)}, 0, {},
                -20)),
    solver("saddle-scaled-1e+6", grid(2, 2, 3, {1, 0, 1, 2, 1, 2, 1, 0, 1}, {}, {atVertex(0)}, 0, {}, 20)),
    solver("moved-vertex-needle-faces", grid(3, 3, 0, {0, 0, 0, 0, 0, 0x10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, {}, {atVertex(0)}),
           is(false, false)),
    solver("moved-vertex-zero-area-face-in-grid",
           grid(2, 2, 0, {0, 0, 0, 0, 0x90, 0, 0, 0, 0}, {}, {atVertex(0)})),
    // Lattice soups.
    solver("zero-area-face-between-two-sources",
           soup({{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {2, 2, 0}, {2, -2, 1}}, {{0, 1, 3}, {1, 2, 3}, {0, 2, 1}, {0, 4, 2}},
                {atVertex(3), atVertex(4)}),
           [](const SolverCase&, const Verdict& v) {
             return v.degeneracies.zeroAreaFaces > 0 ? "" : "crosses no zero-area face";
           }),
    solver("non-manifold-vertex-bowtie",
           soup({{0, 0, 0}, {3, 1, 0}, {3, -1, 0}, {-3, 1, 1}, {-3, -1, 1}}, {{0, 1, 2}, {0, 3, 4}}, {atVertex(1)})),
    solver("inconsistent-winding-bent-quad",
           soup({{0, 0, 0}, {4, 0, 0}, {4, 4, 2}, {0, 4, 0}}, {{0, 1, 2}, {2, 0, 3}}, {atVertex(1)})),
    solver("duplicated-position-crack",
           soup({{0, 0, 0}, {4, 0, 0}, {2, 3, 0}, {4, 0, 0}, {2, 3, 0}, {6, 3, 1}}, {{0, 1, 2}, {3, 5, 4}}, {atVertex(0)}),
           someUnreachable()),
    solver("closed-cube-cone-vertices",
           soup({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 4}, {4, 0, 4}, {4, 4, 4}, {0, 4, 4}},
                {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6},
                 {3, 0, 4}, {3, 4, 7}},
                {atVertex(0)})),
    solver("closed-tetrahedron-edge-source",
           soup({{0, 0, 0}, {6, 0, 0}, {3, 5, 0}, {3, 2, 5}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}, {onEdge(0, 0, n(5))})),
    // Options: a stop distance half-way, targets near the source, and d(a, b) = d(b, a).
    solver("stop-distance-half-way", grid(4, 4, 0, {}, {}, {atVertex(0)}, 1, n(3))),
    solver("targets-vertex-and-face-near-the-source", grid(4, 4, 0, {}, {}, {atVertex(0)}, 4 | (6 << 3))),
    solver("symmetry-vertex-to-farthest",
           grid(3, 3, 3, {0, 1, 2, 1, 2, 1, 2, 1, 0, 1, 0, 1, 2, 1, 2, 1}, {}, {atVertex(0)}, 2)),
    // Path tracing through a zero-area face: the tracer prices each step through every face at
    // the point, so the path from vertex 4, reaching (2, 0, 0) on the long edge of the zero-area
    // face (0, 2, 1), passes through that face along its line to vertex 1 at the same position
    // instead of turning to vertex 0 (path.cpp; tests/unit/geodesic_solver_test.cpp).
    {.name = "path-length-through-zero-area-face",
     .bytes = encode(soup({{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {2, 2, 0}, {2, -2, 1}},
                          {{0, 1, 3}, {1, 2, 3}, {0, 2, 1}, {0, 4, 2}}, {atVertex(3)})),
     .expect = {},
     .dir = "regress"},
  };
}

}  // namespace geodex::verify
