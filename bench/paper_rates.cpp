// The degeneracy rates of Liu, Zhou & Hu 2007 (Table 1, Figs. 1 and 8) counted several ways on
// our meshes, one markdown row per mesh: docs/paper.md is made from its output.
//
//   geodex_paper_rates MESH[:VERTEX] ...      (the source is vertex 0 unless given)
//
// Per propagation case (one window across one face) the observer below applies the paper's own
// incidence rules of Sect. 4.1 with its ε, machine precision, absolute and in the file's units:
// s on e0, s = b0, s = b1, s b0 v1 collinear, s b1 v1 collinear. It also counts the cases whose
// window starts or ends at an end of its edge (b0 = v0 or b1 = v2, the coincidence Fig. 6 asks
// about before G4 and G5). The solver's own counters give G1–G5 at geodex's tolerances, D1–D4,
// and the degenerate-case rate (a G leaf or a D repair at its children: the paper's reading,
// docs/paper.md).

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "geodex/error.h"
#include "geodex/geodesic_solver.h"
#include "geodex/mesh_io.h"

namespace {

using geodex::Vec2;

class PaperRules : public geodex::SolverObserver {
 public:
  explicit PaperRules(double unit) : unit_(unit) {}

  void onPropagation(const geodex::PropagationEvent& e) override {
    ++cases;
    const geodex::LocalWindow& w = e.local;
    // The paper's ε is absolute: lengths in the file's units, not geodex's mesh units.
    const Vec2 s = w.source * unit_, v1 = w.apex * unit_;
    const Vec2 b0(w.b0 * unit_, 0.0), b1(w.b1 * unit_, 0.0);
    const double eps = std::numeric_limits<double>::epsilon();
    const auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
    const bool onE0 = std::abs(s.y()) < eps;
    const bool atB0 = (s - b0).norm() < eps, atB1 = (s - b1).norm() < eps;
    const bool throughB0 = std::abs(cross(s - b0, b0 - v1)) < eps;
    const bool throughB1 = std::abs(cross(s - b1, b1 - v1)) < eps;
    if (onE0 || atB0 || atB1 || throughB0 || throughB1) ++paperRuleCases;
    if (w.b0 == 0.0 || w.b1 == w.edgeLength) ++atAnEdgeEnd;
  }

  std::uint64_t cases = 0, paperRuleCases = 0, atAnEdgeEnd = 0;

 private:
  double unit_;
};

double percent(std::uint64_t n, std::uint64_t total) {
  return total == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(total);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: geodex_paper_rates MESH[:VERTEX] ...\n");
    return 2;
  }
  std::printf("| mesh | faces | cases | G1 | G2 | G3 | G4 | G5 | D1 | D2 | D3 | D4 | Fig. 6 rate | "
              "paper's rules, ε = 2.2e-16 | window at an edge end | degenerate-case rate |\n");
  std::printf("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (int i = 1; i < argc; ++i) {
    std::string path = argv[i];
    geodex::Index source = 0;
    if (const auto colon = path.rfind(':'); colon != std::string::npos && colon + 1 < path.size() &&
                                            path.find('/', colon) == std::string::npos) {
      source = static_cast<geodex::Index>(std::stoul(path.substr(colon + 1)));
      path.resize(colon);
    }
    try {
      const geodex::Mesh mesh = geodex::loadMesh(path);
      geodex::GeodesicSolver solver(mesh);
      PaperRules rules(mesh.unit());
      solver.setObserver(&rules);
      solver.solve(std::vector<geodex::SurfacePoint>{geodex::SurfacePoint::atVertex(source)});
      const geodex::DegeneracyCounters& c = solver.counters();
      using geodex::DegeneracyKind;
      const std::string name = path.substr(path.find_last_of('/') + 1);
      const auto count = [&](DegeneracyKind k) { return static_cast<unsigned long long>(c[k]); };
      std::printf("| %s (v%u) | %zu | %llu | %llu | %llu | %llu | %llu | %llu | %.1f %% | %.1f %% | "
                  "%.1f %% | %.2f %% | %.4f %% | %.4f %% | %.1f %% | %.1f %% |\n",
                  name.c_str(), static_cast<unsigned>(source), mesh.numFaces(),
                  static_cast<unsigned long long>(c.cases), count(DegeneracyKind::G1),
                  count(DegeneracyKind::G2), count(DegeneracyKind::G3), count(DegeneracyKind::G4),
                  count(DegeneracyKind::G5),
                  percent(c[DegeneracyKind::D1], c.cases), percent(c[DegeneracyKind::D2], c.cases),
                  percent(c[DegeneracyKind::D3], c.cases), percent(c[DegeneracyKind::D4], c.cases),
                  percent(c.geometricTotal(), c.cases), percent(rules.paperRuleCases, rules.cases),
                  percent(rules.atAnEdgeEnd, rules.cases), percent(c.degenerateCases, c.cases));
      std::fflush(stdout);
    } catch (const geodex::InputError& e) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
      return 2;
    }
  }
  return 0;
}
