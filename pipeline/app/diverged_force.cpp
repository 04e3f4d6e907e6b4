#include "pipeline/app/diverged_force.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <string>

#include "pipeline/fsi/numerical_failure.hpp"

namespace flapsim::app {

double fastest_wing_point_speed(const mbd::BaseMotion& base, double period, const Eigen::Matrix3Xd& nodes,
                                const Eigen::Vector3d& free_stream, int samples) {
  double fastest = 0.0;
  for (int k = 0; k < samples; ++k) {
    const mbd::BasePose p = base(period * k / samples);
    for (Eigen::Index n = 0; n < nodes.cols(); ++n) {
      const Eigen::Vector3d r = p.rotation * nodes.col(n);
      fastest = std::max(fastest, (free_stream - p.velocity - p.angular_velocity.cross(r)).norm());
    }
  }
  return fastest;
}

double diverged_force_limit(double rho, double fastest_speed, double area) {
  return kDivergedForceCoefficient * 0.5 * rho * fastest_speed * fastest_speed * area;
}

void throw_if_force_diverged(const Eigen::Vector3d& force, double limit, long step, double time,
                             const std::string& advice) {
  const double f = force.norm();
  if (!(f > limit)) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the aerodynamic force reached %.3g N, beyond %.3g N (%.0f times the dynamic pressure of the "
                "wing's fastest point times its area): the lattice has diverged (docs/fsi.md, \"Failures\")",
                f, limit, kDivergedForceCoefficient);
  throw NumericalFailure(advice.empty() ? std::string(text) : std::string(text) + "; " + advice, step, time);
}

std::string diverged_lattice_advice(const io::Case::Numerics& n) {
  if (n.leading_edge != uvlm::LeadingEdge::Shed) return {};
  const std::string default_model =
      "or leading_edge = \"separated\", the default, which sheds no sheet (docs/uvlm.md, "
      "\"Leading-edge vortex shedding: measurements\")";
  const double sheet_core = n.sheet_core_radius > 0.0 ? n.sheet_core_radius : n.core_radius;  // [mean chords]
  if (sheet_core >= 0.5)
    return "with leading_edge = \"shed\" the leading-edge sheet has come apart: " + default_model;
  return "with leading_edge = \"shed\" the leading-edge sheet has come apart: "
         "numerics.sheet_core_radius = 0.5 keeps it together in more runs, " +
         default_model;
}

}  // namespace flapsim::app
