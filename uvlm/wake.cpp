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

void build_wake_segments(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int ns = m.spanwise, W = d.wake_rows;
  const int n1 = ns + 1;
  const auto& P = d.wake_nodes;
  auto G = [&](int r, int j) {
    return (r < 0 || r >= W || j < 0 || j >= ns) ? 0.0 : d.wake_gamma[static_cast<std::size_t>(r) * ns + j];
  };
  d.wake_segments.clear();
  if (W == 0) return;
  // Spanwise, node row q, direction j → j+1: rear side of ring q minus front side of ring q−1.
  for (int q = 0; q <= W; ++q)
    for (int j = 0; j < ns; ++j) {
      const std::size_t a = static_cast<std::size_t>(q) * n1 + j;
      d.wake_segments.push(P.x[a], P.y[a], P.z[a], P.x[a + 1], P.y[a + 1], P.z[a + 1],
                           G(q, j) - G(q - 1, j));
    }
  // Streamwise, column j, from row r+1 (upstream) to row r: root side of ring (r, j) minus
  // tip side of ring (r, j−1).
  for (int r = 0; r < W; ++r)
    for (int j = 0; j <= ns; ++j) {
      const std::size_t a = static_cast<std::size_t>(r + 1) * n1 + j;
      const std::size_t b = static_cast<std::size_t>(r) * n1 + j;
      d.wake_segments.push(P.x[a], P.y[a], P.z[a], P.x[b], P.y[b], P.z[b], G(r, j) - G(r, j - 1));
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
  --d.wake_rows;
  d.wake_nodes.size -= n1;
}

}  // namespace

void advance(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise;
  const std::size_t n1 = ns + 1;
  detail::attach_wake_to_trailing_edge(m, d);  // rows 0..wake_rows

  // Velocity of every wake node.
  auto& P = d.wake_nodes;
  P.zero_velocity();
  if (m.wake_model == WakeModel::Free) {
    detail::build_wake_segments(m, d);
    if (d.wake_segments.size() > 0) {
      if (m.single_precision_wake) {
        d.wake_segments.update_single_precision();
        add_induced_velocity_single(d.wake_segments, P, m.core);
      } else {
        add_induced_velocity(d.wake_segments, P, m.core);
      }
    }
    add_induced_velocity(d.bound_segments, P, m.core);
    add_induced_velocity(d.trailing_edge_segments, P, m.core);
  }
  const double dt = d.dt;
  const Eigen::Vector3d& V = d.free_stream;
  for (int r = 0; r <= d.wake_rows; ++r) {
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
  detail::attach_wake_to_trailing_edge(m, d);

  d.gamma_accepted_before = d.gamma_accepted;
  d.gamma_accepted = d.gamma;
  ++d.accepted_steps;
}

}  // namespace flapsim::uvlm
