#pragma once
// Plain SVG pictures of a case for `geodex repro --svg`: panels mapping world rectangles onto the
// picture (y up), a document of lines, polygons, dots and labels, colours by pseudo-source, and
// a mesh projected onto its two widest axes. Private to verify/src/cases (hence namespace detail).

#include <iomanip>
#include <map>
#include <ostream>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "geodex/interval.h"
#include "geodex/mesh.h"

namespace geodex::verify::detail {

inline constexpr const char* kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                           "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

/// A rectangle of the picture showing a world rectangle, y up; uniform keeps the aspect ratio.
struct Panel {
  double px, py, pw, ph;
  double minX = 0, minY = 0, sx = 1, sy = 1, ox = 0, oy = 0;
  Panel(double x, double y, double w, double h, double x0, double y0, double x1, double y1, bool uniform)
      : px(x), py(y), pw(w), ph(h) {
    if (!(x1 > x0)) x0 -= 0.5, x1 += 0.5;
    if (!(y1 > y0)) y0 -= 0.5, y1 += 0.5;
    const double mx = 0.06 * (x1 - x0), my = 0.08 * (y1 - y0);
    x0 -= mx, x1 += mx, y0 -= my, y1 += my;
    minX = x0, minY = y0;
    sx = pw / (x1 - x0), sy = ph / (y1 - y0);
    if (uniform) {
      const double k = std::min(sx, sy);
      ox = 0.5 * (pw - k * (x1 - x0));
      oy = 0.5 * (ph - k * (y1 - y0));
      sx = sy = k;
    }
  }
  Vec2 map(const Vec2& p) const { return {px + ox + (p.x() - minX) * sx, py + ph - oy - (p.y() - minY) * sy}; }
};

class SvgDoc {
 public:
  SvgDoc(double w, double h) : w_(w), h_(h) { body_ << std::setprecision(6); }
  void line(const Panel& P, const Vec2& a, const Vec2& b, const std::string& color, double width, bool dashed = false) {
    const Vec2 A = P.map(a), B = P.map(b);
    body_ << "<line x1='" << A.x() << "' y1='" << A.y() << "' x2='" << B.x() << "' y2='" << B.y()
          << "' stroke='" << color << "' stroke-width='" << width << "'"
          << (dashed ? " stroke-dasharray='6,4'" : "") << " stroke-linecap='round'/>\n";
  }
  void polyline(const Panel& P, const std::vector<Vec2>& pts, const std::string& color, double width, bool dashed = false) {
    body_ << "<polyline fill='none' stroke='" << color << "' stroke-width='" << width << "'"
          << (dashed ? " stroke-dasharray='6,4'" : "") << " points='";
    for (const Vec2& p : pts) {
      const Vec2 q = P.map(p);
      body_ << q.x() << "," << q.y() << " ";
    }
    body_ << "'/>\n";
  }
  void polygon(const Panel& P, const std::vector<Vec2>& pts, const std::string& fill, const std::string& stroke) {
    body_ << "<polygon fill='" << fill << "' stroke='" << stroke << "' stroke-width='1' points='";
    for (const Vec2& p : pts) {
      const Vec2 q = P.map(p);
      body_ << q.x() << "," << q.y() << " ";
    }
    body_ << "'/>\n";
  }
  void dot(const Panel& P, const Vec2& p, double r, const std::string& color) {
    const Vec2 q = P.map(p);
    body_ << "<circle cx='" << q.x() << "' cy='" << q.y() << "' r='" << r << "' fill='" << color << "'/>\n";
  }
  void label(const Panel& P, const Vec2& p, const std::string& text, double size = 12,
             const std::string& color = "#000", double dx = 4, double dy = -4) {
    const Vec2 q = P.map(p);
    labelPx(q.x() + dx, q.y() + dy, text, size, color);
  }
  void labelPx(double x, double y, const std::string& text, double size = 12, const std::string& color = "#000") {
    body_ << "<text x='" << x << "' y='" << y << "' font-family='monospace' font-size='" << size
          << "' fill='" << color << "'>" << escape(text) << "</text>\n";
  }
  void write(std::ostream& out) const {
    out << "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='"
        << w_ << "' height='" << h_ << "' viewBox='0 0 " << w_ << " " << h_ << "'>\n"
        << "<rect width='100%' height='100%' fill='white'/>\n"
        << body_.str() << "</svg>\n";
  }

 private:
  static std::string escape(const std::string& s) {
    std::string r;
    for (char ch : s) {
      if (ch == '<') r += "&lt;";
      else if (ch == '>') r += "&gt;";
      else if (ch == '&') r += "&amp;";
      else r += ch;
    }
    return r;
  }
  double w_, h_;
  std::ostringstream body_;
};

/// x to 6 significant digits, for labels.
std::string shortNum(double x);

/// Colours by pseudo-source: the same function (source, σ, side, origin) keeps its colour.
class SourceColours {
 public:
  const char* operator()(const Interval& w) {
    const auto key = std::make_tuple(w.source.x(), w.source.y(), w.sigma, w.side, w.origin);
    auto it = index_.find(key);
    if (it == index_.end()) it = index_.emplace(key, index_.size()).first;
    return kPalette[it->second % std::size(kPalette)];
  }

 private:
  std::map<std::tuple<double, double, double, int, int>, std::size_t> index_;
};

/// The mesh projected onto the plane of its two widest bounding-box axes, its vertices labelled
/// with their index and, where given, their distance d; sources as red dots.
void svgMesh(const TriangleSoup& soup, const std::vector<Vec3>& sources, std::span<const double> d,
             const std::string& title, std::ostream& out);

}  // namespace geodex::verify::detail
