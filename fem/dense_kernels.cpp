#include "fem/dense_kernels.hpp"

#include "fem/dense_kernels_variants.hpp"

#include <cstdlib>
#include <string_view>

namespace flapsim::fem::dense {

namespace {

enum class Variant { Sse2, Avx2 };

// AVX2 where the CPU has it; FLAPSIM_KERNEL=scalar chooses SSE2 (the same bits, to
// measure what a CPU without AVX2 gets). Read once.
Variant choose() {
  const char* env = std::getenv("FLAPSIM_KERNEL");
  if (env != nullptr && std::string_view(env) == "scalar") return Variant::Sse2;
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") ? Variant::Avx2 : Variant::Sse2;
}

Variant variant() {
  static const Variant chosen = choose();
  return chosen;
}

}  // namespace

void gemm(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
          long bj, long bl, double beta, double* c, int ldc) {
  if (variant() == Variant::Avx2)
    detail::gemm_avx2(m, n, k, alpha, a, lda, b, bj, bl, beta, c, ldc);
  else
    detail::gemm_sse2(m, n, k, alpha, a, lda, b, bj, bl, beta, c, ldc);
}

void syrk_lower(int n, int k, double alpha, const double* a, int lda, double beta, double* c,
                int ldc) {
  if (variant() == Variant::Avx2)
    detail::syrk_lower_avx2(n, k, alpha, a, lda, beta, c, ldc);
  else
    detail::syrk_lower_sse2(n, k, alpha, a, lda, beta, c, ldc);
}

void trsm_right_lower_transposed(int m, int n, const double* l, int ldl, double* b, int ldb) {
  if (variant() == Variant::Avx2)
    detail::trsm_right_lower_transposed_avx2(m, n, l, ldl, b, ldb);
  else
    detail::trsm_right_lower_transposed_sse2(m, n, l, ldl, b, ldb);
}

void gemv(int m, int n, double alpha, const double* a, int lda, const double* x, double beta,
          double* y) {
  if (variant() == Variant::Avx2)
    detail::gemv_avx2(m, n, alpha, a, lda, x, beta, y);
  else
    detail::gemv_sse2(m, n, alpha, a, lda, x, beta, y);
}

void gemv_transposed(int m, int n, double alpha, const double* a, int lda, const double* x,
                     double beta, double* y) {
  if (variant() == Variant::Avx2)
    detail::gemv_transposed_avx2(m, n, alpha, a, lda, x, beta, y);
  else
    detail::gemv_transposed_sse2(m, n, alpha, a, lda, x, beta, y);
}

void trsv_lower(int n, const double* l, int ldl, double* x) {
  if (variant() == Variant::Avx2)
    detail::trsv_lower_avx2(n, l, ldl, x);
  else
    detail::trsv_lower_sse2(n, l, ldl, x);
}

void trsv_lower_transposed(int n, const double* l, int ldl, double* x) {
  if (variant() == Variant::Avx2)
    detail::trsv_lower_transposed_avx2(n, l, ldl, x);
  else
    detail::trsv_lower_transposed_sse2(n, l, ldl, x);
}

std::string_view variant_name() { return variant() == Variant::Avx2 ? "avx2" : "sse2"; }

}  // namespace flapsim::fem::dense
