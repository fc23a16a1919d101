#pragma once
// The coverage gate of the property suite: every property reports the degenerate cases its
// inputs reached — Fig. 6 leaves of local decisions (degeneracyOf(branch)), Algorithm 2 runs
// (EdgeUpdateReport::degeneracies) and whole solves (GeodesicSolver::counters()) — into one
// process-wide tally. After the last test of the run, CoverageGate (a GoogleTest environment,
// whose TearDown runs after every test of the process whatever their order, shuffled or not)
// prints the table and fails the run if any of G1–G5, D1–D4 was reached fewer than
// kMinHitsPerCase times.
//
// The gate only judges complete runs: with a --gtest_filter, or when RapidCheck replays a
// failure (RC_PARAMS="reproduce=…", which runs only the failing properties), it prints the table
// and says why it does not judge. GEODEX_COVERAGE_GATE=force judges anyway.

#include <gtest/gtest.h>

#include <cstdint>

#include "geodex/degeneracy.h"
#include "geodex/propagate.h"

namespace geodex::proptest {

inline constexpr std::uint64_t kMinHitsPerCase = 100;

/// Where a count came from (the table's columns).
enum class CoverageSource { Local, Algorithm2, Solve, kCount };

/// A Fig. 6 leaf reached by a local property.
void recordLocal(Fig6Branch branch);
/// The D1–D4 found by one Algorithm 2 insertion run by a property.
void recordAlgorithm2(const DegeneracyCounters& counters);
/// The counters of one whole solve run by a property.
void recordSolve(const DegeneracyCounters& counters);

/// The error (relative to the mesh's bounding-box diagonal) one check of a whole-solve property
/// found; the worst per check is printed with the table: how far inside its tolerance the solver
/// actually is.
void recordAccuracy(const char* check, double relativeError);

/// Count of one case from one source so far in this run.
std::uint64_t coverageCount(DegeneracyKind kind, CoverageSource source);

class CoverageGate : public ::testing::Environment {
 public:
  void SetUp() override;
  void TearDown() override;
};

}  // namespace geodex::proptest
