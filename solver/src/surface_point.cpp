#include "geodex/surface_point.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "geodex/check.h"
#include "geodex/error.h"
#include "geodex/tolerance.h"
#include "from_chars_double.h"

namespace geodex {
namespace {

[[noreturn]] void badSpec(const std::string& spec, const std::string& why) {
  throw InputError("bad-spec", "bad point '" + spec + "': " + why +
                                   " (expected v:I, e:I,J,T or f:F,A,B,C)");
}

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    parts.push_back(s.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

Index parseIndex(const std::string& spec, const std::string& token) {
  unsigned long long value = 0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (token.empty() || ec != std::errc() || ptr != end || value >= kNoIndex)
    badSpec(spec, "'" + token + "' is not a valid index");
  return static_cast<Index>(value);
}

double parseNumber(const std::string& spec, const std::string& token) {
  double value = 0.0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = detail::fromCharsDouble(token.data(), end, value);
  if (token.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
    badSpec(spec, "'" + token + "' is not a finite number");
  return value;
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace

SurfacePoint parseSurfacePoint(const std::string& spec) {
  if (spec.size() < 3 || spec[1] != ':') badSpec(spec, "missing kind prefix");
  const std::vector<std::string> parts = splitCommas(spec.substr(2));
  switch (spec[0]) {
    case 'v':
      if (parts.size() != 1) badSpec(spec, "a vertex takes one index");
      return SurfacePoint::atVertex(parseIndex(spec, parts[0]));
    case 'e':
      if (parts.size() != 3) badSpec(spec, "an edge point takes two vertex indices and a fraction");
      return SurfacePoint::onEdge(parseIndex(spec, parts[0]), parseIndex(spec, parts[1]),
                                  parseNumber(spec, parts[2]));
    case 'f':
      if (parts.size() != 4) badSpec(spec, "a face point takes a face index and 3 barycentrics");
      return SurfacePoint::inFace(parseIndex(spec, parts[0]), parseNumber(spec, parts[1]),
                                  parseNumber(spec, parts[2]), parseNumber(spec, parts[3]));
    default:
      badSpec(spec, "unknown kind '" + std::string(1, spec[0]) + "'");
  }
}

std::string formatSurfacePoint(const SurfacePoint& p) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return "v:" + std::to_string(p.vertex);
    case SurfacePoint::Kind::Edge:
      return "e:" + std::to_string(p.vertex) + "," + std::to_string(p.toVertex) + "," + num(p.t);
    case SurfacePoint::Kind::Face:
      return "f:" + std::to_string(p.face) + "," + num(p.bary[0]) + "," + num(p.bary[1]) + "," +
             num(p.bary[2]);
  }
  return "?";
}

ResolvedPoint resolve(const Mesh& mesh, const SurfacePoint& p) {
  const auto vertexPoint = [&](Index v) {
    return ResolvedPoint{SurfacePoint::Kind::Vertex, v, 0.0, {}, mesh.position(v)};
  };
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      if (p.vertex >= mesh.numVertices()) {
        throw InputError("bad-point", "vertex " + std::to_string(p.vertex) +
                                          " does not exist (the mesh has " +
                                          std::to_string(mesh.numVertices()) + " vertices)");
      }
      return vertexPoint(p.vertex);
    case SurfacePoint::Kind::Edge: {
      // Named only when refused: a query's point is resolved on every distance() call.
      const auto what = [&] { return "edge point " + formatSurfacePoint(p); };
      if (p.vertex >= mesh.numVertices() || p.toVertex >= mesh.numVertices())
        throw InputError("bad-point", what() + ": vertex index out of range");
      const Index e = mesh.findEdge(p.vertex, p.toVertex);
      if (e == kNoIndex) {
        throw InputError("bad-point", what() + ": vertices " + std::to_string(p.vertex) + " and " +
                                          std::to_string(p.toVertex) + " share no edge");
      }
      if (!(p.t >= 0.0 && p.t <= 1.0)) throw InputError("bad-point", what() + ": fraction not in [0, 1]");
      if (p.t <= tol::kSnapParam) return vertexPoint(p.vertex);
      if (p.t >= 1.0 - tol::kSnapParam) return vertexPoint(p.toVertex);
      const Edge& E = mesh.edge(e);
      const double fromStart = E.vertex[0] == p.vertex ? p.t : 1.0 - p.t;
      const Vec3 pos = (1.0 - fromStart) * mesh.position(E.vertex[0]) + fromStart * mesh.position(E.vertex[1]);
      return ResolvedPoint{SurfacePoint::Kind::Edge, e, fromStart * E.length, {}, pos};
    }
    case SurfacePoint::Kind::Face: {
      const auto what = [&] { return "face point " + formatSurfacePoint(p); };
      if (p.face >= mesh.numFaces())
        throw InputError("bad-point", what() + ": face " + std::to_string(p.face) + " does not exist (the mesh has " +
                                          std::to_string(mesh.numFaces()) + " faces)");
      const auto& b = p.bary;
      // (isfinite first: comparing a NaN raises FE_INVALID, which the debug tests trap.)
      for (double x : b)
        if (!std::isfinite(x) || x < 0.0) throw InputError("bad-point", what() + ": barycentrics must be finite and >= 0");
      if (std::abs(b[0] + b[1] + b[2] - 1.0) > 1e-9)
        throw InputError("bad-point", what() + ": barycentrics must sum to 1");
      const auto& corners = mesh.face(p.face);
      for (int k = 0; k < 3; ++k)
        if (b[k] >= 1.0 - tol::kSnapParam) return vertexPoint(corners[k]);
      for (int k = 0; k < 3; ++k) {
        if (b[k] <= tol::kSnapParam) {  // on the edge opposite corner k
          const Index a = corners[(k + 1) % 3], c = corners[(k + 2) % 3];
          const double t = b[(k + 2) % 3] / (b[(k + 1) % 3] + b[(k + 2) % 3]);
          return resolve(mesh, SurfacePoint::onEdge(a, c, t));
        }
      }
      const double sum = b[0] + b[1] + b[2];
      const Vec3 pos = (b[0] * mesh.position(corners[0]) + b[1] * mesh.position(corners[1]) +
                        b[2] * mesh.position(corners[2])) / sum;
      return ResolvedPoint{SurfacePoint::Kind::Face, p.face, 0.0, {b[0] / sum, b[1] / sum, b[2] / sum}, pos};
    }
  }
  throw InputError("bad-point", "unknown point kind");
}

Vec2 pointInFaceFrame(const Mesh& mesh, const ResolvedPoint& p, Index f, Index e) {
  const FaceFrame& fr = mesh.frame(f, e);
  const Edge& E = mesh.edge(e);
  const auto corner = [&](Index v) -> Vec2 {
    if (v == E.vertex[0]) return Vec2(0.0, 0.0);
    if (v == E.vertex[1]) return Vec2(E.length, 0.0);
    GEODEX_REQUIRE(v == fr.apex, "vertex " << v << " is not a corner of face " << f);
    return fr.apexPos;
  };
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return corner(p.element);
    case SurfacePoint::Kind::Edge: {
      if (p.element == e) return Vec2(p.t, 0.0);
      const Edge& S = mesh.edge(p.element);
      const Vec2 a = corner(S.vertex[0]), b = corner(S.vertex[1]);
      return a + (p.t / S.length) * (b - a);
    }
    case SurfacePoint::Kind::Face: {
      GEODEX_REQUIRE(p.element == f, "face point of face " << p.element << " is not in face " << f);
      const auto& corners = mesh.face(f);
      return p.bary[0] * corner(corners[0]) + p.bary[1] * corner(corners[1]) +
             p.bary[2] * corner(corners[2]);
    }
  }
  return Vec2(0.0, 0.0);
}

}  // namespace geodex
