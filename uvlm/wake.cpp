/// \file wake.cpp
/// \brief The wake of a vortex lattice: its segments, its convection (free or prescribed,
/// Euler or Adams–Bashforth 2), shedding from the trailing edge and truncation.

#include "uvlm/lattice_internal.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

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
  d.wake_segments.clear();
  if (W == 0) return;
  // Spanwise, node row q, direction j → j+1: rear side of ring q minus front side of ring q−1.
  for (int q = 0; q <= W; ++q)
    for (int j = 0; j < ns; ++j) {
      const std::size_t a = static_cast<std::size_t>(q) * n1 + j;
      const double g = G(q, j) - G(q - 1, j);
      d.wake_segments.push(P.x[a], P.y[a], P.z[a], P.x[a + 1], P.y[a + 1], P.z[a + 1], g,
                           ratio(g, age[q]));
    }
  // Streamwise, column j, from row r+1 (upstream) to row r: root side of ring (r, j) minus
  // tip side of ring (r, j−1).
  for (int r = 0; r < W; ++r)
    for (int j = 0; j <= ns; ++j) {
      const std::size_t a = static_cast<std::size_t>(r + 1) * n1 + j;
      const std::size_t b = static_cast<std::size_t>(r) * n1 + j;
      const double g = G(r, j) - G(r, j - 1);
      d.wake_segments.push(P.x[a], P.y[a], P.z[a], P.x[b], P.y[b], P.z[b], g,
                           ratio(g, 0.5 * (age[r] + age[r + 1])));
    }
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

void advance(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise;
  const std::size_t n1 = ns + 1;
  detail::attach_wake_to_trailing_edge(m, d);  // rows 0..wake_rows

  // Rows older than the frozen-wake age (a prefix: row 0 is the oldest) keep their place.
  int first_free = 0;
  if (m.frozen_wake_age > 0.0)
    while (first_free <= d.wake_rows && d.wake_row_age[first_free] > m.frozen_wake_age) ++first_free;
  const std::size_t first = static_cast<std::size_t>(first_free) * n1;

  // Velocity of every free wake node.
  auto& P = d.wake_nodes;
  P.zero_velocity();
  if (m.wake_model == WakeModel::Free && first < P.size) {
    const std::size_t n = P.size - first;
    double *x = P.x.data() + first, *y = P.y.data() + first, *z = P.z.data() + first;
    double *u = P.u.data() + first, *v = P.v.data() + first, *w = P.w.data() + first;
    detail::build_wake_segments(m, d, detail::WakeView::Wake);
    if (m.wake_sum == WakeSum::Tree && d.wake_segments.size() >= m.tree_min_segments) {
      d.wake_tree.build(d.wake_segments, m.core, tree_parameters(m.tree_tolerance));
      d.wake_tree.add_induced_velocity(x, y, z, n, u, v, w);
    } else if (d.wake_segments.size() > 0) {
      if (m.single_precision_wake) {
        d.wake_segments.update_single_precision();
        add_induced_velocity_single(d.wake_segments, x, y, z, n, u, v, w, m.core);
      } else {
        add_induced_velocity(d.wake_segments, x, y, z, n, u, v, w, m.core);
      }
    }
    // Near-wing treatment, the other way round: the wake sees the bound vortices through
    // the near-wing core, so a wake node passing close to the lattice is not flung away.
    const VortexCore bound_seen_from_wake{m.core.model, std::max(m.core.radius, m.near_wing_core)};
    add_induced_velocity(d.bound_segments, x, y, z, n, u, v, w, bound_seen_from_wake);
    add_induced_velocity(d.trailing_edge_segments, x, y, z, n, u, v, w, m.core);
  }
  const double dt = d.dt;
  const Eigen::Vector3d& V = d.free_stream;
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
