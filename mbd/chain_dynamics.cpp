#include "mbd/chain_dynamics.hpp"

#include "mbd/chain_kinematics.hpp"

#include <Eigen/Cholesky>

namespace flapsim::mbd {

void compute_mass_matrix_and_bias(const ChainModel& model, ChainData& data) {
  data.mass_matrix.setZero();
  data.inertial_bias.setZero();
  Eigen::Vector3d f, torque;
  for (int i = model.first_jointed_body(); i < model.num_bodies(); ++i) {
    const BodyKinematics& b = data.bodies[i];
    const double m = model.bodies[i].mass;
    // Only the columns of joints 0..i are non-zero; restrict the products to them.
    const int cols = model.dof_of_body(i) + 2;
    const auto jv = b.com_jacobian.leftCols(cols);
    const auto jw = b.angular_jacobian.leftCols(cols);
    // Products straight into M (no heap temporaries in the time loop).
    data.mass_matrix.topLeftCorner(cols, cols).noalias() += (m * jv.transpose()) * jv;
    auto ijw = data.inertia_times_jacobian.leftCols(cols);
    ijw.noalias() = b.inertia_ground * jw;
    data.mass_matrix.topLeftCorner(cols, cols).noalias() += jw.transpose() * ijw;
    // Newton–Euler with the bias accelerations: F = m a_c, N = I ω̇ + ω × I ω.
    f = m * b.com_acceleration;
    torque = b.inertia_ground * b.angular_acceleration +
             b.angular_velocity.cross(b.inertia_ground * b.angular_velocity);
    data.inertial_bias.head(cols).noalias() += jv.transpose() * f;
    data.inertial_bias.head(cols).noalias() += jw.transpose() * torque;
  }
}

void compute_spring_forces(const ChainModel& model, ChainData& data, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v) {
  // Full matrices (bend–twist and joint-to-joint coupling); no heap temporaries.
  data.deflection = q - data.rest;
  data.spring_force.noalias() = data.stiffness * data.deflection;
  data.spring_force.noalias() += data.damping * v;
}

void compute_all_terms(const ChainModel& model, ChainData& data, const BasePose& base,
                       const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Loads& loads) {
  forward_kinematics(model, data, base, q, v);
  compute_mass_matrix_and_bias(model, data);
  compute_spring_forces(model, data, q, v);
  compute_generalized_loads(model, data, loads);
}

void forward_dynamics(const ChainModel& model, ChainData& data, const BasePose& base,
                      const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Loads& loads,
                      Eigen::VectorXd& qdd) {
  compute_all_terms(model, data, base, q, v, loads);
  qdd = data.generalized_load - data.inertial_bias - data.spring_force;
  Eigen::LLT<Eigen::MatrixXd> llt(data.mass_matrix);  // small (≤ ~40); off the hot path
  qdd = llt.solve(qdd);
  update_accelerations(model, data, qdd);
}

}  // namespace flapsim::mbd
