#include "uvlm/vortex_lattice.hpp"

#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/lattice_internal.hpp"
#include "uvlm/load_terms.hpp"
#include "uvlm/old_wake_hold.hpp"
#include "uvlm/rigid_motion.hpp"
#include "uvlm/skin_friction.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

VortexLatticeData::VortexLatticeData(const VortexLatticeModel& m) {
  if (m.chordwise < 1 || m.spanwise < 1)
    throw std::invalid_argument("vortex lattice: chordwise and spanwise panel counts must be >= 1");
  if (!(m.core.radius > 0.0) || !(m.bound_core_fraction > 0.0))
    throw std::invalid_argument("vortex lattice: core radius and bound core fraction must be > 0");
  if (m.wake_capacity < 1) throw std::invalid_argument("vortex lattice: wake_capacity must be >= 1");
  if (m.max_wake_rows < 0) throw std::invalid_argument("vortex lattice: max_wake_rows must be >= 0");
  if (m.young_wake_rows < 0) throw std::invalid_argument("vortex lattice: young_wake_rows must be >= 0");
  if (m.wake_sum == WakeSum::Tree && !(m.tree_tolerance > 0.0))
    throw std::invalid_argument("vortex lattice: tree tolerance must be > 0");
  if (!(m.near_wing_core >= 0.0) || !(m.frozen_wake_age >= 0.0) || !(m.near_wing_min_age >= 0.0))
    throw std::invalid_argument("vortex lattice: near-wing core and frozen-wake age must be >= 0");
  if (!(m.far_wake_age >= 0.0) || (m.far_wake_age > 0.0 && m.frozen_wake_age > 0.0))
    throw std::invalid_argument("vortex lattice: far-wake age must be >= 0 and excludes a frozen wake");
  if (m.far_wake_age > 0.0 && (!(m.far_wake_disk_area > 0.0) || !(m.far_wake_speed_factor > 0.0)))
    throw std::invalid_argument("vortex lattice: a convected far wake needs a disk area and speed factor > 0");
  if (m.leading_edge == LeadingEdge::Shed && !(m.lesp_critical > 0.0))
    throw std::invalid_argument("vortex lattice: the critical leading-edge suction parameter must be > 0");
  if (!(m.sheet_core_radius >= 0.0) || !std::isfinite(m.sheet_core_radius))
    throw std::invalid_argument("vortex lattice: the leading-edge sheet's core radius must be >= 0 (0: the wake's)");
  if (m.core_growth.enabled &&
      (!(m.core_growth.kinematic_viscosity > 0.0) || !(m.core_growth.squire_a1 >= 0.0)))
    throw std::invalid_argument("vortex lattice: core growth needs a viscosity > 0 and a1 >= 0");
  const int nc = m.chordwise, ns = m.spanwise, np = m.panels(), nn = m.nodes();
  spanwise = ns;
  wake_capacity = m.wake_capacity;

  nodes.setZero(3, nn);
  node_velocities.setZero(3, nn);
  ring_nodes.setZero(3, nn);
  collocation.setZero(3, np);
  normal.setZero(3, np);
  chord_tangent.setZero(3, np);
  span_tangent.setZero(3, np);
  chord_length.setZero(np);
  span_length.setZero(np);
  area.setZero(np);
  surface_velocity.setZero(3, np);
  wake_velocity.setZero(3, np);
  panel_air_velocity.setZero(3, np);
  panel_gamma_gradient.setZero(3, np);
  segment_air_velocity.setZero(3, np);
  held_edge_side.setZero(ns);
  gamma.setZero(np);
  gamma_accepted.setZero(np);
  gamma_accepted_before.setZero(np);
  influence.setZero(np, np);
  lu = Eigen::PartialPivLU<Eigen::MatrixXd>(np);
  matrix_nodes.setZero(3, nn);
  matrix_ring_nodes.setZero(3, nn);
  shed_lift.setZero(3, ns + 1);
  influence_nodes.setZero(3, nn);
  rhs.setZero(np);

  // One spare row: the steady solve's horseshoe row and the row being shed.
  const std::size_t rows = static_cast<std::size_t>(wake_capacity) + 1;
  const std::size_t wake_nodes_n = (rows + 1) * (ns + 1);
  wake_nodes.reserve(wake_nodes_n);
  wake_gamma.assign(rows * ns, 0.0);
  wake_prev_u.assign(wake_nodes_n, 0.0);
  wake_prev_v.assign(wake_nodes_n, 0.0);
  wake_prev_w.assign(wake_nodes_n, 0.0);
  wake_row_has_prev.assign(rows + 1, 0);
  wake_row_age.assign(rows + 1, 0.0);

  const std::size_t bound_n = static_cast<std::size_t>((nc + 1) * ns + nc * (ns + 1));
  bound_segments.reserve(bound_n);
  trailing_edge_segments.reserve(ns);
  // With a leading edge that sheds, the sheet's segments (of up to model.sheet_capacity
  // rings, else wake_capacity + 1; le_sheet.allocate below) join the wake's.
  const bool sheds = m.leading_edge == LeadingEdge::Shed;
  const int sheet_rings = m.sheet_capacity > 0 ? m.sheet_capacity : wake_capacity + 1;
  wake_segments.reserve((rows + 1) * ns + rows * (ns + 1) + (sheds ? sheet_segment_capacity(ns, sheet_rings) : 0));
  wake_edge_segments.reserve(static_cast<std::size_t>(2 * ns + 1) + (sheds ? sheet_edge_segment_capacity(ns) : 0));
  wake_lattice.reserve(wake_nodes_n, static_cast<std::size_t>(ns) + 1);
  // (and as many of the sheet's, which gains a node row a step at most: old_wake_hold.hpp)
  young_wake_segments.reserve(static_cast<std::size_t>(m.young_wake_rows + 1) * (2 * ns + 1) *
                              (sheds ? 2 : 1));
  old_wake[0].reserve(static_cast<std::size_t>(np));
  old_wake[1].reserve(bound_n);
  if (m.far_wake_by_tree()) {
    far_wake_segments.reserve(wake_segments.capacity());
    far_targets.reserve(std::max(wake_nodes_n, std::max<std::size_t>(bound_n, np)));
  }
  if (m.wake_sum == WakeSum::Tree) wake_tree.reserve(wake_segments.capacity());
  influence_segments.reserve(nc, ns, omp_get_max_threads());
  horseshoe.reserve(4);
  if (m.iterative_min_panels > 0 && np >= m.iterative_min_panels) gmres.reserve(np, m.iterative_restart);
  eval.reserve(std::max<std::size_t>(bound_n, np));

  if (sheds) {
    le_sheet.allocate(ns, np, sheet_rings);
    collocation_older.reserve(static_cast<std::size_t>(np));
  }

  loads.force.setZero(3, np);
  loads.point.setZero(3, np);
  loads.point_velocity.setZero(3, np);
  loads.leading_edge_force.setZero(3, np);
  loads.skin_friction_force.setZero(3, np);
  loads.unsteady_force.setZero(3, np);
  loads.suction.setZero(3, ns);
  loads.pressure_jump.setZero(np);
}

Eigen::Vector3d moment_about(const PanelLoads& loads, const Eigen::Vector3d& point) {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (Eigen::Index k = 0; k < loads.force.cols(); ++k)
    m += (loads.point.col(k) - point).cross(loads.force.col(k));
  return m;
}

namespace detail {

namespace {

/// The trailing-edge vortex at trailing-edge node j (update_geometry in lattice_internal.hpp):
/// the corner of the last rings' rear segment, in the extension of the last panel's
/// chordwise side, behind the edge by a = a quarter of the chordwise part of the step's path
/// of the edge relative to the air, ¼ (V∞ − v_j) Δt = a t + b e + c n in the oblique basis
/// (t chordwise, e along the edge, n the normal), and at least
/// kMinTrailingEdgeVortexFraction of the last panel's chord; a quarter of that chord when
/// there is no time step (the steady solve). `lift` receives c n, the path's part normal
/// to the panel, which the shed row gets back when it leaves (advance).
Eigen::Vector3d trailing_edge_vortex_node(const VortexLatticeModel& m, const Eigen::Matrix3Xd& P,
                                          const Eigen::Matrix3Xd& V, int j,
                                          const Eigen::Vector3d& free_stream, double dt,
                                          Eigen::Ref<Eigen::Vector3d> lift) {
  const int nc = m.chordwise, ns = m.spanwise;
  lift.setZero();
  const Eigen::Vector3d te = P.col(m.node(nc, j)), last = te - P.col(m.node(nc - 1, j));
  const double panel = last.norm();  // chord of the trailing-edge panel [m]
  if (!(dt > 0.0) || !(panel > 0.0)) return te + 0.25 * last;  // steady, or a tip of zero chord
  const Eigen::Vector3d t = last / panel;  // chordwise, toward the wake
  const Eigen::Vector3d e =
      (P.col(m.node(nc, std::min(j + 1, ns))) - P.col(m.node(nc, std::max(j - 1, 0)))).normalized();
  const double cos_te = t.dot(e);
  const double min_behind = kMinTrailingEdgeVortexFraction * panel;
  const Eigen::Vector3d s = 0.25 * dt * (free_stream - V.col(m.node(nc, j)));  // [m]
  if (!(1.0 - cos_te * cos_te > 1e-12)) return te + std::max(s.dot(t), min_behind) * t;  // degenerate corner
  const Eigen::Vector3d n = e.cross(t).normalized();
  // s = (s·n) n + a t + b e: the chordwise part a, at least min_behind; b e dropped.
  const Eigen::Vector3d w = s - s.dot(n) * n;
  const double a = (w.dot(t) - w.dot(e) * cos_te) / (1.0 - cos_te * cos_te);
  lift = s.dot(n) * n;
  return te + std::max(a, min_behind) * t;
}

}  // namespace

void update_geometry(const VortexLatticeModel& m, VortexLatticeData& d, const Eigen::Matrix3Xd& P,
                     const Eigen::Matrix3Xd& V, const Eigen::Vector3d& free_stream, double dt) {
  const int nc = m.chordwise, ns = m.spanwise;
  d.nodes = P;
  d.node_velocities = V;
  for (int j = 0; j <= ns; ++j) {
    for (int i = 0; i < nc; ++i)
      d.ring_nodes.col(m.node(i, j)) = P.col(m.node(i, j)) + 0.25 * (P.col(m.node(i + 1, j)) - P.col(m.node(i, j)));
    d.ring_nodes.col(m.node(nc, j)) = trailing_edge_vortex_node(m, P, V, j, free_stream, dt, d.shed_lift.col(j));
  }
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const int k = m.panel(i, j);
      const auto a = P.col(m.node(i, j)), b = P.col(m.node(i + 1, j));
      const auto c = P.col(m.node(i, j + 1)), e = P.col(m.node(i + 1, j + 1));
      d.collocation.col(k) = three_quarter_chord(m, P, i, j);
      d.surface_velocity.col(k) = three_quarter_chord(m, V, i, j);
      const Eigen::Vector3d d1 = e - a;  // toward trailing edge and tip
      const Eigen::Vector3d d2 = c - b;  // toward tip and leading edge
      const Eigen::Vector3d n = d2.cross(d1);
      d.area(k) = 0.5 * n.norm();
      d.normal.col(k) = n / n.norm();
      const Eigen::Vector3d tc = 0.5 * ((b + e) - (a + c));
      const Eigen::Vector3d ts = 0.5 * ((c + e) - (a + b));
      d.chord_length(k) = tc.norm();
      d.span_length(k) = ts.norm();
      d.chord_tangent.col(k) = tc / d.chord_length(k);
      d.span_tangent.col(k) = ts / d.span_length(k);
    }
}

void build_bound_segments(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise;
  const bool sheet = d.le_sheet.active();  // ring −1: the leading-edge ring (leading_edge_sheet.hpp)
  auto G = [&](int i, int j) {
    if (sheet && i == -1 && j >= 0 && j < ns) return d.le_sheet.current(j);
    return (i < 0 || i >= nc || j < 0 || j >= ns) ? 0.0 : d.gamma(m.panel(i, j));
  };
  d.bound_segments.clear();
  d.trailing_edge_segments.clear();
  push_ring_segments(m, d.ring_nodes, G, d.bound_segments, d.trailing_edge_segments);
}

namespace {

/// The sums of induced_at_eval_points over chunks of d.eval's points (lattice_internal.hpp).
struct EvalSums {
  const VortexLatticeModel& m;
  VortexLatticeData& d;
  int slot;     ///< the wing's point set (WingPoints), −1 for none
  bool held;    ///< the older wake's part from its record
  bool record;  ///< the older wake's part recorded

  bool keep_older = false;   ///< the part before the edge's segments kept (VortexLatticeData::collocation_older)
  bool reuse_older = false;  ///< … and taken from there instead of summed

  EvalSums(const VortexLatticeModel& model, VortexLatticeData& data, std::size_t n, WingPoints points,
           OlderPart older_part = OlderPart::None)
      : m(model), d(data), slot(static_cast<int>(points)) {
    const bool apart = slot >= 0 && old_wake_kept_apart(m, d);
    held = apart && d.old_wake_held && d.old_wake[slot].size == n;
    const bool older =
        points == WingPoints::Collocation && m.single_precision_wake && d.collocation_older.x.size() >= n;
    keep_older = older && older_part == OlderPart::Keep;
    reuse_older = older && older_part == OlderPart::Reuse && d.collocation_older_size == n;
    record = apart && !held && !reuse_older;
  }
  bool far() const { return d.far_tree_rows > 0 && d.far_wake_segments.size() > 0; }
  std::size_t wake_segments() const {
    if (reuse_older) return d.wake_edge_segments.size();
    return (held ? 0 : d.wake_segments.size()) + d.young_wake_segments.size() + d.wake_edge_segments.size();
  }
  std::size_t bound_segments() const { return d.bound_segments.size() + d.trailing_edge_segments.size(); }
  /// Before the wake's sums: the single-precision copies.
  void prepare_wake() {
    if (reuse_older) return;
    if (m.single_precision_wake && !held) d.wake_segments.update_single_precision();
    if (d.young_wake_segments.size() > 0) d.young_wake_segments.update_single_precision();
  }
  /// The wake's direct sums (the whole or the older part held, then the younger rows and
  /// the edge's segments) at points i0 … i0 + c − 1.
  void wake(std::size_t i0, std::size_t c) {
    PointSet& e = d.eval;
    const double *x = e.x.data() + i0, *y = e.y.data() + i0, *z = e.z.data() + i0;
    double *u = e.u.data() + i0, *v = e.v.data() + i0, *w = e.w.data() + i0;
    PointSet& older = d.collocation_older;
    if (reuse_older) {  // the sums before the edge's segments, as the last Keep left them
      std::copy_n(older.u.data() + i0, c, u);
      std::copy_n(older.v.data() + i0, c, v);
      std::copy_n(older.w.data() + i0, c, w);
    } else {
      if (held) {
        d.old_wake[slot].held(i0, c, x, y, z, u, v, w);
      } else if (m.single_precision_wake) {
        add_induced_velocity_single(d.wake_segments, x, y, z, c, u, v, w, m.core);
      } else {
        add_induced_velocity(d.wake_segments, x, y, z, c, u, v, w, m.core);
      }
      if (record) d.old_wake[slot].record(i0, c, x, y, z, u, v, w);  // the older wake's part alone
      if (d.young_wake_segments.size() > 0)
        add_induced_velocity_single(d.young_wake_segments, x, y, z, c, u, v, w, m.core);
      if (keep_older) {
        std::copy_n(u, c, older.u.data() + i0);
        std::copy_n(v, c, older.v.data() + i0);
        std::copy_n(w, c, older.w.data() + i0);
      }
    }
    if (d.wake_edge_segments.size() > 0) add_induced_velocity(d.wake_edge_segments, x, y, z, c, u, v, w, m.core);
  }
  /// After the wake's sums at all n points.
  void finish_wake(std::size_t n) {
    if (record) d.old_wake[slot].finish(n);
    if (keep_older) d.collocation_older_size = n;
    if (reuse_older) ++d.solver_counts.reused_collocation_sums;
    if (slot == static_cast<int>(WingPoints::Collocation) && held) ++d.solver_counts.held_old_wake;
  }
  /// The bound and trailing-edge segments' sums at points i0 … i0 + c − 1.
  void bound(std::size_t i0, std::size_t c) {
    PointSet& e = d.eval;
    const double *x = e.x.data() + i0, *y = e.y.data() + i0, *z = e.z.data() + i0;
    double *u = e.u.data() + i0, *v = e.v.data() + i0, *w = e.w.data() + i0;
    add_induced_velocity(d.bound_segments, x, y, z, c, u, v, w, m.bound_core());
    add_induced_velocity(d.trailing_edge_segments, x, y, z, c, u, v, w, m.core);
  }
};

}  // namespace

void induced_at_eval_points(const VortexLatticeModel& m, VortexLatticeData& d, std::size_t n,
                            bool include_bound, WingPoints points, OlderPart older) {
  d.eval.size = n;
  if (include_bound && d.wake_summed_at_eval == n && n > 0) {
    // The wake's part is there already (wake_at_eval_points_alongside): the bound's added.
    d.wake_summed_at_eval = 0;
    EvalSums sums(m, d, n, WingPoints::None);
    for_target_chunks(n, n * sums.bound_segments(), [&](std::size_t i0, std::size_t c) { sums.bound(i0, c); });
    return;
  }
  d.wake_summed_at_eval = 0;
  d.eval.zero_velocity();
  PointSet& e = d.eval;
  // Wake (and leading-edge sheet: wake_segments holds both), far wake (tree), then bound
  // and trailing-edge segments: at each point the sums in this order, the direct ones in
  // one parallel region unless the far wake's tree comes between them (lattice_internal.hpp).
  EvalSums sums(m, d, n, points, older);
  const bool far = sums.far();
  const bool bound_with_wake = include_bound && !far;
  sums.prepare_wake();
  const std::size_t segments = sums.wake_segments() + (bound_with_wake ? sums.bound_segments() : 0);
  if (segments > 0)
    for_target_chunks(n, n * segments, [&](std::size_t i0, std::size_t c) {
      sums.wake(i0, c);
      if (bound_with_wake) sums.bound(i0, c);
    });
  sums.finish_wake(n);
  if (far) {
    add_far_wake_velocity(d, e.x.data(), e.y.data(), e.z.data(), n, e.u.data(), e.v.data(), e.w.data());
    if (include_bound)
      for_target_chunks(n, n * sums.bound_segments(), [&](std::size_t i0, std::size_t c) { sums.bound(i0, c); });
  }
}

bool wake_at_eval_points_alongside(const VortexLatticeModel& m, VortexLatticeData& d, std::size_t n,
                                   WingPoints points, const std::function<void()>& solo) {
  EvalSums sums(m, d, n, points);
  if (sums.far() || n == 0) return false;
  d.eval.size = n;
  d.eval.zero_velocity();
  sums.prepare_wake();
  if (alongside_target_chunks(n, n * sums.wake_segments(), solo, [&](std::size_t i0, std::size_t c) { sums.wake(i0, c); }))
    ++d.solver_counts.beside_wake_sums;
  sums.finish_wake(n);
  d.wake_summed_at_eval = n;
  return true;
}

void set_bound_midpoints(VortexLatticeData& d, std::size_t n) {
  const auto& S = d.bound_segments;
  for (std::size_t s = 0; s < n; ++s) {
    d.eval.x[s] = 0.5 * (S.ax()[s] + S.bx()[s]);
    d.eval.y[s] = 0.5 * (S.ay()[s] + S.by()[s]);
    d.eval.z[s] = 0.5 * (S.az()[s] + S.bz()[s]);
  }
}

void induced_at_bound_midpoints(const VortexLatticeModel& m, VortexLatticeData& d, std::size_t n) {
  const auto& S = d.bound_segments;
  if (d.wake_summed_at_eval != n) set_bound_midpoints(d, n);  // else set, and the wake summed there
  induced_at_eval_points(m, d, n, true, WingPoints::Midpoints);
  for (std::size_t s = 0; s < n; ++s) {
    const Eigen::Vector3d own = segment_velocity(S, s, d.eval.position(s), m.bound_core());
    d.eval.u[s] -= own.x();
    d.eval.v[s] -= own.y();
    d.eval.w[s] -= own.z();
  }
}

void compute_loads(const VortexLatticeModel& m, VortexLatticeData& d) {
  if (m.load_method == LoadMethod::Bernoulli)
    compute_bernoulli_loads(m, d);
  else
    compute_kutta_joukowski_loads(m, d);
  if (m.skin_friction_viscosity > 0.0) {
    add_skin_friction(m, d);
    finish_loads(d);  // the totals and the power again, friction included
  }
}

}  // namespace detail

namespace {

void check_inputs(const VortexLatticeModel& m, const Eigen::Matrix3Xd& nodes,
                  const Eigen::Matrix3Xd& vel, double dt, double rho) {
  if (nodes.cols() != m.nodes() || vel.cols() != m.nodes())
    throw std::invalid_argument("vortex lattice: expected " + std::to_string(m.nodes()) +
                                " surface nodes and velocities, got " + std::to_string(nodes.cols()) +
                                " and " + std::to_string(vel.cols()));
  if (!(dt > 0.0)) throw std::invalid_argument("vortex lattice: time step must be > 0");
  if (!(rho > 0.0)) throw std::invalid_argument("vortex lattice: air density must be > 0");
}

/// Wake-induced velocity at the collocation points into d.wake_velocity (`older`:
/// detail::OlderPart).
void wake_velocity_at_collocation(const VortexLatticeModel& m, VortexLatticeData& d,
                                  detail::OlderPart older = detail::OlderPart::None) {
  const int np = m.panels();
  for (int k = 0; k < np; ++k) d.eval.set(k, d.collocation.col(k));
  detail::induced_at_eval_points(m, d, np, false, detail::WingPoints::Collocation, older);
  for (int k = 0; k < np; ++k) d.wake_velocity.col(k) = d.eval.velocity(k);
}

/// The influence matrix of the current rings, rebuilt when the surface moved since it was built.
void update_influence(const VortexLatticeModel& m, VortexLatticeData& d) {
  if (d.has_matrix && d.nodes == d.matrix_nodes && d.ring_nodes == d.matrix_ring_nodes) return;
  // Under a rigid motion of the whole surface only the last row's columns change (their
  // rings end on the trailing-edge vortex, which follows the edge's speed): the others
  // are kept from the last full computation (against whose nodes the motion is checked,
  // so nothing accumulates).
  const bool rigid = m.reuse_rigid_influence && d.has_influence && is_rigid_motion(d.influence_nodes, d.nodes);
  detail::build_influence(m, d, rigid);
  if (!rigid) {
    d.influence_nodes = d.nodes;
    d.has_influence = true;
  }
  d.matrix_nodes = d.nodes;
  d.matrix_ring_nodes = d.ring_nodes;
  d.has_matrix = true;
  d.factorisation_current = false;
}

void factorise(VortexLatticeData& d) {
  d.lu.compute(d.influence);
  d.has_factorisation = true;
  d.factorisation_current = true;
  ++d.solver_counts.factorisations;
}

/// d.gamma = A⁻¹ d.rhs: by the factorisation of A (the direct solve), or by GMRES from the
/// last circulations, preconditioned by the factorisation of an earlier A (model.iterative).
void solve_circulations(const VortexLatticeModel& m, VortexLatticeData& d) {
  ++d.solver_counts.solves;
  if (!d.factorisation_current && !(m.iterative(m.panels()) && d.has_factorisation)) factorise(d);
  if (d.factorisation_current) {
    d.gamma = d.lu.solve(d.rhs);
    return;
  }
  const PreconditionedGmres::Result r =
      d.gmres.solve(d.influence, d.lu, d.rhs, d.gamma, m.iterative_tolerance, m.iterative_max_iterations);
  ++d.solver_counts.iterative_solves;
  d.solver_counts.iterations += r.iterations;
  if (!r.converged) {  // the earlier factorisation is too far from this matrix
    factorise(d);
    d.gamma = d.lu.solve(d.rhs);
    return;
  }
  d.solver_counts.worst_residual = std::max(d.solver_counts.worst_residual, r.relative_residual);
  // The matrix has moved far from the factorised one: factorise this one for the next solves.
  if (r.iterations > m.refactor_iterations) factorise(d);
}

}  // namespace

namespace {

/// The steady lattice (solve_steady), with the surface velocities in the boundary condition.
void solve_steady_lattice(const VortexLatticeModel& model, VortexLatticeData& d,
                          const Eigen::Matrix3Xd& nodes, const Eigen::Matrix3Xd& node_velocities,
                          const Eigen::Vector3d& free_stream, double rho, double wake_length,
                          const Eigen::Vector3d& wake_direction) {
  const VortexLatticeModel m = detail::steady_lattice_model(model);
  d.steady_solution = true;
  if (!(free_stream.norm() > 0.0) || !(wake_length > 0.0))
    throw std::invalid_argument("steady vortex lattice: needs a free stream and a wake length > 0");
  if (!(wake_direction.dot(free_stream) > 0.0))
    throw std::invalid_argument("steady vortex lattice: the wake must leave downstream");
  const int nc = m.chordwise, ns = m.spanwise, np = m.panels();
  d.free_stream = free_stream;
  d.dt = 1.0;
  d.rho = rho;
  detail::update_geometry(m, d, nodes, node_velocities, free_stream, 0.0);  // no time step: ¼ panel
  detail::build_influence(m, d);
  d.has_factorisation = d.factorisation_current = false;  // the matrix below includes the wake
  d.has_matrix = d.has_influence = false;

  // One straight wake row, trailing-edge row 1 and far row 0, carried by the trailing-edge ring.
  const Eigen::Vector3d dir = wake_direction.normalized();
  d.wake_rows = 1;
  d.wake_nodes.size = 2 * (ns + 1);
  for (int j = 0; j <= ns; ++j) {
    const Eigen::Vector3d te = d.ring_nodes.col(m.node(nc, j));
    d.wake_nodes.set(ns + 1 + j, te);
    d.wake_nodes.set(j, te + wake_length * dir);
  }
  // Influence of each unit horseshoe (wake ring j, traversed like a bound ring) joins the
  // column of ring (nc−1, j).
  SegmentSet& horseshoe = d.horseshoe;
  for (int k = 0; k < np; ++k) d.eval.set(k, d.collocation.col(k));
  for (int j = 0; j < ns; ++j) {
    const Eigen::Vector3d f0 = d.wake_nodes.position(ns + 1 + j), f1 = d.wake_nodes.position(ns + 2 + j);
    const Eigen::Vector3d r0 = d.wake_nodes.position(j), r1 = d.wake_nodes.position(j + 1);
    horseshoe.clear();
    horseshoe.push(f1, f0, 1.0);
    horseshoe.push(f0, r0, 1.0);
    horseshoe.push(r0, r1, 1.0);
    horseshoe.push(r1, f1, 1.0);
    d.eval.size = np;
    d.eval.zero_velocity();
    add_induced_velocity(horseshoe, d.eval, m.core);
    for (int k = 0; k < np; ++k)
      d.influence(k, m.panel(nc - 1, j)) += d.eval.velocity(k).dot(d.normal.col(k));
  }
  d.lu.compute(d.influence);
  for (int k = 0; k < np; ++k)
    d.rhs(k) = -(free_stream - d.surface_velocity.col(k)).dot(d.normal.col(k));
  d.gamma = d.lu.solve(d.rhs);
  d.gamma_accepted = d.gamma;
  d.gamma_accepted_before = d.gamma;
  for (int j = 0; j < ns; ++j) d.wake_gamma[j] = d.gamma(m.panel(nc - 1, j));
  detail::build_wake_segments(m, d, detail::WakeView::Wing);
  wake_velocity_at_collocation(m, d);
  detail::build_bound_segments(m, d);
  detail::compute_loads(m, d);
}

}  // namespace

namespace detail {

/// The steady lattice's straight wake (the trailing-edge vortex and the horseshoes) is seen
/// through the bound rings' core. The wake's core (model.core, 0.2 mean chords from a case)
/// smooths a wake that the wing meets again; this wake never comes back, and that core
/// beside the last panels' collocation points smoothed the horseshoes' legs and raised the
/// lift with the core (an elliptic AR 4 wing at 5°, 8 × 16: CL 0.3484 with 0.2 c̄, 0.3323
/// with 0.05 c̄ and 0.02 c̄; docs/uvlm.md, "Steady lattice").
VortexLatticeModel steady_lattice_model(const VortexLatticeModel& m) {
  VortexLatticeModel s = m;
  s.core.radius = m.bound_core().radius;
  s.bound_core_fraction = 1.0;
  s.near_wing_core = 0.0;
  s.core_growth.enabled = false;
  return s;
}

}  // namespace detail

void factorise_current_matrix(VortexLatticeData& d) {
  if (d.has_matrix && !d.factorisation_current) factorise(d);
}

void solve(const VortexLatticeModel& m, VortexLatticeData& d, const Eigen::Matrix3Xd& nodes,
           const Eigen::Matrix3Xd& node_velocities, const Eigen::Vector3d& free_stream, double dt,
           double rho) {
  check_inputs(m, nodes, node_velocities, dt, rho);
  if (m.steady()) {
    solve_steady_lattice(m, d, nodes, node_velocities, free_stream, rho, m.steady_wake_length, free_stream);
    d.dt = dt;
    return;
  }
  d.steady_solution = false;
  d.free_stream = free_stream;
  d.dt = dt;
  d.rho = rho;
  detail::update_geometry(m, d, nodes, node_velocities, free_stream, dt);
  update_influence(m, d);
  detail::attach_wake_to_trailing_edge(m, d);
  detail::build_wake_segments(m, d, detail::WakeView::Wing);
  const bool shed = m.leading_edge == LeadingEdge::Shed;
  if (shed) {  // the leading-edge sheet with every strip's leading-edge ring as accepted
    detail::place_release_row(m, d);
    d.le_sheet.current = d.le_sheet.accepted;
    detail::build_sheet_segments(m, d, detail::WakeView::Wing);
  }
  // With a sheet, the part before the edge's segments kept for the sum again after shedding.
  wake_velocity_at_collocation(m, d, shed ? detail::OlderPart::Keep : detail::OlderPart::None);
  const int np = m.panels();
  for (int k = 0; k < np; ++k)
    d.rhs(k) = -(free_stream - d.surface_velocity.col(k) + d.wake_velocity.col(k)).dot(d.normal.col(k));
  if (shed) detail::add_leading_edge_ring_to_rhs(m, d);
  // The wake's velocity at the loads' bound midpoints does not depend on the circulations:
  // the other threads sum it while one solves them (GMRES is serial). Not with a shed
  // leading edge, whose sheet may change after the solve.
  bool alongside = false;
  if (!shed) {
    detail::build_bound_segments(m, d);  // their places (the circulations: the last solve's)
    const std::size_t mid = detail::loads_midpoints(m.load_method, m, d);
    detail::set_bound_midpoints(d, mid);
    alongside = detail::wake_at_eval_points_alongside(m, d, mid, detail::WingPoints::Midpoints,
                                                      [&] { solve_circulations(m, d); });
  }
  if (!alongside) solve_circulations(m, d);  // the sheet's columns below need the factorisation of this matrix: direct
  if (shed && detail::shed_leading_edge_vorticity(m, d)) {  // strips beyond LESP_crit shed
    detail::build_sheet_segments(m, d, detail::WakeView::Wing);
    // Only the leading-edge rings changed, all in the edge's segments: the rest is reused.
    wake_velocity_at_collocation(m, d, detail::OlderPart::Reuse);
  }
  detail::build_bound_segments(m, d);
  detail::compute_loads(m, d);
}

void solve_steady(const VortexLatticeModel& m, VortexLatticeData& d, const Eigen::Matrix3Xd& nodes,
                  const Eigen::Vector3d& free_stream, double rho, double wake_length) {
  solve_steady(m, d, nodes, free_stream, rho, wake_length, free_stream);
}

void solve_steady(const VortexLatticeModel& m, VortexLatticeData& d, const Eigen::Matrix3Xd& nodes,
                  const Eigen::Vector3d& free_stream, double rho, double wake_length,
                  const Eigen::Vector3d& wake_direction) {
  const Eigen::Matrix3Xd zero = Eigen::Matrix3Xd::Zero(3, m.nodes());
  check_inputs(m, nodes, zero, 1.0, rho);
  solve_steady_lattice(m, d, nodes, zero, free_stream, rho, wake_length, wake_direction);
}

}  // namespace flapsim::uvlm
