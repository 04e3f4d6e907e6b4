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

double base_power(const ChainModel& model, const ChainData& data, const BasePose& base,
                  const Loads& loads) {
  // Moment balance about the fixed pivot (ground origin) for the whole chain:
  // N_base + Σ (moments of loads and gravity) = Σ d/dt (c × m v_c + I ω).
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const bool has_loads = loads.num_bodies() == model.num_bodies();
  for (int i = 0; i < model.num_bodies(); ++i) {
    const BodyKinematics& b = data.bodies[i];
    const double m = model.bodies[i].mass;
    n += b.com.cross(m * b.com_acceleration) + b.inertia_ground * b.angular_acceleration +
         b.angular_velocity.cross(b.inertia_ground * b.angular_velocity);
    n -= b.com.cross(m * model.gravity);
    if (has_loads) {
      Eigen::Vector3d f, mo;
      loads.resultant(i, b.rotation, f, mo);
      n -= b.origin.cross(f) + mo;
    }
  }
  return base.angular_velocity.dot(n);
}

}  // namespace flapsim::mbd
