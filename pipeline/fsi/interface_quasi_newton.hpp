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
///
/// Reuse (IQN-ILS(q), Degroote et al. 2009): the pairs of the q previous time steps are
/// kept beside the current step's (never a difference across two steps), so a step's first
/// update is already a quasi-Newton one and the fixed point's slow and diverging modes,
/// which change little from step to step, need not be found again in every step. Old pairs
/// can make the least squares ill-conditioned, so with q > 0 the pairs pass a filter
/// (QR2 of Haelterman et al. 2016): by Gram–Schmidt from the newest, a pair whose residual
/// difference has less than kReuseFilterLimit of its length outside the newer ones is
/// dropped for good. The earlier steps' pairs are also all dropped once the step's residual
/// has grown beyond its first one: their Jacobian no longer fits (a film that snaps into
/// another shape; docs/fsi.md, "Coupling"), and least squares would keep mixing them in.
/// With q = 0 nothing is kept across steps and the least squares is the
/// rank-revealing QR of the step's pairs, as before reuse existed.

#include <Eigen/Core>

#include <vector>

namespace flapsim::fsi {

class InterfaceQuasiNewton {
 public:
  /// \param max_columns  secant pairs kept (the oldest dropped beyond; at most the size
  ///                     of the residual is useful)
  /// \param reuse_steps  earlier time steps whose pairs are kept (q; 0: none)
  explicit InterfaceQuasiNewton(int max_columns, int reuse_steps = 0);

  /// Starts a new time step: forgets the pairs of more than reuse_steps steps ago (all of
  /// the earlier steps' with q = 0); the step's first residual pairs with nothing before it.
  void start_step();

  /// Records sub-iteration k: residual r (the part the least squares fit, size fixed
  /// per step) and output x̂ (the whole state). Returns false while there is no secant
  /// pair yet (the caller relaxes otherwise), else true with the next input in `next`.
  bool next(const Eigen::VectorXd& r, const Eigen::VectorXd& output, Eigen::VectorXd& next);

  int columns() const { return columns_; }  ///< secant pairs in use
  long filtered() const { return filtered_; }  ///< pairs the filter has dropped so far
  long stale_drops() const { return stale_drops_; }  ///< times the earlier steps' pairs were dropped as stale

  /// A pair whose residual difference keeps less than this fraction of its length after
  /// the newer pairs' directions are taken out of it is dropped (reuse only).
  static constexpr double kReuseFilterLimit = 1e-2;

 private:
  void drop_column(int j);
  bool filtered_update(const Eigen::VectorXd& r, Eigen::VectorXd& c);

  int max_columns_;
  int reuse_steps_;
  int columns_ = 0;
  long step_ = 0;
  long filtered_ = 0;
  long stale_drops_ = 0;
  double first_norm_ = 0.0;  ///< |r| of the step's first sub-iteration
  std::vector<long> column_step_;  ///< the time step each pair came from, newest first
  Eigen::MatrixXd q_, r_;          ///< the filter's Gram–Schmidt factors (reuse only)
  Eigen::VectorXd qtr_, coefficients_;
  bool has_previous_ = false;
  Eigen::VectorXd previous_r_, previous_output_;
  Eigen::MatrixXd v_, w_;  ///< newest column first
};

}  // namespace flapsim::fsi
