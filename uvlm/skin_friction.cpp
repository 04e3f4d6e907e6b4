#include "uvlm/skin_friction.hpp"

#include <cmath>

namespace flapsim::uvlm {

double blasius_mean_skin_friction(double reynolds) { return 1.328 / std::sqrt(reynolds); }

void add_skin_friction(const VortexLatticeModel& m, VortexLatticeData& d) {
  d.loads.skin_friction_force.setZero();
  const double nu = m.skin_friction_viscosity;  // [m²/s]
  if (!(nu > 0.0)) return;
  for (int j = 0; j < m.spanwise; ++j) {
    double chord = 0.0;  // the strip's [m]
    for (int i = 0; i < m.chordwise; ++i) chord += d.chord_length(m.panel(i, j));
    for (int i = 0; i < m.chordwise; ++i) {
      const int k = m.panel(i, j);
      const Eigen::Vector3d n = d.normal.col(k);
      const Eigen::Vector3d air = d.free_stream - d.surface_velocity.col(k) + d.wake_velocity.col(k);
      const Eigen::Vector3d tangential = air - air.dot(n) * n;  // [m/s]
      const double speed = tangential.norm();
      if (!(speed > 0.0) || !(chord > 0.0)) continue;
      const double cf = blasius_mean_skin_friction(speed * chord / nu);
      // Both sides: ½ ρ |u_t|² c_f per side, 2A of wetted area, along u_t.
      const Eigen::Vector3d f = (d.rho * speed * cf * d.area(k)) * tangential;
      d.loads.skin_friction_force.col(k) = f;
      d.loads.force.col(k) += f;
    }
  }
}

}  // namespace flapsim::uvlm
