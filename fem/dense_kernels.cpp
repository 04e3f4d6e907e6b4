#include "fem/dense_kernels.hpp"

#include "fem/dense_kernels_variants.hpp"

#include <cstdlib>
#include <string_view>

namespace flapsim::fem::dense {

namespace {

// AVX2 where the CPU has it; FLAPSIM_KERNEL=scalar chooses SSE2 (the same bits, to
// measure what a CPU without AVX2 gets). Read once.
bool use_avx2() {
  const char* env = std::getenv("FLAPSIM_KERNEL");
  if (env != nullptr && std::string_view(env) == "scalar") return false;
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}

const detail::KernelTable& kernels() {
  static const detail::KernelTable& chosen = use_avx2() ? detail::avx2_kernels() : detail::sse2_kernels();
  return chosen;
}

}  // namespace

void gemm(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
          long bj, long bl, double beta, double* c, int ldc) {
  kernels().gemm(m, n, k, alpha, a, lda, b, bj, bl, beta, c, ldc);
}

void syrk_lower(int n, int k, double alpha, const double* a, int lda, double beta, double* c,
                int ldc) {
  kernels().syrk_lower(n, k, alpha, a, lda, beta, c, ldc);
}

void trsm_right_lower_transposed(int m, int n, const double* l, int ldl, double* b, int ldb) {
  kernels().trsm_right_lower_transposed(m, n, l, ldl, b, ldb);
}

void gemv(int m, int n, double alpha, const double* a, int lda, const double* x, double beta,
          double* y) {
  kernels().gemv(m, n, alpha, a, lda, x, beta, y);
}

void gemv_transposed(int m, int n, double alpha, const double* a, int lda, const double* x,
                     double beta, double* y) {
  kernels().gemv_transposed(m, n, alpha, a, lda, x, beta, y);
}

void trsv_lower(int n, const double* l, int ldl, double* x) { kernels().trsv_lower(n, l, ldl, x); }

void trsv_lower_transposed(int n, const double* l, int ldl, double* x) {
  kernels().trsv_lower_transposed(n, l, ldl, x);
}

std::string_view variant_name() { return &kernels() == &detail::avx2_kernels() ? "avx2" : "sse2"; }

}  // namespace flapsim::fem::dense
