#pragma once
/// \file strip_mass.hpp
/// \brief Rigid-body mass properties of strips of FEM nodes, taken from the FEM's
/// own (consistent) mass matrix so that the strips add up to the FEM totals to
/// round-off (docs/reduction.md, "Mass").

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace flapsim::reduction {

/// Mass, first moment and inertia of a body about the frame origin, all in one frame.
struct RigidMass {
  double mass = 0.0;                                          ///< [kg]
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();     ///< Σ m r [kg m]
  Eigen::Matrix3d inertia_origin = Eigen::Matrix3d::Zero();   ///< about the origin [kg m²]

  /// Centre of mass [m] (origin if massless).
  Eigen::Vector3d center_of_mass() const {
    return mass > 0.0 ? Eigen::Vector3d(first_moment / mass) : Eigen::Vector3d::Zero();
  }
  /// Inertia tensor about the centre of mass (parallel-axis theorem) [kg m²].
  Eigen::Matrix3d inertia_about_center() const;
  /// Inertia tensor about point \p p [kg m²].
  Eigen::Matrix3d inertia_about(const Eigen::Vector3d& p) const;
  /// The 6×6 rigid-body mass matrix about the origin, [v; ω] ordering.
  Eigen::Matrix<double, 6, 6> matrix() const;
  RigidMass& operator+=(const RigidMass& other);
};

/// \brief Splits a 6×6 rigid-body mass matrix [m I, −m[c]×; m[c]×, I_O] into its parts.
/// The mass is the mean of the translational diagonal; the first moment the mean of
/// the two off-diagonal blocks' skew parts.
RigidMass rigid_mass_from_matrix(const Eigen::Matrix<double, 6, 6>& r);

/// \brief Rigid-body mass properties of each strip of nodes.
///
/// Strip k's share of the rigid-body mass matrix is R_k = ½(Φᵀ S_k M Φ + Φᵀ M S_k Φ),
/// Φ the rigid-body modes about the origin and S_k the selector of the strip's DOFs,
/// so Σ_k R_k = Φᵀ M Φ exactly.
/// \param mass            FEM mass matrix, 6 DOF per node in the order (ux, uy, uz,
///                        rx, ry, rz), DOF index 6·node + component, unconstrained [kg, kg m, kg m²]
/// \param nodes           node positions, one column per node [m]
/// \param strip_of_node   strip index of each node in [0, num_strips); −1 leaves a node out
/// \param num_strips      number of strips
/// \return one RigidMass per strip, about the origin of the node coordinates
std::vector<RigidMass> strip_rigid_masses(const Eigen::SparseMatrix<double>& mass,
                                          const Eigen::Matrix3Xd& nodes,
                                          const std::vector<int>& strip_of_node, int num_strips);

/// \brief Rigid-body mass properties of the whole model (Φᵀ M Φ).
RigidMass total_rigid_mass(const Eigen::SparseMatrix<double>& mass, const Eigen::Matrix3Xd& nodes);

}  // namespace flapsim::reduction
