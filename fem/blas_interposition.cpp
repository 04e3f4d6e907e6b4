/// \file blas_interposition.cpp
/// \brief dgemm_, dsyrk_, dtrsm_, dgemv_ and dtrsv_ for the programs that link flapsim_fem
/// (docs/fem.md, "The dense kernels under the factorisation"). A program's own definition
/// of a BLAS routine comes before the shared library's, so CHOLMOD and LAPACK call these.
/// The forms the Cholesky factorisation and its solves use (dgemm "N" with "N" or "T",
/// dsyrk "L" "N", dtrsm "R" "L" "T" "N" with α = 1, dgemv "N" and "T" and dtrsv "L" "N"/"T"
/// "N" with unit strides) run in fem/dense_kernels.hpp, element by element as the reference
/// BLAS computes them; every other form, and every call with a bad argument (for the
/// machine's error report), goes on to the machine's BLAS (the next definition).
/// fem/CMakeLists.txt makes the linker keep this file (-u dgemm_ …).

#include "fem/dense_kernels.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdlib>

namespace {

using GemmFn = void (*)(const char*, const char*, const int*, const int*, const int*,
                        const double*, const double*, const int*, const double*, const int*,
                        const double*, double*, const int*, std::size_t, std::size_t);
using SyrkFn = void (*)(const char*, const char*, const int*, const int*, const double*,
                        const double*, const int*, const double*, double*, const int*,
                        std::size_t, std::size_t);
using GemvFn = void (*)(const char*, const int*, const int*, const double*, const double*,
                        const int*, const double*, const int*, const double*, double*,
                        const int*, std::size_t);
using TrsvFn = void (*)(const char*, const char*, const char*, const int*, const double*,
                        const int*, double*, const int*, std::size_t, std::size_t, std::size_t);
using TrsmFn = void (*)(const char*, const char*, const char*, const char*, const int*,
                        const int*, const double*, const double*, const int*, double*,
                        const int*, std::size_t, std::size_t, std::size_t, std::size_t);

// The machine's own routine (the next definition after this program's).
void* next_definition(const char* name) {
  void* f = dlsym(RTLD_NEXT, name);
  if (f == nullptr) {
    std::fprintf(stderr, "flapsim: the machine's BLAS has no %s (libblas3 installed?)\n", name);
    std::abort();
  }
  return f;
}

char upper(const char* c) { return (*c >= 'a' && *c <= 'z') ? static_cast<char>(*c - 32) : *c; }

}  // namespace

extern "C" {

void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b,
            const int* ldb, const double* beta, double* c, const int* ldc, std::size_t,
            std::size_t) {
  const char ta = upper(transa), tb = upper(transb);
  const bool b_plain = tb == 'N', b_transposed = tb == 'T' || tb == 'C';
  const bool ours = ta == 'N' && (b_plain || b_transposed) && *m >= 0 && *n >= 0 && *k >= 0 &&
                    *lda >= std::max(1, *m) && *ldb >= std::max(1, b_plain ? *k : *n) &&
                    *ldc >= std::max(1, *m) && *alpha != 0.0;
  if (!ours) {
    static const auto system = reinterpret_cast<GemmFn>(next_definition("dgemm_"));
    system(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc, 1, 1);
    return;
  }
  if (*m == 0 || *n == 0 || (*k == 0 && *beta == 1.0)) return;
  const long bj = b_plain ? *ldb : 1, bl = b_plain ? 1 : *ldb;
  flapsim::fem::dense::gemm(*m, *n, *k, *alpha, a, *lda, b, bj, bl, *beta, c, *ldc);
}

void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* beta, double* c,
            const int* ldc, std::size_t, std::size_t) {
  const bool ours = upper(uplo) == 'L' && upper(trans) == 'N' && *n >= 0 && *k >= 0 &&
                    *lda >= std::max(1, *n) && *ldc >= std::max(1, *n) && *alpha != 0.0;
  if (!ours) {
    static const auto system = reinterpret_cast<SyrkFn>(next_definition("dsyrk_"));
    system(uplo, trans, n, k, alpha, a, lda, beta, c, ldc, 1, 1);
    return;
  }
  if (*n == 0 || (*k == 0 && *beta == 1.0)) return;
  flapsim::fem::dense::syrk_lower(*n, *k, *alpha, a, *lda, *beta, c, *ldc);
}

void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag,
            const int* m, const int* n, const double* alpha, const double* a, const int* lda,
            double* b, const int* ldb, std::size_t, std::size_t, std::size_t, std::size_t) {
  const char t = upper(transa);
  const bool ours = upper(side) == 'R' && upper(uplo) == 'L' && (t == 'T' || t == 'C') &&
                    upper(diag) == 'N' && *alpha == 1.0 && *m >= 0 && *n >= 0 &&
                    *lda >= std::max(1, *n) && *ldb >= std::max(1, *m);
  if (!ours) {
    static const auto system = reinterpret_cast<TrsmFn>(next_definition("dtrsm_"));
    system(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb, 1, 1, 1, 1);
    return;
  }
  if (*m == 0 || *n == 0) return;
  flapsim::fem::dense::trsm_right_lower_transposed(*m, *n, a, *lda, b, *ldb);
}

void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a,
            const int* lda, const double* x, const int* incx, const double* beta, double* y,
            const int* incy, std::size_t) {
  const char t = upper(trans);
  const bool plain = t == 'N', transposed = t == 'T' || t == 'C';
  const bool ours = (plain || transposed) && *m >= 0 && *n >= 0 && *lda >= std::max(1, *m) &&
                    *incx == 1 && *incy == 1 && *alpha != 0.0;
  if (!ours) {
    static const auto system = reinterpret_cast<GemvFn>(next_definition("dgemv_"));
    system(trans, m, n, alpha, a, lda, x, incx, beta, y, incy, 1);
    return;
  }
  if (*m == 0 || *n == 0) return;  // the reference returns before its β step too
  if (plain)
    flapsim::fem::dense::gemv(*m, *n, *alpha, a, *lda, x, *beta, y);
  else
    flapsim::fem::dense::gemv_transposed(*m, *n, *alpha, a, *lda, x, *beta, y);
}

void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a,
            const int* lda, double* x, const int* incx, std::size_t, std::size_t, std::size_t) {
  const char t = upper(trans);
  const bool plain = t == 'N', transposed = t == 'T' || t == 'C';
  const bool ours = upper(uplo) == 'L' && (plain || transposed) && upper(diag) == 'N' &&
                    *n >= 0 && *lda >= std::max(1, *n) && *incx == 1;
  if (!ours) {
    static const auto system = reinterpret_cast<TrsvFn>(next_definition("dtrsv_"));
    system(uplo, trans, diag, n, a, lda, x, incx, 1, 1, 1);
    return;
  }
  if (*n == 0) return;
  if (plain)
    flapsim::fem::dense::trsv_lower(*n, a, *lda, x);
  else
    flapsim::fem::dense::trsv_lower_transposed(*n, a, *lda, x);
}

}  // extern "C"
