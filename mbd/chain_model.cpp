#include "mbd/chain_model.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>
#include <string>

namespace flapsim::mbd {

Eigen::MatrixXd ChainModel::stiffness() const {
  if (stiffness_matrix.size() > 0) return stiffness_matrix;
  Eigen::VectorXd k(num_dofs());
  for (int b = first_jointed_body(); b < num_bodies(); ++b) {
    k(dof_of_body(b)) = joints[b].bend_stiffness;
    k(dof_of_body(b) + 1) = joints[b].twist_stiffness;
  }
  return k.asDiagonal();
}

Eigen::MatrixXd ChainModel::damping() const {
  if (damping_matrix.size() > 0) return damping_matrix;
  Eigen::VectorXd c(num_dofs());
  for (int b = first_jointed_body(); b < num_bodies(); ++b) {
    c(dof_of_body(b)) = joints[b].bend_damping;
    c(dof_of_body(b) + 1) = joints[b].twist_damping;
  }
  return c.asDiagonal();
}

Eigen::VectorXd ChainModel::stiffness_diagonal() const { return stiffness().diagonal(); }

Eigen::VectorXd ChainModel::damping_diagonal() const { return damping().diagonal(); }

void ChainModel::scale_stiffness(double factor) {
  for (auto& j : joints) {
    j.bend_stiffness *= factor;
    j.twist_stiffness *= factor;
  }
  stiffness_matrix *= factor;
}

Eigen::VectorXd ChainModel::rest_angles() const {
  Eigen::VectorXd r(num_dofs());
  for (int b = first_jointed_body(); b < num_bodies(); ++b) {
    r(dof_of_body(b)) = joints[b].bend_rest;
    r(dof_of_body(b) + 1) = joints[b].twist_rest;
  }
  return r;
}

double ChainModel::total_mass() const {
  double m = 0.0;
  for (const auto& b : bodies) m += b.mass;
  return m;
}

void ChainModel::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("chain: " + what); };
  if (bodies.empty()) fail("no bodies");
  if (joints.size() != bodies.size())
    fail("joints must have one entry per body (" + std::to_string(bodies.size()) + "), got " +
         std::to_string(joints.size()));
  if (!root_offset.allFinite()) fail("root offset is not finite");
  const Eigen::Matrix3d rtr = root_rotation.transpose() * root_rotation;
  if (!root_rotation.allFinite() || (rtr - Eigen::Matrix3d::Identity()).norm() > 1e-9 ||
      root_rotation.determinant() < 0.0)
    fail("root rotation is not a proper rotation matrix");
  for (int i = 0; i < num_bodies(); ++i) {
    const ChainBody& b = bodies[i];
    const std::string name = "body " + std::to_string(i + 1) + ": ";  // 1-based, as in the chain file
    if (!(b.length > 0.0) || !std::isfinite(b.length)) fail(name + "length must be > 0");
    // A welded body may be massless (the part of the span inside a root clamp that the
    // wing does not reach, e.g. the robofly's); a moving body needs mass.
    const bool welded = i < first_jointed_body();
    if (!std::isfinite(b.mass) || !(welded ? b.mass >= 0.0 : b.mass > 0.0))
      fail(name + (welded ? "mass must be >= 0" : "mass must be > 0"));
    if (!b.center_of_mass.allFinite() || !b.outboard_joint.allFinite() || !b.inertia.allFinite())
      fail(name + "non-finite centre of mass, outboard joint or inertia");
    const double scale = b.inertia.norm();
    if ((b.inertia - b.inertia.transpose()).norm() > 1e-9 * scale)
      fail(name + "inertia tensor is not symmetric");
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(b.inertia);
    const Eigen::Vector3d p = es.eigenvalues();  // principal moments, ascending
    if (p(0) < -1e-12 * scale) fail(name + "inertia tensor is not positive semi-definite");
    if (p(0) + p(1) < p(2) * (1.0 - 1e-9))
      fail(name + "principal moments violate the triangle inequality I1 + I2 >= I3");
  }
  if (root == RootAttachment::rigid && (welded_bodies < 1 || welded_bodies > num_bodies()))
    fail("welded bodies must be between 1 and the number of bodies (" + std::to_string(num_bodies()) +
         "), got " + std::to_string(welded_bodies));
  const int n = num_dofs();
  auto check_matrix = [&](const Eigen::MatrixXd& m, const std::string& what) {
    if (m.size() == 0) return;
    if (m.rows() != n || m.cols() != n)
      fail(what + " must be " + std::to_string(n) + " x " + std::to_string(n) + " (2 per joint), got " +
           std::to_string(m.rows()) + " x " + std::to_string(m.cols()));
    if (!m.allFinite()) fail(what + " has non-finite entries");
    const double scale = m.cwiseAbs().maxCoeff();
    if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) fail(what + " is not symmetric");
    if (n > 0) {
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (m + m.transpose()), Eigen::EigenvaluesOnly);
      if (es.eigenvalues()(0) < -1e-10 * scale)
        fail(what + " is not positive semi-definite (smallest eigenvalue " +
             std::to_string(es.eigenvalues()(0)) + ")");
    }
  };
  check_matrix(stiffness_matrix, "stiffness matrix");
  check_matrix(damping_matrix, "damping matrix");
  for (int k = first_jointed_body(); k < num_bodies(); ++k) {
    const ChainJoint& j = joints[k];
    const std::string name = "joint " + std::to_string(k + 1) + ": ";  // joint k+1 is inboard of body k+1
    if (!(j.bend_stiffness >= 0.0) || !(j.twist_stiffness >= 0.0) || !std::isfinite(j.bend_stiffness) ||
        !std::isfinite(j.twist_stiffness))
      fail(name + "spring stiffness must be finite and >= 0");
    if (!(j.bend_damping >= 0.0) || !(j.twist_damping >= 0.0) || !std::isfinite(j.bend_damping) ||
        !std::isfinite(j.twist_damping))
      fail(name + "damping must be finite and >= 0");
    if (!std::isfinite(j.bend_rest) || !std::isfinite(j.twist_rest))
      fail(name + "rest angles must be finite");
  }
}

ChainModel make_uniform_cantilever_chain(double length, double bending_stiffness,
                                         double torsional_stiffness, double mass_per_length,
                                         double torsional_inertia_per_length, int num_bodies) {
  if (num_bodies < 1) throw std::invalid_argument("uniform chain: need at least one body");
  ChainModel model;
  model.root = RootAttachment::sprung;
  const double a = length / num_bodies;
  const double m = mass_per_length * a;
  for (int i = 0; i < num_bodies; ++i) {
    ChainBody b;
    b.length = a;
    b.mass = m;
    b.center_of_mass = Eigen::Vector3d(0.0, 0.5 * a, 0.0);
    const double i_bend = m * a * a / 12.0;                // slender bar about its centre
    const double i_twist = torsional_inertia_per_length * a;  // about the span axis
    b.inertia = Eigen::Vector3d(i_bend, i_twist, i_bend + i_twist).asDiagonal();
    b.outboard_joint = Eigen::Vector3d(0.0, a, 0.0);
    model.bodies.push_back(b);
    ChainJoint j;
    const double cell = (i == 0) ? 0.5 * a : a;  // the root joint carries half a cell
    j.bend_stiffness = bending_stiffness / cell;
    j.twist_stiffness = torsional_stiffness / cell;
    model.joints.push_back(j);
  }
  return model;
}

}  // namespace flapsim::mbd
