// Plain SVG pictures (svg.h).
#include "svg.h"

#include <algorithm>
#include <cmath>

namespace geodex::verify::detail {

std::string shortNum(double x) {
  std::ostringstream os;
  os << std::setprecision(6) << x;
  return os.str();
}

void svgMesh(const TriangleSoup& soup, const std::vector<Vec3>& sources, std::span<const double> d,
             const std::string& title, std::ostream& out) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : soup.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec3 ext = hi - lo;
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (ext[k] < ext[drop]) drop = k;
  const int ax = drop == 0 ? 1 : 0, ay = drop == 2 ? 1 : 2;
  auto proj = [&](const Vec3& p) { return Vec2(p[ax], p[ay]); };
  SvgDoc doc(900, 900);
  Panel P(20, 40, 860, 840, lo[ax], lo[ay], hi[ax], hi[ay], true);
  for (const auto& f : soup.faces)
    doc.polygon(P, {proj(soup.positions[f[0]]), proj(soup.positions[f[1]]), proj(soup.positions[f[2]])},
                "#dde8f4", "#6b7f99");
  for (std::size_t x = 0; x < soup.positions.size(); ++x) {
    doc.dot(P, proj(soup.positions[x]), 2.5, "#333");
    std::string text = std::to_string(x);
    if (x < d.size()) text += ": " + (std::isfinite(d[x]) ? shortNum(d[x]) : std::string("inf"));
    doc.label(P, proj(soup.positions[x]), text, 10, "#333");
  }
  for (const Vec3& s : sources) doc.dot(P, proj(s), 6, "#d62728");
  const char* axes = "xyz";
  doc.labelPx(20, 22, title + " (projected onto " + axes[ax] + axes[ay] + "; sources red)", 14);
  doc.write(out);
}

}  // namespace geodex::verify::detail
