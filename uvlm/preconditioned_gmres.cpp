#include "uvlm/preconditioned_gmres.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flapsim::uvlm {

namespace {

/// w = A z, the rows in kProductBlocks fixed blocks shared among the threads: each
/// entry is summed alike whatever the thread count. One thread below kParallelRows.
constexpr int kProductBlocks = 4;
constexpr Eigen::Index kParallelRows = 400;

void multiply(const Eigen::MatrixXd& a, const Eigen::VectorXd& z, Eigen::VectorXd& w) {
  const Eigen::Index n = a.rows();
  const bool parallel = n >= kParallelRows && !omp_in_parallel() && omp_get_max_threads() > 1;
#pragma omp parallel for schedule(static) if (parallel)
  for (int b = 0; b < kProductBlocks; ++b) {
    const Eigen::Index r0 = n * b / kProductBlocks, r1 = n * (b + 1) / kProductBlocks;
    w.segment(r0, r1 - r0).noalias() = a.middleRows(r0, r1 - r0) * z;
  }
}

}  // namespace

void PreconditionedGmres::reserve(int n, int restart) {
  if (n < 1 || restart < 1) throw std::invalid_argument("GMRES: size and restart length must be >= 1");
  basis_.setZero(n, restart + 1);
  hessenberg_.setZero(restart + 1, restart);
  cosine_.setZero(restart);
  sine_.setZero(restart);
  g_.setZero(restart + 1);
  y_.setZero(restart);
  w_.setZero(n);
  z_.setZero(n);
  r_.setZero(n);
}

PreconditionedGmres::Result PreconditionedGmres::solve(const Eigen::MatrixXd& a,
                                                       const Eigen::PartialPivLU<Eigen::MatrixXd>& preconditioner,
                                                       const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                                       double tolerance, int max_iterations) {
  const Eigen::Index n = basis_.rows();
  const int restart = static_cast<int>(hessenberg_.cols());
  if (a.rows() != n || a.cols() != n || b.size() != n || x.size() != n)
    throw std::invalid_argument("GMRES: the system's size is not the reserved one");
  Result result;
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    x.setZero();
    result.converged = true;
    return result;
  }
  const double target = tolerance * b_norm;
  while (true) {
    // The true residual of the current x: the test that ends the solve.
    multiply(a, x, r_);
    r_ = b - r_;
    const double beta = r_.norm();
    result.relative_residual = beta / b_norm;
    if (beta <= target) {
      result.converged = true;
      return result;
    }
    if (result.iterations >= max_iterations || !std::isfinite(beta)) return result;
    basis_.col(0) = r_ / beta;
    g_.setZero();
    g_(0) = beta;
    int j = 0;
    for (; j < restart && result.iterations < max_iterations;) {
      z_ = preconditioner.solve(basis_.col(j));
      multiply(a, z_, w_);
      for (int i = 0; i <= j; ++i) {  // modified Gram–Schmidt
        const double h = w_.dot(basis_.col(i));
        hessenberg_(i, j) = h;
        w_ -= h * basis_.col(i);
      }
      const double h_next = w_.norm();
      hessenberg_(j + 1, j) = h_next;
      if (h_next > 0.0) basis_.col(j + 1) = w_ / h_next;
      for (int i = 0; i < j; ++i) {  // the earlier rotations on the new column
        const double h0 = hessenberg_(i, j), h1 = hessenberg_(i + 1, j);
        hessenberg_(i, j) = cosine_(i) * h0 + sine_(i) * h1;
        hessenberg_(i + 1, j) = -sine_(i) * h0 + cosine_(i) * h1;
      }
      const double h0 = hessenberg_(j, j), h1 = hessenberg_(j + 1, j);
      const double rho = std::hypot(h0, h1);
      cosine_(j) = rho > 0.0 ? h0 / rho : 1.0;
      sine_(j) = rho > 0.0 ? h1 / rho : 0.0;
      hessenberg_(j, j) = rho;
      hessenberg_(j + 1, j) = 0.0;
      g_(j + 1) = -sine_(j) * g_(j);
      g_(j) = cosine_(j) * g_(j);
      ++j;
      ++result.iterations;
      // |g(j)| is the residual of the least-squares solution after j iterations; stop a
      // little below the target so that the recomputed residual passes the test.
      if (std::abs(g_(j)) <= 0.5 * target || h_next == 0.0) break;
    }
    // x += M⁻¹ V y, H y = g (upper triangular, j × j).
    for (int i = j - 1; i >= 0; --i) {
      double s = g_(i);
      for (int k = i + 1; k < j; ++k) s -= hessenberg_(i, k) * y_(k);
      y_(i) = s / hessenberg_(i, i);
    }
    w_.noalias() = basis_.leftCols(j) * y_.head(j);
    z_ = preconditioner.solve(w_);
    x += z_;
  }
}

}  // namespace flapsim::uvlm
