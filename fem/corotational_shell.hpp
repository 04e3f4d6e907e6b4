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
  Eigen::Matrix3d reference_axes;        ///< T₀ (rows)
  std::array<Eigen::Vector3d, 3> reference_local;  ///< X̄_a about the centroid [m]
};

/// \brief Reference data of a triangle with corners p (global) and properties s.
CorotationalShell make_corotational_shell(const std::array<int, 3>& nodes,
                                          const std::array<Eigen::Vector3d, 3>& p,
                                          const ShellProperties& s);

/// \brief Current co-rotated frame and spin map of the triangle.
CorotatedFrame<3> shell_corotated_frame(const std::array<Eigen::Vector3d, 3>& x);

}  // namespace flapsim::fem
