#include "pipeline/app/diverged_force.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <string>

#include "pipeline/fsi/numerical_failure.hpp"

namespace flapsim::app {

namespace {

// The largest of `value(pose, r)` over the lattice's nodes r (in G) at `samples` instants of
// the run's first period and as many of its last (a run of `duration` [s]; 0: one period).
template <typename Value>
double largest_over_first_and_last_period(const mbd::BaseMotion& base, double period, const Eigen::Matrix3Xd& nodes,
                                          int samples, double duration, const Value& value) {
  double largest = 0.0;
  const double last_start = std::max(0.0, duration - period);
  for (const double start : {0.0, last_start}) {
    for (int k = 0; k < samples; ++k) {
      const mbd::BasePose p = base(start + period * k / samples);
      for (Eigen::Index n = 0; n < nodes.cols(); ++n) largest = std::max(largest, value(p, p.rotation * nodes.col(n)));
    }
    if (last_start == 0.0) break;
  }
  return largest;
}

}  // namespace

double fastest_wing_point_speed(const mbd::BaseMotion& base, double period, const Eigen::Matrix3Xd& nodes,
                                const Eigen::Vector3d& free_stream, int samples, double duration) {
  return largest_over_first_and_last_period(
      base, period, nodes, samples, duration, [&](const mbd::BasePose& p, const Eigen::Vector3d& r) {
        return (free_stream - p.velocity - p.angular_velocity.cross(r)).norm();
      });
}

double fastest_wing_point_acceleration(const mbd::BaseMotion& base, double period, const Eigen::Matrix3Xd& nodes,
                                       int samples, double duration) {
  return largest_over_first_and_last_period(
      base, period, nodes, samples, duration, [](const mbd::BasePose& p, const Eigen::Vector3d& r) {
        return (p.acceleration + p.angular_acceleration.cross(r) + p.angular_velocity.cross(p.angular_velocity.cross(r)))
            .norm();
      });
}

double diverged_force_limit(double rho, double fastest_speed, double area, double fastest_acceleration,
                            double mean_chord) {
  return kDivergedForceCoefficient * (0.5 * rho * fastest_speed * fastest_speed * area +
                                      std::numbers::pi / 4 * rho * mean_chord * fastest_acceleration * area);
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

std::string diverged_lattice_advice(const io::Case::Numerics& n, LiftJump jump, long recorded_steps) {
  if (n.leading_edge != uvlm::LeadingEdge::Shed) return {};
  char evidence[400];
  if (jump.step >= 2 && jump.step > recorded_steps)
    std::snprintf(
        evidence, sizeof evidence,
        "With leading_edge = \"shed\" the lift coefficient changed by up to %.3g from one step to the "
        "next (into step %ld, the step that failed: its lift is in no output, history.csv ends at step "
        "%ld), as it does where the leading-edge sheet comes apart near the wing: ",
        jump.size, jump.step, recorded_steps);
  else if (jump.step >= 2)
    std::snprintf(
        evidence, sizeof evidence,
        "With leading_edge = \"shed\" the lift coefficient changed by up to %.3g from one step to the "
        "next (into step %ld; history.csv CL), as it does where the leading-edge sheet comes apart near "
        "the wing: ",
        jump.size, jump.step);
  else  // no two steps to compare (it said "changed by up to 0 ... (into step 0")
    std::snprintf(evidence, sizeof evidence,
                  "With leading_edge = \"shed\" the run stopped before two steps could be compared; the "
                  "leading-edge sheet may come apart near the wing: ");
  const std::string default_model =
      "leading_edge = \"separated\", the default, sheds no sheet (docs/uvlm.md, "
      "\"Leading-edge vortex shedding: measurements\")";
  const double sheet_core = n.sheet_core_radius > 0.0 ? n.sheet_core_radius : n.core_radius;  // [mean chords]
  if (sheet_core >= 0.5) return evidence + default_model;
  return evidence + std::string("numerics.sheet_core_radius = 0.5 keeps it together in more runs, or ") +
         default_model;
}

}  // namespace flapsim::app
