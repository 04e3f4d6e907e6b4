#include "mbd/chain_energy.hpp"

namespace flapsim::mbd {

double kinetic_energy(const ChainModel& model, const ChainData& data) {
  double t = 0.0;
  for (int i = 0; i < model.num_bodies(); ++i) {
    const BodyKinematics& b = data.bodies[i];
    t += 0.5 * model.bodies[i].mass * b.com_velocity.squaredNorm() +
         0.5 * b.angular_velocity.dot(b.inertia_ground * b.angular_velocity);
  }
  return t;
}

double spring_energy(const ChainModel& model, const Eigen::VectorXd& q) {
  return 0.5 * (model.stiffness_diagonal().array() * (q - model.rest_angles()).array().square()).sum();
}

double damper_power(const ChainModel& model, const Eigen::VectorXd& v) {
  return (model.damping_diagonal().array() * v.array().square()).sum();
}

double base_power(const ChainModel& model, const ChainData& data, const BasePose& base,
                  const Loads& loads) {
  // Force and moment balance about the pivot O for the whole chain: the base's force F and
  // moment N (about O) plus the loads and gravity make Σ m a_c and Σ (c − O) × m a_c + I ω̇ + ω × I ω.
  // The base's power is ω · N + v_O · F.
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), force = Eigen::Vector3d::Zero();
  const bool has_loads = loads.num_bodies() == model.num_bodies();
  const Eigen::Vector3d& o = base.position;
  for (int i = 0; i < model.num_bodies(); ++i) {
    const BodyKinematics& b = data.bodies[i];
    const double m = model.bodies[i].mass;
    n += (b.com - o).cross(m * b.com_acceleration) + b.inertia_ground * b.angular_acceleration +
         b.angular_velocity.cross(b.inertia_ground * b.angular_velocity);
    n -= (b.com - o).cross(m * model.gravity);
    force += m * (b.com_acceleration - model.gravity);
    if (has_loads) {
      Eigen::Vector3d f, mo;
      loads.resultant(i, b.rotation, f, mo);
      n -= (b.origin - o).cross(f) + mo;
      force -= f;
    }
  }
  return base.angular_velocity.dot(n) + base.velocity.dot(force);
}

}  // namespace flapsim::mbd
