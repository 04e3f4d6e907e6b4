#include "pipeline/app/quasi_steady_fluid_loads.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace flapsim::app {

double revolving_wing_normal_coefficient(double alpha) {
  alpha = std::clamp(alpha, 0.0, 0.5 * std::numbers::pi);
  constexpr double deg = std::numbers::pi / 180.0;
  const double cl = 0.225 + 1.58 * std::sin(2.13 * alpha - 7.20 * deg);
  const double cd = 1.92 - 1.55 * std::cos(2.04 * alpha - 9.82 * deg);
  return cl * std::cos(alpha) + cd * std::sin(alpha);
}

void add_quasi_steady_fluid_loads(const fsi::WingAttachment& attachment, int chordwise, int spanwise,
                                  const mbd::ChainData& data, double density,
                                  const Eigen::Vector3d& freestream, mbd::Loads& loads) {
  Eigen::Matrix3Xd x, v;  // the lattice's nodes: positions [m], velocities [m/s], ground frame
  fsi::deformed_nodes(attachment, data, x, v);
  const auto node = [&](int i, int j) { return i + (chordwise + 1) * j; };
  for (int j = 0; j < spanwise; ++j)
    for (int i = 0; i < chordwise; ++i) {
      const int c[4] = {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
      const Eigen::Vector3d centroid = 0.25 * (x.col(c[0]) + x.col(c[1]) + x.col(c[2]) + x.col(c[3]));
      const Eigen::Vector3d velocity = 0.25 * (v.col(c[0]) + v.col(c[1]) + v.col(c[2]) + v.col(c[3]));
      // Area vector: half the cross product of the diagonals (a plane quadrilateral's area).
      const Eigen::Vector3d area = 0.5 * (x.col(c[2]) - x.col(c[0])).cross(x.col(c[3]) - x.col(c[1]));
      const double a = area.norm();
      const Eigen::Vector3d u = freestream - velocity;  // the fluid relative to the panel
      const double speed = u.norm();
      if (!(a > 0.0) || !(speed > 0.0)) continue;
      const Eigen::Vector3d normal = area / a;
      const double un = u.dot(normal);
      const double alpha = std::asin(std::min(1.0, std::abs(un) / speed));
      const double force = 0.5 * density * speed * speed * revolving_wing_normal_coefficient(alpha) * a;
      const int body = attachment.panel_body[static_cast<std::size_t>(i + chordwise * j)];
      const mbd::BodyKinematics& b = data.bodies[static_cast<std::size_t>(body)];
      const Eigen::Vector3d local = b.rotation.transpose() * (centroid - b.origin);
      loads.add_force(body, local, (un >= 0.0 ? force : -force) * normal, mbd::LoadFrame::ground);
    }
}

}  // namespace flapsim::app
