#include "geodex/verify/same_solve.h"

#include <cstring>
#include <string>

namespace geodex::verify {
namespace {

// Bits, not values: -0.0 against 0.0, or one NaN against another, is a difference.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameInterval(const Interval& a, const Interval& b) {
  return sameBits(a.b0, b.b0) && sameBits(a.b1, b.b1) && sameBits(a.source.x(), b.source.x()) &&
         sameBits(a.source.y(), b.source.y()) && sameBits(a.sigma, b.sigma) &&
         a.origin == b.origin && a.side == b.side && a.flags == b.flags && a.regrown == b.regrown;
}

std::string firstStatDifference(const SolveStats& s1, const SolveStats& s2) {
  if (s1.intervalsCreated != s2.intervalsCreated) return "intervalsCreated";
  if (s1.intervalsPropagated != s2.intervalsPropagated) return "intervalsPropagated";
  if (s1.pseudoSourceEvents != s2.pseudoSourceEvents) return "pseudoSourceEvents";
  if (s1.maxIntervalsPerEdge != s2.maxIntervalsPerEdge) return "maxIntervalsPerEdge";
  if (s1.intervalsAtEnd != s2.intervalsAtEnd) return "intervalsAtEnd";
  if (s1.shadowsClosed != s2.shadowsClosed) return "shadowsClosed";
  if (s1.windowsDroppedAtEdgeEnd != s2.windowsDroppedAtEdgeEnd) return "windowsDroppedAtEdgeEnd";
  if (s1.windowsDroppedAlongEdge != s2.windowsDroppedAlongEdge) return "windowsDroppedAlongEdge";
  if (s1.edgesReleased != s2.edgesReleased) return "edgesReleased";
  if (s1.releaseUndone != s2.releaseUndone) return "releaseUndone";
  if (s1.batchesBesideTheFront != s2.batchesBesideTheFront) return "batchesBesideTheFront";
  if (!sameBits(s1.radius, s2.radius)) return "radius";
  return "";
}

}  // namespace

std::string firstDifference(const GeodesicSolver& a, const GeodesicSolver& b, bool lists) {
  const auto d1 = a.vertexDistancesInMeshUnits(), d2 = b.vertexDistancesInMeshUnits();
  if (d1.size() != d2.size()) return "vertex count";
  for (std::size_t v = 0; v < d1.size(); ++v)
    if (!sameBits(d1[v], d2[v])) return "distance of vertex " + std::to_string(v);
  if (std::string stat = firstStatDifference(a.stats(), b.stats()); !stat.empty()) return stat;
  const DegeneracyCounters &c1 = a.counters(), &c2 = b.counters();
  if (c1.count != c2.count || c1.cases != c2.cases || c1.degenerateCases != c2.degenerateCases ||
      c1.zeroAreaFaces != c2.zeroAreaFaces ||
      c1.sourceOnEdgeLineOutside != c2.sourceOnEdgeLineOutside ||
      c1.childEdgesSeenFromOutside != c2.childEdgesSeenFromOutside ||
      c1.d1FansRelayed != c2.d1FansRelayed || c1.apexFansRelayed != c2.apexFansRelayed ||
      c1.tieStripsKept != c2.tieStripsKept)
    return "degeneracy counters";
  if (!lists) return "";
  const auto e1 = a.edgeIntervals(), e2 = b.edgeIntervals();
  if (e1.size() != e2.size()) return "edge count";
  for (std::size_t e = 0; e < e1.size(); ++e) {
    const auto l1 = e1[e].intervals(), l2 = e2[e].intervals();
    if (l1.size() != l2.size()) return "list length of edge " + std::to_string(e);
    for (std::size_t i = 0; i < l1.size(); ++i)
      if (!sameInterval(l1[i], l2[i]))
        return "interval " + std::to_string(i) + " of edge " + std::to_string(e);
  }
  return "";
}

}  // namespace geodex::verify
