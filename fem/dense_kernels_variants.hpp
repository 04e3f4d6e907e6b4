#pragma once
/// \file dense_kernels_variants.hpp
/// \brief The dense kernels of dense_kernels.hpp once per instruction set (defined in
/// dense_kernels_sse2.cpp and dense_kernels_avx2.cpp; chosen in dense_kernels.cpp).

namespace flapsim::fem::dense::detail {

void gemm_sse2(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
               long bj, long bl, double beta, double* c, int ldc);
void syrk_lower_sse2(int n, int k, double alpha, const double* a, int lda, double beta,
                     double* c, int ldc);
void trsm_right_lower_transposed_sse2(int m, int n, const double* l, int ldl, double* b,
                                      int ldb);

void gemm_avx2(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
               long bj, long bl, double beta, double* c, int ldc);
void syrk_lower_avx2(int n, int k, double alpha, const double* a, int lda, double beta,
                     double* c, int ldc);
void trsm_right_lower_transposed_avx2(int m, int n, const double* l, int ldl, double* b,
                                      int ldb);

void gemv_sse2(int m, int n, double alpha, const double* a, int lda, const double* x,
               double beta, double* y);
void gemv_transposed_sse2(int m, int n, double alpha, const double* a, int lda,
                          const double* x, double beta, double* y);
void trsv_lower_sse2(int n, const double* a, int lda, double* x);
void trsv_lower_transposed_sse2(int n, const double* a, int lda, double* x);

void gemv_avx2(int m, int n, double alpha, const double* a, int lda, const double* x,
               double beta, double* y);
void gemv_transposed_avx2(int m, int n, double alpha, const double* a, int lda,
                          const double* x, double beta, double* y);
void trsv_lower_avx2(int n, const double* a, int lda, double* x);
void trsv_lower_transposed_avx2(int n, const double* a, int lda, double* x);

}  // namespace flapsim::fem::dense::detail
