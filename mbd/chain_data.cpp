#include "mbd/chain_data.hpp"

namespace flapsim::mbd {

ChainData::ChainData(const ChainModel& model) {
  const int nb = model.num_bodies();
  const int n = model.num_dofs();
  bodies.resize(nb);
  for (auto& b : bodies) {
    b.com_jacobian = Eigen::MatrixXd::Zero(3, n);
    b.angular_jacobian = Eigen::MatrixXd::Zero(3, n);
  }
  mass_matrix = Eigen::MatrixXd::Zero(n, n);
  inertial_bias = Eigen::VectorXd::Zero(n);
  spring_force = Eigen::VectorXd::Zero(n);
  generalized_load = Eigen::VectorXd::Zero(n);
  stiffness = model.stiffness();
  damping = model.damping();
  stiffness_abs = stiffness.cwiseAbs();
  rest = model.rest_angles();
  deflection = Eigen::VectorXd::Zero(n);
  inertia_times_jacobian = Eigen::MatrixXd::Zero(3, n);
  load_damping.matrix = Eigen::MatrixXd::Zero(n, n);
  load_damping.reference = Eigen::VectorXd::Zero(n);
  step.jacobian = Eigen::MatrixXd::Zero(n, n);
  step.jacobian_damping = Eigen::MatrixXd::Zero(n, n);
  step.lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  for (Eigen::VectorXd* v : {&step.x, &step.dx, &step.r, &step.r_new, &step.dr, &step.jdx, &step.q,
                             &step.v, &step.a, &step.scratch, &step.scratch2})
    *v = Eigen::VectorXd::Zero(n);
}

}  // namespace flapsim::mbd
