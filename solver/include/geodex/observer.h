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

struct PropagationEvent {
  Index face;                    ///< the face crossed
  Index edge;                    ///< e0, the window's edge
  const Interval& window;        ///< the window propagated
  const LocalWindow& local;      ///< its local configuration (Fig. 3 frame)
  const LocalPropagation& result;  ///< the Fig. 6 leaf and the children's ranges
};

struct EdgeUpdateEvent {
  Index edge;
  double edgeLength;
  /// The edge's list before Algorithm 2; empty for an observer whose readsIntervalLists() is
  /// false (copying it cost 8 % of a solve).
  std::span<const Interval> before;
  const Interval& incoming;          ///< the new interval
  std::span<const Interval> after;   ///< the list after steps 1–5
  const EdgeUpdateReport& report;    ///< Eq. 1 breakpoints, D1–D4 found
  /// The Fig. 6 leaf that produced the incoming interval (nullptr for source/pseudo-source
  /// intervals, which come from no propagation case).
  const Fig6Branch* branch;
};

/// A window the solver drops before adding it to its edge (the edge-end rule,
/// GeodesicSolver::dominatedAtAnEdgeEnd): a path through `vertex`, an end of the edge, at
/// `vertexDistance` and then along the edge, is shorter at the window's far end from that vertex,
/// so the window is longer than a real path everywhere on the edge and beyond it.
struct WindowDroppedEvent {
  Index edge;
  double edgeLength;
  const Interval& window;  ///< as it would have been added (edge coordinates, side, σ)
  Index vertex;            ///< the end of the edge whose path is shorter
  double vertexDistance;   ///< its distance when the window was dropped (mesh units)
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
