#include "geodex/verify/cgal_oracle.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace geodex::verify {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, CgalMesh>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
using VertexIndex = CgalMesh::Vertex_index;
using FaceIndex = CgalMesh::Face_index;
using Barycentric = Traits::Barycentric_coordinates;  // std::array<FT, 3>

constexpr double kInf = std::numeric_limits<double>::infinity();

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void require(bool cond, const std::string& message) {
  if (!cond) throw std::invalid_argument("cgal oracle: " + message);
}

// === CGAL's convention for sources on edges ====================================================
//
// A face location with exactly one zero barycentric coordinate is rooted on that edge
// (expand_root → expand_edge_root). In CGAL 5.5.1 that path reads the coordinate of the
// halfedge's source as t0 and then calls face_location(halfedge, t0), which puts t0 on the
// halfedge's *target*: the source point is mirrored about the edge's midpoint (an edge point at
// t = 0.2 is seeded at t = 0.8). Face-interior and vertex sources are not affected. Rather than
// hard-code a version check, probe once what this CGAL does, for an interior and a border edge,
// and pre-swap the two weights where it mirrors.

struct EdgeSourceConvention {
  bool interiorMirrored = false;
  bool borderMirrored = false;
};

/// Whether a source at weights (w_a, w_b) on the edge ab of a face ends up at (w_b, w_a).
bool probeMirrored(bool border) {
  // The unit square split along 0–2: edge 0–2 is interior, edge 0–1 is on the border.
  CgalMesh mesh;
  const VertexIndex v[4] = {mesh.add_vertex({0, 0, 0}), mesh.add_vertex({1, 0, 0}),
                            mesh.add_vertex({1, 1, 0}), mesh.add_vertex({0, 1, 0})};
  const FaceIndex face = mesh.add_face(v[0], v[1], v[2]);
  mesh.add_face(v[0], v[2], v[3]);
  const VertexIndex a = v[0], b = border ? v[1] : v[2];
  const auto h = mesh.halfedge(face);
  const VertexIndex corner[3] = {mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))};
  Barycentric bary{};
  for (int i = 0; i < 3; ++i) bary[i] = corner[i] == a ? 0.25 : corner[i] == b ? 0.75 : 0.0;
  ShortestPath shortestPath(mesh);
  shortestPath.add_source_point(face, bary);
  // The point is 0.75 of the way from a to b: its distance to a is 0.75 |ab| unless mirrored.
  const double length = border ? 1.0 : std::sqrt(2.0);
  const double d = CGAL::to_double(shortestPath.shortest_distance_to_source_points(a).first);
  return std::abs(d - 0.25 * length) < std::abs(d - 0.75 * length);
}

const EdgeSourceConvention& edgeSourceConvention() {
  static const EdgeSourceConvention convention{probeMirrored(false), probeMirrored(true)};
  return convention;
}

}  // namespace

struct CgalGeodesicOracle::Impl {
  TriangleSoup soup;  // a copy: the caller's soup need not outlive the oracle
  CgalMesh mesh;
  std::vector<VertexIndex> vertexOf;  // soup vertex → CGAL vertex (null if unreferenced)
  std::vector<FaceIndex> faceOf;      // soup face → CGAL face
  std::unique_ptr<ShortestPath> shortestPath;  // refers to `mesh`: built after it
  bool solved = false;
  CgalTiming timing;

  /// The CGAL face location of a point of soup face f with barycentrics over soup.faces[f].
  /// CGAL orders a face's coordinates as source(h), target(h), target(next(h)) for
  /// h = halfedge(face), which need not start at soup.faces[f][0]: map them by vertex.
  ShortestPath::Face_location location(Index f, const std::array<double, 3>& bary) const {
    const FaceIndex face = faceOf[f];
    const auto h = mesh.halfedge(face);
    const VertexIndex corner[3] = {mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))};
    Barycentric b{};
    for (int i = 0; i < 3; ++i) {
      int k = 0;
      while (k < 3 && vertexOf[soup.faces[f][k]] != corner[i]) ++k;
      require(k < 3, "face " + std::to_string(f) + " does not match its CGAL face");
      b[i] = bary[k];
    }
    return {face, b};
  }

  /// A face holding the edge from → to, with the point's barycentrics in it.
  ShortestPath::Face_location edgeLocation(Index from, Index to, double t) const {
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
      const auto& v = soup.faces[f];
      const auto kFrom = std::find(v.begin(), v.end(), from) - v.begin();
      const auto kTo = std::find(v.begin(), v.end(), to) - v.begin();
      if (kFrom < 3 && kTo < 3 && from != to) {
        std::array<double, 3> bary{0.0, 0.0, 0.0};
        bary[kFrom] = 1.0 - t;
        bary[kTo] = t;
        return location(static_cast<Index>(f), bary);
      }
    }
    require(false, "no face holds the edge " + std::to_string(from) + "-" + std::to_string(to));
    return {};
  }

  /// A source CGAL will root on an edge (exactly one zero coordinate): make the two weights
  /// sum to exactly 1 (expand_edge_root requires it) and pre-swap them where this CGAL mirrors
  /// edge sources (see EdgeSourceConvention).
  void adjustEdgeSource(ShortestPath::Face_location& location) const {
    Barycentric& b = location.second;
    const int zeros = (b[0] == 0.0) + (b[1] == 0.0) + (b[2] == 0.0);
    if (zeros != 1) return;
    const int zero = b[0] == 0.0 ? 0 : b[1] == 0.0 ? 1 : 2;
    const int i = (zero + 1) % 3, j = (zero + 2) % 3;
    // 1 − x + x is exactly 1 in binary floating point when x is the smaller weight.
    if (b[i] <= b[j]) b[j] = 1.0 - b[i];
    else b[i] = 1.0 - b[j];
    // The edge joins corners i and j, i.e. CGAL's halfedge next^i(halfedge(face)).
    auto h = mesh.halfedge(location.first);
    for (int k = 0; k < i; ++k) h = mesh.next(h);
    const bool border = mesh.is_border(mesh.opposite(h));
    const EdgeSourceConvention& convention = edgeSourceConvention();
    if (border ? convention.borderMirrored : convention.interiorMirrored) std::swap(b[i], b[j]);
  }

  ShortestPath::Face_location locate(const SurfacePoint& p) const {
    switch (p.kind) {
      case SurfacePoint::Kind::Vertex: {
        require(p.vertex < soup.positions.size() && vertexOf[p.vertex] != CgalMesh::null_vertex(),
                "vertex " + std::to_string(p.vertex) + " is not on the mesh");
        // Any face around the vertex, with coordinate 1 at it.
        const auto h = mesh.halfedge(vertexOf[p.vertex]);  // a halfedge pointing to the vertex
        const FaceIndex face = mesh.is_border(h) ? mesh.face(mesh.opposite(h)) : mesh.face(h);
        const auto h0 = mesh.halfedge(face);
        const VertexIndex corner[3] = {mesh.source(h0), mesh.target(h0),
                                       mesh.target(mesh.next(h0))};
        Barycentric b{};
        for (int i = 0; i < 3; ++i) b[i] = corner[i] == vertexOf[p.vertex] ? 1.0 : 0.0;
        return {face, b};
      }
      case SurfacePoint::Kind::Edge:
        require(p.vertex < soup.positions.size() && p.toVertex < soup.positions.size(),
                "edge point vertex out of range");
        require(std::isfinite(p.t) && p.t >= 0.0 && p.t <= 1.0, "edge parameter outside [0, 1]");
        return edgeLocation(p.vertex, p.toVertex, p.t);
      case SurfacePoint::Kind::Face:
        require(p.face < soup.faces.size(), "face " + std::to_string(p.face) + " out of range");
        return location(p.face, p.bary);
    }
    require(false, "unknown surface point kind");
    return {};
  }
};

CgalGeodesicOracle::CgalGeodesicOracle(const TriangleSoup& soup) : impl_(std::make_unique<Impl>()) {
  Stopwatch clock;
  Impl& m = *impl_;
  m.soup = soup;
  const std::size_t numVertices = soup.positions.size();
  std::vector<std::uint8_t> referenced(numVertices, 0);
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    for (Index v : soup.faces[f]) {
      require(v < numVertices, "face " + std::to_string(f) + " references vertex " +
                                   std::to_string(v) + " out of range");
      referenced[v] = 1;
    }
  }
  // Only referenced vertices go in: isolated vertices have no halfedge to start a query from.
  m.vertexOf.assign(numVertices, CgalMesh::null_vertex());
  for (std::size_t v = 0; v < numVertices; ++v) {
    if (!referenced[v]) continue;
    const Vec3& p = soup.positions[v];
    m.vertexOf[v] = m.mesh.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  }
  m.faceOf.reserve(soup.faces.size());
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    const auto& v = soup.faces[f];
    const FaceIndex face = m.mesh.add_face(m.vertexOf[v[0]], m.vertexOf[v[1]], m.vertexOf[v[2]]);
    require(face != CgalMesh::null_face(),
            "face " + std::to_string(f) + " (" + std::to_string(v[0]) + ", " +
                std::to_string(v[1]) + ", " + std::to_string(v[2]) +
                ") cannot be added: repeated index, non-manifold, or inconsistent winding");
    m.faceOf.push_back(face);
  }
  m.shortestPath = std::make_unique<ShortestPath>(m.mesh);
  m.timing.buildMeshSeconds = clock.seconds();
}

CgalGeodesicOracle::~CgalGeodesicOracle() = default;
CgalGeodesicOracle::CgalGeodesicOracle(CgalGeodesicOracle&&) noexcept = default;
CgalGeodesicOracle& CgalGeodesicOracle::operator=(CgalGeodesicOracle&&) noexcept = default;

void CgalGeodesicOracle::solve(const std::vector<SurfacePoint>& sources) {
  require(!sources.empty(), "no source");
  Impl& m = *impl_;
  // Locate every source before touching CGAL's state, so a bad one leaves the oracle unchanged.
  std::vector<ShortestPath::Face_location> locations;
  locations.reserve(sources.size());
  for (const SurfacePoint& p : sources) locations.push_back(m.locate(p));
  for (auto& location : locations) m.adjustEdgeSource(location);
  Stopwatch clock;
  m.shortestPath->remove_all_source_points();
  for (const auto& location : locations) m.shortestPath->add_source_point(location);
  m.shortestPath->build_sequence_tree();
  m.timing.sequenceTreeSeconds = clock.seconds();
  m.timing.querySeconds = 0.0;
  m.solved = true;
}

std::vector<double> CgalGeodesicOracle::vertexDistances() {
  Impl& m = *impl_;
  require(m.solved, "vertexDistances() before solve()");
  Stopwatch clock;
  std::vector<double> d(m.soup.positions.size(), kInf);
  for (std::size_t v = 0; v < d.size(); ++v) {
    if (m.vertexOf[v] == CgalMesh::null_vertex()) continue;
    const auto result = m.shortestPath->shortest_distance_to_source_points(m.vertexOf[v]);
    // A negative distance is CGAL's "no source reachable".
    if (result.first >= 0) d[v] = CGAL::to_double(result.first);
  }
  m.timing.querySeconds += clock.seconds();
  return d;
}

double CgalGeodesicOracle::distance(const SurfacePoint& p) {
  Impl& m = *impl_;
  require(m.solved, "distance() before solve()");
  const auto location = m.locate(p);
  Stopwatch clock;
  const auto result =
      m.shortestPath->shortest_distance_to_source_points(location.first, location.second);
  m.timing.querySeconds += clock.seconds();
  return result.first >= 0 ? CGAL::to_double(result.first) : kInf;
}

const CgalTiming& CgalGeodesicOracle::timing() const { return impl_->timing; }

std::vector<double> cgalGeodesicDistances(const TriangleSoup& soup,
                                          const std::vector<SurfacePoint>& sources,
                                          CgalTiming* timing) {
  CgalGeodesicOracle oracle(soup);
  oracle.solve(sources);
  std::vector<double> d = oracle.vertexDistances();
  if (timing) *timing = oracle.timing();
  return d;
}

}  // namespace geodex::verify
