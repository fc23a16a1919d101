// A source point of the mesh targets (source_spec.h).
#include "geodex/verify/cases/source_spec.h"

#include <algorithm>

namespace geodex::verify {

SourceSpec atVertex(int v) {
  SourceSpec s;
  s.kind = 0;
  s.element = static_cast<std::uint8_t>(v);
  return s;
}

SourceSpec onEdge(int f, int k, Quantity t) {
  SourceSpec s;
  s.kind = 1;
  s.element = static_cast<std::uint8_t>(f);
  s.corner = static_cast<std::uint8_t>(k);
  s.t = t;
  return s;
}

SourceSpec inFace(int f, Quantity a, Quantity b) {
  SourceSpec s;
  s.kind = 2;
  s.element = static_cast<std::uint8_t>(f);
  s.a = a, s.b = b;
  return s;
}

SourceSpec readSourceSpec(ByteReader& r) {
  SourceSpec s;
  s.kind = r.u8();
  s.element = r.u8();
  s.corner = r.u8();
  s.t = r.quantity();
  s.a = r.quantity();
  s.b = r.quantity();
  return s;
}

void writeSourceSpec(ByteWriter& w, const SourceSpec& s) {
  w.u8(s.kind);
  w.u8(s.element);
  w.u8(s.corner);
  w.quantity(s.t);
  w.quantity(s.a);
  w.quantity(s.b);
}

SurfacePoint makeSource(const SourceSpec& s, const TriangleSoup& soup) {
  const auto nf = soup.faces.size();
  const auto& face = soup.faces[s.element % nf];
  switch (s.kind % 3) {
    case 0: {
      Index v = static_cast<Index>(s.element % soup.positions.size());
      bool referenced = false;
      for (const auto& f : soup.faces)
        if (f[0] == v || f[1] == v || f[2] == v) referenced = true;
      if (!referenced) v = face[s.corner % 3];
      return SurfacePoint::atVertex(v);
    }
    case 1: {
      const int k = s.corner % 3;
      const double t = std::clamp(fieldValue(s.t, 0, 16, 1.0 / 16.0, 1.0), 0.0, 1.0);
      return SurfacePoint::onEdge(face[k], face[(k + 1) % 3], t);
    }
    default: {
      double a = std::clamp(fieldValue(s.a, 0, 16, 1.0 / 16.0, 1.0), 0.0, 1.0);
      double b = std::clamp(fieldValue(s.b, 0, 16, 1.0 / 16.0, 1.0), 0.0, 1.0);
      if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
      const double c = std::max(0.0, 1.0 - a - b);
      return SurfacePoint::inFace(s.element % nf, a, b, c);
    }
  }
}

}  // namespace geodex::verify
