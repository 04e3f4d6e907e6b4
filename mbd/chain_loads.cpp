#include "mbd/chain_loads.hpp"

#include <stdexcept>
#include <string>

namespace flapsim::mbd {

namespace {
// Axial vector of the antisymmetric part: m = Σ (R p) × F for S = Σ p Fᵀ reads
// m_a = ε_abc (R S)_bc.
Eigen::Vector3d axial(const Eigen::Matrix3d& a) {
  return Eigen::Vector3d(a(1, 2) - a(2, 1), a(2, 0) - a(0, 2), a(0, 1) - a(1, 0));
}
}  // namespace

Loads::Loads(int num_bodies) : per_body_(static_cast<std::size_t>(num_bodies)) {}

void Loads::clear() {
  for (auto& s : per_body_) s = BodySums{};
}

void Loads::add_force(int body, const Eigen::Vector3d& point_body, const Eigen::Vector3d& force,
                      LoadFrame frame) {
  if (body < 0 || body >= num_bodies())
    throw std::out_of_range("Loads::add_force: no body " + std::to_string(body));
  BodySums& s = per_body_[body];
  if (frame == LoadFrame::ground) {
    s.force_ground += force;
    s.arm_force_ground.noalias() += point_body * force.transpose();
  } else {
    s.force_body += force;
    s.moment_body += point_body.cross(force);
  }
}

void Loads::add_moment(int body, const Eigen::Vector3d& moment, LoadFrame frame) {
  if (body < 0 || body >= num_bodies())
    throw std::out_of_range("Loads::add_moment: no body " + std::to_string(body));
  if (frame == LoadFrame::ground)
    per_body_[body].moment_ground += moment;
  else
    per_body_[body].moment_body += moment;
}

void Loads::resultant(int body, const Eigen::Matrix3d& rotation, Eigen::Vector3d& force,
                      Eigen::Vector3d& moment_about_origin) const {
  const BodySums& s = per_body_[body];
  force = s.force_ground + rotation * s.force_body;
  moment_about_origin = s.moment_ground + axial(rotation * s.arm_force_ground) +
                        rotation * s.moment_body;
}

void compute_generalized_loads(const ChainModel& model, ChainData& data, const Loads& loads) {
  data.generalized_load.setZero();
  const bool has_loads = loads.num_bodies() == model.num_bodies();
  if (!has_loads && loads.num_bodies() != 0)
    throw std::invalid_argument("Loads sized for " + std::to_string(loads.num_bodies()) +
                                " bodies, chain has " + std::to_string(model.num_bodies()));
  Eigen::Vector3d f, m;
  for (int i = model.first_jointed_body(); i < model.num_bodies(); ++i) {
    const BodyKinematics& b = data.bodies[i];
    f = model.bodies[i].mass * model.gravity;
    m.setZero();
    if (has_loads) {
      Eigen::Vector3d fl, ml;
      loads.resultant(i, b.rotation, fl, ml);
      f += fl;
      m = ml - (b.com - b.origin).cross(fl);  // moment about the centre of mass
    }
    data.generalized_load.noalias() += b.com_jacobian.transpose() * f;
    data.generalized_load.noalias() += b.angular_jacobian.transpose() * m;
  }
}

double load_power(const ChainModel& model, const ChainData& data, const Loads& loads) {
  double p = 0.0;
  for (int i = 0; i < model.num_bodies(); ++i) {
    const BodyKinematics& b = data.bodies[i];
    p += model.bodies[i].mass * model.gravity.dot(b.com_velocity);
    if (loads.num_bodies() == model.num_bodies()) {
      Eigen::Vector3d f, m;
      loads.resultant(i, b.rotation, f, m);
      p += f.dot(b.origin_velocity) + m.dot(b.angular_velocity);
    }
  }
  return p;
}

}  // namespace flapsim::mbd
