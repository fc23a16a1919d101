#pragma once
// Algorithm 2 step 6, checked live: an observer the solver calls after every edge update and at
// the end of a solve. It shares none of the solver's repair logic: it only looks at the lists.
//
//   cheap tier (every update): sorted by b0; each a range 0 ≤ b0 < b1 ≤ |e|; no overlap; no gap
//     below ε left unsewn; no interval shorter than ε; d0, d1, σ finite and ≥ 0; a real unfolded
//     source (source height ≥ 0, |d0 − d1| ≤ b1 − b0 + ε); the two distances agree at every Eq. 1
//     breakpoint. (Elsewhere neighbours may legitimately disagree mid-run: the ends of an
//     incoming interval's range are where the wavefront has not arrived yet.)
//   Both tiers look at what the update rewrote and its neighbours, once they have seen that the
//     rest of the list is the same intervals as before (then it holds from the updates that
//     wrote it); when it is not, or the event does not say, at the whole list.
//   full tier (adds): the pointwise-min property — the list after the update equals the minimum
//     of the list before and the incoming interval (or every one of a run), sampled along the edge
//     (except inside the tiny intervals step 3 removed, where a neighbour's values stand in by the
//     paper's contract, and within the slack step 4 may sew); and at the end, every edge reached is
//     fully covered, every vertex's distance is the same from all its edges (the final field is
//     continuous), and no window that has a face to cross is still pending (the wavefront was
//     exhausted); and every window the solver dropped by the edge-end rule is nowhere shorter than
//     the final distances, on its edge or in the face it would have crossed.
// A violation throws InvariantViolation, which carries everything needed to replay it.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "geodex/geodesic_solver.h"
#include "geodex/observer.h"

namespace geodex::verify {

enum class CheckLevel { Cheap, Full };

/// One failed invariant, with the edge update it happened in.
class InvariantViolation : public std::runtime_error {
 public:
  InvariantViolation(std::string invariant, const std::string& message) : std::runtime_error(message), invariant_(std::move(invariant)) {}
  const std::string& invariant() const { return invariant_; }

  // The edge update (empty lists for end-of-run invariants).
  Index edge = kNoIndex;
  double edgeLength = 0.0;
  std::vector<Interval> before, after;
  std::vector<Interval> incoming;  ///< one, or the run of children the update merged
  std::string branch;  ///< the Fig. 6 leaf that made the (first) incoming interval, or "source"

 private:
  std::string invariant_;
};

/// Per-invariant tallies, for reports.
struct InvariantTally {
  std::string name;
  std::uint64_t checked = 0;
  std::uint64_t violated = 0;
  double worst = 0.0;  ///< largest relative error seen (0 for yes/no invariants)
};

class InvariantChecker : public SolverObserver {
 public:
  explicit InvariantChecker(CheckLevel level = CheckLevel::Cheap, bool throwOnViolation = true);

  /// Checks what the update changed, with its neighbours: the rest of the list is taken as the
  /// updates before left it and were checked then. So a checker must see every update of a list
  /// from the empty one (as an observer set before GeodesicSolver::solve does); one update over a
  /// list it never saw is checked only where that update changed it.
  void onEdgeUpdate(const EdgeUpdateEvent& e) override;
  /// Full tier: kept until onFinish, which samples the window against the final distances (a
  /// solve that throws before its end leaves them to the next onFinish: use a fresh checker then).
  void onWindowDropped(const WindowDroppedEvent& e) override;
  void onFinish(const GeodesicSolver& solver) override;
  /// The end-of-run invariants (full tier) on given lists: every edge in a component holding a
  /// source fully covered (when the solve ran to the end), every vertex distance equal to what
  /// each incident edge gives there. onFinish calls this with the solver's state.
  void checkFinal(const Mesh& mesh, std::span<const EdgeIntervals> edges, std::span<const double> d,
                  std::span<const ResolvedPoint> sources, bool ranToEnd);

  const std::vector<InvariantTally>& tallies() const { return tallies_; }
  std::uint64_t violations() const;
  /// The first violation (when not throwing), else nullptr.
  const InvariantViolation* firstViolation() const { return first_.get(); }

  /// Checks one list as the cheap tier does; returns the name of the first broken invariant and
  /// a description in `why`, or "" if the list is well formed. Usable on its own (tests, fuzzers).
  static std::string checkList(std::span<const Interval> list, double edgeLength, std::string& why);
  /// The same on list[lo, hi) and the pairs they form, the ends of the edge only when the range
  /// reaches them: what an update can have broken when the rest of the list is as it was.
  static std::string checkListRange(std::span<const Interval> list, std::size_t lo, std::size_t hi,
                                    double edgeLength, std::string& why);

 private:
  enum Id { Sorted, InRange, NoOverlap, NoTinyGap, NoTinyInterval, FiniteNonNegative, RealSource,
            ContinuousAtEq1, PointwiseMin, FullCoverage, VertexAgreement, WavefrontExhausted,
            DroppedWindowDominated, kNumInvariants };
  void record(Id id, bool ok, double error, const std::string& why, const EdgeUpdateEvent* e);

  // The checks of one edge update, in the order onEdgeUpdate makes them; [lo, hi) is the part of
  // e.after they look at (what the update rewrote, with a neighbour on each side).
  struct ChangedRange;
  static ChangedRange changedRange(const EdgeUpdateEvent& e);
  void checkWellFormed(const EdgeUpdateEvent& e, std::size_t lo, std::size_t hi);
  void checkContinuityAtEq1(const EdgeUpdateEvent& e, std::size_t lo, std::size_t hi);
  void checkExhausted(const Mesh& mesh, Index e, std::span<const Interval> list);
  void checkDroppedWindows(const GeodesicSolver& solver);
  void checkPointwiseMin(const EdgeUpdateEvent& e, const ChangedRange& changed, std::size_t lo,
                         std::size_t hi);
  // The samples that need the general evaluation; those well inside a piece are evaluated as the
  // walk makes them, into `interior`.
  struct PointwiseMinError;
  std::span<const double> pointwiseMinSamples(const EdgeUpdateEvent& e, const ChangedRange& changed,
                                              std::span<const Interval> beforeNear,
                                              std::span<const Interval> afterNear, double tiny,
                                              PointwiseMinError& interior);
  PointwiseMinError worstPointwiseMinError(const EdgeUpdateEvent& e, std::span<const double> xs,
                                           double tiny);

  CheckLevel level_;
  bool throw_;
  std::vector<InvariantTally> tallies_;
  std::unique_ptr<InvariantViolation> first_;
  // The pointwise-minimum samples, those found besides the walk's, and the endpoints of lists out
  // of order (sorted there), reused between updates.
  std::vector<double> samples_, extraSamples_, ends_;
  // Every value the repaired list may take at one sample, and the interval each is of
  // (worstPointwiseMinError), reused between updates.
  std::vector<double> candidates_;
  std::vector<const Interval*> candidateOf_;
  // The windows dropped by the edge-end and along-edge rules in this solve (full tier).
  struct DroppedWindow {
    Index edge;
    Interval window;
    Index vertex;
    double vertexDistance;
    DropRule rule;
  };
  std::vector<DroppedWindow> dropped_;
};

/// Writes a violation as a text reproducer `geodex repro` reads back (format in docs/fuzzing.md).
void writeReproducer(const InvariantViolation& v, const std::string& path);

}  // namespace geodex::verify
