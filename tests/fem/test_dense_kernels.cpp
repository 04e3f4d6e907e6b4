// The dense kernels under the Cholesky factorisation (fem/dense_kernels.hpp) and the BLAS
// entry points that CHOLMOD and LAPACK call (fem/blas_interposition.cpp): the same bits as
// the reference BLAS's loops, in both variants, on shapes that leave every remainder of
// the blocking, with exact zeros where the reference skips work.
//
// Source of the expected values: the reference BLAS's definitions (Dongarra, Du Croz,
// Hammarling & Duff 1990, "A set of level 3 basic linear algebra subprograms", ACM TOMS
// 16:1–17; the model implementation's loop order), written out below loop for loop.
#include "fem/dense_kernels.hpp"
#include "fem/dense_kernels_variants.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <random>
#include <vector>

extern "C" {
void dgemm_(const char*, const char*, const int*, const int*, const int*, const double*,
            const double*, const int*, const double*, const int*, const double*, double*,
            const int*, std::size_t, std::size_t);
void dsyrk_(const char*, const char*, const int*, const int*, const double*, const double*,
            const int*, const double*, double*, const int*, std::size_t, std::size_t);
void dtrsm_(const char*, const char*, const char*, const char*, const int*, const int*,
            const double*, const double*, const int*, double*, const int*, std::size_t,
            std::size_t, std::size_t, std::size_t);
void dgemv_(const char*, const int*, const int*, const double*, const double*, const int*,
            const double*, const int*, const double*, double*, const int*, std::size_t);
void dtrsv_(const char*, const char*, const char*, const int*, const double*, const int*,
            double*, const int*, std::size_t, std::size_t, std::size_t);
}

namespace {

using Matrix = std::vector<double>;  // column-major

// Random entries in [−1, 1] with about a fifth exactly zero (the reference skips those).
Matrix random_matrix(std::mt19937& rng, int rows, int cols) {
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::bernoulli_distribution zero(0.2);
  Matrix m(static_cast<std::size_t>(rows) * cols);
  for (double& x : m) x = zero(rng) ? 0.0 : value(rng);
  return m;
}

// The reference's C ← αA·op(B) + βC, op(B) = B ("N") or Bᵀ ("T"), loop for loop.
void reference_gemm(bool b_transposed, int m, int n, int k, double alpha, const Matrix& a,
                    int lda, const Matrix& b, int ldb, double beta, Matrix& c, int ldc) {
  for (int j = 0; j < n; ++j) {
    if (beta == 0.0)
      for (int i = 0; i < m; ++i) c[i + j * ldc] = 0.0;
    else if (beta != 1.0)
      for (int i = 0; i < m; ++i) c[i + j * ldc] = beta * c[i + j * ldc];
    for (int l = 0; l < k; ++l) {
      // LAPACK 3.11's dgemm adds every term (no skip of b = 0, so that a NaN propagates).
      const double temp = alpha * (b_transposed ? b[j + l * ldb] : b[l + j * ldb]);
      for (int i = 0; i < m; ++i) c[i + j * ldc] = c[i + j * ldc] + temp * a[i + l * lda];
    }
  }
}

// The reference's lower C ← αAAᵀ + βC.
void reference_syrk_lower(int n, int k, double alpha, const Matrix& a, int lda, double beta,
                          Matrix& c, int ldc) {
  for (int j = 0; j < n; ++j) {
    if (beta == 0.0)
      for (int i = j; i < n; ++i) c[i + j * ldc] = 0.0;
    else if (beta != 1.0)
      for (int i = j; i < n; ++i) c[i + j * ldc] = beta * c[i + j * ldc];
    for (int l = 0; l < k; ++l) {
      if (a[j + l * lda] == 0.0) continue;
      const double temp = alpha * a[j + l * lda];
      for (int i = j; i < n; ++i) c[i + j * ldc] = c[i + j * ldc] + temp * a[i + l * lda];
    }
  }
}

// The reference's B ← B L⁻ᵀ (right side, lower, transposed, non-unit, α = 1).
void reference_trsm(int m, int n, const Matrix& l, int ldl, Matrix& b, int ldb) {
  for (int k = 0; k < n; ++k) {
    const double temp = 1.0 / l[k + k * ldl];
    for (int i = 0; i < m; ++i) b[i + k * ldb] = temp * b[i + k * ldb];
    for (int j = k + 1; j < n; ++j) {
      if (l[j + k * ldl] == 0.0) continue;
      const double t = l[j + k * ldl];
      for (int i = 0; i < m; ++i) b[i + j * ldb] = b[i + j * ldb] - t * b[i + k * ldb];
    }
  }
}

// The reference's y ← αA x + βy ("N") and y ← αAᵀx + βy ("T", each sum from 0 in row order).
void reference_gemv(bool transposed, int m, int n, double alpha, const Matrix& a, int lda,
                    const Matrix& x, double beta, Matrix& y) {
  const int ny = transposed ? n : m;
  for (int i = 0; i < ny; ++i) y[i] = beta == 0.0 ? 0.0 : (beta != 1.0 ? beta * y[i] : y[i]);
  for (int j = 0; j < n; ++j) {
    if (transposed) {
      double temp = 0.0;
      for (int i = 0; i < m; ++i) temp = temp + a[i + j * lda] * x[i];
      y[j] = y[j] + alpha * temp;
    } else {
      const double temp = alpha * x[j];  // LAPACK 3.11: no skip of x_j = 0
      for (int i = 0; i < m; ++i) y[i] = y[i] + temp * a[i + j * lda];
    }
  }
}

// The reference's x ← L⁻¹x (column form, skipping x_j = 0) and x ← L⁻ᵀx (dot form, rows
// from the last up).
void reference_trsv(bool transposed, int n, const Matrix& l, int ldl, Matrix& x) {
  if (!transposed) {
    for (int j = 0; j < n; ++j) {
      if (x[j] == 0.0) continue;
      x[j] = x[j] / l[j + j * ldl];
      const double temp = x[j];
      for (int i = j + 1; i < n; ++i) x[i] = x[i] - temp * l[i + j * ldl];
    }
  } else {
    for (int j = n - 1; j >= 0; --j) {
      double temp = x[j];
      for (int i = n - 1; i > j; --i) temp = temp - l[i + j * ldl] * x[i];
      x[j] = temp / l[j + j * ldl];
    }
  }
}

// A well-conditioned lower triangle (diagonal 1 … 2, so the solve stays bounded).
Matrix lower_triangle(std::mt19937& rng, int n, int ldl) {
  Matrix l = random_matrix(rng, ldl, n);
  std::uniform_real_distribution<double> diagonal(1.0, 2.0);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < j; ++i) l[i + j * ldl] = 1.0e300;  // above: never read
    l[j + j * ldl] = diagonal(rng);
    for (int i = j + 1; i < n; ++i) l[i + j * ldl] *= 0.3;
  }
  return l;
}

bool same_bits(const Matrix& x, const Matrix& y) {
  return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
}

// Rows and columns around every block edge of both variants (2, 4, 8 rows; 4 columns; 128
// values of l; 256-row panels).
const int kRowCounts[] = {1, 2, 3, 5, 8, 11, 37, 259};
const int kColumnCounts[] = {1, 3, 4, 6, 9};
const int kDepths[] = {0, 1, 7, 130};

TEST(DenseKernels, TheProgramsDgemmGivesTheReferenceLoopsBitsInBothForms) {
  std::mt19937 rng(11);
  for (const bool transposed : {false, true})
    for (int m : kRowCounts)
      for (int n : kColumnCounts)
        for (int k : kDepths)
          for (const double beta : {0.0, 1.0, -0.5}) {
            const int lda = m + 3, ldb = (transposed ? n : k) + 2, ldc = m + 1;
            const Matrix a = random_matrix(rng, lda, std::max(k, 1));
            const Matrix b = transposed ? random_matrix(rng, ldb, std::max(k, 1))
                                        : random_matrix(rng, ldb, n);
            Matrix expected = random_matrix(rng, ldc, n), got = expected;
            const double alpha = -1.0;
            reference_gemm(transposed, m, n, k, alpha, a, lda, b, ldb, beta, expected, ldc);
            dgemm_("N", transposed ? "T" : "N", &m, &n, &k, &alpha, a.data(), &lda, b.data(),
                   &ldb, &beta, got.data(), &ldc, 1, 1);
            ASSERT_TRUE(same_bits(expected, got))
                << "m " << m << " n " << n << " k " << k << " beta " << beta << " transposed "
                << transposed << " (" << flapsim::fem::dense::variant_name() << ")";
          }
}

TEST(DenseKernels, TheProgramsDsyrkGivesTheReferenceLoopsBits) {
  std::mt19937 rng(12);
  for (int n : kRowCounts)
    for (int k : kDepths)
      for (const double beta : {0.0, 1.0}) {
        const int lda = n + 2, ldc = n + 5;
        const Matrix a = random_matrix(rng, lda, std::max(k, 1));
        Matrix expected = random_matrix(rng, ldc, n), got = expected;
        const double alpha = beta == 0.0 ? 1.0 : -1.0;  // CHOLMOD's and dpotrf's calls
        reference_syrk_lower(n, k, alpha, a, lda, beta, expected, ldc);
        dsyrk_("L", "N", &n, &k, &alpha, a.data(), &lda, &beta, got.data(), &ldc, 1, 1);
        ASSERT_TRUE(same_bits(expected, got)) << "n " << n << " k " << k << " beta " << beta;
      }
}

TEST(DenseKernels, TheProgramsDtrsmGivesTheReferenceLoopsBits) {
  std::mt19937 rng(13);
  for (int m : kRowCounts)
    for (int n : {1, 2, 4, 5, 9, 23, 140}) {
      const int ldl = n + 1, ldb = m + 4;
      const Matrix l = lower_triangle(rng, n, ldl);
      Matrix expected = random_matrix(rng, ldb, n), got = expected;
      reference_trsm(m, n, l, ldl, expected, ldb);
      const double one = 1.0;
      dtrsm_("R", "L", "T", "N", &m, &n, &one, l.data(), &ldl, got.data(), &ldb, 1, 1, 1, 1);
      ASSERT_TRUE(same_bits(expected, got)) << "m " << m << " n " << n;
    }
}

TEST(DenseKernels, TheProgramsDgemvAndDtrsvGiveTheReferenceLoopsBitsInBothForms) {
  std::mt19937 rng(16);
  for (const bool transposed : {false, true}) {
    for (int m : kRowCounts)
      for (int n : {1, 3, 4, 7, 130})
        for (const double beta : {0.0, 1.0}) {
          const int lda = m + 2, one = 1;
          const Matrix a = random_matrix(rng, lda, n);
          const Matrix x = random_matrix(rng, transposed ? m : n, 1);
          Matrix expected = random_matrix(rng, transposed ? n : m, 1), got = expected;
          const double alpha = -1.0;  // CHOLMOD's solves
          reference_gemv(transposed, m, n, alpha, a, lda, x, beta, expected);
          dgemv_(transposed ? "T" : "N", &m, &n, &alpha, a.data(), &lda, x.data(), &one, &beta,
                 got.data(), &one, 1);
          ASSERT_TRUE(same_bits(expected, got))
              << "gemv m " << m << " n " << n << " beta " << beta << " transposed " << transposed;
        }
    for (int n : {1, 2, 5, 9, 40, 140}) {
      const int ldl = n + 3, one = 1;
      const Matrix l = lower_triangle(rng, n, ldl);
      Matrix expected = random_matrix(rng, n, 1), got = expected;
      reference_trsv(transposed, n, l, ldl, expected);
      dtrsv_("L", transposed ? "T" : "N", "N", &n, l.data(), &ldl, got.data(), &one, 1, 1, 1);
      ASSERT_TRUE(same_bits(expected, got)) << "trsv n " << n << " transposed " << transposed;
    }
  }
}

// Each variant the CPU has gives the reference loops' bits (the CPU decides which one a
// run uses; the tests above go through the one chosen, these through each).
TEST(DenseKernels, EachVariantTheCpuHasGivesTheReferenceLoopsBits) {
  namespace d = flapsim::fem::dense::detail;
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("avx2");
  std::mt19937 rng(14);
  const int m = 259, n = 9, k = 130, lda = m, ldc = m;
  const Matrix a = random_matrix(rng, lda, k), b = random_matrix(rng, n, k);
  const Matrix l = lower_triangle(rng, n, n);
  const Matrix c0 = random_matrix(rng, ldc, n), s0 = random_matrix(rng, ldc, m);
  Matrix c_ref = c0, s_ref = s0, t_ref = c0;
  reference_gemm(true, m, n, k, -1.0, a, lda, b, n, 1.0, c_ref, ldc);
  reference_syrk_lower(m, k, -1.0, a, lda, 1.0, s_ref, ldc);
  reference_trsm(m, n, l, n, t_ref, ldc);
  const Matrix x = random_matrix(rng, m, 1), y0 = random_matrix(rng, k, 1);
  Matrix y_ref = y0;
  reference_gemv(true, m, k, -1.0, a, lda, x, 1.0, y_ref);
  for (const bool wide : {false, true}) {
    if (wide && !avx2) continue;  // a CPU without AVX2 runs the SSE2 variant only
    const d::KernelTable& kernels = wide ? d::avx2_kernels() : d::sse2_kernels();
    Matrix c = c0, s = s0, t = c0;
    kernels.gemm(m, n, k, -1.0, a.data(), lda, b.data(), 1, n, 1.0, c.data(), ldc);
    kernels.syrk_lower(m, k, -1.0, a.data(), lda, 1.0, s.data(), ldc);
    kernels.trsm_right_lower_transposed(m, n, l.data(), n, t.data(), ldc);
    EXPECT_TRUE(same_bits(c_ref, c)) << (wide ? "avx2" : "sse2");
    EXPECT_TRUE(same_bits(s_ref, s)) << (wide ? "avx2" : "sse2");
    EXPECT_TRUE(same_bits(t_ref, t)) << (wide ? "avx2" : "sse2");
    Matrix y = y0;
    kernels.gemv_transposed(m, k, -1.0, a.data(), lda, x.data(), 1.0, y.data());
    EXPECT_TRUE(same_bits(y_ref, y)) << (wide ? "avx2" : "sse2");
  }
}

// A form the factorisation does not use goes on to the machine's BLAS: its product is
// still right (C = AᵀB against the sums written out; tolerance: the machine's BLAS may
// add in another order, 1e-14 of terms of size 1).
TEST(DenseKernels, AFormTheFactorisationDoesNotUseGoesToTheMachinesBlas) {
  std::mt19937 rng(15);
  const int m = 5, n = 3, k = 7;
  const Matrix a = random_matrix(rng, k, m), b = random_matrix(rng, k, n);
  Matrix c(m * n, 0.0);
  const double one = 1.0, zero = 0.0;
  dgemm_("T", "N", &m, &n, &k, &one, a.data(), &k, b.data(), &k, &zero, c.data(), &m, 1, 1);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      double s = 0.0;
      for (int l = 0; l < k; ++l) s += a[l + i * k] * b[l + j * k];
      EXPECT_NEAR(c[i + j * m], s, 1e-14) << i << ", " << j;
    }
}

}  // namespace
