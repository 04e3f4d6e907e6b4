#pragma once
/// \file vortex_lattice.hpp
/// \brief Unsteady vortex-lattice method (Katz & Plotkin, ch. 13): a constant model
/// (what the lattice is) and a mutable workspace (geometry, circulations, wake, loads),
/// all storage allocated once in the workspace's constructor.
///
/// One time step, with FSI sub-iterations in mind:
///   1. `solve(model, data, nodes, node_velocities, free_stream, dt, rho)` — circulations
///      and loads for the given surface; the wake is not changed, so it may be called
///      several times per step (the FSI loop moves the surface in between);
///   2. `advance(model, data)` — accepts the last solve: convects the wake (free, or with
///      the free stream only) and sheds one row from the trailing edge.
///
/// Lattice: vortex rings whose leading edge lies at the quarter chord of each panel;
/// the last ring's trailing segment (where the wake is attached) lies in the extension of
/// the last panel, behind the edge by a quarter of the chordwise part of the edge's path
/// relative to the air in the last step (Katz & Plotkin §13.12; lattice_internal.hpp
/// update_geometry), in the steady solve a quarter panel chord behind the edge.
/// Collocation points at the three-quarter chord point of each panel, normals from the
/// panel diagonals. Kutta condition (Katz & Plotkin §13.12): the wake ring shed at the
/// end of a step carries the trailing-edge circulation of that step (Kelvin's theorem),
/// and at the next step it stretches from the new trailing edge to the convected old one.
///
/// Index conventions: surface node (i, j) → i + (nc+1) j, i = 0..nc leading to trailing
/// edge, j = 0..ns root to tip; panel/ring (i, j) → i + nc j. A positive ring circulation
/// pushes along the panel normal n = (span direction) × (chordwise direction toward the
/// trailing edge); for a wing in the wing frame n = +z_W (lift for positive incidence).

#include "uvlm/biot_savart.hpp"
#include "uvlm/core_growth.hpp"
#include "uvlm/influence_matrix.hpp"
#include "uvlm/lattice_segments.hpp"
#include "uvlm/leading_edge_sheet.hpp"
#include "uvlm/old_wake_record.hpp"
#include "uvlm/preconditioned_gmres.hpp"
#include "uvlm/segment_tree.hpp"
#include "uvlm/vortex_core.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <vector>

namespace flapsim::uvlm {

enum class WakeModel {
  Free,       ///< wake nodes move with the local velocity (free stream + induced)
  Prescribed  ///< wake nodes move with the free stream only (flat wake; verification cases)
};
enum class WakeIntegrator { Euler, AdamsBashforth2 };
/// How the wake's velocity at its own nodes is summed.
enum class WakeSum {
  Direct,  ///< every node × every segment (biot_savart.hpp)
  Tree     ///< Barnes–Hut tree code with multipoles (segment_tree.hpp), O(N log N)
};
enum class LoadMethod {
  Bernoulli,      ///< unsteady Bernoulli pressure jump per panel from the surface gradient of Γ
  KuttaJoukowski  ///< ρ Γ (V × dl) on every bound segment, plus the ∂Γ/∂t term
};
/// What becomes of the leading-edge suction, the in-plane Kutta–Joukowski force on the
/// leading-edge bound segments (docs/uvlm.md, "Loads").
enum class LeadingEdge {
  None,      ///< dropped: normal (pressure) forces only
  Attached,  ///< kept in the panel plane (potential flow: induced drag, thrust)
  Separated, ///< its magnitude turned to the panel normal (Polhamus' suction analogy, NASA TN D-3767)
  /// Kept in the panel plane while the leading-edge suction parameter (LESP) of the strip
  /// stays below model.lesp_critical; beyond it vorticity leaves the leading edge as a
  /// free vortex sheet of the strength that holds the LESP at the critical value
  /// (Ramesh et al. 2014, J. Fluid Mech. 751; Hirato et al. 2021, J. Aircraft;
  /// leading_edge_sheet.hpp)
  Shed
};

/// What the lattice is: constant during a run.
struct VortexLatticeModel {
  int chordwise = 6;   ///< nc panels, leading to trailing edge
  int spanwise = 10;   ///< ns panels, root to tip
  VortexCore core;     ///< regularisation of the wake's segments, and of every segment seen from the wake
  /// The bound rings seen from the surface (influence matrix, load velocities) use the same
  /// core model with radius core.radius × bound_core_fraction: a core comparable to the
  /// panels would flatten the influence matrix and makes the trailing-edge shedding unstable.
  /// The trailing-edge segments keep the wake core: they coincide with the wake's newest
  /// row and carry the vorticity being shed, so the two must be regularised alike.
  double bound_core_fraction = 1e-3;
  WakeModel wake_model = WakeModel::Free;
  WakeIntegrator wake_integrator = WakeIntegrator::AdamsBashforth2;
  LoadMethod load_method = LoadMethod::Bernoulli;
  LeadingEdge leading_edge = LeadingEdge::Attached;
  /// The critical leading-edge suction parameter of LeadingEdge::Shed (leading_edge_sheet.hpp):
  /// 0.11, Ramesh et al. 2014's value for a thin flat plate at Re = 1000 (J. Fluid Mech. 751;
  /// stated so in the authors' code documentation, UnsteadyFlowSolvers.jl), the closest of
  /// their flat-plate values to insect Reynolds numbers (10²–10³); not fitted to any case.
  double lesp_critical = 0.11;
  /// With LeadingEdge::Shed: merge the sheet's older rings in pairs, the first pairs once
  /// their newer ring is this many steps old, a pair of merged rings of k rows each once it
  /// is k times as old (at most kSheetMergeMaxRows rows a ring); 0 = never
  /// (leading_edge_sheet.hpp, "Merging the older rings"). A resolution of the sheet (a
  /// merged ring is about 1/M of the distance it has travelled long), not a time; what it
  /// moves was measured (docs/uvlm.md, "Merging the sheet's older rings").
  int sheet_merge_steps = 0;
  /// With LeadingEdge::Shed and sheet_merge_steps > 0: the releases each merge is spread over
  /// (its circulations and middle node row moved a part at each; leading_edge_sheet.hpp,
  /// "Merging the older rings"); 1 = at once. Spread, a hover's per-step lift loses the
  /// spikes of merges next to the wing (docs/uvlm.md, "Merging the sheet's older rings").
  int sheet_merge_spread_steps = 1;
  /// With LeadingEdge::Shed: the core radius of the leading-edge sheet's segments [m] (the
  /// core model's), as `core` is the trailing-edge wake's: its free segments in every sum
  /// and the legs of the leading-edge rings, grown with age like the wake's when core_growth
  /// is on; 0 = core.radius. A larger core smooths the wing's circulation where the wing
  /// sweeps back through its sheet (hover) and smears the vortex's suction over the wing
  /// (revolving wings lift less): measured in docs/uvlm.md, "Why the shed hover's lift is
  /// rough: the sheet's core".
  double sheet_core_radius = 0.0;
  /// Evaluate the wake's direct sums in single precision: its self-induced velocity (the
  /// free-wake convection, the cost of a run) and its velocity at the wing's collocation
  /// and load points; about twice as fast, relative error ~1e-6 in these velocities (the
  /// loads' error: docs/uvlm.md, "Performance"). The bound segments' sums, the circulations and
  /// the loads are computed in double precision; the tree code is double precision. The
  /// leading-edge sheet (LeadingEdge::Shed) is summed with the wake, in the same precision.
  bool single_precision_wake = true;
  /// ∂Γ/∂t of the pressure by backward Euler at every step (first order) instead of BDF2
  /// from the third step on: the MAV film wing (25 µm, areal mass about the air's added
  /// mass) at 160 steps a wingbeat grew a sawtooth of period 2Δt in its lift with BDF2 and
  /// flew smoothly with it (docs/fsi.md, "Film wings").
  bool first_order_circulation_rate = false;
  int max_wake_rows = 0;   ///< keep at most this many wake rows (oldest dropped); 0 = keep all
  int wake_capacity = 0;   ///< wake rows the workspace holds (the run's step count, or max_wake_rows)
  /// Rings the leading-edge sheet (LeadingEdge::Shed) holds; 0: wake_capacity + 1. Neither
  /// max_wake_rows nor the far wake shortens the sheet: a run sets it from its steps
  /// (merged_sheet_rings, leading_edge_sheet.hpp).
  int sheet_capacity = 0;
  /// Viscous growth of the wake's cores with age (core_growth.hpp); off: every wake
  /// segment keeps `core`.
  CoreGrowth core_growth;
  /// ν [m²/s] of the panels' laminar skin friction (skin_friction.hpp); 0: none (inviscid).
  double skin_friction_viscosity = 0.0;
  /// Near-wing treatment: the wing (collocation and load points) sees every wake segment
  /// older than near_wing_min_age through a core of at least this radius [m], so a wake
  /// vortex that comes back close to or through the lattice cannot put a spike into the
  /// circulations; 0: the wake's own cores. Far from the segment the core makes no
  /// difference. The younger wake (the vorticity just shed, which sets the Kutta
  /// condition with the trailing-edge segments) keeps its own core. The wake nodes see the
  /// bound segments (not the trailing edge) through this core too.
  double near_wing_core = 0.0;
  double near_wing_min_age = 0.0;  ///< [s]
  /// With VortexLatticeData::old_wake_apart, the wake's node rows at most this many steps
  /// old (besides its newest, wake_edge_segments) are summed at the wing's points apart
  /// from the older ones, whose sums a coupled step may hold (old_wake_hold.hpp). A quarter
  /// cycle in a case (fsi_setup.cpp). Measured on the 12 × 20 hover (held against summed
  /// anew): off by up to 4·10⁻⁷ of the wake's velocity at 25 steps of 100 a cycle; by
  /// 2·10⁻⁶ there, and 4·10⁻⁵ at 10 steps, holding the last record without its secant.
  int young_wake_rows = 25;
  /// Far wake: wake nodes older than this [s] no longer move (they still induce velocity,
  /// and their velocity is not computed any more); 0: the whole wake is free.
  double frozen_wake_age = 0.0;
  /// Convected far wake: wake nodes older than this [s] move with the far-wake velocity of
  /// momentum theory (far_wake_velocity) instead of their induced velocity; they keep
  /// inducing velocity on the wing and on the younger wake, nothing is dropped. 0: off.
  /// Excludes frozen_wake_age.
  double far_wake_age = 0.0;
  /// The disk the stroke sweeps [m²] (momentum theory's actuator disk; for a wing of
  /// length R sweeping the angle Φ: Φ R²/2). Needed when far_wake_age > 0.
  double far_wake_disk_area = 0.0;
  /// The far wake moves with this multiple of the momentum-theory induced velocity v_i:
  /// 1 = the slipstream boundary, which moves with the mean of the jet's 2 v_i inside and
  /// the still air outside (docs/uvlm.md, "Far wake").
  double far_wake_speed_factor = 1.0;
  /// Fewest steps between rebuilds of the far wake's tree (it translates exactly in between,
  /// and the rows that join the far wake meanwhile are summed directly); the interval grows
  /// with the far wake (far_tree_rebuild_interval). With core growth the interval itself: the
  /// tree's cores are up to this many steps old. With max_wake_rows (the case's wake_max_rows) it is
  /// rebuilt every step.
  int far_tree_rebuild_steps = 10;
  /// True when the far wake is convected and summed by the tree code (for the wing and
  /// the younger wake alike), the younger wake by the direct sum.
  bool far_wake_by_tree() const { return far_wake_age > 0.0 && wake_sum == WakeSum::Tree; }
  /// The wake's self-induced velocity: direct sum or tree code (in double precision, to
  /// a relative error of tree_tolerance; the direct sum is used while the wake has fewer
  /// than tree_min_segments segments, where the tree does not pay). The leading-edge
  /// sheet's segments are part of the same set: the tree holds both, and sums both at the
  /// wake's and at the sheet's nodes.
  WakeSum wake_sum = WakeSum::Direct;
  double tree_tolerance = 1e-4;
  std::size_t tree_min_segments = 2000;
  /// Keep the influence coefficients of the rings off the last chordwise row while the
  /// surface moves rigidly (they do not change under a rigid motion of the whole lattice;
  /// the last row's rings end on the trailing-edge vortex, which moves with the edge's
  /// speed, and are recomputed every solve). false: the whole matrix at every solve
  /// (the reference for tests).
  bool reuse_rigid_influence = true;
  /// The circulations of lattices with at least this many panels are solved by GMRES
  /// (preconditioned_gmres.hpp) on the current influence matrix, preconditioned by the LU
  /// factorisation of an earlier one, to ‖r − A Γ‖₂ ≤ iterative_tolerance ‖r‖₂; the matrix
  /// is factorised anew only when a solve needs more than refactor_iterations iterations
  /// (or does not converge). Smaller lattices, a leading edge that sheds and the steady
  /// solve factorise every new matrix (the direct solve). 0: always the direct solve.
  /// docs/uvlm.md, "Solving for the circulations".
  int iterative_min_panels = 150;
  double iterative_tolerance = 1e-13;
  int refactor_iterations = 12;
  int iterative_restart = 30;        ///< GMRES restart length
  int iterative_max_iterations = 90; ///< then the direct solve
  bool iterative(int panels) const {
    return iterative_min_panels > 0 && panels >= iterative_min_panels && leading_edge != LeadingEdge::Shed &&
           !steady();
  }

  /// Steady lattice in every solve() when > 0 [m]: the wake is one straight row of this
  /// length along the free stream from the trailing-edge vortex (a horseshoe per strip,
  /// solve_steady), solved together with the bound rings; the surface velocities enter
  /// the boundary condition, ∂Γ/∂t is zero and advance() sheds and convects nothing. The
  /// result does not depend on Δt (for a wing at rest in a free stream; a moving wing gets
  /// the quasi-steady lattice of each instant). 0: the unsteady lattice.
  double steady_wake_length = 0.0;
  bool steady() const { return steady_wake_length > 0.0; }

  VortexCore bound_core() const { return {core.model, core.radius * bound_core_fraction}; }
  /// The leading-edge sheet's core (sheet_core_radius, or the wake's).
  VortexCore sheet_core() const { return {core.model, sheet_core_radius > 0.0 ? sheet_core_radius : core.radius}; }
  int panels() const { return chordwise * spanwise; }
  int nodes() const { return (chordwise + 1) * (spanwise + 1); }
  int panel(int i, int j) const { return i + chordwise * j; }
  int node(int i, int j) const { return i + (chordwise + 1) * j; }
};

/// Steps from a build of the far wake's tree (model.far_wake_by_tree) to the next: the
/// build costs about SegmentTree::kBuildPairsPerSegment × N direct pairs for its N segments,
/// and the rows that join the far wake until the next one are summed directly by the
/// `targets` points that see the far wake at each step (2 ns + 1 segments a row, k/2 rows on
/// average), so k = √(2 × 188 N / ((2 ns + 1) targets)) balances the two (their sum per step
/// is least there), at least model.far_tree_rebuild_steps. With core growth
/// model.far_tree_rebuild_steps itself (the tree's cores are as old as the tree). A 20-cycle
/// hover's far wake (40 771 segments, 621 targets): 34 steps; 300 cycles (629 000): 135.
long far_tree_rebuild_interval(const VortexLatticeModel& m, std::size_t segments, double targets);

/// Aerodynamic loads on the panels of the last solve (ground frame).
struct PanelLoads {
  Eigen::Matrix3Xd force;          ///< force on each panel, leading-edge force included [N]
  Eigen::Matrix3Xd point;          ///< its point of action (panel quarter chord, mid-span) [m]
  Eigen::Matrix3Xd point_velocity; ///< velocity of that point [m/s]
  /// The leading-edge part of `force` (zero off the leading-edge row): the suction in the
  /// panel plane (attached), the same magnitude along the normal (separated), or zero [N].
  Eigen::Matrix3Xd leading_edge_force;
  /// The ρ (∂Γ/∂t) A n part of `force` (the pressure's unsteady term; with the first-order
  /// rate its impulse over the step is ρ (Γₙ₊₁ − Γₙ) A n): a structure that splits the step
  /// holds it over the step rather than interpolating it (pipeline/fsi/fem_structure.hpp) [N]
  Eigen::Matrix3Xd unsteady_force;
  /// The laminar skin friction's part of `force` (skin_friction.hpp; zero without it) [N]
  Eigen::Matrix3Xd skin_friction_force;
  /// Suction of each strip, 3 × ns: the in-plane Kutta–Joukowski forces on its spanwise
  /// bound segments summed, before the leading-edge model acts on it [N]
  Eigen::Matrix3Xd suction;
  Eigen::VectorXd pressure_jump;   ///< force·n / area: pressure below minus above [Pa]
  Eigen::Vector3d total_force = Eigen::Vector3d::Zero();  ///< Σ force [N]
  /// Aerodynamic power the wing spends on the air, −Σ force · point_velocity [W]
  double power = 0.0;
};

/// Moment [N·m] of the panel forces about `point` [m].
Eigen::Vector3d moment_about(const PanelLoads& loads, const Eigen::Vector3d& point);

/// How the circulations of the solves so far were found (for benchmarks and docs).
struct LatticeSolverCounts {
  long solves = 0;            ///< linear solves (one per solve() with a new right-hand side)
  long factorisations = 0;    ///< LU factorisations of the influence matrix
  long iterative_solves = 0;  ///< solves by GMRES
  long iterations = 0;        ///< their GMRES iterations
  long held_old_wake = 0;     ///< solves that took the older wake's sums from the records (old_wake_hold.hpp)
  /// solves whose circulations were solved while the other threads summed the wake at the
  /// loads' points (detail::alongside_target_chunks)
  long beside_wake_sums = 0;
  /// sums at the collocation points after shedding that took the part before the edge's
  /// segments from the solve's first sum (VortexLatticeData::collocation_older)
  long reused_collocation_sums = 0;
  double worst_residual = 0;  ///< largest relative residual a GMRES solve returned
};

/// Mutable workspace of one lattice: geometry of the last solve, circulations, the
/// wake and the loads. Constructed once per run; nothing in solve/advance allocates.
struct VortexLatticeData {
  /// \throws std::invalid_argument for a model without panels, a core radius <= 0 or
  /// wake_capacity < 1.
  explicit VortexLatticeData(const VortexLatticeModel& model);

  // Surface geometry of the last solve (ground frame).
  Eigen::Matrix3Xd nodes;            ///< surface nodes [m]
  Eigen::Matrix3Xd node_velocities;  ///< [m/s]
  Eigen::Matrix3Xd ring_nodes;       ///< vortex-ring corners, (nc+1)(ns+1) [m]
  /// Per trailing-edge node j: the part of ¼ of the step's path of the edge relative to the
  /// air normal to the last panel, left out of the trailing-edge vortex (which stays in the
  /// panel's extension) and given back to the row shed from it (advance) [m]; 3 × (ns+1)
  Eigen::Matrix3Xd shed_lift;
  Eigen::Matrix3Xd collocation;      ///< three-quarter chord points [m]
  Eigen::Matrix3Xd normal;           ///< unit normals
  Eigen::Matrix3Xd chord_tangent;    ///< unit chordwise direction (toward the trailing edge)
  Eigen::Matrix3Xd span_tangent;     ///< unit spanwise direction (toward the tip)
  Eigen::VectorXd chord_length;      ///< panel chord [m]
  Eigen::VectorXd span_length;       ///< panel span [m]
  Eigen::VectorXd area;              ///< panel area [m²]
  Eigen::Matrix3Xd surface_velocity;  ///< surface velocity at the collocation points [m/s]
  Eigen::Matrix3Xd wake_velocity;     ///< wake-induced velocity at the collocation points [m/s]
  /// Of the Bernoulli loads of the last solve, per panel: the air's velocity relative to the
  /// panel at its collocation point [m/s] and the surface gradient of Γ [m/s] (zero after
  /// the Kutta–Joukowski route); the added-mass response's quasi-steady part uses them.
  Eigen::Matrix3Xd panel_air_velocity, panel_gamma_gradient;
  /// Of the loads of the last solve (both routes): the air's velocity relative to the
  /// surface at the midpoints of the spanwise bound segments of rows q < nc, segment
  /// q ns + j [m/s]; the leading-edge force's response uses it (leading_edge_response.hpp).
  Eigen::Matrix3Xd segment_air_velocity;
  /// Per strip: the side (+1, −1) its separated leading-edge force is held to within the
  /// current step, 0 where it follows Γ(0, j) (leading_edge_side.hpp).
  Eigen::VectorXi held_edge_side;
  /// The wing's sums over the older wake, kept apart to be held within a step
  /// (old_wake_hold.hpp; set by a caller that may hold them): the segments of the wake's
  /// model.young_wake_rows newest rows before the newest are then young_wake_segments, and
  /// each solve records what the older ones induce at the collocation points
  /// (old_wake[0]) and at the bound segments' midpoints (old_wake[1]).
  bool old_wake_apart = false;
  SegmentSet young_wake_segments;
  OldWakeRecord old_wake[2];
  bool old_wake_held = false;  ///< the solves take the records (until the next advance)
  /// With a shed leading edge a solve sums the wake and the sheet at the collocation points
  /// twice when strips shed, and between the two only the leading-edge rings' strengths
  /// change, whose segments are all in wake_edge_segments (leading_edge_sheet.hpp,
  /// kSheetEdgeRows). The first sum keeps here each point's velocity of the segments summed
  /// before those (the single-precision wake and sheet, the young rows); the second starts
  /// from it instead of summing them again: the same bits, a shorter sum (detail::OlderPart).
  PointSet collocation_older;          ///< its velocities [m/s] (u, v, w; positions unused)
  std::size_t collocation_older_size = 0;  ///< points kept by the last sum that kept them

  // Circulations [m²/s], panel index i + nc j.
  Eigen::VectorXd gamma;           ///< last solve
  Eigen::VectorXd gamma_accepted;  ///< last accepted step (for ∂Γ/∂t); zero before the first
  Eigen::VectorXd gamma_accepted_before;  ///< the accepted step before that (BDF2 ∂Γ/∂t)

  // Influence matrix (rebuilt when the surface moved) and a factorisation: of this matrix
  // (the direct solve), or of an earlier one, which preconditions GMRES (iterative solve).
  Eigen::MatrixXd influence;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::Matrix3Xd matrix_nodes;       ///< the nodes `influence` was built at
  Eigen::Matrix3Xd matrix_ring_nodes;  ///< the trailing-edge vortex moves with the edge's speed
  bool has_matrix = false;
  /// The last solve was the steady lattice's (solve_steady, model.steady()): its wake is
  /// seen through the bound rings' core (detail::steady_lattice_model), and the loads
  /// computed from it afterwards too.
  bool steady_solution = false;
  bool has_factorisation = false;      ///< lu holds a factorisation (possibly of an earlier matrix)
  bool factorisation_current = false;  ///< lu factorises `influence` itself
  InfluenceSegments influence_segments;  ///< the segments the matrix is built from (scratch)
  PreconditionedGmres gmres;           ///< storage of the iterative solve (model.iterative_min_panels)
  LatticeSolverCounts solver_counts;
  /// The nodes at which the whole influence matrix was last computed (its columns of the
  /// rings off the last row hold for every rigid motion of them; model.reuse_rigid_influence).
  Eigen::Matrix3Xd influence_nodes;
  bool has_influence = false;
  Eigen::VectorXd rhs;

  // Wake: node rows 0..wake_rows (row r, node j at r (ns+1) + j; row wake_rows follows
  // the trailing edge), ring r between rows r and r+1 with circulation wake_gamma[r ns + j].
  int wake_rows = 0;
  PointSet wake_nodes;
  std::vector<double> wake_gamma;
  std::vector<double> wake_prev_u, wake_prev_v, wake_prev_w;  ///< velocity of the last step (AB2)
  std::vector<char> wake_row_has_prev;
  std::vector<double> wake_row_age;  ///< time since each node row left the trailing edge [s]

  // Segment sets (unique segments with net circulation) and evaluation points.
  SegmentSet bound_segments;          ///< bound segments except the trailing edge
  SegmentSet trailing_edge_segments;  ///< the last rings' trailing segments (wake core)
  /// The free vortices' segments summed as one set (by the direct sum in the wake's
  /// precision, or the tree code): the trailing-edge wake's (build_wake_segments), then,
  /// with a leading edge that sheds, the leading-edge sheet's (build_sheet_segments).
  SegmentSet wake_segments;
  /// The segments that move with the wing within a step, when the wing's points see the
  /// free vortices in single precision (WakeView::Wing): summed in double. The wake's at
  /// its newest node row (it follows the trailing edge), then the sheet's at its
  /// kSheetEdgeRows node rows nearest the edge (the release row, placed at every solve, and
  /// the last step's) and its leading-edge ring's legs; empty otherwise (all in wake_segments).
  SegmentSet wake_edge_segments;
  /// How many of wake_segments, wake_edge_segments and young_wake_segments are the
  /// trailing-edge wake's (the sheet's follow them).
  std::size_t trailing_wake_segments = 0, trailing_wake_edge_segments = 0, trailing_young_wake_segments = 0;
  /// The same segments in lattice form (lattice_segments.hpp), for the wake's own direct
  /// sum in double precision (built with WakeView::Wake and !single_precision_wake only,
  /// without a leading-edge sheet: detail::wake_sum_by_lattice).
  LatticeSegments wake_lattice;
  /// The convected far wake's segments when it is summed by the tree code
  /// (far_wake_age > 0 and wake_sum = Tree); empty otherwise (all in wake_segments).
  SegmentSet far_wake_segments;
  int far_tree_rows = 0;     ///< node rows of the far wake in the tree (0: no tree)
  long far_tree_step = 0;    ///< accepted_steps when the tree was built
  long far_tree_interval = 0;  ///< steps from that build to the next (far_tree_rebuild_interval)
  Eigen::Vector3d far_tree_shift = Eigen::Vector3d::Zero();  ///< far-wake displacement since [m]
  PointSet far_targets;      ///< target points moved back by far_tree_shift (scratch)
  SegmentTree wake_tree;              ///< the tree code's storage (model.wake_sum = Tree)
  /// The vortex sheet shed from the leading edge (model.leading_edge = Shed; empty otherwise).
  LeadingEdgeSheet le_sheet;
  SegmentSet horseshoe;  ///< the steady solve's unit horseshoe (scratch)
  PointSet eval;
  /// The first this many points of eval hold the bound segments' midpoints with the wake's
  /// velocity summed there while the circulations were solved (solve; 0: none).
  std::size_t wake_summed_at_eval = 0;

  PanelLoads loads;

  // Inputs of the last solve.
  Eigen::Vector3d free_stream = Eigen::Vector3d::Zero();  ///< [m/s]
  double dt = 0.0;    ///< [s]
  double rho = 0.0;   ///< [kg/m³]
  long accepted_steps = 0;
  /// Σ total_force dt over the accepted steps [N s] and Σ dt [s]: the mean aerodynamic
  /// force so far (the thrust of the far wake's momentum theory).
  Eigen::Vector3d force_impulse = Eigen::Vector3d::Zero();
  double force_time = 0.0;

  int spanwise = 0;       ///< ns (copied from the model)
  int wake_capacity = 0;  ///< wake rows the storage holds
  int wake_panels() const { return wake_rows * spanwise; }
};

/// Solve for the ring circulations and loads of the given surface; the wake is not
/// changed (call again freely within a step). Loads by model.load_method.
/// \param nodes            surface nodes, 3 × (nc+1)(ns+1), ground frame [m]
/// \param node_velocities  their velocities [m/s]
/// \param free_stream      air velocity far away [m/s] (zero in hover)
/// \param dt               time step [s] (for ∂Γ/∂t and the next advance)
/// \param rho              air density [kg/m³]
/// \throws std::invalid_argument on wrong sizes or non-positive dt/rho
void solve(const VortexLatticeModel& model, VortexLatticeData& data, const Eigen::Matrix3Xd& nodes,
           const Eigen::Matrix3Xd& node_velocities, const Eigen::Vector3d& free_stream, double dt,
           double rho);

/// Factorise the influence matrix of the last solve unless its factorisation is current
/// (the iterative path, model.iterative(), keeps an earlier matrix's): the right-hand
/// sides of added_mass_force_change are then solved directly, and the next solves' GMRES
/// is preconditioned by this matrix. The last solve's results are not changed.
void factorise_current_matrix(VortexLatticeData& data);

/// Accept the last solve: convect the wake over dt and shed one row from the trailing edge
/// (with model.steady(): only accept the circulations and count the force impulse).
/// \throws std::length_error when the wake would exceed model.wake_capacity rows
void advance(const VortexLatticeModel& model, VortexLatticeData& data);

/// Velocity [m/s] of the convected far wake (model.far_wake_age): the free stream plus
/// k v_i along −F̄/|F̄|, with F̄ the mean aerodynamic force of the accepted steps, k =
/// model.far_wake_speed_factor and v_i the induced velocity of momentum theory at the disk
/// of area A = model.far_wake_disk_area (Glauert's relation, Leishman 2006 ch. 2):
///     v_i |V∞ − v_i F̂| = |F̄| / (2 ρ A),   hover (V∞ = 0): v_i = sqrt(|F̄| / (2 ρ A)).
/// The free stream alone before any step was accepted or while F̄ = 0.
Eigen::Vector3d far_wake_velocity(const VortexLatticeModel& model, const VortexLatticeData& data);

/// Steady solution of a fixed surface in a uniform stream: the wake is one straight row of
/// length wake_length along the free stream with the trailing-edge circulation (a
/// horseshoe per spanwise strip), solved together with the bound rings (exact Kutta).
/// Leaves gamma_accepted = gamma (no ∂Γ/∂t) and the loads by model.load_method.
/// \param wake_length  [m], e.g. 100 chords
void solve_steady(const VortexLatticeModel& model, VortexLatticeData& data,
                  const Eigen::Matrix3Xd& nodes, const Eigen::Vector3d& free_stream, double rho,
                  double wake_length);

/// The same with the straight wake along wake_direction (need not be unit; its component
/// along the free stream must be > 0) instead of the free stream: e.g. in the wing's plane,
/// the wake of linear lifting-surface theory, which Polhamus' potential-lift constant
/// assumes (docs/uvlm.md, "Leading edge").
void solve_steady(const VortexLatticeModel& model, VortexLatticeData& data,
                  const Eigen::Matrix3Xd& nodes, const Eigen::Vector3d& free_stream, double rho,
                  double wake_length, const Eigen::Vector3d& wake_direction);

/// Loads by the unsteady Bernoulli equation on the last solve (fills data.loads):
///   Δp = ρ (V · ∇_s Γ + ∂Γ/∂t)
/// with ∇_s Γ the surface gradient of Γ from its differences along the panel's two edge
/// directions through the panel's dual basis (right on any quadrilateral, not only on
/// orthogonal panels), V the air velocity relative to the panel at its collocation point,
/// and ∂Γ/∂t following the panel (BDF2 over the accepted steps). The leading-edge row gets
/// the leading-edge force of model.leading_edge in addition.
void compute_bernoulli_loads(const VortexLatticeModel& model, VortexLatticeData& data);

/// Loads by Kutta–Joukowski on each bound segment (velocity at its midpoint without the
/// segment's own influence; the trailing-edge segment is part of the shed wake and
/// carries no load) plus ρ ∂Γ/∂t A n per panel (fills data.loads). The in-plane force on
/// the leading-edge segments is the suction: kept, turned or dropped by model.leading_edge.
void compute_kutta_joukowski_loads(const VortexLatticeModel& model, VortexLatticeData& data);

/// Lift and induced drag of a steady solve (solve_steady) from the circulation its
/// straight wake carries far downstream (the Trefftz plane; Katz & Plotkin §8.3):
///   D = (ρ/2) Σ_j Γ_j w_j |s_j|,  L = ρ |V∞| Σ_j Γ_j |s_j|,
/// s_j the trailing-edge segment of strip j projected onto the plane normal to V∞, w_j the
/// downwash at its midpoint from the trailing vortices Γ_j − Γ_(j−1) as 2-D point vortices.
struct TrefftzPlaneLoads {
  double lift = 0.0;  ///< [N]
  double drag = 0.0;  ///< induced drag [N]
};
TrefftzPlaneLoads trefftz_plane_loads(const VortexLatticeModel& model, const VortexLatticeData& data);

}  // namespace flapsim::uvlm
