// Differential search for mutants of edge_intervals.cpp: random sequences of Algorithm 2 updates
// on one edge, built to meet in slivers, near-equal distances and nearly equal sources (ends a
// few 1e-12..1e-10 apart around four points, three sources moved by 1e-11, σ set so that the new
// interval meets an old one somewhere), printing the list after every update. Build it with
// edge_intervals.cpp as it is and with the mutant planted, and compare the outputs: the first line
// that differs names the seed and update to make a test of (SHOW=1 prints each update as a
// make(...) call; NMAX sets the longest sequence, 9 updates by default). With 713e4d70 planted,
// 275 of the list states of seeds 0..20000 differ.
//   cp build/release/solver/libgeodex.a /tmp/rest.a && ar d /tmp/rest.a edge_intervals.cpp.o
//   g++ -O2 -std=c++20 -Isolver/include -isystem /usr/include/eigen3 \
//     scripts/mutation-evidence/update_sequences.cpp EDGE_INTERVALS_CPP /tmp/rest.a -o /tmp/seq
//   /tmp/seq 0 200000 > states.txt
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "geodex/edge_intervals.h"

using namespace geodex;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s FIRST_SEED END_SEED\n", argv[0]);
    return 2;
  }
  const long first = std::atol(argv[1]), end = std::atol(argv[2]);
  const int longest = std::getenv("NMAX") ? std::atoi(std::getenv("NMAX")) : 8;
  const bool show = std::getenv("SHOW") != nullptr;
  for (long seed = first; seed < end; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    const double L = 10.0;
    EdgeIntervals list;
    EdgeUpdateReport report;
    std::vector<Interval> scratch;
    double points[4];
    for (double& p : points) p = u(rng) * L;
    Vec2 sources[3];
    for (Vec2& s : sources) s = Vec2(u(rng) * 20 - 5, u(rng) * 5);
    const double offsetScale[3] = {1e-12, 1e-11, 1e-10};
    auto offset = [&] { return (int(rng() % 21) - 10) * offsetScale[rng() % 3]; };
    const int n = 2 + int(rng() % longest);
    for (int i = 0; i < n; ++i) {
      double a = points[rng() % 4] + offset();
      double b = points[rng() % 4] + offset();
      if (rng() % 4 == 0) b = a + (1 + rng() % 9) * offsetScale[rng() % 3];
      if (a > b) std::swap(a, b);
      a = std::max(a, 0.0);
      b = std::min(b, L);
      if (!(a < b)) continue;
      Interval w;
      w.b0 = a;
      w.b1 = b;
      Vec2 s =
          sources[rng() % 3] + Vec2((int(rng() % 5) - 2) * 1e-11, (int(rng() % 5) - 2) * 1e-11);
      s.y() = std::max(s.y(), 0.0);
      w.source = s;
      double sigma = u(rng);
      if (!list.intervals().empty() && rng() % 2) {  // meet an old interval somewhere
        const Interval& o = list.intervals()[rng() % list.intervals().size()];
        const double x = std::clamp(o.b0 + u(rng) * (o.b1 - o.b0), a, b);
        sigma =
            std::max(0.0, o.distanceAt(x) - (Vec2(x, 0) - s).norm() + (int(rng() % 5) - 2) * 1e-11);
      }
      w.sigma = sigma;
      if (show)
        std::printf("insert make(%a, %a, Vec2(%a, %a), %a)\n", w.b0, w.b1, w.source.x(),
                    w.source.y(), w.sigma);
      list.insert(w, L, report, scratch);
      std::printf("%ld %d:", seed, i);
      for (const Interval& v : list.intervals()) std::printf(" [%a %a]", v.b0, v.b1);
      std::printf("\n");
    }
  }
}
