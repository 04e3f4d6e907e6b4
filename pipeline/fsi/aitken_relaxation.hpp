#pragma once
/// \file aitken_relaxation.hpp
/// \brief Dynamic (Aitken Δ²) under-relaxation of a fixed-point iteration
/// x ← x + ω_k r_k, r_k = G(x_k) − x_k (Irons & Tuck 1969; Küttler & Wall 2008,
/// eq. 44): ω_k = −ω_{k−1} r_{k−1}ᵀ(r_k − r_{k−1}) / |r_k − r_{k−1}|².
///
/// The strong FSI coupling uses it on the end-of-step chain state: a light wing in air
/// whose added mass is comparable to its own mass makes the plain fixed point
/// (ω = 1) oscillate or diverge; the secant estimate of ω adapts to it every step.

#include <Eigen/Core>

namespace flapsim::fsi {

class AitkenRelaxation {
 public:
  /// \param first_omega  ω of the first sub-iteration of the first step
  /// \param max_omega    bound on |ω| (the secant estimate can overshoot when the
  ///                     residuals stop changing)
  explicit AitkenRelaxation(double first_omega = 0.5, double max_omega = 2.0);

  /// Starts a new time step: forgets the last residual; the first ω of the step is the
  /// last ω of the previous step (clamped to [min_start, 1]), as Küttler & Wall suggest.
  void start_step();

  /// ω for residual \p r (size fixed per run; the vector is copied into own storage).
  double next(const Eigen::VectorXd& r);

  double omega() const { return omega_; }  ///< last ω returned

 private:
  double first_omega_, max_omega_;
  double omega_;
  bool has_previous_ = false;
  Eigen::VectorXd previous_, difference_;
};

}  // namespace flapsim::fsi
