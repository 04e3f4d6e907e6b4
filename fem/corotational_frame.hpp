#pragma once
/// \file corotational_frame.hpp
/// \brief The 3-D Euler–Bernoulli frame element (frame_element.hpp) made
/// geometrically nonlinear by the EICR kernel (corotational_kernel.hpp,
/// Felippa & Haugen 2005; the frame's axes after Battini & Pacoste 2002).
///
/// Co-rotated frame: x̄ along the current chord; the local z axis is the
/// reference local z carried by the mean of the two nodal rotations,
/// q = ½(R₀ + R₁) z₀, made normal to the chord (Battini & Pacoste 2002, with z
/// in place of their y). Spin map G: ω̃₂ = −(δz̃₁ − δz̃₀)/ℓ, ω̃₃ = (δỹ₁ − δỹ₀)/ℓ,
/// and the twist of the frame ω̃₁ = [½Σ_a (q̃_a,z δω̃_a,1 − q̃_a,x δω̃_a,3) + q̃_x ω̃₃] / q̃_z,
/// with q̃_a = T_r R_a z₀ and q̃ = T_r q: the exact variation of that definition.

#include <array>

#include <Eigen/Core>

#include "fem/corotational_kernel.hpp"
#include "fem/frame_element.hpp"

namespace flapsim::fem {

/// Constant data of one co-rotational frame element.
struct CorotationalFrame {
  std::array<int, 2> nodes{};
  Matrix12d local_stiffness;             ///< k in reference local axes
  Eigen::Matrix3d reference_axes;        ///< T₀ (rows)
  std::array<Eigen::Vector3d, 2> reference_local;  ///< X̄_a about the midpoint [m]
};

/// \brief Reference data of a frame element from a to b.
CorotationalFrame make_corotational_frame(const std::array<int, 2>& nodes, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const FrameProperties& props);

/// \brief Current co-rotated frame and spin map from the end positions and rotations.
CorotatedFrame<2> frame_corotated_frame(const CorotationalFrame& element, const std::array<Eigen::Vector3d, 2>& x,
                                        const std::array<Eigen::Matrix3d, 2>& R);

}  // namespace flapsim::fem
