// SolveOptions::threads: a solve with two threads runs each round's batches on both (runRound in
// geodesic_solver.cpp); the rounds are the same as with one, so everything a solve gives must be
// the same to the bit: distances, lists, counts, and the observer's events, which all come from
// the solving thread. The tsan preset runs these under ThreadSanitizer.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "geodex/geodesic_solver.h"
#include "geodex/mesh_io.h"
#include "geodex/verify/invariant_checker.h"
#include "geodex/verify/mesh_generators.h"
#include "geodex/verify/same_solve.h"

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
        EXPECT_EQ(verify::firstDifference(one, two, !o.vertexDistancesOnly), "")
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
      EXPECT_EQ(verify::firstDifference(fresh, reused, true), "") << threads << " threads";
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
  EXPECT_EQ(verify::firstDifference(one, two, true), "");
}

}  // namespace
}  // namespace geodex
