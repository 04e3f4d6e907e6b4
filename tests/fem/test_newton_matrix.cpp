// The factorised Newton matrix (fem/newton_matrix.hpp): a symmetric matrix that is not
// positive definite (a thin film's tangent in compression) is factorised by LDLᵀ after
// CHOLMOD's LLᵀ refuses it, and solves its system to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include "fem/newton_matrix.hpp"

namespace {

using namespace flapsim;

// A 1-D chain of n DOFs: tridiagonal with diagonal d and off-diagonals −1, the lower
// triangle stored (TangentForm::SymmetricLower). Its eigenvalues are d − 2 cos(kπ/(n+1)),
// k = 1…n: positive definite for d > 2 cos(π/(n+1)), indefinite and nonsingular for
// d = 1.5 (two below zero, none zero for n = 12).
fem::SparseMatrix chain_matrix(int n, double d) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, d);
    if (i + 1 < n) t.emplace_back(i + 1, i, -1.0);
  }
  fem::SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

// Free DOFs that are not whole nodes (no frame rotation is applied).
std::vector<int> first_dofs(int n) {
  std::vector<int> free(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) free[static_cast<std::size_t>(i)] = i;
  return free;
}

double residual_of_solve(fem::NewtonMatrix& m, const fem::SparseMatrix& lower, int n) {
  const Eigen::MatrixXd full = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  Eigen::VectorXd r(n), x;
  for (int i = 0; i < n; ++i) r(i) = std::sin(1.0 + i);
  m.solve(r, Eigen::Matrix3d::Identity(), x);
  return (full * x - r).norm() / r.norm();
}

TEST(NewtonMatrixFactorisation, APositiveDefiniteMatrixIsFactorisedByLltWithoutFallback) {
  const int n = 12;
  fem::NewtonMatrix m(fem::TangentForm::SymmetricLower, first_dofs(n));
  ASSERT_TRUE(m.factorize(chain_matrix(n, 3.0), Eigen::Matrix3d::Identity(), 1e-3));
  EXPECT_EQ(m.lu_fallbacks(), 0);
  EXPECT_LT(residual_of_solve(m, chain_matrix(n, 3.0), n), 1e-14);
}

TEST(NewtonMatrixFactorisation, AnIndefiniteMatrixIsFactorisedAfterLltRefusesIt) {
  // d = 1.5: eigenvalues 1.5 − 2 cos(kπ/13) from −0.44 to 3.44, two of them negative, the
  // smallest in size 0.0030.
  const int n = 12;
  fem::NewtonMatrix m(fem::TangentForm::SymmetricLower, first_dofs(n));
  ASSERT_TRUE(m.factorize(chain_matrix(n, 1.5), Eigen::Matrix3d::Identity(), 1e-3));
  EXPECT_EQ(m.lu_fallbacks(), 1);  // the LLᵀ refused it once
  EXPECT_TRUE(m.valid());
  // Accurate enough for a Newton correction: the system to 1e-12 (condition number
  // 3.44 / 0.0030 ≈ 1200).
  EXPECT_LT(residual_of_solve(m, chain_matrix(n, 1.5), n), 1e-12);
  // The same object then takes a positive definite matrix (by LLᵀ again: no new refusal
  // counted) and solves it as well.
  ASSERT_TRUE(m.factorize(chain_matrix(n, 3.0), Eigen::Matrix3d::Identity(), 1e-3));
  EXPECT_EQ(m.lu_fallbacks(), 1);
  EXPECT_LT(residual_of_solve(m, chain_matrix(n, 3.0), n), 1e-14);
}

TEST(NewtonMatrixFactorisation, ALargeMatrixWithASmallSeparatorIsFactorisedInTwoParts) {
  // A chain of 3000 DOFs (≥ NewtonMatrix's 2000 rows): METIS splits it at one or a few
  // rows, each half is factorised on its own (separated_cholesky.hpp). Positive definite:
  // the two parts and the separator solve it to round-off (condition number < 5).
  const int n = 3000;
  fem::NewtonMatrix m(fem::TangentForm::SymmetricLower, first_dofs(n));
  ASSERT_TRUE(m.factorize(chain_matrix(n, 3.0), Eigen::Matrix3d::Identity(), 1e-3));
  EXPECT_TRUE(m.separated());
  EXPECT_EQ(m.lu_fallbacks(), 0);
  EXPECT_LT(residual_of_solve(m, chain_matrix(n, 3.0), n), 1e-14);
  // Indefinite (d = 1.5: eigenvalues 1.5 − 2 cos(kπ/3001), about a third below zero, the
  // smallest in size 5.4e-4): the parts' LLᵀ refuses it, their LDLᵀ takes it.
  fem::NewtonMatrix indefinite(fem::TangentForm::SymmetricLower, first_dofs(n));
  ASSERT_TRUE(indefinite.factorize(chain_matrix(n, 1.5), Eigen::Matrix3d::Identity(), 1e-3));
  EXPECT_TRUE(indefinite.separated());
  EXPECT_EQ(indefinite.lu_fallbacks(), 1);
  EXPECT_LT(residual_of_solve(indefinite, chain_matrix(n, 1.5), n), 1e-9);
}

}  // namespace
