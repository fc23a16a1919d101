#pragma once
// A finding of `geodex crosscheck` on disk: DIR/NNN-<kind>/ with mesh.off, source.txt,
// expected.txt, got.txt, report.txt and picture.png, and original.off, the case before it was
// minimized (docs/crosscheck.md describes each).

#include <cstddef>
#include <cstdint>
#include <string>

#include "crosscheck_trial.h"

namespace geodex::cli {

/// Where a finding came from and what minimizing it did.
struct FindingOrigin {
  std::string caseLabel;           ///< "case 12 of seed 1 …", or the --mesh file and source
  TriangleSoup originalSoup;       ///< the case before minimizing (written as original.off)
  Index originalSource = 0;
  std::size_t originalFaces = 0;   ///< before minimizing
  std::size_t originalVertices = 0;
  std::size_t trials = 0;          ///< minimization trials
  std::string stoppedBy;           ///< "" or why minimization stopped early ("trials", "time")
};

/// Writes the finding's directory `dir` (created; must not exist yet). Throws InputError when
/// a file cannot be written.
void writeFinding(const std::string& dir, const Trial& t, const FindingOrigin& origin, const CaseRunner& runner);

}  // namespace geodex::cli
