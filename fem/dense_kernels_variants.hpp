#pragma once
/// \file dense_kernels_variants.hpp
/// \brief The dense kernels of dense_kernels.hpp once per instruction set: a table of the
/// routines, defined in dense_kernels_sse2.cpp and dense_kernels_avx2.cpp (each compiling
/// dense_kernels_lanes.hpp for its width) and chosen in dense_kernels.cpp.

namespace flapsim::fem::dense::detail {

struct KernelTable {
  void (*gemm)(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
               long bj, long bl, double beta, double* c, int ldc);
  void (*syrk_lower)(int n, int k, double alpha, const double* a, int lda, double beta,
                     double* c, int ldc);
  void (*trsm_right_lower_transposed)(int m, int n, const double* l, int ldl, double* b,
                                      int ldb);
  void (*gemv)(int m, int n, double alpha, const double* a, int lda, const double* x,
               double beta, double* y);
  void (*gemv_transposed)(int m, int n, double alpha, const double* a, int lda,
                          const double* x, double beta, double* y);
  void (*trsv_lower)(int n, const double* l, int ldl, double* x);
  void (*trsv_lower_transposed)(int n, const double* l, int ldl, double* x);
};

const KernelTable& sse2_kernels();  ///< every x86-64 CPU
const KernelTable& avx2_kernels();  ///< only where the CPU has AVX2

}  // namespace flapsim::fem::dense::detail
