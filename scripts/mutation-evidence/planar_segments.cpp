// Evidence for mutant a4648cb4 (scripts/mutation-equivalents.json): PlanarDomain::segmentInside(p, q)
// and (q, p) with q exactly ε (the domain's tolerance) off a boundary edge's line on either side, p
// random (in and around the domain, and within 1e4 ε of q): one verdict pair per line, to compare
// between builds of verify/src/oracles.cpp with and without the mutant.
//   g++ -O2 -std=c++20 -Isolver/include -Iverify/include -isystem /usr/include/eigen3 \
//     scripts/mutation-evidence/planar_segments.cpp build/release/verify/libgeodex_verify.a \
//     build/release/solver/libgeodex.a -lgmpxx -lgmp -o /tmp/segs && /tmp/segs > verdicts.txt
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>
#include "geodex/verify/oracles.h"
using namespace geodex;
using namespace geodex::verify;
int main() {
  std::vector<std::vector<Polygon2>> shapes;
  const std::vector<Vec2> shifts{{0, 0}, {-1, -1}, {-2, 0}, {0, -2}, {-1, -2}, {-2, -1}};
  for (const Vec2& s : shifts) {
    Polygon2 l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    for (auto& v : l) v += s;
    shapes.push_back({l});
  }
  const std::vector<Vec2> hs{{0, 0}, {-1, -1}, {-3, -3}, {-4, -4}, {-1, -3}, {-3, -1}};
  for (const Vec2& s : hs) {
    Polygon2 o{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, h{{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    for (auto& v : o) v += s;
    for (auto& v : h) v += s;
    shapes.push_back({o, h});
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  long trueCount = 0, n = 0;
  for (const auto& shape : shapes) {
    const PlanarDomain d(shape);
    const double eps = d.tolerance();
    Vec2 lo = shape[0][0], hi = lo;
    for (const auto& loop : shape) for (const Vec2& v : loop) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (int i = 0; i < 400000; ++i) {
      // q: on the x = 0 or y = 0 axis (where edges lie for some shift), exactly ±ε off it.
      const bool onX = rng() & 1;
      const double t = lo[onX ? 1 : 0] + (hi - lo)[onX ? 1 : 0] * u01(rng);
      const double off = (rng() & 1) ? eps : -eps;
      const Vec2 q = onX ? Vec2(off, t) : Vec2(t, off);
      Vec2 p;
      switch (rng() % 3) {
        case 0: p = lo + (hi - lo).cwiseProduct(Vec2(u01(rng), u01(rng))); break;
        case 1: p = lo - Vec2(0.5, 0.5) + (hi - lo + Vec2(1, 1)).cwiseProduct(Vec2(u01(rng), u01(rng))); break;
        default: {  // near q: a few ε to a little away
          const double r = eps * std::pow(10.0, 4.0 * u01(rng)), a = 6.283185307179586 * u01(rng);
          p = q + r * Vec2(std::cos(a), std::sin(a));
        }
      }
      const bool a = d.segmentInside(p, q), b = d.segmentInside(q, p);
      std::printf("%d%d\n", a, b);
      trueCount += a + b, n += 2;
    }
  }
  std::fprintf(stderr, "%ld segments, %ld inside\n", n, trueCount);
}
