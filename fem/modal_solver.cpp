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
    const SerialOpenMpRegions cholmod_on_this_thread;  // CHOLMOD's fixed 4-thread teams
    llt_.compute(A);
    if (llt_.info() != Eigen::Success)
      throw SingularStiffness(
          "modal solve: K − σM is not positive definite (unsupported mechanism, or a shift "
          "above the lowest eigenvalue)");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, K_.rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, K_.rows());
    {
      const SerialOpenMpRegions cholmod_on_this_thread;
      y = llt_.solve(x);
    }
    if (deflate_.cols() > 0) y -= deflate_ * (deflate_.transpose() * (M_ * y));
  }
  /// Modes already found (M-orthonormal columns): removed from every result,
  /// so Lanczos converges to the ones it missed.
  void set_deflation(const Eigen::MatrixXd& V) { deflate_ = V; }

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
  Eigen::MatrixXd deflate_;
};

/// Number of eigenvalues of K x = λ M x below `lambda`: the number of negative
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

  CholmodShiftInvert op(Kf, Mf);
  op.set_shift(sigma);
  Spectra::SparseSymMatProd<double> bop(Mf);
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
        eigs(op, bop, want, cv, sigma);
    // Start from (K − σM)⁻¹ M r: in the range of the operator, free of
    // components the mass matrix cannot see (and of the deflated modes).
    Eigen::VectorXd r(n), start(n);
    for (Eigen::Index i = 0; i < n; ++i) r(i) = uni(rng);
    const Eigen::VectorXd Mr = Mf * r;
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
      const double mn = vec2.col(k).dot(Mf * vec2.col(k));
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
    const double top = lam.maxCoeff();
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
