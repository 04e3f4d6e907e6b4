#pragma once
/// \file nodal_rotation.hpp
/// \brief Finite rotations of the co-rotational FEM: nodal rotations are stored
/// as rotation matrices R (reference → current) and updated multiplicatively
/// with a spatial (left) spin increment, R ← exp(Δω̂) R, exp by the Rodrigues
/// formula. A rotation vector is only ever extracted from the small
/// deformational rotation of one element (|θ| ≪ π), so no singularity at π
/// is met in use.
///
/// References: Felippa & Haugen 2005 (CMAME 194), §4–5 and Appendix; Argyris
/// 1982 (the exponential map); [Felippa & Haugen 2005] in docs/references.md.

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "fem/skew.hpp"

namespace flapsim::fem {

/// \brief exp(θ̂) by the Rodrigues formula; θ the rotation vector [rad].
inline Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& theta) {
  const double t2 = theta.squaredNorm();
  const Eigen::Matrix3d S = skew(theta);
  double a, b;  // sin t / t, (1 − cos t) / t²
  if (t2 < 1e-8) {
    a = 1.0 - t2 / 6.0;
    b = 0.5 - t2 / 24.0;
  } else {
    const double t = std::sqrt(t2);
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t2;
  }
  return Eigen::Matrix3d::Identity() + a * S + b * S * S;
}

/// \brief log(R): the rotation vector of R [rad] (|θ| ≤ π).
inline Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

/// \brief H(θ) = J_l(θ)⁻¹: maps a spatial spin variation δω (δR = δω̂ R) to the
/// variation of the rotation vector, δθ = H(θ) δω. H = I − ½θ̂ + η θ̂²,
/// η = (1 − (t/2) cot(t/2)) / t² (Felippa & Haugen 2005, eq. (4.21)).
inline Eigen::Matrix3d inverse_tangent(const Eigen::Vector3d& theta) {
  const double t2 = theta.squaredNorm();
  const Eigen::Matrix3d S = skew(theta);
  double eta;
  if (t2 < 1e-6) {
    eta = 1.0 / 12.0 + t2 / 720.0;
  } else {
    const double t = std::sqrt(t2);
    eta = (1.0 - 0.5 * t / std::tan(0.5 * t)) / t2;
  }
  return Eigen::Matrix3d::Identity() - 0.5 * S + eta * S * S;
}

/// \brief Λ(θ, m) = ∂(H(θ)ᵀ m)/∂θ for a fixed vector m: the derivative that
/// gives the moment-correction stiffness K_GM of Felippa & Haugen 2005 (§6.3).
/// With Hᵀm = m + ½ θ×m + η θ×(θ×m) and μ = η'(t)/t:
/// Λ = −½ m̂ + η [(θ·m) I + θ mᵀ − 2 m θᵀ] + μ (θ×(θ×m)) θᵀ.
inline Eigen::Matrix3d inverse_tangent_derivative(const Eigen::Vector3d& theta, const Eigen::Vector3d& m) {
  const double t2 = theta.squaredNorm();
  double eta, mu;
  if (t2 < 1e-4) {
    eta = 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
    mu = 1.0 / 360.0 + t2 / 7560.0;
  } else {
    const double t = std::sqrt(t2), c = 1.0 / std::tan(0.5 * t), s = std::sin(0.5 * t);
    eta = (1.0 - 0.5 * t * c) / t2;
    const double deta = -(0.5 * c - t / (4.0 * s * s)) / t2 - 2.0 * (1.0 - 0.5 * t * c) / (t2 * t);
    mu = deta / t;
  }
  const Eigen::Vector3d ttm = theta.cross(theta.cross(m));
  return -0.5 * skew(m) +
         eta * (theta.dot(m) * Eigen::Matrix3d::Identity() + theta * m.transpose() - 2.0 * m * theta.transpose()) +
         mu * ttm * theta.transpose();
}

}  // namespace flapsim::fem
