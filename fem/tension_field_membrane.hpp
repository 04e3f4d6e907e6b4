#pragma once
/// \file tension_field_membrane.hpp
/// \brief A membrane that cannot carry compression: the tension-field
/// (wrinkling) law of an isotropic plane-stress film.
///
/// A film a few µm thick buckles into wrinkles under the least compressive
/// stress, at a wavelength set by its bending stiffness that no wing mesh
/// resolves; on a coarser mesh the compressed film instead buckles at the mesh's
/// own wavelength, within a fraction of a time step (docs/fsi.md, "Film wings").
/// Tension-field theory replaces the wrinkles by their mean effect: the film
/// carries tension along the wrinkles and nothing across them (Wagner 1929;
/// Pipkin 1986, "The relaxed energy density for isotropic elastic membranes",
/// IMA J. Appl. Math. 36:85–99; the mixed stress–strain criterion of Kang & Im
/// 1997, "Finite element analysis of wrinkling membranes", J. Appl. Mech.
/// 64:263–269). With ε₁ ≥ ε₂ the principal strains and n₁ the direction of ε₁:
///   taut      ε₂ + ν ε₁ > 0 (both principal stresses ≥ 0):  σ = C ε
///   wrinkled  ε₁ > 0 ≥ ε₂ + ν ε₁:  uniaxial σ = E ε₁ n₁⊗n₁ (an isotropic film
///             wrinkles across its major principal strain, so the tension runs
///             along n₁ and the wrinkling strain takes up the rest)
///   slack     ε₁ ≤ 0:  σ = 0
/// The relaxed energy density, in one expression
///   w = ½ E ⟨ε₁⟩₊² + E/(2(1 − ν²)) ⟨ε₂ + ν ε₁⟩₊²,
/// is continuous with its first derivative across the boundaries, and its tangent
/// is symmetric and positive semidefinite, so the structure's Newton matrix (with
/// its mass term) stays LLᵀ-factorisable wherever the film is compressed. Only C¹,
/// though, and a film at rest sits exactly on the kinks: on the 75 mm film wing
/// Newton converges linearly there (docs/fsi.md, "Film wings").

#include <Eigen/Core>

namespace flapsim::fem {

/// Which part of the tension-field law a strain falls in.
enum class MembraneState { Taut, Wrinkled, Slack };

/// Stress, tangent and energy density of one membrane strain.
struct MembraneResponse {
  Eigen::Vector3d stress;          ///< (σxx, σyy, τxy) [Pa]
  Eigen::Matrix3d tangent;         ///< ∂σ/∂ε [Pa], symmetric positive semidefinite
  double energy_density = 0.0;     ///< w [J/m³]
  MembraneState state = MembraneState::Taut;
};

/// \brief The tension-field response to the strain (εxx, εyy, γxy) (engineering
/// shear) of an isotropic film of Young's modulus E [Pa] and Poisson ratio ν.
MembraneResponse tension_field_response(const Eigen::Vector3d& strain, double E, double nu);

}  // namespace flapsim::fem
