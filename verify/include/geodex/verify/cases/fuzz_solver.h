#pragma once
// fuzz_solver: a whole solve on a small mesh (≤ 64 faces: a height field on a grid with holes,
// moved vertices and steps, or a soup of lattice points; coplanar faces, 2π vertices, collinear
// rays, zero-area faces, several components are frequent) from 1–3 sources on vertices, edges or
// faces. Checks: the full InvariantChecker and the unfolding check during the solve; Euclidean
// lower bound, edge-graph Dijkstra upper bound, Lipschitz along edges, edge-midpoint queries
// within their bounds, path length = distance; planar meshes agree with the Euclidean (convex)
// or planar-domain distance to 1e-9 × diagonal; optionally a stop distance, targets and
// d(a, b) = d(b, a).
// Its libFuzzer main is fuzz/fuzz_solver.cpp.

#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <vector>

#include "geodex/mesh.h"
#include "geodex/surface_point.h"
#include "geodex/verify/cases/byte_codec.h"
#include "geodex/verify/cases/fuzz_target.h"
#include "geodex/verify/cases/source_spec.h"

namespace geodex::verify {

// What a case may ask for (the fuzzing budget, docs/fuzzing.md): the decoder caps each, so that
// every input runs in bounded time.
inline constexpr int kMaxFuzzFaces = 64;          ///< faces of a mesh
inline constexpr int kMaxFuzzGridCells = 32;      ///< cells of a grid: 2 faces per cell
inline constexpr int kMaxFuzzSoupPoints = 24;     ///< points of a lattice soup
inline constexpr int kMaxFuzzSources = 3;

/// The bytes: a small mesh and its sources.
struct SolverSpec {
  std::int8_t unitExp = 0;
  std::uint8_t mode = 0;  ///< mod 2: 0 height field on a grid, 1 lattice soup
  // --- mode 0: a grid of nx × ny cells (1 + byte mod 8 each, ny cut so nx·ny ≤ 32)
  std::uint8_t nx = 1, ny = 1;
  std::uint8_t levels = 0;  ///< z ∈ [0, max(1, levels mod 5)): 0 and 1 are flat
  std::uint8_t zStep = 0;   ///< mod 4: z unit = 1, 1/2, 2, 1/4 × the lattice unit
  /// One byte per vertex ((nx+1)(ny+1), row by row): bits 0–3 level (mod levels); bits 4–5 and
  /// 6–7 move the vertex by {0, +1/2, −1/2, 0} cell in x and y (collinear, zero-area and
  /// needle faces).
  std::vector<std::uint8_t> vertexBytes;
  /// One byte per cell: bit 0 the other diagonal, bit 1 the cell is removed (holes,
  /// disconnected parts, unreferenced vertices).
  std::vector<std::uint8_t> cellBytes;
  // --- mode 1: a soup of lattice points (count 3 + byte mod 22) and faces (1 + byte mod 64)
  std::vector<std::array<std::int8_t, 3>> points;  ///< coordinates wrapped into [−8, 8]
  std::vector<std::array<std::uint8_t, 3>> faces;  ///< indices mod #points
  // --- both
  std::vector<SourceSpec> sources;  ///< count 1 + byte mod 3
  /// bit 0: solve again with stopDistance = stop and compare; bit 1: check d(a, b) = d(b, a);
  /// bit 2: solve again with two targets, vertex k mod #vertices and the centroid of face k mod
  /// #faces, k = flags >> 3, and compare.
  std::uint8_t flags = 0;
  Quantity stop;  ///< ∈ [0, 64] lattice units
};

std::vector<std::uint8_t> encode(const SolverSpec& s);

struct SolverCase {
  TriangleSoup soup;
  std::vector<SurfacePoint> sources;
  std::optional<double> stopDistance;
  std::vector<SurfacePoint> targets;  ///< for the target solve; empty: none
  bool checkSymmetry = false;
  bool planar = false;     ///< a flat grid without moved vertices: the planar oracles apply
  bool rectangle = false;  ///< … and without removed cells: convex, distances are Euclidean
};

/// The case the bytes describe, or nullopt when the target skips them: too long, or a mesh
/// that is empty, over kMaxFuzzFaces or refused by the validator.
std::optional<SolverCase> decodeSolver(std::span<const std::uint8_t> bytes);

Verdict checkSolver(const SolverCase& c);
/// checkSolver with a wrong distance planted in the solver's vertex distances before the oracles
/// judge them (`errorInMeshUnits` added at `vertex`): how a test shows that the checks catch an
/// error of a given size, and which check does.
Verdict checkSolverWithPlantedError(const SolverCase& c, Index vertex, double errorInMeshUnits);

/// The mesh as a tiny OFF file, the sources as `source SPEC` lines (SPEC as the CLI's --source
/// takes it), and the options.
void describe(const SolverCase& c, std::ostream& out);
/// The mesh projected onto its two widest axes, the sources, and each vertex's distance.
void writeSvg(const SolverCase& c, std::ostream& out);

/// The committed corpus (corpus/fuzz_solver/): flat grids, holes, L shapes, saddles, cones,
/// terraces, moved vertices and lattice soups with sources on vertices, edges and faces, each
/// named after the mesh-level case it is, and the regress files that can be described.
std::vector<Seed> solverSeeds();

}  // namespace geodex::verify
