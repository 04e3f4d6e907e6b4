#pragma once
/// \file dense_kernels_lanes.hpp
/// \brief The bodies of the dense kernels (dense_kernels.hpp) for one vector width,
/// included by dense_kernels_sse2.cpp and dense_kernels_avx2.cpp, each compiled for its
/// instruction set (fem/CMakeLists.txt). Everything here is TU-local, so no copy built
/// for one instruction set is linked into another.
///
/// Every element of C receives the reference BLAS's operations in the reference's order:
/// c ← c + t_l a_l for l = 0, 1, … with t_l = α b_l, a multiply and an add each (these
/// files are compiled without FMA), skipping l where b_l = 0 where the reference does
/// (LAPACK 3.11's dsyrk and dtrsm skip, its dgemm adds every term so that a NaN
/// propagates). The blocking below only decides which elements are in registers at the
/// same time.

#include <algorithm>
#include <cstring>

#include "fem/dense_kernels_variants.hpp"

#ifndef FLAPSIM_DENSE_VECTOR_BYTES  // set by each variant file
#error "define FLAPSIM_DENSE_VECTOR_BYTES (16 or 32) before including dense_kernels_lanes.hpp"
#endif

namespace flapsim::fem::dense::detail {
namespace {

constexpr int kLanes = FLAPSIM_DENSE_VECTOR_BYTES / 8;  // doubles in a vector register
typedef double Vec __attribute__((vector_size(FLAPSIM_DENSE_VECTOR_BYTES)));
constexpr int kRows = 2 * kLanes;  // rows of C held in registers at once
constexpr int kCols = 4;           // columns of C held in registers at once
constexpr int kChunk = 128;        // values of l whose coefficients are gathered at once
constexpr int kRowPanel = 256;     // rows of A swept per column block (A's panel in L2)

inline Vec load(const double* p) {
  Vec v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store(double* p, Vec v) { std::memcpy(p, &v, sizeof v); }
inline Vec splat(double x) {
  Vec v;
  for (int i = 0; i < kLanes; ++i) v[i] = x;
  return v;
}

/// The coefficients t(j, l) = α b(j, l) of up to kCols columns over kChunk values of l,
/// with a bit per column for the terms added: all, or (skip_zero) those with b(j, l) ≠ 0.
struct Coefficients {
  double t[kChunk][kCols];
  unsigned char nonzero[kChunk];
};

inline void gather(Coefficients& co, int nc, int kl, double alpha, const double* b, long bj,
                   long bl, bool skip_zero) {
  for (int l = 0; l < kl; ++l) {
    unsigned bits = 0;
    for (int j = 0; j < nc; ++j) {
      const double bv = b[j * bj + l * bl];
      co.t[l][j] = 0.0;
      if (bv != 0.0 || !skip_zero) {
        co.t[l][j] = alpha * bv;
        bits |= 1u << j;
      }
    }
    co.nonzero[l] = static_cast<unsigned char>(bits);
  }
}

/// C(0:m, 0:NC) += Σ_l t(j, l) A(0:m, l) for l = 0 … kl−1 in order, the terms of co's bits.
template <int NC>
void accumulate(int m, int kl, const double* a, long lda, const Coefficients& co, double* c,
                long ldc) {
  constexpr unsigned all = (1u << NC) - 1u;
  int i = 0;
  for (; i + kRows <= m; i += kRows) {
    Vec c0[NC], c1[NC];
    for (int j = 0; j < NC; ++j) {
      c0[j] = load(c + i + j * ldc);
      c1[j] = load(c + i + kLanes + j * ldc);
    }
    const double* ap = a + i;
    for (int l = 0; l < kl; ++l, ap += lda) {
      const Vec a0 = load(ap), a1 = load(ap + kLanes);
      const auto add = [&](int j) {
        const Vec t = splat(co.t[l][j]);
        c0[j] = c0[j] + t * a0;
        c1[j] = c1[j] + t * a1;
      };
      const unsigned nz = co.nonzero[l];
      if (nz == all)  // the common case without a test per column
        for (int j = 0; j < NC; ++j) add(j);
      else
        for (int j = 0; j < NC; ++j)
          if (nz >> j & 1u) add(j);
    }
    for (int j = 0; j < NC; ++j) {
      store(c + i + j * ldc, c0[j]);
      store(c + i + kLanes + j * ldc, c1[j]);
    }
  }
  for (; i + kLanes <= m; i += kLanes) {
    Vec c0[NC];
    for (int j = 0; j < NC; ++j) c0[j] = load(c + i + j * ldc);
    const double* ap = a + i;
    for (int l = 0; l < kl; ++l, ap += lda) {
      const Vec a0 = load(ap);
      const unsigned nz = co.nonzero[l];
      for (int j = 0; j < NC; ++j)
        if (nz >> j & 1u) c0[j] = c0[j] + splat(co.t[l][j]) * a0;
    }
    for (int j = 0; j < NC; ++j) store(c + i + j * ldc, c0[j]);
  }
  for (; i < m; ++i)
    for (int j = 0; j < NC; ++j) {
      double s = c[i + j * ldc];
      for (int l = 0; l < kl; ++l)
        if (co.nonzero[l] >> j & 1u) s = s + co.t[l][j] * a[i + l * lda];
      c[i + j * ldc] = s;
    }
}

/// C(0:m, 0:nc) += α A(0:m, 0:k) b(0:nc, 0:k)ᵀ, b(j, l) = b[j bj + l bl], nc ≤ kCols;
/// skip_zero: as the reference's dsyrk and dtrsm, no term where b(j, l) = 0.
void update_columns(int m, int nc, int k, double alpha, const double* a, long lda,
                    const double* b, long bj, long bl, double* c, long ldc, bool skip_zero) {
  Coefficients co;
  for (int l0 = 0; l0 < k; l0 += kChunk) {
    const int kl = std::min(kChunk, k - l0);
    gather(co, nc, kl, alpha, b + l0 * bl, bj, bl, skip_zero);
    const double* al = a + static_cast<long>(l0) * lda;
    switch (nc) {
      case 4: accumulate<4>(m, kl, al, lda, co, c, ldc); break;
      case 3: accumulate<3>(m, kl, al, lda, co, c, ldc); break;
      case 2: accumulate<2>(m, kl, al, lda, co, c, ldc); break;
      default: accumulate<1>(m, kl, al, lda, co, c, ldc); break;
    }
  }
}

/// The reference's β step of one column's rows [from, to): 0 when β = 0, β c when β ≠ 1.
inline void scale_rows(double* c, int from, int to, double beta) {
  if (beta == 0.0)
    for (int i = from; i < to; ++i) c[i] = 0.0;
  else if (beta != 1.0)
    for (int i = from; i < to; ++i) c[i] = beta * c[i];
}

void gemm_body(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
               long bj, long bl, double beta, double* c, int ldc) {
  for (int j = 0; j < n; ++j) scale_rows(c + static_cast<long>(j) * ldc, 0, m, beta);
  for (int i0 = 0; i0 < m; i0 += kRowPanel) {
    const int mi = std::min(kRowPanel, m - i0);
    for (int j0 = 0; j0 < n; j0 += kCols)
      update_columns(mi, std::min(kCols, n - j0), k, alpha, a + i0, lda, b + j0 * bj, bj, bl,
                     c + i0 + static_cast<long>(j0) * ldc, ldc, false);
  }
}

void syrk_lower_body(int n, int k, double alpha, const double* a, int lda, double beta,
                     double* c, int ldc) {
  for (int j = 0; j < n; ++j) scale_rows(c + static_cast<long>(j) * ldc, j, n, beta);
  for (int j0 = 0; j0 < n; j0 += kCols) {
    const int nc = std::min(kCols, n - j0);
    // The block's own triangle (rows j0 … j0+nc−1, on and below the diagonal).
    for (int j = j0; j < j0 + nc; ++j)
      for (int i = j; i < j0 + nc; ++i) {
        double s = c[i + static_cast<long>(j) * ldc];
        for (int l = 0; l < k; ++l) {
          const double bv = a[j + static_cast<long>(l) * lda];
          if (bv != 0.0) s = s + alpha * bv * a[i + static_cast<long>(l) * lda];
        }
        c[i + static_cast<long>(j) * ldc] = s;
      }
    // The rows below it.
    for (int i0 = j0 + nc; i0 < n; i0 += kRowPanel)
      update_columns(std::min(kRowPanel, n - i0), nc, k, alpha, a + i0, lda, a + j0, 1, lda,
                     c + i0 + static_cast<long>(j0) * ldc, ldc, true);
  }
}

void trsm_right_lower_transposed_body(int m, int n, const double* l, int ldl, double* b,
                                      int ldb) {
  // Element (i, J) receives b ← b − L(J,K) b(i,K) for K = 0 … J−1 in order (skipping
  // L(J,K) = 0), then b ← (1/L(J,J)) b: the reference's order, column block by block.
  for (int i0 = 0; i0 < m; i0 += kRowPanel) {
    const int mi = std::min(kRowPanel, m - i0);
    double* bp = b + i0;
    for (int j0 = 0; j0 < n; j0 += kCols) {
      const int nc = std::min(kCols, n - j0);
      if (j0 > 0)
        update_columns(mi, nc, j0, -1.0, bp, ldb, l + j0, 1, ldl, bp + static_cast<long>(j0) * ldb,
                       ldb, true);
      for (int j = j0; j < j0 + nc; ++j) {
        double* bj = bp + static_cast<long>(j) * ldb;
        for (int kk = j0; kk < j; ++kk) {
          const double t = l[j + static_cast<long>(kk) * ldl];
          if (t == 0.0) continue;
          const double* bk = bp + static_cast<long>(kk) * ldb;
          for (int i = 0; i < mi; ++i) bj[i] = bj[i] - t * bk[i];
        }
        const double inverse = 1.0 / l[j + static_cast<long>(j) * ldl];
        for (int i = 0; i < mi; ++i) bj[i] = inverse * bj[i];
      }
    }
  }
}

void gemv_body(int m, int n, double alpha, const double* a, int lda, const double* x,
               double beta, double* y) {
  // y(i) ← β-step, then y(i) + (α x_j) A(i, j) for j = 0, 1, …: C = y, b(0, l) = x_l.
  gemm_body(m, 1, n, alpha, a, lda, x, 0, 1, beta, y, m);
}

void gemv_transposed_body(int m, int n, double alpha, const double* a, int lda,
                          const double* x, double beta, double* y) {
  // y(j) ← β-step, then y(j) + α (0 + A(0,j) x_0 + A(1,j) x_1 + …), the sum in row
  // order: four columns' sums side by side (independent chains), each in its order.
  scale_rows(y, 0, n, beta);
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    const double* a0 = a + static_cast<long>(j) * lda;
    const double *a1 = a0 + lda, *a2 = a1 + lda, *a3 = a2 + lda;
    double t0 = 0.0, t1 = 0.0, t2 = 0.0, t3 = 0.0;
    for (int i = 0; i < m; ++i) {
      const double xi = x[i];
      t0 = t0 + a0[i] * xi;
      t1 = t1 + a1[i] * xi;
      t2 = t2 + a2[i] * xi;
      t3 = t3 + a3[i] * xi;
    }
    y[j] = y[j] + alpha * t0;
    y[j + 1] = y[j + 1] + alpha * t1;
    y[j + 2] = y[j + 2] + alpha * t2;
    y[j + 3] = y[j + 3] + alpha * t3;
  }
  for (; j < n; ++j) {
    const double* aj = a + static_cast<long>(j) * lda;
    double t = 0.0;
    for (int i = 0; i < m; ++i) t = t + aj[i] * x[i];
    y[j] = y[j] + alpha * t;
  }
}

void trsv_lower_body(int n, const double* a, int lda, double* x) {
  // The reference's column form: x_j ← x_j / L(j,j) and x_i ← x_i − x_j L(i,j) below,
  // skipping j where x_j = 0.
  for (int j = 0; j < n; ++j) {
    if (x[j] == 0.0) continue;
    const double* aj = a + static_cast<long>(j) * lda;
    x[j] = x[j] / aj[j];
    const double t = x[j];
    for (int i = j + 1; i < n; ++i) x[i] = x[i] - t * aj[i];
  }
}

void trsv_lower_transposed_body(int n, const double* a, int lda, double* x) {
  // The reference's dot form from the last row up: x_j ← (x_j − Σ_{i>j} L(i,j) x_i) / L(j,j),
  // the sum from i = n−1 down.
  for (int j = n - 1; j >= 0; --j) {
    const double* aj = a + static_cast<long>(j) * lda;
    double t = x[j];
    for (int i = n - 1; i > j; --i) t = t - aj[i] * x[i];
    x[j] = t / aj[j];
  }
}

/// This width's routines (dense_kernels_variants.hpp).
constexpr KernelTable kKernels{gemm_body,       syrk_lower_body, trsm_right_lower_transposed_body,
                               gemv_body,       gemv_transposed_body,
                               trsv_lower_body, trsv_lower_transposed_body};

}  // namespace
}  // namespace flapsim::fem::dense::detail
