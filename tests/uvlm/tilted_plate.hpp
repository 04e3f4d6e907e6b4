#pragma once
// A rectangular plate for the lattice's tests: chord 10 mm, span 40 mm, the model's
// chordwise × spanwise panels, turned by `angle` [rad] about the span axis (y).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::test {

inline Eigen::Matrix3Xd tilted_plate(const uvlm::VortexLatticeModel& m, double angle) {
  uvlm::PlanformGridOptions o;
  o.chordwise = m.chordwise;
  o.spanwise = m.spanwise;
  const uvlm::PlanformGrid g = uvlm::make_rectangular_grid(0.010, 0.040, o);
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix() * g.nodes;
}

}  // namespace flapsim::test
