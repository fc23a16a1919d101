#pragma once
// Shrinking a failing mesh case to few faces (delta debugging over the face list, Zeller &
// Hildebrandt 2002): remove a run of faces, keep the removal when the failure persists, halve the
// runs down to single faces. `geodex crosscheck` minimizes its findings with it, asking whether
// the same kind of finding persists; the minimizer itself knows nothing of programs.
//
// Deterministic: the trials depend only on the case and the answers, and the trial budget is a
// count. The time budget is a safety net for programs that take long on every trial.

#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

#include "geodex/mesh.h"

namespace geodex::verify {

struct MinimizeBudget {
  std::size_t maxTrials = 500;                 ///< calls of the predicate at most
  std::chrono::duration<double> maxTime{60.0};  ///< wall time at most (checked between trials)
};

struct MinimizedCase {
  TriangleSoup soup;       ///< the smallest failing soup found (the input if nothing could go)
  Index source = 0;        ///< the source, renumbered into it
  std::size_t trials = 0;  ///< predicate calls made
  /// Why it stopped before trying every single face: "" (it did not), "trials" or "time".
  const char* stoppedBy = "";
};

/// The predicate: true when the candidate (the soup with some faces removed, unreferenced
/// vertices dropped, the source renumbered) still fails in the same way. Candidates in which no
/// face uses the source are not asked about.
using StillFails = std::function<bool(const TriangleSoup& soup, Index source)>;

/// Removes faces from `soup` while `stillFails` holds, runs of ⌈n/2⌉ faces first, then halves.
/// The result has no face whose removal alone (with the rest kept) still fails, unless the
/// budget ran out first.
/// @param[in] firstTry  #F flags: a subset of the faces the caller expects to fail on its own
///                      (e.g. the faces near a wrong vertex), tried before anything else; empty
///                      for none
MinimizedCase minimizeFaces(const TriangleSoup& soup, Index source, const StillFails& stillFails,
                            const MinimizeBudget& budget = {}, const std::vector<bool>& firstTry = {});

}  // namespace geodex::verify
