// The cases of `geodex crosscheck` (crosscheck_cases.h): each family calls generators that exist
// for the property tests and the fuzz targets; this file only chooses their parameters.
#include "geodex/verify/crosscheck_cases.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "cases/mesh_case.h"
#include "geodex/verify/cases/fuzz_solver.h"
#include "geodex/verify/cases/fuzz_two_faces.h"
#include "geodex/verify/mesh_generators.h"

namespace geodex::verify {

namespace {

// ===  Choices ====================================================================================

std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string str(int x) { return std::to_string(x); }

/// An integer in [lo, hi).
int pick(SplitMix64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng.next() % static_cast<std::uint64_t>(hi - lo));
}

template <typename T, std::size_t N>
T pickOf(SplitMix64& rng, const std::array<T, N>& values) {
  return values[rng.next() % N];
}

/// A size that grows by one per step from `lo`, plus 0 or 1 at random, at most `hi`.
int grow(int step, int lo, int hi, SplitMix64& rng) { return std::min(hi, lo + step + pick(rng, 0, 2)); }

DiagonalPattern pickPattern(SplitMix64& rng, std::string& recipeSuffix) {
  const bool alternating = rng.next() % 2 == 1;
  recipeSuffix = alternating ? ", Alternating)" : ")";
  return alternating ? DiagonalPattern::Alternating : DiagonalPattern::AllOneWay;
}

/// A source vertex: a third of the time the first vertex (a corner of every grid: rays from it
/// run exactly through lattice vertices), else any vertex a face uses.
Index pickSource(const TriangleSoup& soup, SplitMix64& rng) {
  std::vector<bool> used(soup.positions.size(), false);
  for (const auto& f : soup.faces)
    for (Index v : f) used[v] = true;
  std::vector<Index> referenced;
  for (Index v = 0; v < used.size(); ++v)
    if (used[v]) referenced.push_back(v);
  if (rng.next() % 3 == 0) return referenced.front();
  return referenced[rng.next() % referenced.size()];
}

/// The vertex a fuzz case's source point is on or next to: crosscheck's programs take vertices.
Index nearestVertex(const TriangleSoup& soup, const SurfacePoint& p) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return p.vertex;
    case SurfacePoint::Kind::Edge: return p.t <= 0.5 ? p.vertex : p.toVertex;
    case SurfacePoint::Kind::Face: break;
  }
  const auto& corners = soup.faces[p.face];
  const int k = static_cast<int>(std::max_element(p.bary.begin(), p.bary.end()) - p.bary.begin());
  return corners[k];
}

CrossCheckCase make(const char* family, std::string recipe, TriangleSoup soup, Index source,
                    PlanarOracle planar = PlanarOracle::None) {
  return {family, std::move(recipe), std::move(soup), source, planar};
}

// ===  Families from the fuzz targets' corpus and decoder ==========================================

/// Seed number `step` (cyclically) of a target's committed corpus that its decoder accepts.
template <typename Decode>
auto nthDecodedSeed(const std::vector<Seed>& seeds, int step, Decode decode, std::string& name) {
  for (std::size_t tries = 0; tries < seeds.size(); ++tries) {
    const Seed& seed = seeds[(static_cast<std::size_t>(step) + tries) % seeds.size()];
    if (auto decoded = decode(seed.bytes)) {
      name = seed.dir + "/" + seed.name;
      return *decoded;
    }
  }
  throw std::logic_error("crosscheck: no seed of the corpus decodes");
}

CrossCheckCase twoFaces(int step, SplitMix64&) {
  static const std::vector<Seed> seeds = twoFaceSeeds();
  std::string name;
  const TwoFaceCase c = nthDecodedSeed(seeds, step, decodeTwoFaces, name);
  return make("two-faces", "corpus/fuzz_two_faces/" + name, c.soup, nearestVertex(c.soup, c.source));
}

PlanarOracle planarOf(const SolverCase& c) {
  return c.rectangle ? PlanarOracle::Convex : c.planar ? PlanarOracle::Domain : PlanarOracle::None;
}

CrossCheckCase fuzzSolverSeed(int step, SplitMix64&) {
  static const std::vector<Seed> seeds = solverSeeds();
  std::string name;
  const SolverCase c = nthDecodedSeed(seeds, step, decodeSolver, name);
  return make("fuzz-solver-seed", "corpus/fuzz_solver/" + name, c.soup,
              nearestVertex(c.soup, c.sources.front()), planarOf(c));
}

/// fuzz_solver's byte format filled from the generator the way a fuzzer mutates it, biased
/// towards grids (lattice soups of random faces are mostly refused by the validator): levels,
/// moved vertices (needles, zero-area faces), removed cells (holes, components).
SolverSpec randomSolverSpec(SplitMix64& rng, int step) {
  SolverSpec s;
  s.mode = rng.next() % 4 == 0 ? 1 : 0;
  s.nx = static_cast<std::uint8_t>(std::min(7, step / 2 + pick(rng, 0, 3)));
  s.ny = static_cast<std::uint8_t>(std::min(7, step / 2 + pick(rng, 0, 3)));
  s.levels = static_cast<std::uint8_t>(rng.next());
  s.zStep = static_cast<std::uint8_t>(rng.next());
  for (int i = 0; i < 81; ++i) {
    std::uint8_t b = static_cast<std::uint8_t>(rng.next() & 0x0f);
    if (rng.next() % 6 == 0) b |= static_cast<std::uint8_t>(rng.next() & 0xf0);
    s.vertexBytes.push_back(b);
  }
  for (int i = 0; i < 32; ++i)
    s.cellBytes.push_back(static_cast<std::uint8_t>((rng.next() % 2) | (rng.next() % 8 == 0 ? 2 : 0)));
  const int points = pick(rng, 3, 12);
  for (int i = 0; i < points; ++i)
    s.points.push_back({static_cast<std::int8_t>(pick(rng, -4, 5)), static_cast<std::int8_t>(pick(rng, -4, 5)),
                        static_cast<std::int8_t>(pick(rng, -2, 3))});
  const int faces = pick(rng, 1, 2 * points);
  for (int i = 0; i < faces; ++i)
    s.faces.push_back({static_cast<std::uint8_t>(rng.next()), static_cast<std::uint8_t>(rng.next()),
                       static_cast<std::uint8_t>(rng.next())});
  s.sources.push_back(atVertex(static_cast<int>(rng.next() % 256)));
  return s;
}

CrossCheckCase fuzzSolverRandom(int step, SplitMix64& rng) {
  // A draw the decoder skips (a soup the validator refuses) is followed by the next one, so
  // the case still depends on nothing but the seed and the index; after many, a plain grid,
  // which it always takes.
  constexpr int kDraws = 256;
  for (int attempt = 0;; ++attempt) {
    SolverSpec spec = randomSolverSpec(rng, step);
    if (attempt >= kDraws) {
      spec.mode = 0;
      spec.vertexBytes.clear();
      spec.cellBytes.clear();
    }
    const std::vector<std::uint8_t> bytes = encode(spec);
    if (const auto c = decodeSolver(bytes)) {
      std::string hex;
      char two[3];
      for (std::uint8_t b : bytes) std::snprintf(two, sizeof two, "%02x", b), hex += two;
      return make("fuzz-solver", "fuzz_solver bytes (geodex repro reads them) " + hex, c->soup,
                  nearestVertex(c->soup, c->sources.front()), planarOf(*c));
    }
  }
}

// ===  Families from the mesh generators =========================================================

CrossCheckCase flatGrid(int step, SplitMix64& rng) {
  const int nx = grow(step, 1, 24, rng), ny = grow(step, 1, 24, rng);
  const double w = pickOf(rng, std::array{1.0, 3.0, 0.7}), h = pickOf(rng, std::array{1.0, 0.5, 2.0});
  std::string suffix;
  const DiagonalPattern pattern = pickPattern(rng, suffix);
  TriangleSoup soup = gridMesh(nx, ny, w, h, pattern);
  const Index source = pickSource(soup, rng);
  return make("flat-grid", "gridMesh(" + str(nx) + ", " + str(ny) + ", " + num(w) + ", " + num(h) + suffix,
              std::move(soup), source, PlanarOracle::Convex);
}

CrossCheckCase nearFlatGrid(int step, SplitMix64& rng) {
  const int n = grow(step, 2, 24, rng);
  // From far inside the collinearity tolerances to clearly generic.
  const double jitter = pickOf(rng, std::array{1e-13, 1e-11, 1e-10, 1e-7, 1e-3, 0.05, 0.15});
  const std::uint64_t seed = rng.next() % 1000;
  std::string suffix;
  const DiagonalPattern pattern = pickPattern(rng, suffix);
  TriangleSoup soup = jitteredGridMesh(n, n, 1.0, 1.0, jitter, seed, pattern);
  const Index source = pickSource(soup, rng);
  return make("near-flat-grid",
              "jitteredGridMesh(" + str(n) + ", " + str(n) + ", 1, 1, " + num(jitter) + ", " +
                  std::to_string(seed) + suffix,
              std::move(soup), source, PlanarOracle::Convex);
}

CrossCheckCase needleFan(int step, SplitMix64& rng) {
  const int n = std::min(240, 1 + 4 * step + pick(rng, 0, 4));
  const double angle = std::numbers::pi / n * std::pow(10.0, -7.0 * rng.uniform());
  TriangleSoup soup = needleFanMesh(n, angle, 1.0);
  // The apex (vertex 0) half the time: every needle's sharp corner is the source.
  const Index source = rng.next() % 2 == 0 ? 0 : pickSource(soup, rng);
  return make("needle-fan", "needleFanMesh(" + str(n) + ", " + num(angle) + ", 1)", std::move(soup), source,
              PlanarOracle::Convex);
}

CrossCheckCase lShape(int step, SplitMix64& rng) {
  const int n = 2 * grow(step, 1, 12, rng);
  std::string suffix;
  const DiagonalPattern pattern = pickPattern(rng, suffix);
  TriangleSoup soup = lShapeMesh(n, 1.0, pattern);
  const Index source = pickSource(soup, rng);
  return make("l-shape", "lShapeMesh(" + str(n) + ", 1" + suffix, std::move(soup), source, PlanarOracle::Domain);
}

CrossCheckCase squareWithHole(int step, SplitMix64& rng) {
  const int n = grow(step, 3, 24, rng);
  const double fraction = pickOf(rng, std::array{0.2, 0.35, 0.5, 0.65});
  std::string suffix;
  const DiagonalPattern pattern = pickPattern(rng, suffix);
  TriangleSoup soup = squareWithHoleMesh(n, 1.0, fraction, pattern);
  const Index source = pickSource(soup, rng);
  return make("square-with-hole", "squareWithHoleMesh(" + str(n) + ", 1, " + num(fraction) + suffix,
              std::move(soup), source, PlanarOracle::Domain);
}

CrossCheckCase terraces(int step, SplitMix64& rng) {
  const int nx = grow(step, 3, 24, rng), ny = grow(step, 3, 24, rng);
  const std::uint64_t seed = rng.next() % 1000;
  const int levels = pick(rng, 2, 5);
  TriangleSoup soup = quantizedHeightField(nx, ny, seed, levels);
  const Index source = pickSource(soup, rng);
  return make("terraces",
              "quantizedHeightField(" + str(nx) + ", " + str(ny) + ", " + std::to_string(seed) + ", " +
                  str(levels) + ")",
              std::move(soup), source);
}

CrossCheckCase bumpy(int step, SplitMix64& rng) {
  const int nx = grow(step, 2, 20, rng), ny = grow(step, 2, 20, rng);
  const double amplitude = pickOf(rng, std::array{0.05, 0.3, 1.0});
  const std::uint64_t seed = rng.next() % 1000;
  TriangleSoup soup = bumpyHeightField(nx, ny, amplitude, seed);
  const Index source = pickSource(soup, rng);
  return make("bumpy",
              "bumpyHeightField(" + str(nx) + ", " + str(ny) + ", " + num(amplitude) + ", " +
                  std::to_string(seed) + ")",
              std::move(soup), source);
}

CrossCheckCase icosphere(int step, SplitMix64& rng) {
  const int subdivisions = std::min(step, 4);
  TriangleSoup soup = icosphereMesh(subdivisions, 1.0);
  const Index source = pickSource(soup, rng);
  return make("icosphere", "icosphereMesh(" + str(subdivisions) + ", 1)", std::move(soup), source);
}

CrossCheckCase uvSphere(int step, SplitMix64& rng) {
  const int rings = grow(step, 2, 32, rng), segments = grow(step, 3, 48, rng);
  TriangleSoup soup = uvSphereMesh(rings, segments, 1.0);
  const Index source = pickSource(soup, rng);
  return make("uv-sphere", "uvSphereMesh(" + str(rings) + ", " + str(segments) + ", 1)", std::move(soup), source);
}

CrossCheckCase components(int step, SplitMix64& rng) {
  const int n = grow(step, 1, 16, rng), subdivisions = std::min(step / 4, 2);
  TriangleSoup soup = gridMesh(n, n, 1.0, 1.0);
  const TriangleSoup sphere = icosphereMesh(subdivisions, 0.5);
  const Index offset = static_cast<Index>(soup.positions.size());
  for (const Vec3& p : sphere.positions) soup.positions.push_back(p + Vec3(2.0, 0.5, 0.0));
  for (const auto& f : sphere.faces) soup.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  // The source on either part: the other is unreachable.
  const Index source = rng.next() % 2 == 0 ? 0 : offset;
  return make("components",
              "gridMesh(" + str(n) + ", " + str(n) + ", 1, 1) and icosphereMesh(" + str(subdivisions) +
                  ", 0.5) moved by (2, 0.5, 0)",
              std::move(soup), source);
}

CrossCheckCase farSource(int step, SplitMix64& rng) {
  const int n = grow(step, 2, 16, rng);
  const double far = n * std::pow(10.0, 4.0 + 3.0 * rng.uniform());
  const std::uint64_t seed = rng.next() % 1000;
  TriangleSoup soup = farSourceBumpyPatch(n, far, seed);
  // The far vertex (the last) half the time: its windows are the ones D4 is about.
  const Index source = rng.next() % 2 == 0 ? static_cast<Index>(soup.positions.size() - 1) : pickSource(soup, rng);
  return make("far-source", "farSourceBumpyPatch(" + str(n) + ", " + num(far) + ", " + std::to_string(seed) + ")",
              std::move(soup), source);
}

using FamilyMaker = CrossCheckCase (*)(int step, SplitMix64& rng);

struct Family {
  std::string_view name;
  FamilyMaker make;
};

constexpr std::array kFamilies{
    Family{"two-faces", twoFaces},         Family{"fuzz-solver-seed", fuzzSolverSeed},
    Family{"flat-grid", flatGrid},         Family{"near-flat-grid", nearFlatGrid},
    Family{"needle-fan", needleFan},       Family{"l-shape", lShape},
    Family{"square-with-hole", squareWithHole}, Family{"terraces", terraces},
    Family{"icosphere", icosphere},        Family{"uv-sphere", uvSphere},
    Family{"components", components},      Family{"bumpy", bumpy},
    Family{"far-source", farSource},       Family{"fuzz-solver", fuzzSolverRandom},
};

}  // namespace

const std::vector<std::string_view>& crossCheckFamilies() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> v;
    for (const Family& f : kFamilies) v.push_back(f.name);
    return v;
  }();
  return names;
}

CrossCheckCase crossCheckCase(std::uint64_t seed, std::size_t index) {
  const Family& family = kFamilies[index % kFamilies.size()];
  const int step = static_cast<int>(std::min<std::size_t>(index / kFamilies.size(), 1 << 20));
  // One stream per (seed, index): a case does not depend on how many came before it.
  SplitMix64 mixer(seed);
  SplitMix64 rng(mixer.next() ^ (0x9e3779b97f4a7c15ULL * (index + 1)));
  return family.make(step, rng);
}

TriangleSoup keepFaces(const TriangleSoup& soup, const std::vector<bool>& keep, Index& source) {
  std::vector<Index> renumbered(soup.positions.size(), kNoIndex);
  for (std::size_t f = 0; f < soup.faces.size(); ++f)
    if (keep[f])
      for (Index v : soup.faces[f]) renumbered[v] = 0;
  TriangleSoup kept;
  for (Index v = 0; v < soup.positions.size(); ++v) {
    if (renumbered[v] == kNoIndex) continue;
    renumbered[v] = static_cast<Index>(kept.positions.size());
    kept.positions.push_back(soup.positions[v]);
  }
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    if (!keep[f]) continue;
    const auto& t = soup.faces[f];
    kept.faces.push_back({renumbered[t[0]], renumbered[t[1]], renumbered[t[2]]});
  }
  source = source < renumbered.size() ? renumbered[source] : kNoIndex;
  return kept;
}

std::string offText(const TriangleSoup& soup) { return detail::describeSoup(soup); }

}  // namespace geodex::verify
