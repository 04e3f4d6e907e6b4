/// \file wake.cpp
/// \brief The wake of a vortex lattice: its segments, its convection (free or prescribed,
/// Euler or Adams–Bashforth 2; frozen or convected far wake), shedding from the trailing
/// edge and truncation.

#include "uvlm/lattice_internal.hpp"
#include "uvlm/leading_edge_side.hpp"
#include "uvlm/old_wake_hold.hpp"
#include "uvlm/vortex_lattice.hpp"
#include "uvlm/wake_age.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

long far_tree_rebuild_interval(const VortexLatticeModel& m, std::size_t segments, double targets) {
  const long fewest = std::max(1, m.far_tree_rebuild_steps);
  if (m.core_growth.enabled || !(targets > 0.0)) return fewest;
  const double row = 2.0 * m.spanwise + 1.0;  // segments a ring row adds
  const double k =
      std::sqrt(2.0 * SegmentTree::kBuildPairsPerSegment * static_cast<double>(segments) / (row * targets));
  return std::max(fewest, std::lround(k));
}

namespace detail {

void attach_wake_to_trailing_edge(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise;
  const std::size_t base = static_cast<std::size_t>(d.wake_rows) * (ns + 1);
  for (int j = 0; j <= ns; ++j) d.wake_nodes.set(base + j, d.ring_nodes.col(m.node(nc, j)));
  d.wake_nodes.size = base + ns + 1;
}

void build_wake_segments(const VortexLatticeModel& m, VortexLatticeData& d, WakeView view) {
  const int ns = m.spanwise, W = d.wake_rows;
  const int n1 = ns + 1;
  const auto& P = d.wake_nodes;
  auto G = [&](int r, int j) {
    return (r < 0 || r >= W || j < 0 || j >= ns) ? 0.0 : d.wake_gamma[static_cast<std::size_t>(r) * ns + j];
  };
  // (r_c / r_c,k)² of a segment of circulation g and age t [s] (core_growth.hpp), with
  // the wing seeing at least the near-wing core.
  const double rc0 = m.core.radius, rc0_2 = rc0 * rc0;
  const double floor2 = view == WakeView::Wing ? m.near_wing_core * m.near_wing_core : 0.0;
  auto ratio = [&](double g, double age) {
    double rc2 = grown_core_radius2(m.core_growth, rc0, age, g);
    if (age > m.near_wing_min_age) rc2 = std::max(rc2, floor2);
    return rc0_2 / rc2;
  };
  const auto& age = d.wake_row_age;
  // Segments of the wake rings: spanwise along node rows q ∈ [q0, q1), direction j → j+1
  // (rear side of ring q minus front side of ring q−1); streamwise along column j from node
  // row r+1 (upstream) to row r for r ∈ [r0, r1) (root side of ring (r, j) minus tip side
  // of ring (r, j−1)); each with the core ratio core_ratio(g, age).
  auto push_rings = [&](auto& out, int q0, int q1, int r0, int r1, auto core_ratio) {
    for (int q = q0; q < q1; ++q)
      for (int j = 0; j < ns; ++j) {
        const std::size_t a = static_cast<std::size_t>(q) * n1 + j;
        const double g = G(q, j) - G(q - 1, j);
        out.push(P.x[a], P.y[a], P.z[a], P.x[a + 1], P.y[a + 1], P.z[a + 1], g, core_ratio(g, age[q]));
      }
    for (int r = r0; r < r1; ++r)
      for (int j = 0; j <= ns; ++j) {
        const std::size_t a = static_cast<std::size_t>(r + 1) * n1 + j;
        const std::size_t b = static_cast<std::size_t>(r) * n1 + j;
        const double g = G(r, j) - G(r, j - 1);
        out.push(P.x[a], P.y[a], P.z[a], P.x[b], P.y[b], P.z[b], g, core_ratio(g, 0.5 * (age[r] + age[r + 1])));
      }
  };
  d.wake_segments.clear();
  d.wake_edge_segments.clear();
  d.young_wake_segments.clear();
  d.trailing_wake_segments = d.trailing_wake_edge_segments = d.trailing_young_wake_segments = 0;
  d.wake_lattice.assign_grid(0, n1);
  if (W == 0) return;
  // Convected far wake by the tree: the far wake moves as a whole (far_wake_velocity), so
  // a tree built over its node rows q < T stays exact for them when the targets are moved
  // back by the far wake's displacement since the build (d.far_tree_shift). It is rebuilt
  // every far_tree_rebuild_steps steps (and whenever rows were dropped); rows that joined
  // the far wake since go to the direct sum. The far wake is seen through its own cores
  // from the wing too: the near-wing floor is for the wake the wing meets.
  int T = 0;
  if (m.far_wake_by_tree()) {
    const int F = far_wake_node_rows(m, d);
    const bool stale = d.far_tree_rows == 0 || d.far_tree_rows > F || m.max_wake_rows > 0 ||
                       d.accepted_steps - d.far_tree_step >= d.far_tree_interval;
    if (stale && F > 1) {
      d.far_wake_segments.clear();
      auto far_ratio = [&](double g, double a) { return rc0_2 / grown_core_radius2(m.core_growth, rc0, a, g); };
      push_rings(d.far_wake_segments, 0, F, 0, F - 1, far_ratio);
      d.wake_tree.build(d.far_wake_segments, m.core, tree_parameters(m.tree_tolerance));
      d.far_tree_rows = F;
      d.far_tree_step = d.accepted_steps;
      const double young_nodes = m.wake_model == WakeModel::Free ? static_cast<double>(W + 1 - F) * n1 : 0.0;
      d.far_tree_interval =
          far_tree_rebuild_interval(m, d.far_wake_segments.size(), young_nodes + m.chordwise * m.spanwise);
      d.far_tree_shift.setZero();
    } else if (stale) {
      d.far_tree_rows = 0;
      d.far_wake_segments.clear();
    }
    T = d.far_tree_rows;
  }
  // The rest, by the direct sum. Seen from the wing in single precision, the segments at
  // the newest node row (the trailing-edge vortex's, which follows the wing through a
  // step's sub-iterations) go to wake_edge_segments, summed in double: rounded to single
  // precision, their ends would move in steps of 4·10⁻⁹ m beside the last panels'
  // collocation points (docs/uvlm.md, "Precision of the wake's sums").
  // With the older wake kept apart (old_wake_hold.hpp), node rows from Y on (the
  // model.young_wake_rows newest before the newest) go to young_wake_segments.
  if (view == WakeView::Wing && m.single_precision_wake && T <= W) {
    const int Y = old_wake_kept_apart(m, d) ? std::max(T, W - m.young_wake_rows) : W;
    const int r0 = std::max(T - 1, 0), ry = std::max(Y - 1, r0);
    push_rings(d.wake_segments, T, Y, r0, ry, ratio);
    push_rings(d.young_wake_segments, Y, W, ry, W - 1, ratio);
    push_rings(d.wake_edge_segments, W, W + 1, W - 1, W, ratio);
  } else {
    push_rings(d.wake_segments, T, W + 1, std::max(T - 1, 0), W, ratio);
  }
  d.trailing_wake_segments = d.wake_segments.size();
  d.trailing_wake_edge_segments = d.wake_edge_segments.size();
  d.trailing_young_wake_segments = d.young_wake_segments.size();
  // The same segments as a lattice of node rows q0 … W (lattice_segments.hpp), which the
  // wake's own direct sum in double precision uses (advance; in single precision the
  // segment kernel is faster, docs/performance.md; with a leading-edge sheet, whose
  // segments join the set, the segment kernel sums both at once): node (q, j) is lattice node
  // (q − q0) n1 + j, a ring row's spanwise segment j → j+1 that node's spanwise segment,
  // the streamwise one from row r+1 to row r node (r − q0, j)'s streamwise segment.
  if (view != WakeView::Wake || !wake_sum_by_lattice(m)) return;
  const int q0 = std::max(T - 1, 0);
  LatticeSegments& L = d.wake_lattice;
  L.assign_grid(static_cast<std::size_t>(W + 1 - q0), static_cast<std::size_t>(n1));
  const std::size_t first = static_cast<std::size_t>(q0) * n1;
  for (std::size_t a = 0; a < L.nodes(); ++a) L.set_node(a, P.x[first + a], P.y[first + a], P.z[first + a]);
  for (int q = T; q <= W; ++q)
    for (int j = 0; j < ns; ++j) {
      const double g = G(q, j) - G(q - 1, j);
      L.set_spanwise(static_cast<std::size_t>(q - q0) * n1 + j, g, ratio(g, age[q]));
    }
  for (int r = q0; r < W; ++r)
    for (int j = 0; j <= ns; ++j) {
      const double g = G(r, j) - G(r, j - 1);
      L.set_streamwise(static_cast<std::size_t>(r - q0) * n1 + j, g, ratio(g, 0.5 * (age[r] + age[r + 1])));
    }
  L.finish(false);
}

void add_free_vortex_velocity(const VortexLatticeModel& m, const VortexLatticeData& d, const double* x,
                              const double* y, const double* z, std::size_t n, double* u, double* v, double* w) {
  if (d.wake_segments.size() == 0) return;
  if (m.single_precision_wake)
    add_induced_velocity_single(d.wake_segments, x, y, z, n, u, v, w, m.core);
  else if (wake_sum_by_lattice(m))  // the same segments as a lattice (lattice_segments.hpp)
    add_induced_velocity(d.wake_lattice, x, y, z, n, u, v, w, m.core);
  else
    add_induced_velocity(d.wake_segments, x, y, z, n, u, v, w, m.core);
}

void add_far_wake_velocity(VortexLatticeData& d, const double* x, const double* y, const double* z,
                           std::size_t n, double* u, double* v, double* w) {
  if (d.far_tree_rows == 0 || d.far_wake_segments.size() == 0) return;
  PointSet& s = d.far_targets;
  const Eigen::Vector3d& o = d.far_tree_shift;
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] = x[i] - o.x();
    s.y[i] = y[i] - o.y();
    s.z[i] = z[i] - o.z();
  }
  d.wake_tree.add_induced_velocity(s.x.data(), s.y.data(), s.z.data(), n, u, v, w);
}

int far_wake_node_rows(const VortexLatticeModel& m, const VortexLatticeData& d) {
  const double far_age = m.far_wake_age > 0.0 ? m.far_wake_age : m.frozen_wake_age;
  int rows = 0;
  if (far_age > 0.0)
    while (rows <= d.wake_rows && reached_age(d.wake_row_age[rows], far_age)) ++rows;
  return rows;
}

}  // namespace detail

namespace {

/// Drop the oldest wake row (ring 0 and node row 0).
void drop_oldest_row(VortexLatticeData& d) {
  const int ns = d.spanwise;
  const std::size_t n1 = ns + 1;
  const std::size_t nodes = d.wake_nodes.size;  // rows 0..wake_rows
  auto shift = [&](std::vector<double>& a, std::size_t by, std::size_t count) {
    std::copy(a.begin() + by, a.begin() + by + count, a.begin());
  };
  for (auto* a : {&d.wake_nodes.x, &d.wake_nodes.y, &d.wake_nodes.z, &d.wake_prev_u,
                  &d.wake_prev_v, &d.wake_prev_w})
    shift(*a, n1, nodes - n1);
  shift(d.wake_gamma, ns, static_cast<std::size_t>(d.wake_rows - 1) * ns);
  std::copy(d.wake_row_has_prev.begin() + 1, d.wake_row_has_prev.begin() + d.wake_rows + 1,
            d.wake_row_has_prev.begin());
  std::copy(d.wake_row_age.begin() + 1, d.wake_row_age.begin() + d.wake_rows + 1, d.wake_row_age.begin());
  --d.wake_rows;
  d.wake_nodes.size -= n1;
}

}  // namespace

Eigen::Vector3d far_wake_velocity(const VortexLatticeModel& m, const VortexLatticeData& d) {
  const Eigen::Vector3d& V = d.free_stream;
  if (!(d.force_time > 0.0) || !(m.far_wake_disk_area > 0.0) || !(d.rho > 0.0)) return V;
  const Eigen::Vector3d F = d.force_impulse / d.force_time;
  const double T = F.norm();
  if (!(T > 0.0)) return V;
  const Eigen::Vector3d down = -F / T;  // the jet leaves against the force
  const double c = T / (2.0 * d.rho * m.far_wake_disk_area);  // v_i |V∞ + v_i down| = c [m²/s²]
  // f(v) = v |V∞ + v down| grows from f(0) = 0 without bound: bisect on [0, hi] with f(hi) ≥ c.
  auto f = [&](double v) { return v * (V + v * down).norm(); };
  double lo = 0.0, hi = std::sqrt(c) + V.norm();
  while (f(hi) < c) hi *= 2.0;
  for (int i = 0; i < 100 && hi - lo > 1e-14 * hi; ++i) (f(0.5 * (lo + hi)) < c ? lo : hi) = 0.5 * (lo + hi);
  return V + m.far_wake_speed_factor * 0.5 * (lo + hi) * down;
}

void advance(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise;
  const std::size_t n1 = ns + 1;
  d.force_impulse += d.loads.total_force * d.dt;
  d.force_time += d.dt;
  release_leading_edge_sides(d);  // held within a step at most (leading_edge_side.hpp)
  release_old_wake_sums(d);       // the same (old_wake_hold.hpp)
  if (m.steady()) {  // the steady lattice's straight wake is rebuilt by every solve
    d.gamma_accepted_before = d.gamma;
    d.gamma_accepted = d.gamma;
    ++d.accepted_steps;
    return;
  }
  detail::attach_wake_to_trailing_edge(m, d);  // rows 0..wake_rows
  // Rows older than the frozen- or far-wake age (a prefix: row 0 is the oldest) keep their
  // place (frozen) or move with the far-wake velocity (convected); either way their own
  // velocity is not summed.
  const int first_free = detail::far_wake_node_rows(m, d);
  const std::size_t first = static_cast<std::size_t>(first_free) * n1;

  // Velocity of every free wake node.
  auto& P = d.wake_nodes;
  P.zero_velocity();
  bool by_tree = false;  // the tree holds the wake and the sheet (for the sheet's nodes too)
  if (m.wake_model == WakeModel::Free && first < P.size) {
    const std::size_t n = P.size - first;
    double *x = P.x.data() + first, *y = P.y.data() + first, *z = P.z.data() + first;
    double *u = P.u.data() + first, *v = P.v.data() + first, *w = P.w.data() + first;
    detail::build_wake_segments(m, d, detail::WakeView::Wake);
    // The leading-edge sheet's segments (LeadingEdge::Shed) join the wake's: one set of
    // free vortices, summed at the wake's and at the sheet's nodes alike.
    if (m.leading_edge == LeadingEdge::Shed) detail::build_sheet_segments(m, d, detail::WakeView::Wake);
    detail::add_far_wake_velocity(d, x, y, z, n, u, v, w);  // the far wake by the tree, if so
    by_tree = m.wake_sum == WakeSum::Tree && !m.far_wake_by_tree() && d.wake_segments.size() >= m.tree_min_segments;
    if (by_tree) {
      d.wake_tree.build(d.wake_segments, m.core, tree_parameters(m.tree_tolerance));
      d.wake_tree.add_induced_velocity(x, y, z, n, u, v, w);
    } else if (m.single_precision_wake) {
      d.wake_segments.update_single_precision();
    }
    // Near-wing treatment, the other way round: the wake sees the bound vortices through
    // the near-wing core, so a wake node passing close to the lattice is not flung away.
    const VortexCore bound_seen_from_wake{m.core.model, std::max(m.core.radius, m.near_wing_core)};
    const std::size_t segments = (by_tree ? 0 : d.wake_segments.size()) + d.bound_segments.size() +
                                 d.trailing_edge_segments.size();
    // The direct sums at the wake nodes, one parallel region (lattice_internal.hpp).
    detail::for_target_chunks(n, n * segments, [&](std::size_t i0, std::size_t c) {
      const double *xi = x + i0, *yi = y + i0, *zi = z + i0;
      double *ui = u + i0, *vi = v + i0, *wi = w + i0;
      if (!by_tree) detail::add_free_vortex_velocity(m, d, xi, yi, zi, c, ui, vi, wi);
      add_induced_velocity(d.bound_segments, xi, yi, zi, c, ui, vi, wi, bound_seen_from_wake);
      add_induced_velocity(d.trailing_edge_segments, xi, yi, zi, c, ui, vi, wi, m.core);
    });
  }
  if (m.leading_edge == LeadingEdge::Shed) detail::sheet_node_velocities(m, d, by_tree);
  const double dt = d.dt;
  const Eigen::Vector3d& V = d.free_stream;
  if (m.far_wake_age > 0.0 && first_free > 0) {
    const Eigen::Vector3d vf = far_wake_velocity(m, d);
    d.far_tree_shift += dt * vf;  // the tree's rows move with the rest of the far wake
    for (std::size_t k = 0; k < first; ++k) {
      P.x[k] += dt * vf.x();
      P.y[k] += dt * vf.y();
      P.z[k] += dt * vf.z();
      d.wake_prev_u[k] = vf.x();
      d.wake_prev_v[k] = vf.y();
      d.wake_prev_w[k] = vf.z();
    }
  }
  // The row leaving the trailing-edge vortex (in the last panel's extension, where its
  // velocity was taken: there it coincides with the trailing-edge segment) starts from the
  // edge's path: it gets back the path's part normal to the panel (update_geometry), so the
  // wake behind the first ring lies on the line the edge travelled through the air.
  if (d.wake_rows >= first_free)
    for (int j = 0; j <= ns; ++j) {
      const std::size_t k = static_cast<std::size_t>(d.wake_rows) * n1 + j;
      P.x[k] += d.shed_lift(0, j);
      P.y[k] += d.shed_lift(1, j);
      P.z[k] += d.shed_lift(2, j);
    }
  for (int r = first_free; r <= d.wake_rows; ++r) {
    const bool ab2 = m.wake_integrator == WakeIntegrator::AdamsBashforth2 && d.wake_row_has_prev[r];
    for (std::size_t j = 0; j < n1; ++j) {
      const std::size_t k = r * n1 + j;
      const double u = P.u[k] + V.x(), v = P.v[k] + V.y(), w = P.w[k] + V.z();
      if (ab2) {
        P.x[k] += dt * (1.5 * u - 0.5 * d.wake_prev_u[k]);
        P.y[k] += dt * (1.5 * v - 0.5 * d.wake_prev_v[k]);
        P.z[k] += dt * (1.5 * w - 0.5 * d.wake_prev_w[k]);
      } else {
        P.x[k] += dt * u;
        P.y[k] += dt * v;
        P.z[k] += dt * w;
      }
      d.wake_prev_u[k] = u;
      d.wake_prev_v[k] = v;
      d.wake_prev_w[k] = w;
    }
    d.wake_row_has_prev[r] = 1;
  }
  for (int r = 0; r <= d.wake_rows; ++r) d.wake_row_age[r] += dt;
  if (m.leading_edge == LeadingEdge::Shed)
    detail::move_and_release_sheet(m, d, m.far_wake_age > 0.0 ? far_wake_velocity(m, d) : V);

  // Truncation: drop the oldest row first so the new one fits.
  if (m.max_wake_rows > 0)
    while (d.wake_rows >= m.max_wake_rows) drop_oldest_row(d);
  if (d.wake_rows + 1 > d.wake_capacity)
    throw std::length_error("vortex lattice: wake exceeds its capacity of " +
                            std::to_string(d.wake_capacity) + " rows");
  // Shed: ring wake_rows carries this step's trailing-edge circulation; a new node row
  // follows the trailing edge (placed on it again at the next solve).
  for (int j = 0; j < ns; ++j)
    d.wake_gamma[static_cast<std::size_t>(d.wake_rows) * ns + j] = d.gamma(m.panel(nc - 1, j));
  ++d.wake_rows;
  d.wake_row_has_prev[d.wake_rows] = 0;
  d.wake_row_age[d.wake_rows] = 0.0;
  detail::attach_wake_to_trailing_edge(m, d);

  d.gamma_accepted_before = d.gamma_accepted;
  d.gamma_accepted = d.gamma;
  ++d.accepted_steps;
}

}  // namespace flapsim::uvlm
