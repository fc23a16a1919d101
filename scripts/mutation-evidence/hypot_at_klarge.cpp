// Evidence for mutant d8941663 (scripts/mutation-equivalents.json): sqrt(dx*dx + dy*dy) against
// std::hypot(dx, dy) at dx = 1e150 (the one dx the mutant moves to the plain root), for dy over its
// whole range below 1e150.   g++ -O2 -std=c++20 hypot_at_klarge.cpp -o /tmp/h && /tmp/h
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <random>
int main() {
  const double dx = 1e150;
  std::mt19937_64 rng(1);
  long n = 0, differ = 0, maxUlps = 0;
  auto probe = [&](double dy) {
    if (!(dy < 1e150)) return;
    const double a = std::sqrt(dx * dx + dy * dy), b = std::hypot(dx, dy);
    ++n;
    if (a != b) {
      ++differ;
      long u = std::llabs((long)(std::bit_cast<long long>(a) - std::bit_cast<long long>(b)));
      if (u > maxUlps) maxUlps = u;
    }
  };
  std::uniform_real_distribution<double> e(-300.0, 150.0), m(1.0, 10.0);
  for (int i = 0; i < 20000000; ++i) probe(m(rng) * std::pow(10.0, e(rng)));
  std::uniform_real_distribution<double> top(0.0, 1e150);
  for (int i = 0; i < 20000000; ++i) probe(top(rng));
  probe(0.0);
  std::printf("%ld dy values, %ld differ, at most %ld ulp apart\n", n, differ, maxUlps);
}
