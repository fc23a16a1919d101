#pragma once
// fuzz_edge_update: one Algorithm 2 update. A valid interval list and an incoming interval, or a
// run of them (the bytes after the first) → EdgeIntervals::insert or insertRun: the cheap step-6
// invariants and the pointwise minimum (InvariantChecker,
// full tier); no pseudo-source invented; only the slice the update reports is rewritten. Also
// reads the text reproducers of writeReproducer ("geodex-edge-update 1"). Its libFuzzer main is
// fuzz/fuzz_edge_update.cpp.

#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geodex/interval.h"
#include "geodex/verify/cases/byte_codec.h"
#include "geodex/verify/cases/fuzz_target.h"

namespace geodex::verify {

/// The longest list before the update a case may ask for (the fuzzing budget, docs/fuzzing.md).
inline constexpr int kMaxFuzzOldIntervals = 8;
/// At most this many incoming intervals merged as one run (EdgeIntervals::insertRun).
inline constexpr int kMaxFuzzRun = 6;

/// One interval of the bytes.
struct IntervalSpec {
  Quantity start;   ///< old intervals: the gap before it (∈ [0, nL]); incoming: b0 ∈ [0, nL]
  Quantity extent;  ///< old intervals: its length (∈ [0, nL]); incoming: b1 ∈ [0, nL]
  Quantity sourceX, sourceY;  ///< x ∈ [−2 nL, 3 nL], y ∈ [0, 2 nL] (|y| taken)
  Quantity sigma;             ///< σ ∈ [0, 4 nL] (|σ| taken)
  /// bit 0: side τ; bits 1–2: propagated part (none, all, first half, second half: an interval
  /// carries one pending bit, so a half propagated is pending, as one grown after its
  /// propagation is); bit 3: source = that of interval `ref` + (sourceX, sourceY) read as
  /// offsets ∈ [−nL, nL]; bit 4: σ = that of interval `ref` + sigma read as an offset ∈ [−nL, nL].
  std::uint8_t flags = 0;
  /// Which earlier old interval (mod their count) bits 3–4 refer to; for a run's later incoming
  /// intervals, the old ones and the run's earlier ones, in that order.
  std::uint8_t ref = 0;
};

/// The bytes: an edge's list before Algorithm 2 and the incoming interval. Old intervals are
/// laid out left to right (gap, length, gap, length, …) and cut at L; a list the cheap invariants
/// reject is not a valid starting point and the case is skipped.
struct EdgeUpdateSpec {
  std::int8_t unitExp = 0;
  Quantity edgeLength;  ///< L ∈ [1, 64]
  std::vector<IntervalSpec> before;  ///< count byte mod (kMaxFuzzOldIntervals + 1)
  IntervalSpec incoming;
  /// Any bytes after the incoming interval: more of them, merged with it as one run (at most
  /// kMaxFuzzRun in all).
  std::vector<IntervalSpec> laterIncoming;
};

std::vector<std::uint8_t> encode(const EdgeUpdateSpec& s);

struct EdgeUpdateCase {
  double edgeLength = 0.0;
  std::vector<Interval> before;  ///< ids 1..n
  Interval incoming;             ///< id n + 1
  /// A text reproducer of a run update (several incoming lines): the run's other intervals, merged
  /// after `incoming` by EdgeIntervals::insertRun. Empty for one incoming interval.
  std::vector<Interval> laterIncoming;
  std::string note;              ///< where it came from (a text reproducer's invariant, branch)
};

/// The incoming interval and the rest of its run, in order.
std::vector<Interval> incomingRun(const EdgeUpdateCase& c);

/// The case the bytes describe (binary, or a text reproducer), or nullopt when the target skips
/// them: too long, an incoming interval no propagation makes, or a list before the update that
/// step 6 rejects.
std::optional<EdgeUpdateCase> decodeEdgeUpdate(std::span<const std::uint8_t> bytes);

/// The text reproducer of writeReproducer ("geodex-edge-update 1"). Throws InputError when the
/// text is not one.
EdgeUpdateCase parseEdgeUpdateReproducer(std::string_view text);
/// Whether the first line that is not blank or a comment is the text reproducer's magic line.
bool isEdgeUpdateReproducer(std::span<const std::uint8_t> bytes);

Verdict checkEdgeUpdate(const EdgeUpdateCase& c);

/// The edge length and the intervals before and incoming.
void describe(const EdgeUpdateCase& c, std::ostream& out);
/// The distance functions before, incoming and after, coloured by pseudo-source, and the
/// pseudo-sources unfolded below the edge.
void writeSvg(const EdgeUpdateCase& c, std::ostream& out);

/// The committed corpus (corpus/fuzz_edge_update/): one or more seeds per Algorithm 2
/// degeneracy D1–D4 and their composites, each named after what it must hit, updates without
/// degeneracies to mutate from, and the regress files that can be described.
std::vector<Seed> edgeUpdateSeeds();

}  // namespace geodex::verify
