#pragma once
/// \file shell_element.hpp
/// \brief Flat 3-node shell with 6 DOF per node: DKT plate bending (Batoz,
/// Bathe & Ho 1980) plus the ANDES "OPT" membrane with drilling rotations
/// (Felippa 2003), built in the element's own plane and rotated to global axes.
///
/// Why these two: DKT is a Kirchhoff element, so thin plates (h/a = 1/4000 for
/// an insect wing) cannot shear-lock; OPT gives the drilling DOF a physical
/// stiffness, so an all-flat wing has a non-singular K without artificial
/// springs, and it does not lock in in-plane bending.

#include <array>

#include <Eigen/Core>

namespace flapsim::fem {

/// Material of one shell element.
struct ShellProperties {
  double thickness = 0.0;        ///< h [m]
  double youngs_modulus = 0.0;   ///< E [Pa]
  double poisson_ratio = 0.3;    ///< ν [-]
  double density = 0.0;          ///< ρ [kg/m³]
  double nonstructural_mass_per_area = 0.0;  ///< μ [kg/m²]: mass without stiffness
};

using Matrix18d = Eigen::Matrix<double, 18, 18>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;

/// Stiffness and mass of one shell element in global axes; DOF order per node
/// (ux, uy, uz, rx, ry, rz), nodes in the order given.
struct ShellElementMatrices {
  Matrix18d stiffness;
  Matrix18d mass;
};

/// \brief Element axes: rows are local x (along edge 0→1), local y, and the
/// unit normal z = (p1 − p0) × (p2 − p0) / |…|, in global coordinates.
Eigen::Matrix3d shell_axes(const std::array<Eigen::Vector3d, 3>& p);

/// \brief DKT bending stiffness in local coordinates, DOFs (w, θx, θy) per node
/// with θx = ∂w/∂y and θy = −∂w/∂x (right-handed rotations).
/// \param x, y  local corner coordinates [m]
/// \param D     bending stiffness E h³ / (12 (1 − ν²)) [N·m]
/// \param nu    Poisson's ratio
Matrix9d dkt_stiffness(const std::array<double, 3>& x, const std::array<double, 3>& y,
                       double D, double nu);

/// \brief DKT curvatures (κxx, κyy, 2κxy) [1/m] at area point (ξ, η) for local
/// nodal values (w, θx, θy); κ = ∇β with β = −∇w, the convention of Batoz.
Eigen::Vector3d dkt_curvature(const std::array<double, 3>& x, const std::array<double, 3>& y,
                              const Eigen::Matrix<double, 9, 1>& u, double xi, double eta);

/// \brief Plane-stress elasticity (σxx, σyy, τxy) = C (εxx, εyy, γxy) [Pa].
Eigen::Matrix3d plane_stress(double E, double nu);

/// \brief The OPT membrane's basic force lumping L (Felippa 2003, α_b = 3/2), local
/// DOFs (u, v, θz) per node: the element's constant strain is ε = Lᵀ d / (A h) and the
/// nodal forces of a constant stress σ are L σ, so the basic stiffness is L C Lᵀ / (A h).
/// \param h  thickness [m]
Eigen::Matrix<double, 9, 3> opt_basic_lumping(const std::array<double, 3>& x, const std::array<double, 3>& y,
                                              double h);

/// \brief OPT membrane stiffness (α_b = 3/2, β₀ = max(½(1 − 4ν²), 0.01), the
/// optimal β₁…β₉), local DOFs (u, v, θz) per node.
/// \param h  thickness [m]
Matrix9d opt_membrane_stiffness(const std::array<double, 3>& x, const std::array<double, 3>& y,
                                double E, double nu, double h);

/// Where the OPT membrane's 9 DOFs (u, v, θz of nodes 0, 1, 2) and the DKT plate's 9 (w, θx,
/// θy of nodes 0, 1, 2) sit among the element's 18 local ones (u, v, w, θx, θy, θz a node).
inline constexpr int kShellMembraneDofs[9] = {0, 1, 5, 6, 7, 11, 12, 13, 17};
inline constexpr int kShellBendingDofs[9] = {2, 3, 4, 8, 9, 10, 14, 15, 16};

/// \brief Stiffness in the element's own axes (shell_axes), DOF order per node (u, v, w,
/// θx, θy, θz): the OPT membrane on (u, v, θz) and the DKT plate on (w, θx, θy), uncoupled
/// (a flat element), every coupling entry an exact zero.
Matrix18d shell_local_stiffness(const std::array<Eigen::Vector3d, 3>& p, const ShellProperties& props);

/// \brief Stiffness and consistent mass in global axes.
///
/// Mass: consistent linear-triangle translational mass of (ρh + μ) in all three
/// directions, and a lumped rotary inertia ρh³/12 · A/3 on each nodal rotation
/// (including the drilling one; physically negligible for thin shells, it keeps
/// M positive definite for the eigensolver).
ShellElementMatrices shell_element(const std::array<Eigen::Vector3d, 3>& p,
                                   const ShellProperties& props);

}  // namespace flapsim::fem
