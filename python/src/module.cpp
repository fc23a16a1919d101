// The `geodex` Python module's native part (`geodex._geodex`): numpy arrays in, numpy arrays out,
// every input checked as the CLI checks it, geodex::InputError raised as geodex.InputError (a
// ValueError) with the CLI's message, and the GIL released while solving. The Python layer
// (python/geodex/__init__.py) adds the docstrings users read first.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "geodex/error.h"
#include "geodex/geodesic_solver.h"
#include "geodex/mesh_io.h"
#include "geodex/verify/check.h"

namespace py = pybind11;

namespace geodex::python {
namespace {

[[noreturn]] void inputError(const std::string& kind, const std::string& message) {
  throw InputError(kind, message);
}

// V: anything numpy turns into a real (n, 3) array; F: an integer (m, 3) array (a float array is
// refused rather than truncated).
TriangleSoup soupFromArrays(const py::handle& vertices, const py::handle& faces) {
  const py::array V = py::array::ensure(vertices);
  const py::array F = py::array::ensure(faces);
  if (!V) inputError("bad-array", "V must be an array-like of vertex positions, shape (n, 3)");
  if (!F) inputError("bad-array", "F must be an array-like of vertex indices, shape (m, 3)");
  const auto shape = [](const py::array& a) { return py::str(a.attr("shape")).cast<std::string>(); };
  if (V.ndim() != 2 || V.shape(1) != 3) inputError("bad-array", "V must have shape (n, 3), not " + shape(V));
  if (F.ndim() != 2 || F.shape(1) != 3) inputError("bad-array", "F must have shape (m, 3) (triangles), not " + shape(F));
  const char vk = V.dtype().kind();
  if (vk != 'f' && vk != 'i' && vk != 'u')
    inputError("bad-array", std::string("V must hold real numbers, not dtype ") + py::str(V.dtype()).cast<std::string>());
  const char fk = F.dtype().kind();
  if (F.shape(0) > 0 && fk != 'i' && fk != 'u')
    inputError("bad-array", std::string("F must hold integer vertex indices, not dtype ") + py::str(F.dtype()).cast<std::string>());

  TriangleSoup soup;
  const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(V);
  soup.positions.resize(static_cast<std::size_t>(v.shape(0)));
  const auto pv = v.unchecked<2>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i) soup.positions[i] = Vec3(pv(i, 0), pv(i, 1), pv(i, 2));
  const auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(F);
  const auto pf = f.unchecked<2>();
  soup.faces.resize(static_cast<std::size_t>(f.shape(0)));
  for (py::ssize_t i = 0; i < f.shape(0); ++i) {
    for (int k = 0; k < 3; ++k) {
      const std::int64_t x = pf(i, k);
      if (x < 0 || x >= static_cast<std::int64_t>(kNoIndex))
        inputError("index-out-of-range", "face " + std::to_string(i) + " refers to vertex " + std::to_string(x) +
                                             ", but there are only " + std::to_string(soup.positions.size()) + " vertices");
      soup.faces[i][k] = static_cast<Index>(x);
    }
  }
  return soup;
}

// The CLI's checks (validateMesh: every error, the first one raised), then the mesh.
std::shared_ptr<const Mesh> meshFromArrays(const py::handle& vertices, const py::handle& faces) {
  TriangleSoup soup = soupFromArrays(vertices, faces);
  std::vector<MeshIssue> issues;
  validateMesh(soup, issues);
  for (const MeshIssue& issue : issues)
    if (issue.severity == Severity::Error) throw InputError(issue.kind, issue.message);
  return std::make_shared<const Mesh>(std::move(soup));
}

// A source or target: a SurfacePoint, or a vertex index (a Python or numpy integer).
SurfacePoint toPoint(const py::handle& x) {
  if (py::isinstance<SurfacePoint>(x)) return x.cast<SurfacePoint>();
  if (py::isinstance<py::bool_>(x)) inputError("bad-source", "a source is a vertex index or a SurfacePoint, not a bool");
  try {
    const std::int64_t v = py::int_(py::reinterpret_borrow<py::object>(x)).cast<std::int64_t>();
    if (v < 0) inputError("bad-source", "vertex index " + std::to_string(v) + " is negative");
    if (v >= static_cast<std::int64_t>(kNoIndex)) inputError("bad-source", "vertex index " + std::to_string(v) + " is out of range");
    if (!py::isinstance<py::int_>(x) && py::float_(py::reinterpret_borrow<py::object>(x)).cast<double>() != static_cast<double>(v))
      inputError("bad-source", "vertex index " + py::str(x).cast<std::string>() + " is not an integer");
    return SurfacePoint::atVertex(static_cast<Index>(v));
  } catch (const py::error_already_set&) {
    inputError("bad-source", "a source is a vertex index or a SurfacePoint (geodex.vertex, geodex.edge, geodex.face), not " +
                                 py::str(py::type::of(x)).cast<std::string>());
  }
}

std::vector<SurfacePoint> toPoints(const py::handle& xs, const char* what) {
  std::vector<SurfacePoint> points;
  // One point (a SurfacePoint, a number, a string: toPoint says what is wrong with it), or an
  // iterable of points.
  if (py::isinstance<SurfacePoint>(xs) || py::isinstance<py::str>(xs) || !py::isinstance<py::iterable>(xs)) {
    points.push_back(toPoint(xs));
    return points;
  }
  try {
    for (const py::handle& x : py::reinterpret_borrow<py::iterable>(xs)) points.push_back(toPoint(x));
  } catch (const py::error_already_set&) {
    inputError("bad-source", std::string(what) + " must be a vertex index, a SurfacePoint or a sequence of them");
  }
  return points;
}

py::array_t<double> toArray(std::span<const double> d) {
  py::array_t<double> out(static_cast<py::ssize_t>(d.size()));
  std::copy(d.begin(), d.end(), out.mutable_data());
  return out;
}

// One mesh, many queries. The solver is not re-entrant: a lock keeps two Python threads from
// using the same Solver at once, from its solve to the reading of its results (different Solvers
// run in parallel, the GIL released).
class Solver {
 public:
  Solver(const py::handle& vertices, const py::handle& faces)
      : mesh_(meshFromArrays(vertices, faces)), solver_(*mesh_) {}

  py::array_t<double> distances(const py::handle& sources, std::optional<double> stopDistance,
                                const py::handle& targets) {
    const auto lock = solve(sources, stopDistance, targets);
    return toArray(solver_.vertexDistances());
  }

  py::tuple path(const py::handle& source, const py::handle& target) {
    const SurfacePoint to = toPoint(target);
    const auto lock = solve(source, std::nullopt, py::none());
    GeodesicPath p;
    {
      py::gil_scoped_release release;
      p = solver_.path(to);
    }
    py::array_t<double> points({static_cast<py::ssize_t>(p.points.size()), py::ssize_t{3}});
    auto w = points.mutable_unchecked<2>();
    for (std::size_t i = 0; i < p.points.size(); ++i)
      for (int k = 0; k < 3; ++k) w(static_cast<py::ssize_t>(i), k) = p.points[i].position[k];
    return py::make_tuple(points, p.length);
  }

  py::dict stats() {
    const auto lock = lockWithoutGil();
    py::dict s;
    const SolveStats& st = solver_.stats();
    s["intervals_created"] = st.intervalsCreated;
    s["windows_propagated"] = st.intervalsPropagated;
    s["pseudo_source_events"] = st.pseudoSourceEvents;
    s["max_intervals_per_edge"] = st.maxIntervalsPerEdge;
    s["intervals_at_end"] = st.intervalsAtEnd;
    s["shadows_closed"] = st.shadowsClosed;
    s["windows_dropped_at_edge_end"] = st.windowsDroppedAtEdgeEnd;
    s["windows_dropped_along_edge"] = st.windowsDroppedAlongEdge;
    const DegeneracyCounters& c = solver_.counters();
    s["cases"] = c.cases;
    s["degenerate_cases"] = c.degenerateCases;  // a G1–G5 leaf or a D1–D4 repair (docs/paper.md)
    for (std::size_t k = 0; k < kNumDegeneracyKinds; ++k)
      s[py::str(std::string(name(static_cast<DegeneracyKind>(k))))] = c.count[k];
    return s;
  }

  std::size_t numVertices() const { return mesh_->numVertices(); }
  std::size_t numFaces() const { return mesh_->numFaces(); }

 private:
  // The lock is taken with the GIL released (a thread holding it may be waiting for the GIL to
  // copy its results out), and held until the caller has read what it needs.
  std::unique_lock<std::mutex> lockWithoutGil() {
    py::gil_scoped_release release;
    return std::unique_lock<std::mutex>(busy_);
  }

  // Solves with the GIL released; returns holding this Solver's lock, so that the caller reads
  // the results before another thread's solve replaces them.
  std::unique_lock<std::mutex> solve(const py::handle& sources, std::optional<double> stopDistance,
                                     const py::handle& targets) {
    const std::vector<SurfacePoint> from = toPoints(sources, "sources");
    if (from.empty()) inputError("bad-source", "at least one source is needed");
    SolveOptions options;
    if (stopDistance) {
      if (std::isnan(*stopDistance) || *stopDistance < 0.0)
        inputError("usage", "stop_distance must be a non-negative number, not " + std::to_string(*stopDistance));
      options.stopDistance = *stopDistance;
    }
    if (!targets.is_none()) options.targets = toPoints(targets, "targets");
    auto lock = lockWithoutGil();
    py::gil_scoped_release release;
    solver_.solve(from, options);
    return lock;
  }

  std::shared_ptr<const Mesh> mesh_;
  GeodesicSolver solver_;
  std::mutex busy_;
};

py::tuple load(const std::string& path) {
  MeshReadResult result = readMesh(path);
  validateMesh(result.soup, result.issues);
  for (const MeshIssue& issue : result.issues)
    if (issue.severity == Severity::Error) throw InputError(issue.kind, issue.message);
  const TriangleSoup& soup = result.soup;
  py::array_t<double> V({static_cast<py::ssize_t>(soup.positions.size()), py::ssize_t{3}});
  py::array_t<std::int64_t> F({static_cast<py::ssize_t>(soup.faces.size()), py::ssize_t{3}});
  auto v = V.mutable_unchecked<2>();
  auto f = F.mutable_unchecked<2>();
  for (std::size_t i = 0; i < soup.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) v(static_cast<py::ssize_t>(i), k) = soup.positions[i][k];
  for (std::size_t i = 0; i < soup.faces.size(); ++i)
    for (int k = 0; k < 3; ++k) f(static_cast<py::ssize_t>(i), k) = soup.faces[i][k];
  return py::make_tuple(V, F);
}

// `geodex check` on arrays: the solve with the step-6 invariants checked live, then the oracles;
// the report is the CLI's JSON, as a dict.
py::object check(const py::handle& vertices, const py::handle& faces, const py::handle& sources,
                 const std::string& level, const py::handle& oracles) {
  if (level != "cheap" && level != "full") inputError("usage", "level must be 'cheap' or 'full', not '" + level + "'");
  const std::shared_ptr<const Mesh> mesh = meshFromArrays(vertices, faces);
  const std::vector<SurfacePoint> from = toPoints(sources, "sources");
  if (from.empty()) inputError("bad-source", "at least one source is needed");
  verify::CheckOptions options;
  options.level = level == "full" ? verify::CheckLevel::Full : verify::CheckLevel::Cheap;
  if (!oracles.is_none()) {
    if (py::isinstance<py::str>(oracles)) inputError("usage", "oracles is a list of names, not one string");
    for (const py::handle& o : py::reinterpret_borrow<py::iterable>(oracles)) options.oracles.push_back(py::str(o));
  }
  std::ostringstream json;
  {
    py::gil_scoped_release release;
    verify::writeCheckJson(json, verify::runChecks(*mesh, from, options));
  }
  return py::module_::import("json").attr("loads")(json.str());
}

}  // namespace
}  // namespace geodex::python

PYBIND11_MODULE(_geodex, m) {
  using namespace geodex;
  using namespace geodex::python;
  m.doc() = "Exact geodesic distances and paths on triangle meshes (native part; use `import geodex`).";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<SurfacePoint>(m, "SurfacePoint", "A point on the mesh: a vertex, a point on an edge or in a face.")
      .def("__repr__", [](const SurfacePoint& p) { return "geodex.SurfacePoint('" + formatSurfacePoint(p) + "')"; })
      .def_property_readonly("spec", [](const SurfacePoint& p) { return formatSurfacePoint(p); },
                             "The CLI's SPEC of the point: v:I, e:I,J,T or f:F,A,B,C.");
  m.def("vertex", &SurfacePoint::atVertex, py::arg("i"), "The vertex i.");
  m.def("edge", &SurfacePoint::onEdge, py::arg("i"), py::arg("j"), py::arg("t"),
        "The point at fraction t in [0, 1] from vertex i to vertex j on the edge joining them.");
  m.def("face", &SurfacePoint::inFace, py::arg("f"), py::arg("a"), py::arg("b"), py::arg("c"),
        "The point of face f with barycentric coordinates a, b, c (>= 0, sum 1) for its corners in order.");

  py::class_<Solver>(m, "Solver", R"(A mesh prepared once for many queries: Solver(V, F) checks and builds it.

  .distances(sources, *, stop_distance=None, targets=None) -> (n,) float64 array, as
      geodex.distances;
  .path(source, target) -> (points, length): the geodesic from the nearest source to target,
      points an (N, 3) array from the target back to the source, length its length (inf and no
      points when unreachable);
  .stats: the last solve's counters (windows propagated, intervals, all propagation cases and
      the degenerate cases G1-G5 and D1-D4 of Liu, Zhou & Hu 2007, and degenerate_cases: the
      cases with any of them, the paper's Table 1 rate read as in docs/paper.md).
Different Solver objects solve in parallel threads (the GIL is released while solving).)")
      .def(py::init<py::handle, py::handle>(), py::arg("V"), py::arg("F"))
      .def("distances", &Solver::distances, py::arg("sources"), py::kw_only(),
           py::arg("stop_distance") = py::none(), py::arg("targets") = py::none())
      .def("path", &Solver::path, py::arg("source"), py::arg("target"))
      .def_property_readonly("stats", &Solver::stats)
      .def_property_readonly("num_vertices", &Solver::numVertices)
      .def_property_readonly("num_faces", &Solver::numFaces);
  m.def("check", &check, py::arg("V"), py::arg("F"), py::arg("sources"), py::kw_only(), py::arg("level") = "full",
        py::arg("oracles") = py::none());
  m.def("load", &load, py::arg("path"),
        "load(path) -> (V, F): a mesh file (OFF, OBJ or PLY) read and checked as the CLI does, V an "
        "(n, 3) float64 array, F an (m, 3) int64 array. Raises InputError naming the file, line "
        "and element of the first error.");
}
