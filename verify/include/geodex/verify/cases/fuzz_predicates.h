#pragma once
// fuzz_predicates: one Fig. 6 decision (propagateLocal) on a local configuration of Fig. 3
// snapped to a lattice and nudged by multiples of the tolerances, so that G1–G5 and their
// composites are common. Checks: the branch equals the Fig. 6 tree evaluated exactly (GMP
// rationals) wherever each predicate on the path is clearly decided (its value ≤ ε/10 or
// ≥ 11 ε); children's ranges in [0, 1], t0 ≤ t1; the same window at unit scale is decided alike,
// bit for bit; every ray of the wedge that enters the face leaves it inside a child (coverage)
// and every child point is seen from s through [b0, b1] (soundness), up to an angle of 100 × the
// tolerances. Its libFuzzer main is fuzz/fuzz_predicates.cpp.

#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <vector>

#include "geodex/propagate.h"
#include "geodex/verify/cases/byte_codec.h"
#include "geodex/verify/cases/fuzz_target.h"

namespace geodex::verify {

/// The bytes: the local configuration of Fig. 3 (propagate.h), field by field.
struct PredicateSpec {
  std::int8_t unitExp = 0;
  Quantity edgeLength;       ///< L ∈ [1, 64]; nudges relative to the lattice length
  Quantity apexX, apexY;     ///< v1: x ∈ [−2 nL, 3 nL], y ∈ [0, 2 nL] (|y| taken)
  Quantity b0, b1;           ///< ∈ [0, nL], swapped if reversed, clamped to [0, L]
  Quantity sourceX, sourceY; ///< s: x ∈ [−4 nL, 5 nL], y ∈ [−4 nL, 0] (−|y| taken)
  // Nudges of every field are relative to L.
};

std::vector<std::uint8_t> encode(const PredicateSpec& s);

struct PredicateCase {
  LocalWindow window;
};

/// The case the bytes describe, or nullopt when the target skips them: too long, or a window
/// that is empty ([b0, b1] of no length) or not finite.
std::optional<PredicateCase> decodePredicates(std::span<const std::uint8_t> bytes);

Verdict checkPredicates(const PredicateCase& c);

/// The configuration, propagateLocal's branch and children, and the exact tree's branch.
void describe(const PredicateCase& c, std::ostream& out);
/// The face, the window, its wedge and the children (local_window.h's picture).
void writeSvg(const PredicateCase& c, std::ostream& out);

/// The committed corpus (corpus/fuzz_predicates/): one or more seeds per Fig. 6 branch, G1–G5
/// and their composites, each named after the branch it must end in, and the regress files
/// that can be described.
std::vector<Seed> predicateSeeds();

}  // namespace geodex::verify
