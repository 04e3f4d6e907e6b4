/// \file dense_kernels_sse2.cpp
/// \brief The dense kernels for SSE2, which every x86-64 CPU has (dense_kernels_lanes.hpp:
/// the same arithmetic as the AVX2 variant, two doubles at a time).
#define FLAPSIM_DENSE_VECTOR_BYTES 16
#include "fem/dense_kernels_lanes.hpp"
#include "fem/dense_kernels_variants.hpp"

namespace flapsim::fem::dense::detail {

void gemm_sse2(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
               long bj, long bl, double beta, double* c, int ldc) {
  gemm_body(m, n, k, alpha, a, lda, b, bj, bl, beta, c, ldc);
}
void syrk_lower_sse2(int n, int k, double alpha, const double* a, int lda, double beta,
                     double* c, int ldc) {
  syrk_lower_body(n, k, alpha, a, lda, beta, c, ldc);
}
void trsm_right_lower_transposed_sse2(int m, int n, const double* l, int ldl, double* b,
                                      int ldb) {
  trsm_right_lower_transposed_body(m, n, l, ldl, b, ldb);
}

void gemv_sse2(int m, int n, double alpha, const double* a, int lda, const double* x,
               double beta, double* y) {
  gemv_body(m, n, alpha, a, lda, x, beta, y);
}
void gemv_transposed_sse2(int m, int n, double alpha, const double* a, int lda,
                          const double* x, double beta, double* y) {
  gemv_transposed_body(m, n, alpha, a, lda, x, beta, y);
}
void trsv_lower_sse2(int n, const double* a, int lda, double* x) { trsv_lower_body(n, a, lda, x); }
void trsv_lower_transposed_sse2(int n, const double* a, int lda, double* x) {
  trsv_lower_transposed_body(n, a, lda, x);
}

}  // namespace flapsim::fem::dense::detail
