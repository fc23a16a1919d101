#pragma once
// The Fig. 6 decision evaluated exactly: the same double inputs, converted to GMP rationals, with
// every ε of the floating-point tree set to zero. Where a configuration is farther than a few ε
// from every decision boundary the two trees must agree; closer than that the ε decision is a
// choice (the paper's "consistent" degenerate handling), not something exact arithmetic can judge.

#include "geodex/propagate.h"

namespace geodex::verify {

struct ExactFig6 {
  Fig6Branch branch;  ///< the leaf the exact tree reaches
  /// How far the configuration is from ambiguity: the smallest, over the predicates the tree
  /// evaluated, of |value| / its ε (both as the floating-point tree scales them). Above ~10 the
  /// floating-point decision must equal `branch`.
  double margin;
};

/// Runs the decision tree of propagateLocal() with exact predicates.
ExactFig6 exactFig6(const LocalWindow& w);

}  // namespace geodex::verify
