#include "geodex/verify/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace geodex::verify {

namespace {

void require(bool cond, const std::string& message) {
  if (!cond) throw std::invalid_argument(message);
}

// === Grids with some cells removed =============================================================

/// A grid of nx × ny cells keeping only the cells `keep(i, j)` accepts; vertices no kept cell
/// touches are left out (no unreferenced vertices), the rest numbered row by row.
template <class KeepCell, class Height>
TriangleSoup maskedGrid(int nx, int ny, double width, double height, DiagonalPattern pattern,
                        KeepCell keep, Height z) {
  require(nx >= 1 && ny >= 1, "grid: nx and ny must be >= 1");
  require(width > 0.0 && height > 0.0 && std::isfinite(width) && std::isfinite(height),
          "grid: width and height must be finite and > 0");
  const int rowLength = nx + 1;
  std::vector<Index> index(static_cast<std::size_t>(rowLength) * (ny + 1), kNoIndex);
  auto at = [&](int i, int j) -> Index& { return index[static_cast<std::size_t>(j) * rowLength + i]; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (keep(i, j)) at(i, j) = at(i + 1, j) = at(i, j + 1) = at(i + 1, j + 1) = 0;

  TriangleSoup soup;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      if (at(i, j) == kNoIndex) continue;
      at(i, j) = static_cast<Index>(soup.positions.size());
      // i·width/nx rather than i·(width/nx): exact at i = nx, so the far side lands on `width`.
      const double x = width * i / nx;
      const double y = height * j / ny;
      soup.positions.emplace_back(x, y, z(i, j, x, y));
    }
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (!keep(i, j)) continue;
      const Index a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      const bool otherDiagonal = pattern == DiagonalPattern::Alternating && (i + j) % 2 == 1;
      if (otherDiagonal) {  // diagonal b–d
        soup.faces.push_back({a, b, d});
        soup.faces.push_back({b, c, d});
      } else {  // diagonal a–c
        soup.faces.push_back({a, b, c});
        soup.faces.push_back({a, c, d});
      }
    }
  }
  return soup;
}

auto keepAll() {
  return [](int, int) { return true; };
}
auto flat() {
  return [](int, int, double, double) { return 0.0; };
}

}  // namespace

// === Random numbers ============================================================================

std::uint64_t SplitMix64::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double SplitMix64::uniform() {
  // The top 53 bits as a fraction of 2^53: exactly representable, uniform in [0, 1).
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

// === Planar grids ==============================================================================

TriangleSoup gridMesh(int nx, int ny, double width, double height, DiagonalPattern pattern) {
  return maskedGrid(nx, ny, width, height, pattern, keepAll(), flat());
}

TriangleSoup jitteredGridMesh(int nx, int ny, double width, double height, double jitterFraction,
                              std::uint64_t seed, DiagonalPattern pattern) {
  require(jitterFraction >= 0.0 && jitterFraction < 1.0 / 6.0,
          "jitteredGridMesh: jitterFraction must be in [0, 1/6) so that no triangle flips");
  TriangleSoup soup = gridMesh(nx, ny, width, height, pattern);
  SplitMix64 rng(seed);
  const double dx = width / nx, dy = height / ny;
  for (int j = 1; j < ny; ++j) {
    for (int i = 1; i < nx; ++i) {
      Vec3& p = soup.positions[static_cast<std::size_t>(j) * (nx + 1) + i];
      p.x() += rng.uniform(-1.0, 1.0) * jitterFraction * dx;
      p.y() += rng.uniform(-1.0, 1.0) * jitterFraction * dy;
    }
  }
  return soup;
}

TriangleSoup needleFanMesh(int numNeedles, double apexAngleRadians, double radius) {
  require(numNeedles >= 1, "needleFanMesh: numNeedles must be >= 1");
  require(apexAngleRadians > 0.0 && radius > 0.0, "needleFanMesh: angle and radius must be > 0");
  // A small slack over π so that e.g. 1000 × (π/1000) is not refused for rounding.
  require(numNeedles * apexAngleRadians <= std::numbers::pi * (1.0 + 1e-12),
          "needleFanMesh: numNeedles * apexAngle must be <= pi (convex sector)");
  TriangleSoup soup;
  soup.positions.emplace_back(0.0, 0.0, 0.0);
  for (int k = 0; k <= numNeedles; ++k) {
    const double angle = k * apexAngleRadians;
    soup.positions.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
  }
  for (int k = 0; k < numNeedles; ++k)
    soup.faces.push_back({0, static_cast<Index>(k + 1), static_cast<Index>(k + 2)});
  return soup;
}

TriangleSoup lShapeMesh(int n, double size, DiagonalPattern pattern) {
  require(n >= 2 && n % 2 == 0, "lShapeMesh: n must be even and >= 2");
  const int half = n / 2;
  return maskedGrid(n, n, size, size, pattern,
                    [half](int i, int j) { return i < half || j < half; }, flat());
}

int squareHoleCells(int n, double holeFraction) {
  require(n >= 3, "squareWithHoleMesh: n must be >= 3");
  require(holeFraction > 0.0 && holeFraction < 1.0, "squareWithHoleMesh: holeFraction in (0, 1)");
  const int parity = n % 2;
  // The nearest integer of n's parity: n − h must be even for the hole to be centred.
  int h = 2 * static_cast<int>(std::lround((holeFraction * n - parity) / 2.0)) + parity;
  const int lo = parity == 1 ? 1 : 2;
  const int hi = n - 2;
  require(lo <= hi, "squareWithHoleMesh: n too small for a hole with a ring around it");
  if (h < lo) h = lo;
  if (h > hi) h = hi;
  return h;
}

TriangleSoup squareWithHoleMesh(int n, double size, double holeFraction,
                                DiagonalPattern pattern) {
  const int h = squareHoleCells(n, holeFraction);
  const int lo = (n - h) / 2, hi = lo + h;  // hole cells: [lo, hi) along both axes
  return maskedGrid(
      n, n, size, size, pattern,
      [lo, hi](int i, int j) { return !(i >= lo && i < hi && j >= lo && j < hi); }, flat());
}

// === Height fields =============================================================================

TriangleSoup heightFieldMesh(int nx, int ny, double width, double height,
                             const std::function<double(double, double)>& z,
                             DiagonalPattern pattern) {
  require(static_cast<bool>(z), "heightFieldMesh: empty height function");
  return maskedGrid(nx, ny, width, height, pattern, keepAll(),
                    [&z](int, int, double x, double y) { return z(x, y); });
}

TriangleSoup quantizedHeightField(int nx, int ny, std::uint64_t seed, int levels) {
  require(levels >= 1, "quantizedHeightField: levels must be >= 1");
  SplitMix64 rng(seed);
  struct Wave {
    double fx, fy, phase, weight;
  };
  // A few low-frequency waves: a smooth field whose rounding gives wide terraces.
  Wave waves[4];
  double totalWeight = 0.0;
  for (Wave& w : waves) {
    w.fx = rng.uniform(0.5, 2.5) * 2.0 * std::numbers::pi / std::max(nx, 1);
    w.fy = rng.uniform(0.5, 2.5) * 2.0 * std::numbers::pi / std::max(ny, 1);
    w.phase = rng.uniform(0.0, 2.0 * std::numbers::pi);
    w.weight = rng.uniform(0.5, 1.0);
    totalWeight += w.weight;
  }
  auto heightAt = [&](int i, int j, double, double) {
    double s = 0.0;
    for (const Wave& w : waves) s += w.weight * std::sin(w.fx * i + w.fy * j + w.phase);
    const double unit = 0.5 + 0.5 * s / totalWeight;  // in [0, 1]
    const long level = std::lround(unit * (levels - 1));
    return static_cast<double>(std::clamp<long>(level, 0, levels - 1));
  };
  return maskedGrid(nx, ny, nx, ny, DiagonalPattern::AllOneWay, keepAll(), heightAt);
}

TriangleSoup bumpyHeightField(int nx, int ny, double amplitude, std::uint64_t seed) {
  require(amplitude >= 0.0 && std::isfinite(amplitude), "bumpyHeightField: amplitude must be finite and >= 0");
  SplitMix64 rng(seed);
  std::vector<double> z(static_cast<std::size_t>(nx + 1) * static_cast<std::size_t>(ny + 1));
  for (double& v : z) v = rng.uniform(-amplitude, amplitude);
  return maskedGrid(nx, ny, nx, ny, DiagonalPattern::AllOneWay, keepAll(),
                    [&z, nx](int i, int j, double, double) { return z[static_cast<std::size_t>(j * (nx + 1) + i)]; });
}

TriangleSoup farSourceBumpyPatch(int n, double far, std::uint64_t seed) {
  require(far > 0.0 && std::isfinite(far), "farSourceBumpyPatch: far must be finite and > 0");
  SplitMix64 rng(seed);
  TriangleSoup s = gridMesh(n, n, n, n);
  for (Vec3& p : s.positions)
    if (p.x() > 0 && p.x() < n && p.y() > 0 && p.y() < n) p.z() = rng.uniform(-0.3, 0.3);
  const Index apex = static_cast<Index>(s.positions.size());
  s.positions.push_back(Vec3(n / 2.0, -far, 0.0));
  for (int i = 0; i < n; ++i) s.faces.push_back({apex, Index(i + 1), Index(i)});
  return s;
}

// === Spheres ===================================================================================

TriangleSoup icosphereMesh(int subdivisions, double radius) {
  require(subdivisions >= 0 && subdivisions <= 10, "icosphereMesh: subdivisions in [0, 10]");
  require(radius > 0.0, "icosphereMesh: radius must be > 0");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSoup soup;
  soup.positions = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  // Counter-clockwise seen from outside.
  soup.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9},  {5, 11, 4},
                {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6},  {3, 6, 8},
                {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3& p : soup.positions) p.normalize();
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    auto mid = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      auto [it, inserted] = midpoint.try_emplace(key, static_cast<Index>(soup.positions.size()));
      if (inserted) soup.positions.push_back((soup.positions[a] + soup.positions[b]).normalized());
      return it->second;
    };
    std::vector<std::array<Index, 3>> faces;
    faces.reserve(4 * soup.faces.size());
    for (const auto& f : soup.faces) {
      const Index ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      faces.push_back({f[0], ab, ca});
      faces.push_back({f[1], bc, ab});
      faces.push_back({f[2], ca, bc});
      faces.push_back({ab, bc, ca});
    }
    soup.faces = std::move(faces);
  }
  for (Vec3& p : soup.positions) p *= radius;
  return soup;
}

TriangleSoup uvSphereMesh(int rings, int segments, double radius) {
  require(rings >= 2 && segments >= 3, "uvSphereMesh: rings >= 2 and segments >= 3");
  require(radius > 0.0, "uvSphereMesh: radius must be > 0");
  TriangleSoup soup;
  const Index north = 0;
  soup.positions.emplace_back(0.0, 0.0, radius);
  for (int r = 1; r < rings; ++r) {
    const double theta = std::numbers::pi * r / rings;  // polar angle from +z
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      soup.positions.emplace_back(radius * std::sin(theta) * std::cos(phi),
                                  radius * std::sin(theta) * std::sin(phi),
                                  radius * std::cos(theta));
    }
  }
  const Index south = static_cast<Index>(soup.positions.size());
  soup.positions.emplace_back(0.0, 0.0, -radius);

  // Vertex s of latitude circle r (1-based), wrapping around the seam: no duplicated column.
  auto ring = [segments](int r, int s) {
    return static_cast<Index>(1 + (r - 1) * segments + (s % segments));
  };
  // Counter-clockwise seen from outside (normals point away from the origin): every face turns
  // the same way as (north pole, φ_s, φ_s+1), which goes south then east.
  for (int s = 0; s < segments; ++s) soup.faces.push_back({north, ring(1, s), ring(1, s + 1)});
  for (int r = 1; r + 1 < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const Index a = ring(r, s), b = ring(r, s + 1), c = ring(r + 1, s + 1), d = ring(r + 1, s);
      soup.faces.push_back({a, d, c});
      soup.faces.push_back({a, c, b});
    }
  }
  for (int s = 0; s < segments; ++s)
    soup.faces.push_back({south, ring(rings - 1, s + 1), ring(rings - 1, s)});
  return soup;
}

}  // namespace geodex::verify
