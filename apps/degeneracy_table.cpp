#include "degeneracy_table.h"

#include <array>
#include <cstdio>
#include <ostream>
#include <string>

namespace geodex::cli {

namespace {

/// One line per kind, in our words (DESIGN.md; the paper's Sect. 3.1 and 3.2).
constexpr std::array<const char*, kNumDegeneracyKinds> kDescriptions{
    "pseudo-source on the window's edge line (s = b0 or s = b1)",
    "s, b0 and the apex collinear",
    "s, b1 and the apex collinear",
    "s, b0 = v0 and the apex collinear",
    "s, b1 = v2 and the apex collinear",
    "tiny interval removed",
    "overlapping neighbours resolved",
    "tiny gap between neighbours sewn",
    "distance mismatch at a shared endpoint repaired",
};

std::string percent(std::uint64_t count, std::uint64_t total) {
  if (total == 0) return "n/a";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f%%", 100.0 * static_cast<double>(count) /
                                                     static_cast<double>(total));
  return buffer;
}

}  // namespace

void writeDegeneracyTable(std::ostream& out, const DegeneracyCounters& counters) {
  char line[160];
  std::snprintf(line, sizeof line, "%-4s %14s %10s  %s\n", "case", "count", "share", "meaning");
  out << line;
  for (std::size_t i = 0; i < kNumDegeneracyKinds; ++i) {
    const auto kind = static_cast<DegeneracyKind>(i);
    std::snprintf(line, sizeof line, "%-4s %14llu %10s  %s\n", std::string(name(kind)).c_str(),
                  static_cast<unsigned long long>(counters[kind]),
                  percent(counters[kind], counters.cases).c_str(), kDescriptions[i]);
    out << line;
  }
  std::snprintf(line, sizeof line, "%-4s %14llu\n", "all",
                static_cast<unsigned long long>(counters.cases));
  out << line;
  out << "Fig. 6 degeneracy rate (G1–G5 over all propagation cases, geodex's tolerances): "
      << percent(counters.geometricTotal(), counters.cases) << '\n';
  out << "degenerate-case rate (cases with a G1–G5 leaf or a D1–D4 repair at their children; the "
         "paper's Table 1 read this way, docs/paper.md): "
      << percent(counters.degenerateCases, counters.cases) << '\n';
  out << "mesh-level cases: " << counters.zeroAreaFaces << " windows through zero-area faces, "
      << counters.sourceOnEdgeLineOutside << " with the source on the edge's line outside, "
      << counters.childEdgesSeenFromOutside << " child edges seen from outside the face\n";
  out << "D1 at a vertex: " << counters.d1FansRelayed
      << " vertices relaying the fan of a sliver removed there\n";
  out << "G2-G5 at an apex: " << counters.apexFansRelayed
      << " vertices relaying the fan beyond a window's ray through them\n";
  out << "tie strips kept: " << counters.tieStripsKept
      << " strips won by the tie rule only inside another window, left to it\n";
}

}  // namespace geodex::cli
