#pragma once
/// \file corotational_shell.hpp
/// \brief The flat DKT + OPT shell triangle (shell_element.hpp) made
/// geometrically nonlinear by the EICR kernel (corotational_kernel.hpp,
/// Felippa & Haugen 2005): large rotations, small strains, the linear local
/// stiffness unchanged.
///
/// Co-rotated frame: the axes of shell_element.hpp on the current corners
/// (x along the current edge 0→1, z the current normal), origin at the
/// centroid. Its spin map G: rotations about the in-plane axes follow the
/// tilt of the plane, ω̃₁ = Σ ∂N_a/∂ȳ δz̃_a, ω̃₂ = −Σ ∂N_a/∂x̄ δz̃_a (linear
/// triangle shape functions on the current corners); the drilling part
/// follows edge 0→1, ω̃₃ = (δỹ₁ − δỹ₀)/ℓ₀₁.

#include <array>

#include <Eigen/Core>

#include "fem/corotational_kernel.hpp"
#include "fem/shell_element.hpp"

namespace flapsim::fem {

/// Constant data of one co-rotational shell triangle.
struct CorotationalShell {
  std::array<int, 3> nodes{};
  Matrix18d local_stiffness;             ///< k in reference local axes
  /// k's uncoupled parts (shell_element.hpp): the membrane on (u, v, θz) and the plate on
  /// (w, θx, θy), three DOFs a node, the nodes in order (ShellLinearLaw's k d).
  Matrix9d membrane_stiffness, bending_stiffness;
  Eigen::Matrix3d reference_axes;        ///< T₀ (rows)
  std::array<Eigen::Vector3d, 3> reference_local;  ///< X̄_a about the centroid [m]
  /// The split k = k_rest + L C Lᵀ / V of the membrane's constant-strain part (for the
  /// tension-field membrane, tension_field_membrane.hpp): L the OPT basic force lumping
  /// on the 18 local DOFs, V = A h [m³].
  Matrix18d stiffness_without_basic_membrane;
  Eigen::Matrix<double, 18, 3> membrane_lumping;  ///< L [m²]
  double volume = 0.0;                   ///< V [m³]
  double youngs_modulus = 0.0;           ///< E [Pa]
  double poisson_ratio = 0.0;            ///< ν [-]
};

/// The linear local response W = ½ dᵀ k d of a shell: k d as the membrane's and the
/// plate's 9 × 9 products (a quarter of the 18 × 18 product's work and half its memory,
/// which the element force streams at every Newton iteration: docs/fem.md, "The elements'
/// forces and tangents").
struct ShellLinearLaw {
  const CorotationalShell& shell;
  double operator()(const Eigen::Matrix<double, 18, 1>& d, Eigen::Matrix<double, 18, 1>& f_local,
                    Matrix18d* k_local) const;
};

/// The local response of a shell whose membrane cannot carry compression: the
/// constant membrane strain ε = Lᵀ d / V relaxed by the tension-field law, the
/// rest (bending, the OPT's higher-order membrane part) linear. W = ½ dᵀ k_rest d + V w(ε).
struct ShellTensionFieldLaw {
  const CorotationalShell& shell;
  double operator()(const Eigen::Matrix<double, 18, 1>& d, Eigen::Matrix<double, 18, 1>& f_local,
                    Matrix18d* k_local) const;
};

/// \brief The constant membrane strain (εxx, εyy, γxy) of local displacements d.
Eigen::Vector3d shell_membrane_strain(const CorotationalShell& shell, const Eigen::Matrix<double, 18, 1>& d);

/// \brief Reference data of a triangle with corners p (global) and properties s.
CorotationalShell make_corotational_shell(const std::array<int, 3>& nodes,
                                          const std::array<Eigen::Vector3d, 3>& p,
                                          const ShellProperties& s);

/// \brief Current co-rotated frame and spin map of the triangle.
CorotatedFrame<3> shell_corotated_frame(const std::array<Eigen::Vector3d, 3>& x);

}  // namespace flapsim::fem
