"""geodex: exact geodesic distances and paths on triangle meshes that do not break on real data.

The window-propagation algorithm of Mitchell, Mount and Papadimitriou as made practical by
Surazhsky et al. (2005), with every degenerate case of Liu, Zhou and Hu (2007) handled by one
consistent procedure. Distances are exact up to rounding (1e-9 of the mesh's diagonal is the
contract; typically 1e-15), at any scale a double holds; unreachable vertices get +inf.

    >>> import numpy as np, geodex
    >>> V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    >>> F = np.array([[0, 1, 2], [0, 2, 3]])
    >>> geodex.distances(V, F, [0])
    array([0.        , 1.        , 1.41421356, 1.        ])

Every input is checked as the `geodex` command-line tool checks it: a bad one raises
geodex.InputError (a ValueError) with the same message, never a crash or a wrong number.
"""
from ._geodex import InputError, Solver, SurfacePoint, edge, face, load, vertex
from ._geodex import check as _check

__all__ = ["distances", "check", "Solver", "SurfacePoint", "vertex", "edge", "face", "load", "InputError"]


def distances(V, F, sources, *, stop_distance=None, targets=None):
    """Geodesic distance from the nearest of `sources` to every vertex.

    V: (n, 3) array-like of vertex positions (any real dtype, C or Fortran order).
    F: (m, 3) array-like of vertex indices (any integer dtype), one triangle a row.
    sources: a vertex index, a SurfacePoint (geodex.vertex(i), geodex.edge(i, j, t),
        geodex.face(f, a, b, c)), or a sequence of them.
    stop_distance: stop the wavefront there; vertices beyond it get inf.
    targets: stop as soon as the distances of these points are final; vertices not final
        by then get inf.
    Returns a float64 array of n distances, inf where unreachable.
    Raises InputError for a bad mesh, source or option, with the CLI's message.
    """
    return Solver(V, F).distances(sources, stop_distance=stop_distance, targets=targets)


def check(V, F, sources, *, level="full", oracles=None):
    """Solve with every invariant checked and independent oracles: the CLI's `geodex check`.

    V, F, sources: as for distances().
    level: "full" (every Algorithm 2 update checked against the list before it, and coverage at
        the end) or "cheap" (the list's order and continuity after every update).
    oracles: names to run, default all but cgal: "bounds", "lipschitz", "planar", "symmetry",
        "metamorphic", "paths", "exact-predicates".
    Returns the report as a dict, the same object `geodex check --json` prints: "ok", the
    "violations" (one sentence each), per-invariant and per-oracle tallies with the worst error,
    and the degeneracy counters G1-G5, D1-D4.
    Raises InputError for a bad mesh, source or option.
    """
    return _check(V, F, sources, level=level, oracles=oracles)
