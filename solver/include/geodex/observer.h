#pragma once
// The narrow interface through which verify/ watches the solver: the solver calls the observer at
// every propagation case, every edge update and at the end. With no observer attached the solver
// skips building these events; the only cost is one predictable branch per update (measured in
// bench/ and reported in the README).

#include <span>

#include "geodex/degeneracy.h"
#include "geodex/edge_intervals.h"
#include "geodex/interval.h"
#include "geodex/propagate.h"

namespace geodex {

class GeodesicSolver;

/// An interval a propagation case made for one of the crossed face's other edges.
struct MadeChild {
  Index edge;
  Interval interval;  ///< in that edge's frame, as Algorithm 2 will be given it
};

struct PropagationEvent {
  Index face;                    ///< the face crossed
  Index edge;                    ///< e0, the window's edge
  const Interval& window;        ///< the window propagated
  const LocalWindow& local;      ///< its local configuration (Fig. 3 frame)
  const LocalPropagation& result;  ///< the Fig. 6 leaf and the children's ranges
  /// The intervals made of result's children (none for a child whose range came out empty or
  /// whose edge the rays cannot leave through). They reach their edges when the batch of windows
  /// is done, in one run per edge (EdgeUpdateEvent::incoming).
  std::span<const MadeChild> children;
};

struct EdgeUpdateEvent {
  Index edge;
  double edgeLength;
  /// The edge's list before Algorithm 2; empty for an observer whose readsIntervalLists() is
  /// false (copying it cost 8 % of a solve).
  std::span<const Interval> before;
  /// The intervals merged, in the order steps 1 and 2 took them: one source's or pseudo-source's
  /// window, or the run of children one batch of windows sent to this edge
  /// (EdgeIntervals::insertRun: steps 1 and 2 for each, steps 3–5 once). The list after is the
  /// pointwise minimum of the list before and all of them, repaired.
  std::span<const Interval> incoming;
  std::span<const Interval> after;  ///< the list after steps 1–5
  const EdgeUpdateReport& report;   ///< Eq. 1 breakpoints, D1–D4 found
  /// The Fig. 6 leaf of the case each incoming interval came from, in the same order; empty for a
  /// source's or pseudo-source's window, which comes from no propagation case.
  std::span<const Fig6Branch> branches;
};

/// Why the solver dropped a window before adding it to its edge.
enum class DropRule : std::uint8_t {
  /// GeodesicSolver::dominatedAtAnEdgeEnd: a path through `vertex`, an end of the edge, at
  /// `vertexDistance` and then along the edge, is shorter at the window's far end from that
  /// vertex, so the window is longer than a real path everywhere on the edge and beyond it.
  EdgeEnd,
  /// GeodesicSolver::dominatedAlongItsEdge: the window of the pseudo-source `vertex` along its
  /// own edge, where the edge's list covers the edge and no interval of it is longer than the
  /// window (EdgeIntervals::nowhereAbove).
  AlongEdge,
};

/// A window the solver drops before adding it to its edge (DropRule says by which rule).
struct WindowDroppedEvent {
  Index edge;
  double edgeLength;
  const Interval& window;  ///< as it would have been added (edge coordinates, side, σ)
  Index vertex;            ///< the end of the edge the rule reasons from
  double vertexDistance;   ///< its distance when the window was dropped (mesh units)
  DropRule rule;
};

class SolverObserver {
 public:
  virtual ~SolverObserver() = default;
  virtual void onPropagation(const PropagationEvent&) {}
  virtual void onEdgeUpdate(const EdgeUpdateEvent&) {}
  virtual void onWindowDropped(const WindowDroppedEvent&) {}
  /// After the wavefront is exhausted (or stopped); the solver's results are queryable.
  virtual void onFinish(const GeodesicSolver&) {}
  /// Whether the observer reads edges' interval lists (in events or through the solver): then a
  /// solve asked for vertex distances only keeps every list (SolveOptions::vertexDistancesOnly),
  /// and EdgeUpdateEvent::before holds the list before each update (else it is empty).
  /// One that does not may see the events of such a solve that starts again (SolveStats::
  /// releaseUndone) before those of the solve that finishes.
  virtual bool readsIntervalLists() const { return true; }
};

}  // namespace geodex
