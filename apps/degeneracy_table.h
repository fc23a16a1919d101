#pragma once
// The degeneracy table of a solve, laid out as Liu, Zhou & Hu 2007, Table 1: how often each
// enumerated case occurred, as a count and as a share of all propagation cases, the Fig. 6
// degeneracy rate (G1–G5 over all cases) and the degenerate-case rate (cases with any G or D:
// the closest reading of the paper's Table 1, docs/paper.md). Used by `geodex distance --stats`
// and the demo.

#include <iosfwd>

#include "geodex/degeneracy.h"

namespace geodex::cli {

/// Writes the table, one row per kind G1..G5, D1..D4, then the rate lines
///   Fig. 6 degeneracy rate (G1–G5 over all propagation cases, …): X%
///   degenerate-case rate (cases with a G1–G5 leaf or a D1–D4 repair; …): Y%
/// and the mesh-level cases the paper leaves out (zero-area faces, sources on an edge's line).
void writeDegeneracyTable(std::ostream& out, const DegeneracyCounters& counters);

}  // namespace geodex::cli
