#pragma once
/// \file film_triangle.hpp
/// \brief A film triangle: membrane only, three translations per node, total
/// Lagrangian, with the tension-field law (tension_field_membrane.hpp) on the
/// Green–Lagrange strain.
///
/// A 10–50 µm film has a bending stiffness D = E t³/12(1 − ν²) of a few µN m:
/// against the membrane stiffness E t its bending is no structure, and the
/// shell's rotations at nodes only films touch are degrees of freedom with
/// almost no stiffness and no inertia (lowest eigenvalues 10⁻⁶ of the Newton
/// matrix's 10⁵, docs/fsi.md "Film wings"). The film triangle drops them: it is
/// the constant-strain membrane of a sail or an airbag (Bonet & Wood,
/// "Nonlinear Continuum Mechanics for Finite Element Analysis", 2nd ed. 2008,
/// §7.4 and §9.4: the constant-strain triangle with the Green strain), whose
/// energy is exactly invariant under any rigid motion, so its force and
/// tangent are exact derivatives of one energy in the nodal positions (no spin
/// variables, a symmetric tangent).
///
/// With g_a = Σ_i x_i ∂N_i/∂X_a (a = 1, 2 the reference in-plane axes):
///   E_ab = ½ (g_a · g_b − δ_ab),   e = (E₁₁, E₂₂, 2E₁₂)
///   W = V w(e)  (V = A₀ t; w the tension-field energy density)
///   f_i = V B_iᵀ S,   B_i = ∂e/∂x_i = [N_i,1 g₁ᵀ; N_i,2 g₂ᵀ; N_i,1 g₂ᵀ + N_i,2 g₁ᵀ]
///   K_ij = V (B_iᵀ C_t B_j + (S₁₁ N_i,1 N_j,1 + S₂₂ N_i,2 N_j,2 + S₁₂ (N_i,1 N_j,2 + N_i,2 N_j,1)) I₃)
/// with S = ∂w/∂e and C_t = ∂S/∂e (symmetric, positive semidefinite).

#include <array>

#include <Eigen/Core>

namespace flapsim::fem {

/// Constant data of a film triangle.
struct FilmTriangle {
  std::array<int, 3> nodes{};
  Eigen::Matrix<double, 3, 2> shape_gradient;  ///< ∂N_i/∂X_a on the reference plane [1/m]
  double volume = 0.0;                         ///< V = A₀ t [m³]
  double youngs_modulus = 0.0;                 ///< E [Pa]
  double poisson_ratio = 0.0;                  ///< ν [-]
};

/// \brief The film triangle on reference corners p [m] of thickness t [m].
/// Throws std::invalid_argument on a degenerate triangle.
FilmTriangle make_film_triangle(const std::array<int, 3>& nodes, const std::array<Eigen::Vector3d, 3>& p,
                                double thickness, double youngs_modulus, double poisson_ratio);

/// \brief Strain energy [J], internal force f (node a's force in f[3a..3a+2], N) and, if
/// asked, the tangent K = ∂f/∂x [N/m] at the current corners x [m].
double film_triangle_force(const FilmTriangle& film, const std::array<Eigen::Vector3d, 3>& x,
                           Eigen::Matrix<double, 9, 1>& f, Eigen::Matrix<double, 9, 9>* K);

/// \brief Green–Lagrange strain (E₁₁, E₂₂, 2E₁₂) of the triangle at x.
Eigen::Vector3d film_triangle_strain(const FilmTriangle& film, const std::array<Eigen::Vector3d, 3>& x);

}  // namespace flapsim::fem
