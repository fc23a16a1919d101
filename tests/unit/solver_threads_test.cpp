// SolveOptions::threads: a solve with two threads runs each round's batches on both (runRound in
// geodesic_solver.cpp); the rounds are the same as with one, so everything a solve gives must be
// the same to the bit: distances, lists, counts, and the observer's events, which all come from
// the solving thread. The tsan preset runs these under ThreadSanitizer.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "geodex/geodesic_solver.h"
#include "geodex/mesh_io.h"
#include "geodex/verify/invariant_checker.h"
#include "geodex/verify/mesh_generators.h"

namespace geodex {
namespace {

struct NamedMesh {
  std::string name;
  TriangleSoup soup;
};

std::vector<NamedMesh> meshes() {
  return {
      {"icosphere-4", verify::icosphereMesh(4, 1.0)},
      {"bumpy-40", verify::bumpyHeightField(40, 40, 0.3, 7)},
      {"square-with-hole", verify::squareWithHoleMesh(24, 1.0, 0.4)},
      {"needle-fan", verify::needleFanMesh(64, 1e-3, 1.0)},
  };
}

// A vertex, an edge point and a face point near the middle of the mesh, and the three at once.
std::vector<std::vector<SurfacePoint>> sourceSets(const TriangleSoup& soup) {
  const Index f = static_cast<Index>(soup.faces.size() / 2);
  const auto& t = soup.faces[f];
  const SurfacePoint v = SurfacePoint::atVertex(t[0]);
  const SurfacePoint e = SurfacePoint::onEdge(t[1], t[2], 0.3);
  const SurfacePoint p = SurfacePoint::inFace(f, 0.2, 0.3, 0.5);
  return {{v}, {e}, {p}, {SurfacePoint::atVertex(0), e, p}};
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameInterval(const Interval& a, const Interval& b) {
  return sameBits(a.b0, b.b0) && sameBits(a.b1, b.b1) && sameBits(a.source.x(), b.source.x()) &&
         sameBits(a.source.y(), b.source.y()) && sameBits(a.sigma, b.sigma) &&
         a.origin == b.origin && a.side == b.side && a.flags == b.flags;
}

// Everything one solve gives that can be compared, with what it differs in first.
std::string firstDifference(const GeodesicSolver& one, const GeodesicSolver& two, bool lists) {
  const auto d1 = one.vertexDistances(), d2 = two.vertexDistances();
  if (d1.size() != d2.size()) return "vertex count";
  for (std::size_t v = 0; v < d1.size(); ++v)
    if (!sameBits(d1[v], d2[v])) return "distance of vertex " + std::to_string(v);
  const SolveStats &s1 = one.stats(), &s2 = two.stats();
  if (s1.intervalsCreated != s2.intervalsCreated) return "intervalsCreated";
  if (s1.intervalsPropagated != s2.intervalsPropagated) return "intervalsPropagated";
  if (s1.pseudoSourceEvents != s2.pseudoSourceEvents) return "pseudoSourceEvents";
  if (s1.maxIntervalsPerEdge != s2.maxIntervalsPerEdge) return "maxIntervalsPerEdge";
  if (s1.intervalsAtEnd != s2.intervalsAtEnd) return "intervalsAtEnd";
  if (s1.shadowsClosed != s2.shadowsClosed) return "shadowsClosed";
  if (s1.windowsDroppedAtEdgeEnd != s2.windowsDroppedAtEdgeEnd) return "windowsDroppedAtEdgeEnd";
  if (s1.windowsDroppedAlongEdge != s2.windowsDroppedAlongEdge) return "windowsDroppedAlongEdge";
  if (s1.edgesReleased != s2.edgesReleased) return "edgesReleased";
  if (s1.releaseUndone != s2.releaseUndone) return "releaseUndone";
  if (s1.batchesBesideTheFront != s2.batchesBesideTheFront) return "batchesBesideTheFront";
  if (!sameBits(s1.radius, s2.radius)) return "radius";
  const DegeneracyCounters &c1 = one.counters(), &c2 = two.counters();
  if (c1.count != c2.count || c1.cases != c2.cases || c1.degenerateCases != c2.degenerateCases ||
      c1.zeroAreaFaces != c2.zeroAreaFaces ||
      c1.sourceOnEdgeLineOutside != c2.sourceOnEdgeLineOutside ||
      c1.childEdgesSeenFromOutside != c2.childEdgesSeenFromOutside ||
      c1.d1FansRelayed != c2.d1FansRelayed || c1.apexFansRelayed != c2.apexFansRelayed ||
      c1.tieStripsKept != c2.tieStripsKept)
    return "degeneracy counters";
  if (!lists) return "";
  const auto e1 = one.edgeIntervals(), e2 = two.edgeIntervals();
  for (std::size_t e = 0; e < e1.size(); ++e) {
    const auto l1 = e1[e].intervals(), l2 = e2[e].intervals();
    if (l1.size() != l2.size()) return "list length of edge " + std::to_string(e);
    for (std::size_t i = 0; i < l1.size(); ++i)
      if (!sameInterval(l1[i], l2[i]))
        return "interval " + std::to_string(i) + " of edge " + std::to_string(e);
  }
  return "";
}

SolveOptions withThreads(SolveOptions o, unsigned threads) {
  o.threads = threads;
  return o;
}

TEST(SolverThreads, TwoThreadsGiveWhatOneGivesToTheBit) {
  for (const NamedMesh& m : meshes()) {
    const Mesh mesh(m.soup);
    std::uint64_t beside = 0;
    for (const auto& sources : sourceSets(m.soup)) {
      std::vector<std::pair<std::string, SolveOptions>> options(4);
      options[0].first = "lists kept";
      options[1].first = "vertex distances only";
      options[1].second.vertexDistancesOnly = true;
      options[2].first = "stop distance";
      options[2].second.stopDistance = 0.5;
      options[3].first = "targets";
      options[3].second.targets = {
          SurfacePoint::atVertex(static_cast<Index>(mesh.numVertices() - 1))};
      for (const auto& [what, o] : options) {
        GeodesicSolver one(mesh), two(mesh);
        one.solve(sources, withThreads(o, 1));
        two.solve(sources, withThreads(o, 2));
        EXPECT_EQ(firstDifference(one, two, !o.vertexDistancesOnly), "")
            << m.name << ", " << sources.size() << " source(s), " << what;
        beside += two.stats().batchesBesideTheFront;
      }
    }
    // Rounds of one batch would leave the helper nothing to do, and this test nothing to test.
    EXPECT_GT(beside, 1000u) << m.name;
  }
}

// A solver solving again with another thread count gives what a fresh one gives.
TEST(SolverThreads, ASolverSolvesAgainWithEitherThreadCount) {
  const TriangleSoup soup = verify::bumpyHeightField(30, 30, 0.3, 11);
  const Mesh mesh(soup);
  const SurfacePoint a = SurfacePoint::atVertex(0), b = SurfacePoint::atVertex(400);
  GeodesicSolver reused(mesh);
  for (const unsigned threads : {2u, 1u, 2u}) {
    for (const SurfacePoint& s : {a, b}) {
      reused.solve({&s, 1}, withThreads({}, threads));
      GeodesicSolver fresh(mesh);
      fresh.solve({&s, 1});
      EXPECT_EQ(firstDifference(fresh, reused, true), "") << threads << " threads";
    }
  }
}

// What an observer is shown, in order, and whether it came from the thread that called solve().
struct EventLog : SolverObserver {
  std::thread::id solving = std::this_thread::get_id();
  std::size_t elsewhere = 0;
  std::vector<std::string> events;
  void note(std::string e) {
    if (std::this_thread::get_id() != solving) ++elsewhere;
    events.push_back(std::move(e));
  }
  void onPropagation(const PropagationEvent& e) override {
    std::string s = "P " + std::to_string(e.face) + " " + std::to_string(e.edge) + " " +
                    std::to_string(static_cast<int>(e.result.branch));
    for (const MadeChild& c : e.children) s += " " + std::to_string(c.edge);
    note(std::move(s));
  }
  void onEdgeUpdate(const EdgeUpdateEvent& e) override {
    note("U " + std::to_string(e.edge) + " " + std::to_string(e.incoming.size()) + " " +
         std::to_string(e.before.size()) + " " + std::to_string(e.after.size()));
  }
  void onWindowDropped(const WindowDroppedEvent& e) override {
    note("D " + std::to_string(e.edge) + " " + std::to_string(e.vertex));
  }
};

TEST(SolverThreads, AnObserverSeesTheEventsOfOneThreadOnTheSolvingThread) {
  const TriangleSoup soup = verify::icosphereMesh(3, 1.0);
  const Mesh mesh(soup);
  const SurfacePoint s = SurfacePoint::inFace(10, 0.2, 0.3, 0.5);
  EventLog one, two;
  GeodesicSolver a(mesh), b(mesh);
  a.setObserver(&one);
  b.setObserver(&two);
  a.solve({&s, 1}, withThreads({}, 1));
  b.solve({&s, 1}, withThreads({}, 2));
  EXPECT_EQ(two.elsewhere, 0u);
  ASSERT_GT(two.events.size(), 1000u);
  EXPECT_EQ(one.events, two.events);
  EXPECT_GT(b.stats().batchesBesideTheFront, 100u);
}

// The live invariant checker (Algorithm 2 step 6 after every update, the full tier's pointwise
// minimum and coverage) holds on a solve whose rounds ran on two threads.
TEST(SolverThreads, TheFullInvariantTierHoldsWithTwoThreads) {
  std::uint64_t beside = 0;
  for (const NamedMesh& m : meshes()) {
    const Mesh mesh(m.soup);
    verify::InvariantChecker checker(verify::CheckLevel::Full);
    GeodesicSolver solver(mesh);
    solver.setObserver(&checker);
    const SurfacePoint s = SurfacePoint::atVertex(0);
    EXPECT_NO_THROW(solver.solve({&s, 1}, withThreads({}, 2))) << m.name;
    beside += solver.stats().batchesBesideTheFront;
  }
  EXPECT_GT(beside, 1000u);
}

// From vertex 0 of libcgal-demo's pinion_small.off a window reaches a released edge
// (VertexDistancesOnly.AWindowReachingAReleasedEdgeMakesTheSolveStartAgainKeepingTheLists): with
// two threads the batch that meets it may be the helper's, and the solve starts again all the same.
TEST(SolverThreads, AWindowReachingAReleasedEdgeStartsTheSolveAgainWithTwoThreads) {
  const std::filesystem::path path =
      std::filesystem::path(GEODEX_CGAL_MESH_DIR) / "pinion_small.off";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
  const Mesh mesh(readMesh(path.string()).soup);
  const SurfacePoint source = SurfacePoint::atVertex(0);
  SolveOptions o;
  o.vertexDistancesOnly = true;
  GeodesicSolver one(mesh), two(mesh);
  one.solve({&source, 1}, withThreads(o, 1));
  two.solve({&source, 1}, withThreads(o, 2));
  EXPECT_TRUE(two.stats().releaseUndone);
  EXPECT_EQ(firstDifference(one, two, true), "");
}

}  // namespace
}  // namespace geodex
