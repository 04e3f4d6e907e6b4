/// \file trefftz_plane.cpp
/// \brief Lift and induced drag of a steady lattice from its far wake (the Trefftz plane,
/// Katz & Plotkin §8.3): the second, independent evaluation the near-field loads are
/// checked against.

#include "uvlm/vortex_lattice.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace flapsim::uvlm {

TrefftzPlaneLoads trefftz_plane_loads(const VortexLatticeModel& m, const VortexLatticeData& d) {
  const double speed = d.free_stream.norm();
  if (!(speed > 0.0)) throw std::invalid_argument("Trefftz plane: needs a free stream");
  const Eigen::Vector3d u = d.free_stream / speed;
  const int nc = m.chordwise, ns = m.spanwise;
  // Trailing-edge ring nodes projected onto the plane normal to the free stream.
  std::vector<Eigen::Vector3d> p(ns + 1);
  for (int j = 0; j <= ns; ++j) {
    const Eigen::Vector3d x = d.ring_nodes.col(m.node(nc, j));
    p[j] = x - x.dot(u) * u;
  }
  auto strip_gamma = [&](int j) { return (j < 0 || j >= ns) ? 0.0 : d.gamma(m.panel(nc - 1, j)); };
  TrefftzPlaneLoads out;
  for (int j = 0; j < ns; ++j) {
    const Eigen::Vector3d s = p[j + 1] - p[j];
    const Eigen::Vector3d mid = 0.5 * (p[j] + p[j + 1]);
    const Eigen::Vector3d lift_dir = s.cross(u).normalized();
    // Trailing vortex k runs downstream (along u) with circulation Γ_k − Γ_(k−1); its
    // velocity far downstream is that of a 2-D point vortex, (g / 2π) u × r / |r|².
    Eigen::Vector3d vel = Eigen::Vector3d::Zero();
    for (int k = 0; k <= ns; ++k) {
      const Eigen::Vector3d r = mid - p[k];
      vel += (strip_gamma(k) - strip_gamma(k - 1)) / (2.0 * std::numbers::pi) * u.cross(r) / r.squaredNorm();
    }
    const double downwash = -vel.dot(lift_dir);
    out.drag += 0.5 * d.rho * strip_gamma(j) * downwash * s.norm();
    out.lift += d.rho * speed * strip_gamma(j) * s.norm();
  }
  return out;
}

}  // namespace flapsim::uvlm
