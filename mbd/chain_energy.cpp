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
  const Eigen::VectorXd d = q - model.rest_angles();
  return 0.5 * d.dot(model.stiffness() * d);
}

double damper_power(const ChainModel& model, const Eigen::VectorXd& v) {
  return v.dot(model.damping() * v);
}

BaseReaction base_reaction(const ChainModel& model, const ChainData& data, const BasePose& base,
                           const Loads& loads) {
  // Force and moment balance about the pivot O for the whole chain: the base's force F and
  // moment N (about O) plus the loads and gravity make Σ m a_c and Σ (c − O) × m a_c + I ω̇ + ω × I ω.
  BaseReaction r;
  const bool has_loads = loads.num_bodies() == model.num_bodies();
  const Eigen::Vector3d& o = base.position;
  for (int i = 0; i < model.num_bodies(); ++i) {
    const BodyKinematics& b = data.bodies[i];
    const double m = model.bodies[i].mass;
    r.moment += (b.com - o).cross(m * b.com_acceleration) + b.inertia_ground * b.angular_acceleration +
                b.angular_velocity.cross(b.inertia_ground * b.angular_velocity);
    r.moment -= (b.com - o).cross(m * model.gravity);
    r.force += m * (b.com_acceleration - model.gravity);
    if (has_loads) {
      Eigen::Vector3d f, mo;
      loads.resultant(i, b.rotation, f, mo);
      r.moment -= (b.origin - o).cross(f) + mo;
      r.force -= f;
    }
  }
  return r;
}

double base_power(const ChainModel& model, const ChainData& data, const BasePose& base,
                  const Loads& loads) {
  // The base's power is ω · N + v_O · F.
  const BaseReaction r = base_reaction(model, data, base, loads);
  return base.angular_velocity.dot(r.moment) + base.velocity.dot(r.force);
}

}  // namespace flapsim::mbd
