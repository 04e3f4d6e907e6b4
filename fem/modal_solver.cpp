#include "fem/modal_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include "fem/static_solver.hpp"

namespace flapsim::fem {

namespace {

/// y = (K − σM)⁻¹ x with a CHOLMOD factor: the operator Spectra's shift-invert
/// mode needs (rows, cols, set_shift, perform_op).
class CholmodShiftInvert {
 public:
  using Scalar = double;
  CholmodShiftInvert(const SparseMatrix& K, const SparseMatrix& M) : K_(K), M_(M) {}
  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }
  void set_shift(double sigma) {
    const SparseMatrix A = K_ - sigma * M_;
    llt_.compute(A);
    if (llt_.info() != Eigen::Success)
      throw SingularStiffness(
          "modal solve: K − σM is not positive definite (unsupported mechanism, or a shift "
          "above the lowest eigenvalue)");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, K_.rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, K_.rows());
    y = llt_.solve(x);
  }

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
};

}  // namespace

ModalResult solve_modes(const SparseMatrix& K, const SparseMatrix& M,
                        const Constraints& constraints, const ModalOptions& options) {
  const SparseMatrix Kf = constraints.reduce(K);
  const SparseMatrix Mf = constraints.reduce(M);
  const Eigen::Index n = Kf.rows();
  const int nev = std::min<int>(options.num_modes, static_cast<int>(n) - 1);
  if (nev < 1) throw std::invalid_argument("solve_modes: too few free DOFs");
  const int ncv = static_cast<int>(std::min<Eigen::Index>(n, std::max(2 * nev + 1, nev + 20)));

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

  CholmodShiftInvert op(Kf, Mf);
  Spectra::SparseSymMatProd<double> bop(Mf);
  Spectra::SymGEigsShiftSolver<CholmodShiftInvert, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      eigs(op, bop, nev, ncv, sigma);
  // Start from (K − σM)⁻¹ M r: a vector in the range of the operator, free of
  // components the mass matrix cannot see. Fixed seed: reproducible results.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Eigen::VectorXd r(n), start(n);
  for (Eigen::Index i = 0; i < n; ++i) r(i) = uni(rng);
  const Eigen::VectorXd Mr = Mf * r;
  op.perform_op(Mr.data(), start.data());
  eigs.init(start.data());
  eigs.compute(Spectra::SortRule::LargestMagn, options.max_iterations, options.tolerance,
               Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("modal solve: Lanczos did not converge (" +
                             std::to_string(nev) + " modes requested)");
  const Eigen::VectorXd lam = eigs.eigenvalues();
  const Eigen::MatrixXd vec = eigs.eigenvectors();

  ModalResult out;
  out.eigenvalues = lam;
  out.frequencies_hz.resize(lam.size());
  out.shapes.resize(constraints.num_dofs(), lam.size());
  for (Eigen::Index k = 0; k < lam.size(); ++k) {
    const double l = lam(k);
    out.frequencies_hz(k) = std::copysign(std::sqrt(std::abs(l)), l) / (2.0 * std::numbers::pi);
    Eigen::VectorXd v = vec.col(k);
    const double mn = v.dot(Mf * v);
    if (mn > 0.0) v /= std::sqrt(mn);
    out.shapes.col(k) = constraints.expand(v);
  }
  return out;
}

}  // namespace flapsim::fem
