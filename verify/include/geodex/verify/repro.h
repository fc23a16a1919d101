#pragma once
// The fuzz cases and their reproducers: what a corpus file means, for any of the six libFuzzer
// targets in fuzz/, and the functions `geodex repro FILE [--target T] [--svg OUT]` is made of.
// Everything a corpus file means is defined in verify/ (not in fuzz/), so that a reproducer can
// be read, described, re-checked and drawn without the fuzzers.
//
//   std::vector<std::uint8_t> bytes = readFileBytes(path);
//   std::optional<FuzzTarget> t = detectTarget(path, bytes);   // or parseFuzzTarget("fuzz_solver")
//   describe(*t, bytes, std::cout);                             // the case, readable
//   Verdict v = replay(*t, bytes);                              // every check on
//   if (!v.ok()) std::cout << v.failed << ": " << v.message << "\n";
//   writeSvg(*t, bytes, svgStream);                             // the local configuration
//
// or all of it in one call: `return runRepro(path, target, svgPath, std::cout);`.
//
// Each target's byte format, decoder, check, description, picture and seeds are in its own
// header, which this one includes (docs/fuzzing.md has the byte layouts side by side):
//   fuzz_mesh_io      cases/fuzz_mesh_io.h      a file through the readers and the validator
//   fuzz_predicates   cases/fuzz_predicates.h   one Fig. 6 decision against the exact tree
//   fuzz_edge_update  cases/fuzz_edge_update.h  one Algorithm 2 update
//   fuzz_propagation  cases/fuzz_propagation.h  one window across one face
//   fuzz_two_faces    cases/fuzz_two_faces.h    a source across two faces
//   fuzz_solver       cases/fuzz_solver.h       a whole solve on a small mesh
// and what they share: cases/fuzz_target.h (FuzzTarget, Verdict, Seed), cases/byte_codec.h (the
// bytes), cases/source_spec.h (a source point of the two mesh targets).
//
// Link: the implementation uses GMP (exact predicates): link `gmpxx gmp` with geodex_verify when
// calling anything declared here.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "geodex/verify/cases/byte_codec.h"
#include "geodex/verify/cases/fuzz_edge_update.h"
#include "geodex/verify/cases/fuzz_mesh_io.h"
#include "geodex/verify/cases/fuzz_predicates.h"
#include "geodex/verify/cases/fuzz_propagation.h"
#include "geodex/verify/cases/fuzz_solver.h"
#include "geodex/verify/cases/fuzz_target.h"
#include "geodex/verify/cases/fuzz_two_faces.h"
#include "geodex/verify/cases/source_spec.h"

namespace geodex::verify {

// === Decoding and checking =====================================================================

/// The case the bytes describe, or nullopt when the target skips them (too long, or a shape the
/// target does not test: a degenerate range, a mesh the validator refuses, an invalid old list).
std::optional<FuzzCase> decode(FuzzTarget t, std::span<const std::uint8_t> bytes);

/// Runs the target's checks on a decoded case, every one of them, the fuzz targets too: the full
/// invariant tier costs fuzz_solver 2.9x the cheap tier's time and buys the pointwise minimum at
/// every edge update and the end-of-solve coverage and vertex agreement. Never throws: an
/// exception from the code under test is a failed check ("unexpected-exception", or the
/// invariant an InvariantViolation names).
Verdict check(const FuzzCase& c);

/// decode + check. Skipped bytes give an uninteresting passing verdict.
Verdict replay(FuzzTarget t, std::span<const std::uint8_t> bytes);

/// The target's committed corpus as readable descriptions (predicateSeeds(), …), which
/// fuzz/make_seeds writes and checks.
std::vector<Seed> seeds(FuzzTarget t);

// === Reproducers ===============================================================================

/// The whole file (throws InputError if it cannot be read).
std::vector<std::uint8_t> readFileBytes(const std::string& path);

/// Which target a file belongs to: a path component named after a target (corpus/<target>/…,
/// build/fuzz-findings/<target>/…), else the content (a text edge-update reproducer →
/// fuzz_edge_update; an OFF/OBJ/PLY file → fuzz_mesh_io). nullopt when neither tells.
std::optional<FuzzTarget> detectTarget(const std::string& path, std::span<const std::uint8_t> bytes);

/// Prints the case readably: the local configuration, the interval lists, or the mesh as a tiny
/// OFF followed by `source SPEC` lines (SPEC as the CLI's --source takes it).
void describe(FuzzTarget t, std::span<const std::uint8_t> bytes, std::ostream& out);

/// Draws the case as a plain SVG: predicates — the unfolded face, e0, the window, the wedge from
/// s and the children on e1/e2; edge updates — the pseudo-sources and the distance functions of
/// the list before, the incoming interval and the list after, coloured by pseudo-source;
/// propagation — the face and the source unfolded into one plane, the window, its wedge and the
/// child intervals; two faces — both faces unfolded into one plane, the source and the intervals
/// after the solve, coloured by pseudo-source; solver and mesh files — the mesh projected onto
/// its two widest axes with sources and vertex distances.
void writeSvg(FuzzTarget t, std::span<const std::uint8_t> bytes, std::ostream& out);

/// `geodex repro FILE [--target T] [--svg OUT]` in one call: detects (or takes) the target,
/// describes the case, replays it with every check on, prints the verdict, writes the SVG when
/// asked. Returns 0 when every check passes, 1 when one fails, 2 when the target is unknown or
/// the file unreadable (with a message on `out`).
int runRepro(const std::string& path, std::optional<FuzzTarget> target,
             const std::optional<std::string>& svgPath, std::ostream& out);

}  // namespace geodex::verify
