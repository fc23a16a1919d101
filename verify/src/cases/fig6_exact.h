#pragma once
// The Fig. 6 decision tree on exact rationals (GMP), as fuzz_predicates and fuzz_propagation
// judge propagateLocal's branch: a predicate "q ≤ k√S2" is clearly true below a tenth of its
// tolerance and clearly false beyond 11 times it; between the two the ε-decision may go either
// way, and the tree gives no branch. (exact_predicates.h's exactFig6, for `geodex check`, gives
// a margin instead of this clear/near verdict.)

#include <optional>
#include <string>

#include "geodex/propagate.h"

namespace geodex::verify::detail {

struct ExactFig6 {
  std::optional<Fig6Branch> branch;  ///< nullopt: a predicate on the path is near its boundary
  std::string nearWhat;              ///< which predicate, when branch is nullopt
};

/// The Fig. 6 tree on exact rationals, through a double filter where that is certain. A
/// configuration with a non-finite value has no exact decision (GMP raises SIGFPE on one).
ExactFig6 exactFig6(const LocalWindow& w);

}  // namespace geodex::verify::detail
