#pragma once
/// \file synthetic_hover_wake.hpp
/// \brief A hover-like wake of any number of cycles without simulating it, for the tree
/// code's test (tests/uvlm/test_segment_tree.cpp) and benchmark (bench/bench_wake_tree.cpp):
/// a 10-panel span of wake rows, 100 per cycle, swept back and forth at 26.1 Hz through
/// ±60° about the z axis like the hawkmoth's wing (root 5 mm, tip 48.3 mm), sinking at
/// 0.5 m/s with a small waviness, with the circulation of a flapping wing (sin of the span
/// position × sin of the stroke) and Lamb–Oseen cores 0.2 × 16.9 mm grown with age
/// (core_growth.hpp, default constants). Segments in the order of uvlm/wake.cpp:
/// spanwise per node row, then streamwise per ring row. Synthetic, not a computed wake.
/// A test and benchmark helper (tests/uvlm/, on the include path of the tests and of
/// bench/), not part of the flapsim_uvlm library.

#include "uvlm/biot_savart.hpp"
#include "uvlm/core_growth.hpp"
#include "uvlm/lattice_segments.hpp"
#include "uvlm/vortex_core.hpp"

#include <cmath>
#include <cstddef>

namespace flapsim::uvlm {

struct SyntheticHoverWake {
  SegmentSet segments;
  PointSet nodes;  ///< the wake's nodes (targets of its self-induced velocity)
  /// The same segments as a lattice (rows × 11 nodes; lattice_segments.hpp), finished in
  /// double and single precision.
  LatticeSegments lattice;
  VortexCore core{CoreModel::LambOseen, 0.2 * 0.0169};
  explicit SyntheticHoverWake(int cycles);
};

inline SyntheticHoverWake::SyntheticHoverWake(int cycles) {
  const int rows = 100 * cycles, ns = 10, n1 = ns + 1;
  const double f = 26.1, dt = 1.0 / (100 * f);  // [Hz], [s]
  nodes.reserve(static_cast<std::size_t>(rows + 1) * n1);
  nodes.size = static_cast<std::size_t>(rows + 1) * n1;
  for (int r = 0; r <= rows; ++r) {
    const double age = (rows - r) * dt, psi = (60 * M_PI / 180) * std::cos(2 * M_PI * f * r * dt);
    for (int j = 0; j < n1; ++j) {
      const double rad = 0.005 + 0.0433 * j / ns;
      nodes.set(static_cast<std::size_t>(r) * n1 + j,
                {rad * std::cos(psi), rad * std::sin(psi), -0.5 * age - 0.002 * std::sin(0.3 * j + r)});
    }
  }
  CoreGrowth growth;
  growth.enabled = true;
  segments.reserve(static_cast<std::size_t>(rows + 1) * ns + static_cast<std::size_t>(rows) * n1);
  lattice.reserve(nodes.size, n1);
  lattice.assign_grid(static_cast<std::size_t>(rows) + 1, n1);
  for (std::size_t a = 0; a < nodes.size; ++a) lattice.set_node(a, nodes.x[a], nodes.y[a], nodes.z[a]);
  auto gamma = [&](int r, int j) {  // [m²/s]
    if (r < 0 || r >= rows || j < 0 || j >= ns) return 0.0;
    return 0.02 * std::sin(M_PI * (j + 0.5) / ns) * std::sin(2 * M_PI * f * r * dt + 0.3);
  };
  auto push = [&](std::size_t a, std::size_t b, double g, double age) {
    const double rc2 = grown_core_radius2(growth, core.radius, age, g);
    const double ratio = core.radius * core.radius / rc2;
    segments.push(nodes.x[a], nodes.y[a], nodes.z[a], nodes.x[b], nodes.y[b], nodes.z[b], g, ratio);
    if (b == a + 1)
      lattice.set_spanwise(a, g, ratio);
    else
      lattice.set_streamwise(b, g, ratio);  // from node b + 11 to node b
  };
  for (int q = 0; q <= rows; ++q)
    for (int j = 0; j < ns; ++j)
      push(static_cast<std::size_t>(q) * n1 + j, static_cast<std::size_t>(q) * n1 + j + 1,
           gamma(q, j) - gamma(q - 1, j), (rows - q) * dt);
  for (int r = 0; r < rows; ++r)
    for (int j = 0; j <= ns; ++j)
      push(static_cast<std::size_t>(r + 1) * n1 + j, static_cast<std::size_t>(r) * n1 + j,
           gamma(r, j) - gamma(r, j - 1), (rows - r - 0.5) * dt);
  segments.update_single_precision();
  lattice.finish(true);
}


}  // namespace flapsim::uvlm
