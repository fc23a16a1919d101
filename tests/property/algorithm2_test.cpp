// Properties of Algorithm 2 (EdgeIntervals::insert and insertRun) on one edge, fed sequences of
// intervals aimed at D1–D4 and the other hazards of an edge's list (generators.h, "Edge interval
// lists"). After every insertion the list must be well formed (verify::InvariantChecker::checkList,
// the cheap tier of step 6) and equal the pointwise minimum of the list before and the incoming
// interval (the full tier), both judged by verify/, which shares no code with the repair.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "coverage.h"
#include "generators.h"
#include "geodex/edge_intervals.h"
#include "geodex/observer.h"
#include "geodex/verify/invariant_checker.h"
#include "weighted_prop.h"

namespace geodex::proptest {
namespace {

// Where a failing insertion is written as a text reproducer ("geodex-edge-update 1", read by
// fuzz_edge_update and `geodex repro`); the last failure of a run is the shrunk one.
constexpr const char* kFailureReproducerFile = "property-failure-edge-update.txt";

std::string describeList(std::span<const Interval> list) {
  std::ostringstream os;
  os.precision(17);
  for (const Interval& w : list)
    os << "\n    [" << w.b0 << ", " << w.b1 << "] s=(" << w.source.x() << ", " << w.source.y()
       << ") sigma=" << w.sigma;
  return os.str();
}

// Runs the case's insertions through Algorithm 2 with the full-tier checker watching; fails the
// property at the first violation. Those from `runFrom` on are merged as one run
// (EdgeIntervals::insertRun, as the solver merges a batch's children on one edge); the others one
// at a time. Returns the D1–D4 the insertions found.
DegeneracyCounters runAndCheck(const IntervalListCase& c, std::size_t runFrom) {
  EdgeIntervals list;
  EdgeUpdateReport report;
  std::vector<Interval> scratch, before;
  IntervalList work;
  verify::InvariantChecker checker(verify::CheckLevel::Full, /*throwOnViolation=*/true);
  DegeneracyCounters found;
  for (std::size_t i = 0; i < c.inserts.size();) {
    const std::size_t n = i < runFrom ? 1 : c.inserts.size() - i;
    const std::span<const Interval> incoming(c.inserts.data() + i, n);
    before.assign(list.intervals().begin(), list.intervals().end());
    list.insertRun(incoming, c.edgeLength, report, scratch, work);
    found += report.degeneracies;
    recordAlgorithm2(report.degeneracies);

    const EdgeUpdateEvent event{0, c.edgeLength, before, incoming, list.intervals(), report, {}};
    const std::string what =
        n == 1 ? "insertion " + std::to_string(i)
               : "the run of insertions " + std::to_string(i) + " to " + std::to_string(i + n - 1);
    try {
      checker.onEdgeUpdate(event);  // the cheap tier (checkList) and the pointwise minimum
    } catch (const verify::InvariantViolation& v) {
      verify::writeReproducer(v, kFailureReproducerFile);
      RC_FAIL(what + ": " + v.what() + "\n  before:" + describeList(before) +
              "\n  after:" + describeList(list.intervals()) + "\n  reproducer written to " +
              (std::filesystem::current_path() / kFailureReproducerFile).string() +
              " (replay: bin/fuzz_edge_update FILE or geodex repro FILE; keep it as "
              "corpus/fuzz_edge_update/regress/open-<what it broke>)");
    }
    std::string why;
    const std::string broken =
        verify::InvariantChecker::checkList(list.intervals(), c.edgeLength, why);
    if (!broken.empty()) {
      RC_FAIL(what + " left the list broken (" + broken + "): " + why +
              "\n  before:" + describeList(before) + "\n  after:" + describeList(list.intervals()));
    }
    i += n;
  }
  return found;
}

GEODEX_RC_GTEST_PROP(Algorithm2, KeepsTheListWellFormedAndThePointwiseMinimum, kLocalPropertyWeight,
                     ()) {
  const IntervalListCase c = *gen::intervalListCase();
  const DegeneracyCounters found = runAndCheck(c, c.inserts.size());
  RC_TAG(c.target, c.mirrored ? "mirrored" : "as made");
  RC_CLASSIFY(found[DegeneracyKind::D1] > 0, "hit D1");
  RC_CLASSIFY(found[DegeneracyKind::D2] > 0, "hit D2");
  RC_CLASSIFY(found[DegeneracyKind::D3] > 0, "hit D3");
  RC_CLASSIFY(found[DegeneracyKind::D4] > 0, "hit D4");
}

// The same insertions, the last ones merged as one run: steps 1 and 2 for each in turn, steps 3–5
// once over all they changed. The list must still be well formed and the pointwise minimum of the
// list before the run and every interval in it.
GEODEX_RC_GTEST_PROP(Algorithm2, ARunOfInsertionsKeepsTheListWellFormedAndThePointwiseMinimum,
                     kLocalPropertyWeight, ()) {
  const IntervalListCase c = *gen::intervalListCase();
  RC_PRE(c.inserts.size() >= 2);
  const auto runFrom = *rc::gen::inRange<std::size_t>(0, c.inserts.size() - 1);
  const DegeneracyCounters found = runAndCheck(c, runFrom);
  RC_TAG(c.target, c.mirrored ? "mirrored" : "as made");
  RC_CLASSIFY(c.inserts.size() - runFrom >= 3, "a run of three or more");
  RC_CLASSIFY(found[DegeneracyKind::D1] > 0, "hit D1");
  RC_CLASSIFY(found[DegeneracyKind::D2] > 0, "hit D2");
  RC_CLASSIFY(found[DegeneracyKind::D3] > 0, "hit D3");
  RC_CLASSIFY(found[DegeneracyKind::D4] > 0, "hit D4");
}

// The far-source scenario alone, the one that reaches D4 (Eq. 1 loses its digits when σ or the
// source distance is 1e3–1e7 edge lengths): run often enough for the coverage gate.
GEODEX_RC_GTEST_PROP(Algorithm2, FarSourceAgainstNearSourceKeepsThePointwiseMinimum,
                     kLocalPropertyWeight, ()) {
  const IntervalListCase c = *gen::orMirrored(gen::mismatchedEndpointList());
  const DegeneracyCounters found = runAndCheck(c, c.inserts.size());
  RC_TAG(c.target, c.mirrored ? "mirrored" : "as made");
  RC_CLASSIFY(found[DegeneracyKind::D4] > 0, "hit D4");
}

}  // namespace
}  // namespace geodex::proptest
