#pragma once
// What fuzz_two_faces and fuzz_solver share: a soup the validator accepts, the Mesh built from
// it, a solve with the invariant and unfolding checks attached whose failures become a verdict,
// and the soup as text. Private to verify/src/cases (hence namespace detail).

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "geodex/geodesic_solver.h"
#include "geodex/mesh.h"
#include "geodex/observer.h"
#include "geodex/verify/cases/fuzz_target.h"

namespace geodex::verify::detail {

/// Whether validateMesh finds no error in the soup: the mesh cases the targets test.
bool soupValid(const TriangleSoup& soup);

/// The Mesh of a soup validateMesh accepted; nullopt, with "validated-mesh-refused" in v, if
/// Mesh refuses it all the same.
std::optional<Mesh> buildMesh(const TriangleSoup& soup, Verdict& v);

/// The soup as a tiny OFF file, coordinates to 17 digits.
std::string describeSoup(const TriangleSoup& soup);

/// Checks every interval a propagation case creates against an independent 3-D construction: the
/// parent's pseudo-source placed in the crossed face's plane (mirrored across the parent's edge,
/// away from the face's third vertex) and the child edge's points from the mesh positions. The
/// child's σ + |x − s| must equal σ + that 3-D distance. Forwards every event to `next`.
class UnfoldingChecker : public SolverObserver {
 public:
  UnfoldingChecker(const Mesh& mesh, SolverObserver* next) : mesh_(mesh), next_(next) {}
  std::uint64_t checked = 0;

  void onPropagation(const PropagationEvent& e) override {
    if (next_) next_->onPropagation(e);
    for (const MadeChild& child : e.children) checkChild(e, child);
  }
  void onEdgeUpdate(const EdgeUpdateEvent& e) override {
    if (next_) next_->onEdgeUpdate(e);
  }
  void onWindowDropped(const WindowDroppedEvent& e) override {
    if (next_) next_->onWindowDropped(e);
  }
  void onFinish(const GeodesicSolver& s) override {
    if (next_) next_->onFinish(s);
  }

 private:
  void checkChild(const PropagationEvent& p, const MadeChild& child);

  const Mesh& mesh_;
  SolverObserver* next_;
};

/// Runs a solve with the observers, turning what they throw into a verdict. False if it failed.
/// A 'distance-overflow' refusal passes when the solve's own distances (which the checks after
/// this compare with the oracles, in mesh units) do overflow in file units.
bool solveChecked(GeodesicSolver& solver, std::span<const SurfacePoint> sources,
                  const SolveOptions& options, Verdict& v);

}  // namespace geodex::verify::detail
