#pragma once
// Two solves that must be one and the same, compared to the bit: a solve on one thread and on two
// (SolveOptions::threads: the rounds are the same), a solver solving again and a fresh one. The
// invariant checker's comparison of a list before and after an update is another (it reads what
// the invariants read); this one is for everything a solve gives.

#include <string>

#include "geodex/geodesic_solver.h"

namespace geodex::verify {

/// Where solve `b` first differs from solve `a`: a vertex distance, a count of SolveStats or of
/// DegeneracyCounters, or, with `lists`, the length of an edge's list or one of its intervals
/// (every field, doubles by their bits); "" when they are the same. `lists` needs both solves to
/// have kept their lists (not SolveOptions::vertexDistancesOnly).
std::string firstDifference(const GeodesicSolver& a, const GeodesicSolver& b, bool lists);

}  // namespace geodex::verify
