// A sparse SPD matrix factorised in two parts and their separator (fem/separated_cholesky.hpp):
// the solve is the matrix's inverse to round-off (block elimination, Golub & Van Loan 2013,
// §4.2), the same bits on one thread and two, and a matrix that is not positive definite
// is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/Sparse>
#include <omp.h>

#include "fem/separated_cholesky.hpp"

namespace {

using namespace flapsim;

// A plate-like matrix: an nx × ny grid of nodes with `dofs` unknowns each, every node
// coupled to its 8 neighbours (the pattern of a shell mesh's node blocks), lower triangle
// stored. Off-diagonal entries −1 (and a small coupling between a node's own unknowns),
// diagonal `diagonal`: positive definite once the diagonal exceeds the row sums of the
// off-diagonals' sizes (Gershgorin), 8 dofs + (dofs − 1) · 0.1 < diagonal.
fem::SparseMatrix grid_matrix(int nx, int ny, int dofs, double diagonal) {
  std::vector<Eigen::Triplet<double>> t;
  auto index = [&](int x, int y, int d) { return (y * nx + x) * dofs + d; };
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x)
      for (int d = 0; d < dofs; ++d) {
        const int i = index(x, y, d);
        t.emplace_back(i, i, diagonal + 0.01 * std::sin(1.0 + i));
        for (int e = 0; e < d; ++e) t.emplace_back(i, index(x, y, e), 0.1);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int xn = x + dx, yn = y + dy;
            if ((dx == 0 && dy == 0) || xn < 0 || yn < 0 || xn >= nx || yn >= ny) continue;
            for (int e = 0; e < dofs; ++e) {
              const int j = index(xn, yn, e);
              if (j < i) t.emplace_back(i, j, -1.0);
            }
          }
      }
  const int n = nx * ny * dofs;
  fem::SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

Eigen::VectorXd right_hand_side(Eigen::Index n) {
  Eigen::VectorXd r(n);
  for (Eigen::Index i = 0; i < n; ++i) r(i) = std::cos(0.3 * static_cast<double>(i));
  return r;
}

TEST(SeparatedCholesky, SolvesTheSystemToRoundOff) {
  const fem::SparseMatrix a = grid_matrix(40, 30, 3, 25.0);
  fem::SeparatedCholesky split;
  ASSERT_TRUE(split.analyse(a));
  // A 40 × 30 grid bisected by METIS: a line of nodes across it (30 or 40 nodes of 3
  // unknowns, or a little more), the parts about half each.
  EXPECT_GT(split.separator_rows(), 0);
  EXPECT_LE(split.separator_rows(), 3 * 60);
  EXPECT_EQ(split.part_rows(0) + split.part_rows(1) + split.separator_rows(), a.rows());
  EXPECT_GT(split.part_rows(0), a.rows() / 4);
  EXPECT_GT(split.part_rows(1), a.rows() / 4);
  ASSERT_TRUE(split.factorize(a));
  const Eigen::VectorXd r = right_hand_side(a.rows());
  Eigen::VectorXd x;
  split.solve(r, x);
  // Against Eigen's own sparse Cholesky of the whole matrix: both within round-off
  // (condition number < (25 + 24.2) / (25 − 24.2) ≈ 60 by Gershgorin).
  Eigen::SimplicialLLT<fem::SparseMatrix, Eigen::Lower> whole(a);
  ASSERT_EQ(whole.info(), Eigen::Success);
  const Eigen::VectorXd reference = whole.solve(r);
  EXPECT_LT((x - reference).norm() / reference.norm(), 1e-13);
  const Eigen::VectorXd ax = a.selfadjointView<Eigen::Lower>() * x;
  EXPECT_LT((ax - r).norm() / r.norm(), 1e-14);
}

TEST(SeparatedCholesky, OneThreadAndTwoGiveTheSameBits) {
  const fem::SparseMatrix a = grid_matrix(30, 30, 6, 60.0);
  const Eigen::VectorXd r = right_hand_side(a.rows());
  const int threads = omp_get_max_threads();
  Eigen::VectorXd x[2];
  for (int t = 0; t < 2; ++t) {
    omp_set_num_threads(t + 1);
    fem::SeparatedCholesky split;
    ASSERT_TRUE(split.analyse(a));
    ASSERT_TRUE(split.factorize(a));
    split.solve(r, x[t]);
  }
  omp_set_num_threads(threads);
  ASSERT_EQ(x[0].size(), x[1].size());
  EXPECT_EQ(0, std::memcmp(x[0].data(), x[1].data(), sizeof(double) * static_cast<std::size_t>(x[0].size())));
}

TEST(SeparatedCholesky, AMatrixThatIsNotPositiveDefiniteIsRefused) {
  // The same grid with diagonal 5: the constant vector gives xᵀAx < 0 (row sums about
  // 5 − 8 · 1 < 0 inside the grid).
  const fem::SparseMatrix a = grid_matrix(30, 30, 1, 5.0);
  fem::SeparatedCholesky split;
  ASSERT_TRUE(split.analyse(a));
  EXPECT_FALSE(split.factorize(a));
}

TEST(SeparatedCholesky, TheLdltVariantSolvesAnIndefiniteSystemToRoundOff) {
  // The grid with diagonal 5.3 (1 unknown a node): about half its eigenvalues below zero,
  // none near it (the 2-D spectrum 5.3 − Σ of the neighbours' cosines; the smallest in size
  // is checked below through the solve). LLᵀ refuses it; LDLᵀ without pivoting solves it.
  const fem::SparseMatrix a = grid_matrix(30, 30, 1, 5.3);
  fem::SeparatedCholesky llt;
  ASSERT_TRUE(llt.analyse(a));
  EXPECT_FALSE(llt.factorize(a));
  fem::SeparatedCholesky ldlt(true);
  ASSERT_TRUE(ldlt.analyse(a));
  ASSERT_TRUE(ldlt.factorize(a));
  const Eigen::VectorXd r = right_hand_side(a.rows());
  Eigen::VectorXd x;
  ldlt.solve(r, x);
  // Against a dense LU of the same matrix (partial pivoting: an independent method).
  const Eigen::MatrixXd dense = Eigen::MatrixXd(a).selfadjointView<Eigen::Lower>();
  const Eigen::VectorXd reference = dense.partialPivLu().solve(r);
  EXPECT_LT((x - reference).norm() / reference.norm(), 1e-10);
  EXPECT_LT((dense * x - r).norm() / r.norm(), 1e-12);
}

TEST(SeparatedCholesky, AMatrixWithoutAUsefulSeparatorIsNotSplit) {
  // A dense 30 × 30 block: any separator holds all but two rows.
  const fem::SparseMatrix a = grid_matrix(3, 1, 10, 100.0);
  fem::SeparatedCholesky split;
  EXPECT_FALSE(split.analyse(a));
}

}  // namespace
