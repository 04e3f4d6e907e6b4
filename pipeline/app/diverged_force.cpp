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

void throw_if_force_diverged(const Eigen::Vector3d& force, double limit, long step, double time) {
  const double f = force.norm();
  if (!(f > limit)) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the aerodynamic force reached %.3g N, beyond %.3g N (%.0f times the dynamic pressure of the "
                "wing's fastest point times its area): the lattice has diverged (docs/fsi.md, \"Failures\")",
                f, limit, kDivergedForceCoefficient);
  throw NumericalFailure(text, step, time);
}

std::string diverged_lattice_advice(const io::Case::Numerics& n, LiftJump jump) {
  if (n.leading_edge != uvlm::LeadingEdge::Shed) return {};
  char evidence[200];
  std::snprintf(
      evidence, sizeof evidence,
      "With leading_edge = \"shed\" the lift coefficient changed by up to %.3g from one step to the "
      "next (into step %ld; history.csv CL), as it does where the leading-edge sheet comes apart near "
      "the wing: ",
      jump.size, jump.step);
  const std::string default_model =
      "leading_edge = \"separated\", the default, sheds no sheet (docs/uvlm.md, "
      "\"Leading-edge vortex shedding: measurements\")";
  const double sheet_core = n.sheet_core_radius > 0.0 ? n.sheet_core_radius : n.core_radius;  // [mean chords]
  if (sheet_core >= 0.5) return evidence + default_model;
  return evidence + std::string("numerics.sheet_core_radius = 0.5 keeps it together in more runs, or ") +
         default_model;
}

}  // namespace flapsim::app
