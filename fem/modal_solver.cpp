#include "fem/modal_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include "fem/serial_openmp_regions.hpp"
#include "fem/static_solver.hpp"

namespace flapsim::fem {

namespace {

/// y = (K' − σ'M')⁻¹ x for the rescaled pencil K' = 4^-b K, M' = 4^-a M, with a CHOLMOD
/// factor of the unscaled K − σM (σ = 4^(b−a) σ'): the operator Spectra's shift-invert
/// mode needs (rows, cols, set_shift, perform_op). Powers of four keep every rescaling
/// exact (docs/fem.md, "Small wings").
class CholmodShiftInvert {
 public:
  using Scalar = double;
  CholmodShiftInvert(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& M_scaled)
      : K_(K), M_(M), M_scaled_(M_scaled) {}
  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }
  /// K' = 4^-b K, M' = 4^-a M.
  void set_scales(int a, int b) {
    mass_exponent_ = a;
    stiffness_exponent_ = b;
  }
  /// σ' in the rescaled pencil's units; factorises K − σM once per distinct σ.
  void set_shift(double sigma_scaled) {
    const double sigma = std::ldexp(sigma_scaled, 2 * (stiffness_exponent_ - mass_exponent_));
    if (factored_ && sigma == factored_shift_) return;
    factored_ = false;
    const SparseMatrix A = K_ - sigma * M_;
    const SerialOpenMpRegions cholmod_on_this_thread;  // CHOLMOD's fixed 4-thread teams
    llt_.compute(A);
    if (llt_.info() != Eigen::Success)
      throw SingularStiffness(
          "modal solve: K − σM is not positive definite (unsupported mechanism, or a shift "
          "above the lowest eigenvalue)");
    factored_ = true;
    factored_shift_ = sigma;
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, K_.rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, K_.rows());
    {
      const SerialOpenMpRegions cholmod_on_this_thread;
      y = llt_.solve(x);
    }
    if (stiffness_exponent_ != 0) y *= std::ldexp(1.0, 2 * stiffness_exponent_);
    if (deflate_.cols() > 0) y -= deflate_ * (deflate_.transpose() * (M_scaled_ * y));
  }
  /// Modes already found (M'-orthonormal columns): removed from every result,
  /// so Lanczos converges to the ones it missed.
  void set_deflation(const Eigen::MatrixXd& V) { deflate_ = V; }

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  const SparseMatrix& M_scaled_;
  int mass_exponent_ = 0;
  int stiffness_exponent_ = 0;
  bool factored_ = false;
  double factored_shift_ = 0.0;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
  Eigen::MatrixXd deflate_;
};

/// The integer e with 4^e nearest to x > 0 (in the logarithm); 0 for anything else.
int nearest_power_of_four(double x) {
  if (!(x > 0.0) || !std::isfinite(x)) return 0;
  return static_cast<int>(std::lround(std::log2(x) / 2.0));
}

/// The rough size of λ₁ − σ, the shifted pencil's lowest eigenvalue: the Rayleigh quotient
/// of one inverse iteration (K − σM) y = M 1 from a load on every DOF (Rayleigh's method).
/// Only its order of magnitude is used, to choose the rescaling.
double lowest_shifted_eigenvalue_estimate(const SparseMatrix& K, const SparseMatrix& M, double sigma,
                                          CholmodShiftInvert& op) {
  const Eigen::VectorXd load = M * Eigen::VectorXd::Ones(K.rows());
  Eigen::VectorXd y(K.rows());
  op.perform_op(load.data(), y.data());
  const double my = y.dot(M * y);
  return my > 0.0 ? (y.dot(K * y) - sigma * my) / my : 0.0;
}

/// pivots of K − λM (Sylvester's law of inertia, the Sturm sequence check).
int count_eigenvalues_below(const SparseMatrix& K, const SparseMatrix& M, double lambda) {
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(SparseMatrix(K - lambda * M));
  if (ldlt.info() != Eigen::Success) return -1;
  return static_cast<int>((ldlt.vectorD().array() < 0.0).count());
}

}  // namespace

ModalResult solve_modes(const SparseMatrix& K, const SparseMatrix& M,
                        const Constraints& constraints, const ModalOptions& options) {
  const SparseMatrix Kf = constraints.reduce(K);
  const SparseMatrix Mf = constraints.reduce(M);
  const Eigen::Index n = Kf.rows();
  const int nev = std::min<int>(options.num_modes, static_cast<int>(n) - 1);
  if (nev < 1) throw std::invalid_argument("solve_modes: too few free DOFs");

  double sigma = options.shift;
  if (std::isnan(sigma)) {
    if (constraints.num_free() < constraints.num_dofs()) {
      sigma = 0.0;
    } else {
      double lam_max = 0.0;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double m = Mf.coeff(i, i);
        if (m > 0.0) lam_max = std::max(lam_max, Kf.coeff(i, i) / m);
      }
      sigma = -1e-9 * lam_max;
    }
  }

  // Spectra's Lanczos holds absolute thresholds (a residual below ε·√n restarts it, Ritz
  // values converge relative to max(|θ|, ε^(2/3))), so it wants the operator's eigenvalues
  // 1/(λ − σ) near 1: a 40 µm plate's λ ~ 1e13 made its modes 4 … 12 wrong by up to 21 %.
  // Solve K' x = λ' M' x with K' = 4^-b K, M' = 4^-a M, λ = 4^(b−a) λ', chosen so that the
  // largest M'_ii and the lowest λ' − σ' are near 1; a power of four rescales exactly.
  double mass_diagonal_max = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) mass_diagonal_max = std::max(mass_diagonal_max, Mf.coeff(i, i));
  const int mass_exponent = nearest_power_of_four(mass_diagonal_max);
  const SparseMatrix Ms = std::ldexp(1.0, -2 * mass_exponent) * Mf;
  CholmodShiftInvert op(Kf, Mf, Ms);
  op.set_shift(sigma);  // unscaled (a = b = 0) for the estimate
  const int stiffness_exponent =
      mass_exponent + nearest_power_of_four(lowest_shifted_eigenvalue_estimate(Kf, Mf, sigma, op));
  op.set_scales(mass_exponent, stiffness_exponent);
  const double to_unscaled =
      std::ldexp(1.0, 2 * (stiffness_exponent - mass_exponent));  // λ = to_unscaled · λ'
  const double sigma_scaled = sigma / to_unscaled;
  Spectra::SparseSymMatProd<double> bop(Ms);
  std::mt19937 rng(12345);  // fixed seed: reproducible results
  std::uniform_real_distribution<double> uni(-1.0, 1.0);

  // One Lanczos pass for `want` modes, M-orthogonal to the modes in `found`.
  Eigen::VectorXd lam(0);
  Eigen::MatrixXd vec(n, 0);
  auto lanczos = [&](int want) {
    op.set_deflation(vec);
    const int cv = static_cast<int>(std::min<Eigen::Index>(n - vec.cols(), std::max(2 * want + 1, want + 20)));
    Spectra::SymGEigsShiftSolver<CholmodShiftInvert, Spectra::SparseSymMatProd<double>,
                                 Spectra::GEigsMode::ShiftInvert>
        eigs(op, bop, want, cv, sigma_scaled);
    // Start from (K − σM)⁻¹ M r: in the range of the operator, free of
    // components the mass matrix cannot see (and of the deflated modes).
    Eigen::VectorXd r(n), start(n);
    for (Eigen::Index i = 0; i < n; ++i) r(i) = uni(rng);
    const Eigen::VectorXd Mr = Ms * r;
    op.perform_op(Mr.data(), start.data());
    eigs.init(start.data());
    eigs.compute(Spectra::SortRule::LargestMagn, options.max_iterations, options.tolerance,
                 Spectra::SortRule::SmallestAlge);
    if (eigs.info() != Spectra::CompInfo::Successful)
      throw std::runtime_error("modal solve: Lanczos did not converge (" + std::to_string(want) +
                               " modes requested)");
    const Eigen::VectorXd l = eigs.eigenvalues();
    const Eigen::MatrixXd v = eigs.eigenvectors();
    Eigen::VectorXd lam2(lam.size() + l.size());
    lam2 << lam, l;
    Eigen::MatrixXd vec2(n, vec.cols() + v.cols());
    vec2 << vec, v;
    for (Eigen::Index k = vec.cols(); k < vec2.cols(); ++k) {  // M-normalise the new ones
      const double mn = vec2.col(k).dot(Ms * vec2.col(k));
      if (mn > 0.0) vec2.col(k) /= std::sqrt(mn);
    }
    lam = lam2;
    vec = vec2;
  };
  lanczos(nev);
  // Lanczos finds one vector per exactly repeated eigenvalue (e.g. the six
  // rigid-body modes of a free wing) and may miss the others: count the
  // eigenvalues below the highest one found (Sturm check) and search for the
  // missing ones orthogonal to those found.
  const bool sturm = options.sturm_check == ModalOptions::SturmCheck::Always ||
                     (options.sturm_check == ModalOptions::SturmCheck::Auto &&
                      constraints.num_free() == constraints.num_dofs());
  for (int pass = 0; sturm && pass < 4; ++pass) {
    const double top = lam.maxCoeff() * to_unscaled;
    const double probe = top + 1e-6 * std::max(std::abs(top), std::abs(sigma)) + 1e-300;
    const int below = count_eigenvalues_below(Kf, Mf, probe);
    const int missing = below - static_cast<int>(lam.size());
    if (below < 0 || missing <= 0 || vec.cols() + missing >= n) break;
    lanczos(missing);
  }
  // Sort, keep the lowest nev.
  std::vector<Eigen::Index> order(static_cast<size_t>(lam.size()));
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<Eigen::Index>(i);
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return lam(a) < lam(b); });
  order.resize(static_cast<size_t>(std::min<Eigen::Index>(nev, lam.size())));
  Eigen::VectorXd lam_sorted(static_cast<Eigen::Index>(order.size()));
  Eigen::MatrixXd vec_sorted(n, static_cast<Eigen::Index>(order.size()));
  for (size_t i = 0; i < order.size(); ++i) {
    lam_sorted(static_cast<Eigen::Index>(i)) = lam(order[i]);
    vec_sorted.col(static_cast<Eigen::Index>(i)) = vec.col(order[i]);
  }
  lam = lam_sorted;
  vec = vec_sorted;

  lam *= to_unscaled;
  vec *= std::ldexp(1.0, -mass_exponent);  // M'-normalised to M-normalised: φ = 2^-a φ'
  ModalResult out;
  out.eigenvalues = lam;
  out.frequencies_hz.resize(lam.size());
  out.shapes.resize(constraints.num_dofs(), lam.size());
  for (Eigen::Index k = 0; k < lam.size(); ++k) {
    const double l = lam(k);
    out.frequencies_hz(k) = std::copysign(std::sqrt(std::abs(l)), l) / (2.0 * std::numbers::pi);
    out.shapes.col(k) = constraints.expand(vec.col(k));
  }
  return out;
}

}  // namespace flapsim::fem
