// fuzz_edge_update: one Algorithm 2 update (fuzz_edge_update.h).
#include "geodex/verify/cases/fuzz_edge_update.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "check_support.h"
#include "geodex/edge_intervals.h"
#include "geodex/error.h"
#include "geodex/mesh.h"
#include "geodex/verify/invariant_checker.h"
#include "geodex/verify/repro.h"  // FuzzCase, which the seeds' expectations take
#include "svg.h"

namespace geodex::verify {

using namespace detail;

// ===  Format ====================================================================================

namespace {

IntervalSpec readIntervalSpec(ByteReader& r) {
  IntervalSpec s;
  s.start = r.quantity();
  s.extent = r.quantity();
  s.sourceX = r.quantity();
  s.sourceY = r.quantity();
  s.sigma = r.quantity();
  s.flags = r.u8();
  s.ref = r.u8();
  return s;
}

void writeIntervalSpec(ByteWriter& w, const IntervalSpec& s) {
  w.quantity(s.start);
  w.quantity(s.extent);
  w.quantity(s.sourceX);
  w.quantity(s.sourceY);
  w.quantity(s.sigma);
  w.u8(s.flags);
  w.u8(s.ref);
}

EdgeUpdateSpec readEdgeUpdateSpec(ByteReader& r) {
  EdgeUpdateSpec s;
  s.unitExp = r.i8();
  s.edgeLength = r.quantity();
  const int count = r.u8() % (kMaxFuzzOldIntervals + 1);
  for (int i = 0; i < count; ++i) s.before.push_back(readIntervalSpec(r));
  s.incoming = readIntervalSpec(r);
  while (!r.atEnd() && s.laterIncoming.size() < static_cast<std::size_t>(kMaxFuzzRun - 1))
    s.laterIncoming.push_back(readIntervalSpec(r));
  return s;
}

}  // namespace

std::vector<std::uint8_t> encode(const EdgeUpdateSpec& s) {
  ByteWriter w;
  w.i8(s.unitExp);
  w.quantity(s.edgeLength);
  GEODEX_REQUIRE(s.before.size() <= static_cast<std::size_t>(kMaxFuzzOldIntervals),
                 "at most " << kMaxFuzzOldIntervals << " old intervals");
  w.u8(static_cast<std::uint8_t>(s.before.size()));
  for (const IntervalSpec& i : s.before) writeIntervalSpec(w, i);
  writeIntervalSpec(w, s.incoming);
  for (const IntervalSpec& i : s.laterIncoming) writeIntervalSpec(w, i);
  return w.bytes();
}

// ===  Decoding ==================================================================================

namespace {

Interval makeInterval(const IntervalSpec& s, bool incoming, double cursor, double L, long nL,
                      double unit, const std::vector<Interval>& earlier, bool& ok) {
  Interval w;
  if (incoming) {
    double b0 = fieldValue(s.start, 0, nL, unit, L), b1 = fieldValue(s.extent, 0, nL, unit, L);
    if (b0 > b1) std::swap(b0, b1);
    w.b0 = std::max(b0, 0.0);
    w.b1 = std::min(b1, L);
  } else {
    w.b0 = cursor + std::abs(fieldValue(s.start, 0, nL, unit, L));
    w.b1 = std::min(w.b0 + std::abs(fieldValue(s.extent, 0, nL, unit, L)), L);
  }
  ok = w.b0 < w.b1;
  const Interval* ref = earlier.empty() ? nullptr : &earlier[s.ref % earlier.size()];
  if ((s.flags & 8) != 0 && ref != nullptr) {
    w.source = Vec2(ref->source.x() + fieldValue(s.sourceX, -nL, nL, unit, L),
                    std::abs(ref->source.y() + fieldValue(s.sourceY, -nL, nL, unit, L)));
  } else {
    w.source = Vec2(fieldValue(s.sourceX, -2 * nL, 3 * nL, unit, L),
                    std::abs(fieldValue(s.sourceY, 0, 2 * nL, unit, L)));
  }
  if ((s.flags & 16) != 0 && ref != nullptr) {
    w.sigma = std::abs(ref->sigma + fieldValue(s.sigma, -nL, nL, unit, L));
  } else {
    w.sigma = std::abs(fieldValue(s.sigma, 0, 4 * nL, unit, L));
  }
  w.side = s.flags & 1;
  w.origin = -1;
  // 0: pending; 1: propagated; 2, 3 (a half propagated): pending, as an interval grown after its
  // propagation is (an interval carries one pending bit).
  if (((s.flags >> 1) & 3) == 1) w.markPropagated();
  ok = ok && isFinite(w.source) && std::isfinite(w.sigma);
  return w;
}

std::optional<EdgeUpdateCase> makeEdgeUpdateCase(const EdgeUpdateSpec& s) {
  const double unit = unitOf(s.unitExp);
  const auto [L, nL] = edgeLengthOf(s.edgeLength, unit);
  if (!(L > 0.0)) return std::nullopt;
  EdgeUpdateCase c;
  c.edgeLength = L;
  double cursor = 0.0;
  for (const IntervalSpec& is : s.before) {
    if (cursor >= L) break;
    bool ok = false;
    Interval w = makeInterval(is, false, cursor, L, nL, unit, c.before, ok);
    if (w.b0 >= L) break;
    cursor = w.b1;
    if (!ok) continue;
    c.before.push_back(w);
  }
  bool ok = false;
  c.incoming = makeInterval(s.incoming, true, 0.0, L, nL, unit, c.before, ok);
  c.incoming.origin = -2;
  if (!ok) return std::nullopt;
  // The run's later intervals may take their source or σ from an old interval or an earlier one
  // of the run (`ref`): children of one batch often share a pseudo-source.
  std::vector<Interval> earlier = c.before;
  earlier.push_back(c.incoming);
  for (const IntervalSpec& is : s.laterIncoming) {
    Interval w = makeInterval(is, true, 0.0, L, nL, unit, earlier, ok);
    w.origin = -2;
    if (!ok) continue;  // (an empty range is no interval of the run)
    c.laterIncoming.push_back(w);
    earlier.push_back(w);
  }
  // Algorithm 2 starts from a list step 6 accepts; a list it rejects tests nothing.
  std::string why;
  if (!InvariantChecker::checkList(c.before, L, why).empty()) return std::nullopt;
  return c;
}

constexpr std::string_view kReproducerMagic = "geodex-edge-update 1";

}  // namespace

bool isEdgeUpdateReproducer(std::span<const std::uint8_t> bytes) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    pos = end + 1;
    if (line.empty() || line.front() == '#') continue;
    return line == kReproducerMagic;
  }
  return false;
}

EdgeUpdateCase parseEdgeUpdateReproducer(std::string_view text) {
  EdgeUpdateCase c;
  std::istringstream in{std::string(text)};
  std::string line;
  int lineNo = 0;
  bool sawMagic = false, sawIncoming = false, sawLength = false;
  std::string invariant, branch;
  std::size_t announced = 0;
  auto fail = [&](const std::string& what) -> void {
    throw InputError("syntax", "line " + std::to_string(lineNo) + ": " + what);
  };
  auto readInterval = [&](std::istringstream& ls) {
    Interval w;
    double sx = 0, sy = 0;
    int side = 0;
    if (!(ls >> w.b0 >> w.b1 >> sx >> sy >> w.sigma >> side)) fail("expected b0 b1 sx sy sigma side");
    w.source = Vec2(sx, sy);
    w.side = static_cast<std::uint8_t>(side != 0);
    return w;
  };
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line.front() == '#') continue;
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (!sawMagic) {
      if (line != kReproducerMagic) fail("expected '" + std::string(kReproducerMagic) + "'");
      sawMagic = true;
    } else if (key == "invariant") {
      ls >> invariant;
    } else if (key == "branch") {
      ls >> branch;
    } else if (key == "edge-length") {
      if (!(ls >> c.edgeLength)) fail("expected the edge length");
      sawLength = true;
    } else if (key == "before") {
      if (!(ls >> announced)) fail("expected the number of intervals");
    } else if (key == "interval") {
      Interval w = readInterval(ls);
      w.origin = -1;
      c.before.push_back(w);
    } else if (key == "incoming") {
      Interval w = readInterval(ls);
      w.origin = -2;
      if (sawIncoming) {
        c.laterIncoming.push_back(w);
      } else {
        c.incoming = w;
      }
      sawIncoming = true;
    } else {
      fail("unknown key '" + key + "'");
    }
  }
  if (!sawMagic) throw InputError("syntax", "not a geodex edge-update reproducer");
  if (!sawLength || !sawIncoming) throw InputError("syntax", "edge-length or incoming missing");
  if (announced != c.before.size()) {
    throw InputError("syntax", "'before " + std::to_string(announced) + "' but " +
                                   std::to_string(c.before.size()) + " interval lines");
  }
  c.note = "text reproducer: invariant " + invariant + ", branch " + branch;
  return c;
}

std::vector<Interval> incomingRun(const EdgeUpdateCase& c) {
  std::vector<Interval> run{c.incoming};
  run.insert(run.end(), c.laterIncoming.begin(), c.laterIncoming.end());
  return run;
}

std::optional<EdgeUpdateCase> decodeEdgeUpdate(std::span<const std::uint8_t> bytes) {
  if (isEdgeUpdateReproducer(bytes)) {
    try {
      EdgeUpdateCase c = parseEdgeUpdateReproducer(
          std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
      // An incoming interval off the edge, or one no propagation makes, tests nothing: a
      // negative or non-finite σ, a source off the unfolded side (y < 0) or not finite
      // (regress/*-text-reproducer-with-an-invalid-incoming-interval-was-replayed).
      if (!(c.edgeLength > 0.0)) return std::nullopt;
      for (const Interval& in : incomingRun(c)) {
        if (!(in.b0 >= 0.0 && in.b1 <= c.edgeLength && in.b0 < in.b1)) return std::nullopt;
        if (!(std::isfinite(in.sigma) && in.sigma >= 0.0 && std::isfinite(in.source.x()) &&
              std::isfinite(in.source.y()) && in.source.y() >= 0.0))
          return std::nullopt;
      }
      // As for the binary form: Algorithm 2 starts from a list step 6 accepts; a list it rejects
      // (an interval past the edge's end, two overlapping) tests nothing.
      std::string why;
      if (!InvariantChecker::checkList(c.before, c.edgeLength, why).empty()) return std::nullopt;
      return c;
    } catch (const InputError&) {
      return std::nullopt;
    }
  }
  if (bytes.size() > kMaxFuzzInputBytes) return std::nullopt;
  ByteReader r(bytes);
  return makeEdgeUpdateCase(readEdgeUpdateSpec(r));
}

// ===  Check =====================================================================================

namespace {

bool sameFunction(const Interval& a, const Interval& b) {
  return a.source == b.source && a.sigma == b.sigma && a.side == b.side && a.origin == b.origin;
}

/// The case in mesh units, as a mesh holding the edge would have it (MeshUnit): Algorithm 2
/// computes σ + √((x − s.x)² + s.y²) and runs on the solver's lengths, never on a file's
/// huge or tiny ones. Nullopt when a value would not scale exactly (it is or becomes subnormal,
/// far below anything the solver keeps).
std::optional<EdgeUpdateCase> inMeshUnits(const EdgeUpdateCase& c) {
  const MeshUnit unit = meshUnitOf(c.edgeLength);
  bool exact = true;
  auto to = [&](double& x) {
    exact = exact && scalesExactly(x, unit.inverse);
    x *= unit.inverse;
  };
  EdgeUpdateCase m = c;
  to(m.edgeLength);
  auto scale = [&](Interval& w) {
    to(w.b0), to(w.b1), to(w.source.x()), to(w.source.y()), to(w.sigma);
  };
  for (Interval& w : m.before) scale(w);
  scale(m.incoming);
  for (Interval& w : m.laterIncoming) scale(w);
  if (!exact) return std::nullopt;
  return m;
}

}  // namespace

Verdict checkEdgeUpdate(const EdgeUpdateCase& input) {
  Verdict v;
  const auto inUnits = inMeshUnits(input);
  if (!inUnits) return v.summary = "a value would be subnormal in mesh units: outside the solver's range", v;
  const EdgeUpdateCase& c = *inUnits;
  // The list must be one step 6 accepts where Algorithm 2 works, in mesh units: its checks square
  // lengths, which underflow for tiny ones, so a list can pass in one unit and not in the other.
  if (std::string why; !InvariantChecker::checkList(c.before, c.edgeLength, why).empty())
    return v.summary = "the list before breaks step 6 in mesh units: " + why, v;
  v.interesting = true;
  EdgeIntervals list;
  list.assign(c.before);
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  IntervalList work;
  const std::vector<Interval> run = incomingRun(c);
  auto caseText = [&] {
    std::ostringstream os;
    os << std::setprecision(17) << "\n  edge length " << c.edgeLength;
    for (const Interval& w : c.before) os << "\n  before   " << describeInterval(w);
    for (const Interval& w : run) os << "\n  incoming " << describeInterval(w);
    for (const Interval& w : list.intervals()) os << "\n  after    " << describeInterval(w);
    return os.str();
  };
  try {
    list.insertRun(run, c.edgeLength, report, scratch, work);
  } catch (const InternalError& e) {
    return fail(v, "internal-check", e.what() + caseText());
  } catch (const std::exception& e) {
    return fail(v, "unexpected-exception", e.what() + caseText());
  }
  v.degeneracies += report.degeneracies;
  {
    std::ostringstream os;
    os << c.before.size() << " → " << list.intervals().size() << " intervals;";
    for (std::size_t k = static_cast<std::size_t>(DegeneracyKind::D1); k < kNumDegeneracyKinds; ++k)
      if (report.degeneracies.count[k] != 0)
        os << " " << name(static_cast<DegeneracyKind>(k)) << "×" << report.degeneracies.count[k];
    v.summary = os.str();
  }
  const auto after = list.intervals();
  // Step 6: the cheap invariants and the pointwise minimum (the full tier), as the checker runs
  // them inside the solver.
  try {
    InvariantChecker checker(CheckLevel::Full, true);
    checker.onEdgeUpdate({0, c.edgeLength, c.before, run, after, report, {}});
  } catch (const InvariantViolation& e) {
    return fail(v, e.invariant(), e.what() + caseText());
  }
  // No pseudo-source invented: every interval after is a piece of one of the functions before.
  for (const Interval& w : after) {
    bool known = false;
    for (const Interval& in : run) known = known || sameFunction(w, in);
    for (const Interval& b : c.before) known = known || sameFunction(w, b);
    if (!known) return fail(v, "invented-source", "interval " + describeInterval(w) + " has a source no input had" + caseText());
  }
  // Only the slice the report names was rewritten: before and after it the list is the old one,
  // interval for interval (what makes an update cost O(log n + overlap)).
  const auto same = [](const Interval& a, const Interval& b) {
    return a.b0 == b.b0 && a.b1 == b.b1 && a.source == b.source && a.sigma == b.sigma &&
           a.side == b.side && a.origin == b.origin && a.pending() == b.pending();
  };
  if (report.first > report.last || report.last > after.size() ||
      after.size() - report.last > c.before.size() || report.first > c.before.size()) {
    return fail(v, "slice", "the rewritten range [" + std::to_string(report.first) + ", " +
                                std::to_string(report.last) + ") does not fit the lists" + caseText());
  }
  for (std::size_t i = 0; i < report.first; ++i)
    if (!same(after[i], c.before[i]))
      return fail(v, "slice", "interval " + std::to_string(i) + " before the rewritten range changed" + caseText());
  const std::size_t tail = after.size() - report.last;
  for (std::size_t i = 0; i < tail; ++i)
    if (!same(after[report.last + i], c.before[c.before.size() - tail + i]))
      return fail(v, "slice", "interval " + std::to_string(report.last + i) + " after the rewritten range changed" + caseText());
  return v;
}

// ===  Description and picture ===================================================================

void describe(const EdgeUpdateCase& c, std::ostream& out) {
  out << std::setprecision(17);
  out << "# fuzz_edge_update: Algorithm 2 merges the incoming interval into the edge's list\n";
  if (!c.note.empty()) out << "# " << c.note << "\n";
  out << "edge-length " << c.edgeLength << "\n";
  for (const Interval& w : c.before) out << "before   " << describeInterval(w) << "\n";
  for (const Interval& w : incomingRun(c)) out << "incoming " << describeInterval(w) << "\n";
}

void writeSvg(const EdgeUpdateCase& c, std::ostream& out) {
  EdgeIntervals list;
  list.assign(c.before);
  EdgeUpdateReport report;
  std::vector<Interval> scratch;
  IntervalList work;
  const std::vector<Interval> run = incomingRun(c);
  std::string error;
  try {
    list.insertRun(run, c.edgeLength, report, scratch, work);
  } catch (const std::exception& e) {
    error = e.what();
  }
  const std::vector<Interval> after(list.intervals().begin(), list.intervals().end());
  const double L = c.edgeLength;
  double dmin = INFINITY, dmax = -INFINITY;
  auto span = [&](const Interval& w) {
    for (int k = 0; k <= 32; ++k) {
      const double d = w.distanceAt(w.b0 + (w.b1 - w.b0) * k / 32);
      dmin = std::min(dmin, d), dmax = std::max(dmax, d);
    }
  };
  for (const Interval& w : c.before) span(w);
  for (const Interval& w : run) span(w);
  for (const Interval& w : after) span(w);
  SvgDoc doc(900, 900);
  SourceColours colour;
  const char* titles[] = {"before", "incoming", "after Algorithm 2"};
  const std::vector<Interval> rows[] = {c.before, run, after};
  for (int row = 0; row < 3; ++row) {
    Panel P(60, 50 + row * 180, 820, 150, 0.0, dmin, L, dmax, false);
    doc.line(P, Vec2(0, dmin), Vec2(L, dmin), "#999", 1);
    doc.labelPx(10, 45 + row * 180, titles[row], 13);
    doc.labelPx(5, 50 + row * 180 + 150, shortNum(dmin), 10, "#666");
    doc.labelPx(5, 62 + row * 180, shortNum(dmax), 10, "#666");
    for (const Interval& w : rows[row]) {
      std::vector<Vec2> pts;
      for (int k = 0; k <= 48; ++k) {
        const double x = w.b0 + (w.b1 - w.b0) * k / 48;
        pts.emplace_back(x, w.distanceAt(x));
      }
      doc.polyline(P, pts, colour(w), row == 2 ? 3 : 2, row == 1);
      doc.line(P, Vec2(w.b0, dmin), Vec2(w.b1, dmin), colour(w), 5);
    }
  }
  // The edge and the pseudo-sources (drawn below the edge, where they unfold).
  double x0 = 0, x1 = L, y0 = -0.2 * L, y1 = 0.05 * L;
  std::vector<Interval> all = c.before;
  all.insert(all.end(), run.begin(), run.end());
  for (const Interval& w : all) {
    if (w.source.norm() > 6 * L) continue;
    x0 = std::min(x0, w.source.x()), x1 = std::max(x1, w.source.x()), y0 = std::min(y0, -w.source.y());
  }
  Panel G(60, 600, 820, 250, x0, y0, x1, y1, true);
  doc.line(G, Vec2(0, 0), Vec2(L, 0), "#000", 2);
  for (const Interval& w : all) {
    const Vec2 s(w.source.x(), -w.source.y());
    if (w.source.norm() > 6 * L) continue;
    doc.line(G, s, Vec2(w.b0, 0), colour(w), 1, true);
    doc.line(G, s, Vec2(w.b1, 0), colour(w), 1, true);
    doc.dot(G, s, 4, colour(w));
    doc.label(G, s, "σ=" + shortNum(w.sigma), 10, colour(w));
  }
  doc.labelPx(10, 595, "edge [0, " + shortNum(L) + "] and pseudo-sources (unfolded below it; far ones omitted)", 12);
  doc.labelPx(10, 20, "fuzz_edge_update: distance functions coloured by pseudo-source" +
                          (error.empty() ? std::string() : "; insert threw: " + error), 14);
  doc.write(out);
}

// ===  Seeds =====================================================================================

namespace {

using Q = Quantity;
using K = DegeneracyKind;
Q n(int v) { return Q::lattice(v); }

IntervalSpec iv(Q start, Q extent, Q sx, Q sy, Q sigma, std::uint8_t flags = 0, std::uint8_t ref = 0) {
  IntervalSpec s;
  s.start = start, s.extent = extent, s.sourceX = sx, s.sourceY = sy, s.sigma = sigma;
  s.flags = flags, s.ref = ref;
  return s;
}

/// A seed that must hit every one of `kinds` (Algorithm 2's D1–D4 reports).
/// `later`: the rest of a run merged with `incoming` (EdgeIntervals::insertRun).
Seed edgeUpdate(const std::string& name, std::initializer_list<K> kinds, int L,
                std::vector<IntervalSpec> before, IntervalSpec incoming, int unitExp = 0,
                std::vector<IntervalSpec> later = {}) {
  EdgeUpdateSpec s;
  s.unitExp = static_cast<std::int8_t>(unitExp);
  s.edgeLength = n(L);
  s.before = std::move(before);
  s.incoming = incoming;
  s.laterIncoming = std::move(later);
  return {name, encode(s), [want = std::vector<K>(kinds)](const FuzzCase&, const Verdict& v) {
            return kindsNotHit(v, want);
          }};
}

}  // namespace

std::vector<Seed> edgeUpdateSeeds() {
  constexpr std::uint8_t kPropagated = 2, kFirstHalf = 4, kSecondHalf = 6, kRelSource = 8, kRelSigma = 16;
  const Q zero = n(0);
  // Edge of 16 lattice units. Old intervals: (gap before, length, source x, y, σ). Incoming:
  // (b0, b1, source x, y, σ). ε = 1e-11 × 16 here (sources within 16 of the edge).
  const auto left = iv(zero, n(8), n(4), n(2), zero, kPropagated);
  const auto right = iv(zero, n(8), n(12), n(2), zero, kPropagated);
  // A sliver a hair shorter than both neighbours where they meet (√20 at x = 8), as the rounding
  // D1 stands for: a sliver far below them is a distance they lack, and step 3 keeps it.
  const Q justBelow = Q::exact(std::sqrt(20.0) * (1.0 - 1e-13));
  return {
      edgeUpdate("D1-tiny-sliver-won-by-incoming", {K::D1}, 16, {left, right},
                 iv(n(8), n(8).nudged(2, Nudge::TinyInterval, true), n(8), justBelow, zero)),
      edgeUpdate("D1-tiny-remainder-of-split-old-interval", {K::D1}, 16, {left, right},
                 iv(n(0), n(8).nudged(-2, Nudge::TinyInterval, true), n(4), n(1), zero)),
      edgeUpdate("D2-tiny-overlap-at-incoming-start", {K::D2}, 16, {left},
                 iv(n(8).nudged(-3, Nudge::TinyInterval, true), n(16), n(12), n(2), zero)),
      edgeUpdate("D2-tiny-overlap-at-incoming-end", {K::D2}, 16,
                 {iv(n(8), n(8), n(12), n(2), zero)},
                 iv(n(0), n(8).nudged(3, Nudge::TinyInterval, true), n(4), n(2), zero)),
      edgeUpdate("D3-tiny-gap-between-neighbours", {K::D3}, 16, {left},
                 iv(n(8).nudged(3, Nudge::TinyInterval, true), n(16), n(12), n(2), zero)),
      edgeUpdate("D3-tiny-gap-at-edge-start", {K::D3}, 16, {},
                 iv(n(0).nudged(3, Nudge::TinyInterval, true), n(16), n(12), n(2), zero)),
      edgeUpdate("D3-tiny-gaps-at-both-edge-ends", {K::D3}, 16, {},
                 iv(n(0).nudged(3, Nudge::TinyInterval, true),
                    n(16).nudged(-3, Nudge::TinyInterval, true), n(8), n(2), zero)),
      // D4: a pseudo-source near the edge with a large σ against a far one with σ = 0: Eq. 1's
      // coefficients cancel (c² ~ 1e11) and its root is off (tests/unit/edge_intervals_test.cpp).
      edgeUpdate("D4-far-source-against-near-source-large-sigma", {K::D4}, 10,
                 {iv(zero, n(10), Q::exact(106679.50483344488).times8(5),
                     Q::exact(350837.94985744485).times8(5), zero)},
                 iv(n(0), n(10), Q::exact(0.02921229530964543), Q::exact(0.031554045793446041),
                    Q::exact(366698.19360690453).times8(5))),
      edgeUpdate("D1-tiny-incoming-inside-old-interval", {K::D1}, 16, {left, right},
                 iv(n(8).nudged(2, Nudge::TinyInterval, true),
                    n(8).nudged(4, Nudge::TinyInterval, true), n(8), Q::exact(1e-3), zero)),
      edgeUpdate("D2-D3-overlap-one-end-gap-other", {K::D2, K::D3}, 16,
                 {iv(zero, n(4), n(2), n(2), zero), iv(n(8), n(4), n(14), n(2), zero)},
                 iv(n(4).nudged(-3, Nudge::TinyInterval, true),
                    n(12).nudged(-3, Nudge::TinyInterval, true), n(6), n(2), zero)),
      // A near window next to a real gap (2e-10, above ε = 1e-10) becomes a D1 sliver of a far
      // window's ray end (1e6 away: 1e-8) when that window replaces its other neighbour, and goes
      // to it; the gap, now beside the far window, is below its sewing length and is sewn (D3),
      // though it lies outside the range the incoming interval reaches
      // (Algorithm2.AGapBesideTheUpdateIsSewnWhenTheIntervalNextToItGoesToACoarserWindow).
      edgeUpdate(
          "D1-D3-sliver-beside-the-update-goes-to-a-far-window-and-its-gap-is-sewn", {K::D1, K::D3},
          10,
          {iv(zero, Q::exact(5.0 - 2e-10), n(2), n(1), Q::exact(999996.8377223398).times8(6)),
           iv(Q::exact(2e-10), Q::exact(1e-9), n(5), n(2), Q::exact(999998.0).times8(6)),
           iv(zero, n(10), n(5), n(1), Q::exact(999999.0).times8(6))},
          iv(Q::exact(5.0 + 1e-9), n(10), n(5), Q::exact(1e6).times8(6), zero)),
      // Algorithm 2 without degeneracies, for contrast and for the fuzzer to mutate from.
      edgeUpdate("empty-list-whole-edge", {}, 16, {}, iv(n(0), n(16), n(8), n(4), zero)),
      edgeUpdate("incoming-wins-everywhere", {}, 16,
                 {iv(zero, n(16), n(8), n(8), n(4), kPropagated)},
                 iv(n(0), n(16), n(8), n(2), zero)),
      edgeUpdate("incoming-loses-everywhere", {}, 16,
                 {iv(zero, n(16), n(8), n(2), zero, kPropagated)},
                 iv(n(0), n(16), n(8), n(8), n(4))),
      edgeUpdate("eq1-two-crossings", {}, 16, {iv(zero, n(16), n(8), n(8), zero, kPropagated)},
                 iv(n(0), n(16), n(8), n(1), n(5))),
      edgeUpdate("eq1-one-crossing-sources-either-side", {}, 16,
                 {iv(zero, n(16), n(0), n(4), zero, kPropagated)},
                 iv(n(0), n(16), n(16), n(4), zero)),
      edgeUpdate("incoming-fills-gap-between-two", {}, 16,
                 {iv(zero, n(4), n(2), n(2), zero, kPropagated),
                  iv(n(8), n(4), n(14), n(2), zero, kPropagated)},
                 iv(n(2), n(14), n(8), n(3), zero)),
      edgeUpdate("same-source-arrives-again", {}, 16,
                 {iv(zero, n(16), n(5), n(2), n(1), kPropagated)},
                 iv(n(0), n(16), n(5), n(2), n(1))),
      edgeUpdate("near-equal-source-merged-by-step5", {}, 16,
                 {iv(zero, n(6), n(5), n(2), n(1), kPropagated)},
                 iv(n(6), n(16), n(0).nudged(2, Nudge::SameSource, true),
                    n(0).nudged(2, Nudge::SameSource, true),
                    n(0).nudged(2, Nudge::SameSource, true), kRelSource | kRelSigma, 0)),
      edgeUpdate("tie-equal-distances-different-sources", {}, 16,
                 {iv(zero, n(16), n(4), n(3), n(2), kPropagated)},
                 iv(n(0), n(16), n(4), n(3), n(2), 1)),
      edgeUpdate("partially-propagated-intervals-split", {}, 16,
                 {iv(zero, n(8), n(4), n(4), zero, kFirstHalf),
                  iv(zero, n(8), n(12), n(4), zero, kSecondHalf)},
                 iv(n(4), n(12), n(8), n(1), n(2))),
      edgeUpdate("eight-contiguous-intervals", {}, 16,
                 {iv(zero, n(2), n(1), n(1), zero), iv(zero, n(2), n(3), n(1), zero),
                  iv(zero, n(2), n(5), n(1), zero), iv(zero, n(2), n(7), n(1), zero),
                  iv(zero, n(2), n(9), n(1), zero), iv(zero, n(2), n(11), n(1), zero),
                  iv(zero, n(2), n(13), n(1), zero), iv(zero, n(2), n(15), n(1), zero)},
                 iv(n(0), n(16), n(8), n(2), zero)),
      edgeUpdate("large-sigma-far-sources-scaled-1e+6", {}, 16,
                 {iv(zero, n(16), n(-32).times8(6), n(32).times8(6), zero, kPropagated)},
                 iv(n(0), n(16), n(8), n(2), n(64).times8(5)), 20),
      edgeUpdate("tiny-edge-scaled-1e-6", {K::D1}, 16, {left, right},
                 iv(n(8), n(8).nudged(2, Nudge::TinyInterval, true), n(8), justBelow, zero), -20),
      // Runs: the children one batch of windows sends to an edge, merged by one update. A later
      // child meets the earlier ones' pieces as old intervals (steps 1 and 2); steps 3–5 repair
      // once, after the last.
      edgeUpdate("run-D2-later-child-overlaps-an-earlier-one-by-a-hair", {K::D2}, 16, {},
                 iv(n(0), n(8), n(4), n(2), zero), 0,
                 {iv(n(8).nudged(-3, Nudge::TinyInterval, true), n(16), n(12), n(2), zero)}),
      edgeUpdate("run-D3-later-child-leaves-a-hair-gap-to-an-earlier-one", {K::D3}, 16, {},
                 iv(n(0), n(8), n(4), n(2), zero), 0,
                 {iv(n(8).nudged(3, Nudge::TinyInterval, true), n(16), n(12), n(2), zero)}),
      edgeUpdate("run-D1-later-child-cuts-a-sliver-off-an-earlier-one", {K::D1}, 16, {},
                 iv(n(0), n(8), n(4), n(2), zero), 0,
                 {iv(n(8), n(16), n(12), n(2), zero),
                  iv(n(0), n(8).nudged(-2, Nudge::TinyInterval, true), n(4), n(1), zero)}),
      edgeUpdate("run-three-children-of-one-source-joined-by-step5", {}, 16, {},
                 iv(n(0), n(5), n(8), n(3), zero), 0,
                 {iv(n(5), n(11), n(8), n(3), zero), iv(n(11), n(16), n(8), n(3), zero)}),
      edgeUpdate("run-two-crossing-children-over-an-old-window", {}, 16,
                 {iv(zero, n(16), n(8), n(8), n(4), kPropagated)},
                 iv(n(0), n(10), n(4), n(2), zero), 0, {iv(n(6), n(16), n(12), n(2), zero)}),
      // Algorithm 2 step 1 resolves an overlap below ε (D2) where overlapMeetingPoint says (the
      // shorter interval keeps a real overlap), not at the midpoint whichever function is smaller
      // there: at the midpoint this list keeps the larger distance and breaks the pointwise
      // minimum.
      {.name = "pointwise-min-D2-overlap-midpoint-keeps-larger-distance",
       .bytes = encode(EdgeUpdateSpec{
           .edgeLength = n(16),
           .before = {iv(n(0), n(4), n(2), n(2), n(0))},
           .incoming = iv(n(4).nudged(-3, Nudge::TinyInterval, true), n(16), n(8), n(2), n(0)),
           .laterIncoming = {}}),
       .expect = {},
       .dir = "regress"},
  };
}

}  // namespace geodex::verify
