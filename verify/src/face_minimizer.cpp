// Delta debugging over a mesh's faces (face_minimizer.h).
#include "geodex/verify/face_minimizer.h"

#include <algorithm>

#include "geodex/verify/crosscheck_cases.h"

namespace geodex::verify {

MinimizedCase minimizeFaces(const TriangleSoup& soup, Index source, const StillFails& stillFails,
                            const MinimizeBudget& budget, const std::vector<bool>& firstTry) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  MinimizedCase best{soup, source, 0, ""};
  const auto outOfBudget = [&] {
    if (best.trials >= budget.maxTrials) best.stoppedBy = "trials";
    else if (Clock::now() - start >= budget.maxTime) best.stoppedBy = "time";
    return *best.stoppedBy != '\0';
  };
  if (firstTry.size() == soup.faces.size() && std::count(firstTry.begin(), firstTry.end(), true) > 0 &&
      !outOfBudget()) {
    Index candidateSource = source;
    TriangleSoup candidate = keepFaces(soup, firstTry, candidateSource);
    if (candidateSource != kNoIndex && candidate.faces.size() < soup.faces.size()) {
      ++best.trials;
      if (stillFails(candidate, candidateSource)) {
        best.soup = std::move(candidate);
        best.source = candidateSource;
      }
    }
  }
  std::size_t run = (best.soup.faces.size() + 1) / 2;
  while (run >= 1 && best.soup.faces.size() > 1) {
    bool removedAny = false;
    // Faces [first, first + run) of the current best go; after a success the same position
    // holds the next faces, so it is tried again.
    for (std::size_t first = 0; first < best.soup.faces.size();) {
      if (outOfBudget()) return best;
      const std::size_t n = best.soup.faces.size();
      if (run >= n) break;  // removing everything is never a reproducer
      std::vector<bool> keep(n, true);
      std::fill(keep.begin() + static_cast<std::ptrdiff_t>(first),
                keep.begin() + static_cast<std::ptrdiff_t>(std::min(n, first + run)), false);
      Index candidateSource = best.source;
      TriangleSoup candidate = keepFaces(best.soup, keep, candidateSource);
      bool fails = false;
      if (candidateSource != kNoIndex) {
        ++best.trials;
        fails = stillFails(candidate, candidateSource);
      }
      if (fails) {
        best.soup = std::move(candidate);
        best.source = candidateSource;
        removedAny = true;
      } else {
        first += run;
      }
    }
    if (run == 1 && !removedAny) break;
    run = std::max<std::size_t>(1, run / 2);
  }
  return best;
}

}  // namespace geodex::verify
