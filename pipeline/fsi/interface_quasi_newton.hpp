#pragma once
/// \file interface_quasi_newton.hpp
/// \brief Interface quasi-Newton coupling with an inverse Jacobian from a least-squares
/// model (IQN-ILS; [Degroote et al. 2009], docs/references.md):
/// the fixed point x = H(x) of a coupled step is solved with the secant information of
/// the step's earlier sub-iterations. With the residuals r_i = H(x_i) − x_i and the
/// outputs x̂_i = H(x_i), the columns V = [r_{i+1} − r_i], W = [x̂_{i+1} − x̂_i] give
///     c = argmin ‖V c + r_k‖,   x_{k+1} = x̂_k + W c,
/// an affine combination of the step's outputs (its coefficients add up to 1), so a
/// state whose parts are affine in one of them (the chain's Φ, Φ̇ and algorithmic
/// acceleration are affine in Φ̈ within a generalized-α step) stays consistent.
///
/// Unlike one Aitken factor for all degrees of freedom, it relaxes each direction the
/// sub-iterations have seen by its own amount, so a light wing whose added mass makes
/// some modes of the fixed point diverge (factor < −1) and others converge slowly
/// (factor near 1) converges in about as many sub-iterations as it has such modes
/// (docs/fsi.md, "Coupling").

#include <Eigen/Core>

namespace flapsim::fsi {

class InterfaceQuasiNewton {
 public:
  /// \param max_columns  secant pairs kept (the oldest dropped beyond; at most the size
  ///                     of the residual is useful)
  explicit InterfaceQuasiNewton(int max_columns);

  /// Starts a new time step: forgets the previous step's sub-iterations.
  void start_step();

  /// Records sub-iteration k: residual r (the part the least squares fit, size fixed
  /// per step) and output x̂ (the whole state). Returns false while there is no secant
  /// pair yet (the caller relaxes otherwise), else true with the next input in `next`.
  bool next(const Eigen::VectorXd& r, const Eigen::VectorXd& output, Eigen::VectorXd& next);

  int columns() const { return columns_; }  ///< secant pairs in use

 private:
  int max_columns_;
  int columns_ = 0;
  bool has_previous_ = false;
  Eigen::VectorXd previous_r_, previous_output_;
  Eigen::MatrixXd v_, w_;  ///< newest column first
};

}  // namespace flapsim::fsi
