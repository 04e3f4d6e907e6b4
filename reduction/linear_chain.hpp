#pragma once
/// \file linear_chain.hpp
/// \brief Small motions of a bar chain about its straight rest shape with the base
/// held fixed: the linearised mass and stiffness matrices, the chain's modes, its
/// static response to point loads, and displacements of points on its bodies
/// (docs/reduction.md, "Checking the chain against the FEM").
///
/// All vectors are in the chain's root frame R (mbd::ChainModel::root_rotation);
/// the root joint is at R's origin. Used by the reduction to compare the chain
/// with the FEM; the time-domain dynamics are mbd's.

#include <Eigen/Core>

#include <vector>

#include "mbd/chain_model.hpp"

namespace flapsim::reduction {

/// One mode of the linearised chain.
struct ChainMode {
  double frequency_hz = 0.0;  ///< [Hz]
  Eigen::VectorXd shape;      ///< over Φ, mass-normalised
  /// Share of the spring energy in the θ block of K, θᵀK_θθθ / (θᵀK_θθθ + αᵀK_ααα) [-].
  double bending_energy_fraction = 0.0;
  bool is_bending() const { return bending_energy_fraction >= 0.5; }
};

class LinearChain {
 public:
  /// \param chain  a chain with zero rest angles, bodies along R's y axis
  /// \throws std::invalid_argument if the chain is not straight at rest or invalid
  explicit LinearChain(const mbd::ChainModel& chain);

  int num_dofs() const { return static_cast<int>(stiffness_.rows()); }
  /// Linearised mass matrix M_c = Σ_k J_kᵀ R_k J_k [kg m²].
  const Eigen::MatrixXd& mass_matrix() const { return mass_; }
  /// Joint stiffness over Φ (full) [N m/rad].
  const Eigen::MatrixXd& stiffness() const { return stiffness_; }
  /// Rest position of body k's inboard joint in R [m].
  const Eigen::Vector3d& joint_position(int body) const {
    return joints_[static_cast<std::size_t>(body)];
  }
  /// Index of the body that contains span position y (along R's y) [m].
  int body_at(double y) const;

  /// \brief Modes of K q = ω² M q, lowest first.
  std::vector<ChainMode> modes() const;

  /// \brief Generalised force of a force \p force and a torque \p torque acting on
  /// body \p body at the point \p point (R components, point at rest) [N m].
  Eigen::VectorXd generalized_force(int body, const Eigen::Vector3d& point,
                                    const Eigen::Vector3d& force,
                                    const Eigen::Vector3d& torque) const;

  /// \brief Static joint angles under a generalised force: q = K⁻¹ Q [rad].
  Eigen::VectorXd static_response(const Eigen::VectorXd& generalized_force) const;

  /// \brief Small displacement of the point \p point (rest position, R) of body
  /// \p body for joint angles \p q [m].
  Eigen::Vector3d displacement(int body, const Eigen::Vector3d& point,
                               const Eigen::VectorXd& q) const;
  /// \brief Small rotation vector of body \p body for joint angles \p q [rad].
  Eigen::Vector3d rotation(int body, const Eigen::VectorXd& q) const;

 private:
  const mbd::ChainModel* chain_ = nullptr;
  std::vector<Eigen::Vector3d> joints_;
  Eigen::MatrixXd mass_;
  Eigen::MatrixXd stiffness_;
};

}  // namespace flapsim::reduction
