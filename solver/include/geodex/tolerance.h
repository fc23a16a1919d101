#pragma once
// Every tolerance geodex uses, in one place. Each is *relative*: to an edge length, a face's
// longest edge, or a distance value, so that scaling a mesh by 1e-6 or 1e+6 makes the same
// decisions (tests/property checks this). The paper (Liu, Zhou & Hu 2007, Sect. 4.1) uses an
// absolute "machine precision" ε; that breaks under scaling, hence the local lengths here.

namespace geodex::tol {

// ===  Geometric-intersection predicates (Sect. 4.1, Fig. 6) =====================================

/// Two points coincide when closer than this × the face's longest edge (G1, G4, G5: s = b0,
/// s = b1, b0 = v0, b1 = v2). Unfolded sources carry ~1e-14 relative error after a few hundred
/// unfoldings; 1e-11 leaves a margin of 1000 while an error of this size changes a distance by
/// at most twice as much (triangle inequality), far below the 1e-9 × diagonal accuracy target.
inline constexpr double kCoincideRel = 1e-11;

/// Three points are collinear when the sine of the angle they make is below this (G2, G3 and
/// the left/right tests of Fig. 6). Using a sine (cross product over the product of lengths)
/// makes the test independent of scale and of how far away the pseudo-source is.
inline constexpr double kCollinearSin = 1e-11;

/// A face whose height over its longest edge is below this is treated as zero-area: windows pass
/// straight through it along the common line (the limit of the general case as the height → 0).
inline constexpr double kFlatFaceRel = 1e-12;

// ===  Geodesic discontinuities (Sect. 3.2 and 4.2, Algorithm 2 steps 3–5) =====================

/// D1: intervals shorter than this × their length scale are removed (merged into a neighbour).
/// D3: gaps shorter than this × the edge length, plus kRayEndRel × the neighbours' length scale,
///     are sewn (sewLength in edge_intervals.h). That covers a flat vertex's shadow: the two
///     sides' boundary rays both pass through the vertex and differ in direction by its angle
///     defect (below kFlatVertexAngle), so the gap is that × the distance past the vertex, a
///     local length. Neither σ nor the source's distance counts: a slack growing with σ hands a
///     far window a stretch where its neighbour is much shorter, and one growing with a far
///     source's distance closes a near saddle's shadow (sewLength).
/// The length scale of an interval is max(edge length, distance from its pseudo-source to the
/// edge): its ends come from rays cast from that source, so they carry rounding of ~1e-16 × that
/// distance. (A window from a source 1e5 edge lengths away has ends good to ~1e-11 × the edge
/// only, as on tests/unit/geodesic_solver_test.cpp's far-source patch.) See
/// intervalLengthScale() in edge_intervals.h.
/// D2: overlaps below this × the length scale are resolved where the shorter of the two ends
///     (at the midpoint where they agree); larger ones are split by Eq. 1.
inline constexpr double kTinyIntervalRel = 1e-11;

/// D1 beside a coarser neighbour: a window's ends, cast by rays from its pseudo-source, are good
/// to this × its length scale (their rounding is ~1e-16 × the source distance; 100× that). A
/// sliver of a near window at the end of a far one that is shorter than this × the far one's
/// scale may be the far end's rounding and is removed (D1) even when longer than its own ε: left,
/// it stands above the far window, which really reaches on to the vertex
/// (tests/data/regression/rotated-far-source-patch-sliver-at-a-rounded-window-end.off).
/// Not the neighbour's whole ε (kTinyIntervalRel, 1e5× the rounding): a sliver that long is real,
/// the start of a near saddle's shadow that fans out downstream where the far rays never reach;
/// merged into the far window, it takes the saddle's fan with it
/// (tests/data/regression/far-source-edge-end-left-to-a-pseudo-source.off).
inline constexpr double kRayEndRel = 1e-14;
static_assert(kRayEndRel <= kTinyIntervalRel, "step 3 bounds every D1 threshold by ε (edge_intervals.cpp)");

/// A vertex whose height over the opposite edge of one of its faces is below this × that face's
/// longest edge lies on the edge, for its pseudo-source windows: its window on the edge is then
/// at most a D1 sliver (kTinyIntervalRel) beside the direct windows through the face, so its fan
/// into the face across the edge is seeded directly (GeodesicSolver::seedAcrossVertexOnEdge).
/// Four times kTinyIntervalRel: the sliver's width is about the height, up to the unfolding's
/// rounding, so a vertex lifted 5e-12 off the edge loses its fan just as one exactly on it does.
inline constexpr double kVertexOnEdgeRel = 4.0 * kTinyIntervalRel;

/// Step 5: two neighbouring intervals have the same pseudo-source when the unfolded sources are
/// closer than this × edge length and their σ differ by less than this × edge length.
inline constexpr double kSameSourceRel = 1e-11;

/// When the wavefront has passed (the end of a solve), a gap left between two intervals narrower
/// than this × the mesh's bounding-box diagonal is closed at its midpoint: the shadow left between
/// windows that, in exact arithmetic, meet along a ray through a vertex. Computed, such a boundary
/// is off by rounding / (the angle at which its ray crosses the edge it is computed on), and the
/// two sides' rays then diverge: past a flat vertex, past a near-flat saddle of a CAD mesh whose
/// coordinates were rounded (anchor_dense.off has 88 vertices 1e-11 .. 1e-10 off 2π,
/// mannequin-devil.off 180 vertices 1e-9 .. 1e-7 off), between two unfoldings of one
/// pseudo-source, along a saddle's shadow boundary. On anchor_dense, rotor_small and
/// mannequin-devil such gaps are 1e-11 to ~1e-9 of the distance.
/// The width is the accuracy contract itself (1e-9 × the diagonal): a point x of a gap
/// [a, b] closed at its midpoint m takes a neighbour's value f(x), and f and the true distance are
/// both 1-Lipschitz along the edge with f(a) the true distance at a, so |f(x) − true(x)| <=
/// 2 (x − a) <= b − a. (The scale is the contract's, not a local length: what bounds the error is
/// the gap's absolute width.)
/// Not mid-run, where Algorithm 2 step 4 sews only below ε (kTinyIntervalRel, kFlatVertexAngle):
/// there a gap may be the start of a saddle's shadow, which widens downstream; closing it with
/// the direct windows (a tie the saddle's window then cannot break) leaves the saddle's window
/// out and the shadow open further on (fandisk.off).
inline constexpr double kShadowSewRel = 1e-9;

/// D4: the distances of two neighbours at their shared endpoint must agree to this × the
/// distance there (plus the edge-length term below) after an Eq. 1 split; a larger mismatch
/// means the quadratic's root was inaccurate (near-double root) and is polished on the exact
/// difference function.
inline constexpr double kContinuityRel = 1e-10;

/// Eq. 1: a root of the quadratic is taken as the breakpoint when the two distances agree there
/// to this × (distance + edge length); otherwise the change is located by bisection (D4). Below
/// kContinuityRel by what step 5 may still change either function by when it merges it with a
/// near-equal source (kSameSourceRel for the source, kSameSourceRel for σ): a root accepted at
/// the edge of kContinuityRel fails the continuity check once its neighbour is merged
/// (corpus/fuzz_edge_update/regress/continuous-at-eq1-root-accepted-then-neighbour-merged).
inline constexpr double kEq1RootRel = kContinuityRel - 2.0 * kSameSourceRel;

/// Algorithm 2 re-propagates an interval that grew over an unpropagated sliver (D1) or half a
/// sewn gap (D3) at most this many times. Each regrowth is below ε, and so are the children it
/// adds; without a cap two propagated intervals on neighbouring edges can hand each other such a
/// sliver forever (corpus/fuzz_solver/regress/internal-check-two-edges-regrow-each-other-forever).
/// Past the cap the sliver is absorbed without a second propagation, and the sub-ε gap it leaves
/// further on is step 4's.
inline constexpr int kMaxRegrowths = 4;

/// A new interval replaces an old one only where it is shorter by more than this × the distance
/// (or within it, with a σ smaller by more than that: incomingBeats in edge_intervals.cpp).
/// Without it, the same geodesic reached along two unfoldings (equal up to rounding) would keep
/// replacing itself, fragmenting edges and re-propagating for nothing. Losing at most this much
/// per decision keeps results within 1e-12 relative even along long chains of ties.
inline constexpr double kTieRel = 1e-14;

// ===  Mesh-level ================================================================================

/// A vertex is *flat* when its angle sum is within this of 2π (atan2 angle sums carry ~3e-15 of
/// rounding; 1e-12 leaves a margin of ~300). Geodesics pass straight through a flat vertex, so it
/// is not a pseudo-source (Sect. 2): making every flat vertex of a CAD face or a planar grid a
/// pseudo-source (as the reference code does) multiplies the windows per edge by ~15 for nothing.
/// Pseudo-sources are boundary vertices, non-manifold vertices, and vertices whose angle sum
/// exceeds 2π + this. A flat vertex can leave a shadow wedge of at most this angle between the
/// windows passing either side of it, that × the rays' length wide: below kTinyIntervalRel × the
/// length scale, which step 4 sews; rounding can leave more, closed when the wavefront has passed
/// (kShadowSewRel).
inline constexpr double kFlatVertexAngle = 1e-12;


/// The shortest edge geodex computes with, relative to the mesh's largest coordinate magnitude.
/// The solver works in mesh units (Mesh::unit(), that magnitude rounded down to a power of two,
/// so that dividing by it is exact), where every coordinate is below 2 and every edge below 7.
/// The products of more than two lengths rescale themselves by a power of two (the Fig. 6 tests
/// in propagateLocal, Eq. 1 in equalDistanceCandidates); everything else multiplies two lengths
/// and a tolerance: with edges at least 1e-100 long, a square times kTinyIntervalRel² stays
/// above 1e-222, clear of the subnormal range (2.2e-308), and a pseudo-source 1e10 mesh units
/// away stays within 1e110 of the smallest face, whose collinearity products then stay below
/// 1e221. docs/numerics.md has the argument step by step. A mesh with an edge 1e100 times
/// shorter than its extent is refused by name ('edge-length-spread').
inline constexpr double kMinEdgeLengthRel = 1e-100;

/// How far, in sizes of the face it crosses, a window's pseudo-source can be in a mesh geodex
/// accepts: distances stay below 7 × 2^32 mesh units (every edge below 7, fewer than 2^32
/// edges) and faces are at least kMinEdgeLengthRel across, hence 3e10 / 1e-100. Up to there the
/// Fig. 6 products of four lengths stay below 1e221 at unit scale (propagateLocal's contract,
/// which the fuzz checks keep to; beyond it |u|² alone overflows near 1e154 face sizes).
inline constexpr double kMaxSourceDistanceInFaceSizes = 3e10 / kMinEdgeLengthRel;

/// Barycentric or edge parameters within this of 0 or 1 snap a source or target onto the
/// edge or vertex it is on. Ten times kCoincideRel: a source nearer a vertex or an edge than
/// that is neither coincident with it for the Fig. 6 predicates nor clear of it — its windows
/// see it a hair off their edge's line beside the window's end, where G1 ("s on e0's line")
/// and the generic branches disagree, and a face source that close to a flat grid vertex loses
/// its windows into the faces around the vertex unless it is snapped onto it
/// (corpus/fuzz_solver/regress/upper-bound-face-source-2e-11-from-flat-vertex). Moving a
/// source by 1e-10 of its face moves every distance by at most that, far inside the 1e-9 ×
/// diagonal contract.
inline constexpr double kSnapParam = 1e-10;

// ===  Verification (verify/) ====================================================================

/// Rounding of one computed distance σ + |x − s|, relative to its value (a few ulps, 2.2e-16
/// each). A check comparing two computed distances of size D (e.g. the triangle inequality
/// |d0 − d1| ≤ b1 − b0 of a real source) must allow this × D: with a source 1e7 away one ulp is
/// already 2e-9, far above ε × edge length.
inline constexpr double kRoundingRel = 1e-14;

/// How closely the face areas of a flat mesh must add up to the area its boundary loops enclose
/// for the planar oracles to take the mesh as an embedding of that domain, relative to the sum.
/// A face folded over another covers part of the domain twice and adds that part's area once
/// more; the sum's own rounding is a few ulps a face (1e5 faces: 1e-11). A fold thinner than this
/// is a sliver the check cannot tell from rounding.
inline constexpr double kPlanarCoverRel = 1e-10;

/// How far a surface point placed by its 3D position (a + t·(b − a) in doubles, as an oracle
/// does) may lie from the exact point, relative to the largest coordinate magnitude of the mesh:
/// each coordinate is rounded once to its ulp (2.2e-16 relative), √3 over the three, with
/// margin. The solver works with the point's parameters instead, so an oracle comparing
/// distances between 3D positions owes this for each point it places. It matters where the mesh
/// is small next to its distance from the origin: 1e-8-long edges at 262144 have positions good
/// to 6e-11 only (corpus/fuzz_two_faces/regress/two-face-distance-point-rounded-far-from-origin).
inline constexpr double kPositionRoundingRel = 4.0 * 2.220446049250313e-16;


/// How far an edge's distance function may stray from the exact pointwise minimum of the list
/// before an update and the incoming interval (Algorithm 2 step 6, full tier), relative to
/// (distance + edge length). Not a free parameter: it is the sum of what steps 1–5 may move by
/// contract — a breakpoint left with a mismatch up to kContinuityRel, a tiny interval or gap
/// (kTinyIntervalRel) absorbed by a neighbour on either side, and a tie not taken (kTieRel). (The
/// shadows closed at the end of a solve, kShadowSewRel, come after the last update it checks.)
inline constexpr double kPointwiseMinRel = kContinuityRel + 2.0 * kTinyIntervalRel + kTieRel;

/// How well a vertex distance can agree with what an incident edge gives there (the end-of-run
/// step-6 invariant 'vertex-agreement', relative to the distance plus the edge's length, as the
/// Eq. 1 continuity): kContinuityRel, plus what D(v) itself may carry from the *longest* edge at
/// the vertex, since D(v) is the smallest value any incident edge gives at v:
///  - the rounding of positions along it: along an edge of length L positions are known to
///    ulp(L) ≈ 1e-16 × L only (an unfolded source near the far end of a 1e6-long edge is 1.2e-10
///    off); kRoundingRel × 1e6 = 1e-8 covers a planar mesh with 1e6-long thin triangles
///    (tests/property/regressions_test.cpp, case 3).
///  - its own contract: a long edge holds its distance function to kPointwiseMinRel × (d + L) of
///    the exact minimum (its D1–D3 ε is kTinyIntervalRel × L), so D(v) taken from a long edge
///    may sit that far below what the short edges at v agree on, within that edge's contract and
///    the 1e-9 × diagonal target
///    (tests/data/regression/refined-far-source-patch-vertex-agreement.off).
inline double vertexAgreementTolerance(double distance, double edgeLength, double longestIncidentEdge) {
  return kContinuityRel * (distance + edgeLength) +
         (kRoundingRel + kPointwiseMinRel) * longestIncidentEdge;
}

/// How far the final distance may lie above a window the edge-end rule dropped (the full tier's
/// 'dropped-window-dominated', at a point of its edge or of the face beyond): the rule took the
/// window as longer than d(a) + |a x|, with d(a) the end a's distance during the solve, which is
/// held to vertexAgreementTolerance of what a's edges agree on; and the final list holds its
/// function to kPointwiseMinRel × (d + L) of the minimum of what reached it.
inline double droppedWindowTolerance(double distance, double edgeLength, double longestAtEnd) {
  return vertexAgreementTolerance(distance, edgeLength, longestAtEnd) +
         kPointwiseMinRel * (distance + edgeLength);
}

// ===  Path tracing (path.cpp) ===================================================================

/// Two points of a traced path closer than this × the local length (the edge's, or the crossed
/// face's longest edge) are one point. As kCoincideRel, for the same reason: a crossing is
/// computed from an unfolded source that carries ~1e-14 relative rounding, so a geodesic through
/// a vertex (the ray on a window's boundary, a pseudo-source where the path bends) crosses the
/// edge a rounding error beside it. Two uses:
///  - a crossing this close to an end of its edge is that end's vertex, so the path turns at the
///    vertex, not at an edge point a hair from it (the next step starts from the right place);
///  - a corner or an edge of a face this close to a path point is at the point's position (a
///    zero-area face, whose edges lie on one line up to kFlatFaceRel; a vertex beside a duplicate
///    joined to it through one): the tracer gathers every point at the position and takes the
///    cheapest step that moves from any of them, instead of stepping between them at the
///    distance of the position, where rounding decides and a step could lead away from the way
///    on and back (corpus/fuzz_solver/regress/path-length-non-manifold-vertex-beside-a-duplicate-
///    walks-back).
/// Moving a path point by this much changes its length by at most twice as much: far below the
/// 1e-9 × diagonal accuracy the path's length is held to.
inline constexpr double kPathSamePointRel = kCoincideRel;

}  // namespace geodex::tol
