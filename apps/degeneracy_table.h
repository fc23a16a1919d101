#pragma once
// The degeneracy table of a solve, laid out as Liu, Zhou & Hu 2007, Table 1: how often each
// enumerated case occurred, as a count and as a share of all propagation cases, and the Fig. 6
// degeneracy rate (G1–G5 over all cases; not the paper's rate, see README "Degeneracies"). Used by
// `geodex distance --stats` and the demo.

#include <iosfwd>

#include "geodex/degeneracy.h"

namespace geodex::cli {

/// Writes the table, one row per kind G1..G5, D1..D4, then the rate line
///   Fig. 6 degeneracy rate (G1–G5 over all propagation cases, …): X%
/// and the mesh-level cases the paper leaves out (zero-area faces, sources on an edge's line).
void writeDegeneracyTable(std::ostream& out, const DegeneracyCounters& counters);

}  // namespace geodex::cli
