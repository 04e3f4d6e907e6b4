#pragma once
/// \file lattice_internal.hpp
/// \brief Steps of a vortex-lattice solve shared by vortex_lattice.cpp, wake.cpp and
/// aero_loads.cpp (not a public interface).

#include "uvlm/vortex_lattice.hpp"

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <functional>

namespace flapsim::uvlm::detail {

/// The steady lattice's model: `m` with its wake seen through the bound rings' core
/// (vortex_lattice.cpp, solve_steady). The model the loads of `d` are computed with: this
/// one after a steady solve, `m` itself after an unsteady one.
VortexLatticeModel steady_lattice_model(const VortexLatticeModel& m);
inline VortexLatticeModel solved_lattice_model(const VortexLatticeModel& m, const VortexLatticeData& d) {
  return d.steady_solution ? steady_lattice_model(m) : m;
}

/// The three-quarter-chord point of panel (i, j) of a field X on the surface nodes
/// (positions or velocities, 3 × nodes): the mean of the points ¾ along the panel's two
/// chordwise sides (the collocation point, the surface velocity there).
inline Eigen::Vector3d three_quarter_chord(const VortexLatticeModel& m, const Eigen::Matrix3Xd& X, int i, int j) {
  const auto a = X.col(m.node(i, j)), b = X.col(m.node(i + 1, j));
  const auto c = X.col(m.node(i, j + 1)), e = X.col(m.node(i + 1, j + 1));
  return 0.5 * ((a + 0.75 * (b - a)) + (c + 0.75 * (e - c)));
}

/// Point–segment interactions below which one thread does a step's sums alone.
inline constexpr std::size_t kTargetChunkThreshold = 100000;

/// Call sum(i0, count) for contiguous chunks of the targets [0, n), one chunk per thread
/// of ONE parallel region (the Biot–Savart sums called inside run on their calling thread:
/// nested regions are inactive), so that the several sums a step makes at the same
/// targets (wake, bound, trailing edge) cost one fork/join instead of one each; with the
/// passive wait policy each costs a wake-up of the sleeping threads. Chunks hold an even
/// number of targets (the kernel takes points two at a time). Each target's velocity is
/// summed by the same operations in the same order whatever the chunking, so the result
/// does not depend on the thread count. `interactions` (targets × segments of all the sums)
/// decides whether threads are worth starting.
template <class Sum>
void for_target_chunks(std::size_t n, std::size_t interactions, Sum&& sum) {
  if (n == 0) return;
  if (interactions < kTargetChunkThreshold || omp_in_parallel() || omp_get_max_threads() == 1) {
    sum(std::size_t{0}, n);
    return;
  }
  const std::size_t pairs = (n + 1) / 2;
#pragma omp parallel
  {
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t threads = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t i0 = 2 * (pairs * t / threads);
    const std::size_t i1 = std::min(n, 2 * (pairs * (t + 1) / threads));
    if (i1 > i0) sum(i0, i1 - i0);
  }
}

/// solo() on one thread while the team sums chunks of the targets [0, n) (sum(i0, count)
/// as for_target_chunks, chunks handed out one by one, so the thread of solo() joins in when
/// it is done): work that does not depend on solo()'s result fills the time a serial
/// solo() would leave the other threads idle. Each target's sum is the same whatever the
/// chunking (for_target_chunks). One thread, or too little work: the sums, then solo().
/// An exception of solo() is rethrown after the region. Returns whether a team ran them.
template <class Sum>
bool alongside_target_chunks(std::size_t n, std::size_t interactions, const std::function<void()>& solo, Sum&& sum) {
  if (interactions < kTargetChunkThreshold || omp_in_parallel() || omp_get_max_threads() == 1) {
    if (n > 0) sum(std::size_t{0}, n);  // then solo(): its exception after the sums, as in a team
    solo();
    return false;
  }
  constexpr std::size_t kChunk = 16;  // targets per chunk (even: the kernel takes two at a time)
  const long chunks = static_cast<long>((n + kChunk - 1) / kChunk);
  std::exception_ptr failure;
#pragma omp parallel
  {
#pragma omp single nowait
    {
      try {
        solo();
      } catch (...) {
        failure = std::current_exception();
      }
    }
#pragma omp for schedule(dynamic, 1) nowait
    for (long k = 0; k < chunks; ++k) {
      const std::size_t i0 = static_cast<std::size_t>(k) * kChunk;
      sum(i0, std::min(kChunk, n - i0));
    }
  }
  if (failure) std::rethrow_exception(failure);
  return true;
}

/// The trailing-edge vortex's least distance behind the edge, as a fraction of the last
/// panel's chord: when the edge is momentarily at rest relative to the air (a start from
/// rest, a stroke reversal without rotation) the last rings still close behind it.
inline constexpr double kMinTrailingEdgeVortexFraction = 0.01;

/// Rings, collocation points, normals, tangents, areas and surface velocities from the nodes.
/// Ring corners at the quarter of each panel. The last rings' rear (trailing-edge) segment,
/// where the wake's newest row is attached, lies in the extension of the last panel's
/// chordwise side t_j at trailing-edge node j, behind the edge by a quarter of the
/// chordwise part of the path the edge travelled relative to the air in the last step:
///   r_j = x_j + max(¼ a_j, kMinTrailingEdgeVortexFraction Δx_j) t_j,
///   (V∞ − v_j) Δt = a_j t_j + b_j e_j + c_j n_j
/// (v_j the node's velocity: the wing's motion and deformation; e_j along the edge, n_j the
/// panel's normal, Δx_j the last panel's chord). The path's normal part c_j is left out, so
/// every ring lies on the wing surface whatever the panel width: with it the rear segment
/// rose ¼ U Δt sin α out of the plane and corrupted the boundary condition beside
/// spanwise panels narrower than that (docs/uvlm.md, "Model"). Katz & Plotkin §13.12
/// (and the program of that section) put the latest wake vortex 0.2–0.3 of the step's
/// travel behind the trailing edge along the wing's chord. The normal part c_j n_j is kept
/// in d.shed_lift and given back to the row shed from the vortex when it leaves (advance):
/// the wake behind its first ring lies on the line the edge travelled through the air, as
/// before (a revolving wing's lift then changes by +0.5 % from 30 to 60 steps per half
/// revolution instead of +1.5 % with the wake shed from the panel's plane; test U24).
/// dt = 0 (the steady solve,
/// nothing shed; the segment carries no net circulation): ¼ Δx_j along the chord.
void update_geometry(const VortexLatticeModel& m, VortexLatticeData& d, const Eigen::Matrix3Xd& nodes,
                     const Eigen::Matrix3Xd& node_velocities, const Eigen::Vector3d& free_stream, double dt);

/// Influence matrix a(i, k) = (velocity of unit ring k at collocation point i) · n_i; with
/// last_row_only, only the columns of the rings of the last chordwise row (the others kept:
/// valid when the surface moved rigidly since they were computed). A column is the same
/// either way.
void build_influence(const VortexLatticeModel& m, VortexLatticeData& d, bool last_row_only = false);

/// Unique bound segments with their net circulation from d.gamma.
void build_bound_segments(const VortexLatticeModel& m, VortexLatticeData& d);

/// The lattice's unique segments on its ring nodes (3 × nodes) with the ring circulations
/// G(i, j) [m²/s] (0 outside the lattice; row −1 may be a leading-edge ring), appended to
/// `bound` (spanwise rows q < nc first, row-major, then the chordwise columns) and
/// `trailing_edge` (row nc): what build_bound_segments makes of d.gamma, for any G.
template <class Gamma>
void push_ring_segments(const VortexLatticeModel& m, const Eigen::Matrix3Xd& ring_nodes, Gamma G, SegmentSet& bound,
                        SegmentSet& trailing_edge) {
  const int nc = m.chordwise, ns = m.spanwise;
  // Spanwise segments, ring-node row q, direction j → j+1: rear of ring q−1 minus front of
  // ring q; row nc is the trailing edge.
  for (int q = 0; q <= nc; ++q)
    for (int j = 0; j < ns; ++j)
      (q < nc ? bound : trailing_edge)
          .push(ring_nodes.col(m.node(q, j)), ring_nodes.col(m.node(q, j + 1)), G(q - 1, j) - G(q, j));
  // Chordwise segments, column j, direction q → q+1: root side of ring (q, j) minus tip side of (q, j−1).
  for (int j = 0; j <= ns; ++j)
    for (int q = 0; q < nc; ++q)
      bound.push(ring_nodes.col(m.node(q, j)), ring_nodes.col(m.node(q + 1, j)), G(q, j) - G(q, j - 1));
}

/// Who looks at the wake segments: the wing (cores at least model.near_wing_core) or the
/// wake itself (each segment's own, possibly grown, core).
enum class WakeView { Wing, Wake };

/// Unique wake segments with their net circulation and core (row wake_rows must sit on
/// the trailing edge), as seen from `view`. With model.far_wake_by_tree() the far wake's
/// segments go to d.far_wake_segments and the tree is built over them. For WakeView::Wake
/// in double precision without a leading-edge sheet (wake_sum_by_lattice) the direct-sum
/// segments are also put in d.wake_lattice (lattice_segments.hpp).
void build_wake_segments(const VortexLatticeModel& m, VortexLatticeData& d, WakeView view);

/// Whether the free vortices' direct sum at their own nodes uses the lattice form of the
/// wake (d.wake_lattice; double precision, no leading-edge sheet in the set).
inline bool wake_sum_by_lattice(const VortexLatticeModel& m) {
  return !m.single_precision_wake && m.leading_edge != LeadingEdge::Shed;
}

/// Add the velocity of d.wake_segments (the wake, and the leading-edge sheet when it
/// sheds) at n points (x, y, z) [m] to (u, v, w) [m/s] by the direct sum in the wake's
/// precision: single (the copies of update_single_precision), or double (the lattice form
/// when wake_sum_by_lattice).
void add_free_vortex_velocity(const VortexLatticeModel& m, const VortexLatticeData& d, const double* x,
                              const double* y, const double* z, std::size_t n, double* u, double* v, double* w);

/// Number of wake node rows (a prefix, oldest first) older than the frozen or far-wake
/// age: they do not move with their induced velocity.
int far_wake_node_rows(const VortexLatticeModel& m, const VortexLatticeData& d);

/// Add the convected far wake's velocity (the tree of d.far_wake_segments, targets moved
/// back by d.far_tree_shift) at n points; nothing when there is no far-wake tree.
void add_far_wake_velocity(VortexLatticeData& d, const double* x, const double* y, const double* z,
                           std::size_t n, double* u, double* v, double* w);

/// Put the wake's newest node row on the current trailing edge (ring nodes of row nc).
void attach_wake_to_trailing_edge(const VortexLatticeModel& m, VortexLatticeData& d);

/// Which of the wing's point sets d.eval holds, for the older wake's recorded or held sums
/// (VortexLatticeData::old_wake_velocity): none, the collocation points, the bound
/// segments' midpoints.
enum class WingPoints { None = -1, Collocation = 0, Midpoints = 1 };

/// At the collocation points with a single-precision wake, what a sum does with its part
/// before the edge's segments (VortexLatticeData::collocation_older): nothing, keep it, or
/// start from the part kept at the same n points instead of summing it (solve() asks for
/// Reuse only after shedding, when only the edge's segments changed since its Keep).
enum class OlderPart { None, Keep, Reuse };

/// Induced velocity of the wake (and of the bound segments if include_bound) at the first n
/// points of d.eval, written to d.eval.u/v/w (zeroed first). With old_wake_kept_apart(m, d) and
/// one of the wing's point sets, the older wake's part is recorded, or taken from the
/// record while it is held; at the collocation points `older` as above.
void induced_at_eval_points(const VortexLatticeModel& m, VortexLatticeData& d, std::size_t n,
                            bool include_bound, WingPoints points = WingPoints::None,
                            OlderPart older = OlderPart::None);

/// Velocity at the midpoints of the first n bound segments (set here as d.eval's first n
/// points, into its u/v/w): the wake's, the trailing edge's and every other bound segment's.
/// A segment's own velocity at its midpoint is zero only in exact arithmetic: the rounded
/// midpoint lies off the segment's line by about 1e-18 m, and inside the bound core
/// (model.bound_core(), 1e-11 m for a core of 1e-6 of a 10 mm chord) the kernel's velocity
/// grows as Γ 1.26 h/(2π r_c²), about 1 m/s there; so it is taken out, as the sum held it.
void induced_at_bound_midpoints(const VortexLatticeModel& m, VortexLatticeData& d, std::size_t n);

/// The bound segments whose midpoints the loads evaluate (induced_at_bound_midpoints): the
/// spanwise ones of rows q < nc (the first nc·ns of build_bound_segments) for the Bernoulli
/// route's leading-edge force (aero_loads.cpp), all of them for Kutta–Joukowski
/// (kutta_joukowski_loads.cpp). By the route, not the model's load_method: a route may be
/// called on its own.
inline std::size_t loads_midpoints(LoadMethod route, const VortexLatticeModel& m, const VortexLatticeData& d) {
  return route == LoadMethod::Bernoulli ? static_cast<std::size_t>(m.chordwise) * m.spanwise
                                        : d.bound_segments.size();
}

/// The midpoints of the first n bound segments as d.eval's first n points.
void set_bound_midpoints(VortexLatticeData& d, std::size_t n);

/// The wake's part of induced_at_eval_points at d.eval's first n points, summed by the team
/// while one thread runs solo() (alongside_target_chunks); a later induced_at_eval_points
/// at the same n points with include_bound then adds the bound segments' part only (the
/// same sums in the same order at each point). False (nothing done, solo() not run) where
/// the far wake's tree would come between the sums.
bool wake_at_eval_points_alongside(const VortexLatticeModel& m, VortexLatticeData& d, std::size_t n,
                                   WingPoints points, const std::function<void()>& solo);

/// Leading-edge sheet (LeadingEdge::Shed; leading_edge_sheet.hpp, leading_edge_shedding.cpp).
/// Place the release row from the edge's path through the air in half a step (the free
/// stream, the edge's motion and the trailing-edge wake's velocity); drops the sheet's
/// segments from d.wake_segments and d.wake_edge_segments.
void place_release_row(const VortexLatticeModel& m, VortexLatticeData& d);
/// The sheet's segments (the leading-edge rings with d.le_sheet.current), cores as seen
/// from `view`, after the trailing-edge wake's (build_wake_segments before; those of an
/// earlier call replaced): in d.wake_segments, and those that move with the wing within a
/// step in d.wake_edge_segments when the wing sees them in single precision.
void build_sheet_segments(const VortexLatticeModel& m, VortexLatticeData& d, WakeView view);
/// The part of the boundary condition's right-hand side from the segments on the first
/// bound vortices that the leading-edge rings carry at their accepted circulation.
void add_leading_edge_ring_to_rhs(const VortexLatticeModel& m, VortexLatticeData& d);
/// After d.gamma = A⁻¹ r: the LESP of every strip, and the circulations with the
/// leading-edge rings of the strips beyond LESP_crit; true when a strip shed.
bool shed_leading_edge_vorticity(const VortexLatticeModel& m, VortexLatticeData& d);
/// The leading-edge force of strip j with the shed leading edge, from the in-plane suction
/// the lattice gives it (leading_edge_loads.cpp).
Eigen::Vector3d shed_edge_force(const VortexLatticeModel& m, const VortexLatticeData& d, int j,
                                const Eigen::Vector3d& suction);
/// Velocity of the sheet's nodes (into d.le_sheet.nodes u/v/w) from the wake and the sheet
/// (d.wake_segments, built for WakeView::Wake: by the tree when by_tree, else
/// add_free_vortex_velocity), the far wake, the bound and trailing-edge segments; zero for
/// the rows older than the far-wake age, which move with the far-wake velocity.
void sheet_node_velocities(const VortexLatticeModel& m, VortexLatticeData& d, bool by_tree);
/// Convect the sheet's free rows over d.dt (far_velocity for rows older than the far-wake
/// age) and, when a strip shed, release the release row with the leading-edge rings.
void move_and_release_sheet(const VortexLatticeModel& m, VortexLatticeData& d, const Eigen::Vector3d& far_velocity);
/// Merge the sheet's older rings in pairs (model.sheet_merge_steps; leading_edge_sheet.hpp,
/// "Merging the older rings"); returns the merges made.
int merge_older_sheet_rings(const VortexLatticeModel& m, VortexLatticeData& d);

/// Compute the loads selected by the model.
void compute_loads(const VortexLatticeModel& m, VortexLatticeData& d);

}  // namespace flapsim::uvlm::detail
