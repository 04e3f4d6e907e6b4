#pragma once
/// \file dense_kernels.hpp
/// \brief The dense products and triangular solves under CHOLMOD's supernodal Cholesky
/// factorisation, its solves and LAPACK's dpotrf (docs/fem.md, "The dense kernels under
/// the factorisation"), computed element by element in the same order as the reference
/// BLAS, so the factor is the same bits as with the reference BLAS on every x86-64 CPU,
/// whichever variant runs.
///
/// The reference BLAS (Lawson et al. 1979; Dongarra et al. 1990) updates a column of C
/// for one l at a time, streaming the whole column through memory for each l. Here a
/// block of C (up to 4 columns × 2 vector registers of rows) stays in registers over
/// the l loop; each element still receives c ← c + (α b_jl) a_il for l = 1, 2, … in
/// turn, skipping l where b_jl = 0 where LAPACK 3.11's routines do (dsyrk, dtrsm, dtrsv;
/// not dgemm and dgemv), with a multiply and an add
/// (never a fused multiply–add). The vector width then changes how many elements move
/// at once, never an element's arithmetic.
///
/// fem/blas_interposition.cpp defines dgemm_, dsyrk_, dtrsm_, dgemv_ and dtrsv_ for the
/// programs that link this library: the forms the factorisation and its solves use run
/// here, every other form (and every argument error) goes to the machine's BLAS.

#include <string_view>

namespace flapsim::fem::dense {

/// Column-major, Fortran-style leading dimensions; sizes in elements.

/// C(m×n) ← α A B + β C with B given as b(j,l) = b[j·bj + l·bl] (B = Bᵀ-stored or not):
/// A is m×k with leading dimension lda, C has ldc. β = 0 sets C to 0 first.
void gemm(int m, int n, int k, double alpha, const double* a, int lda, const double* b,
          long bj, long bl, double beta, double* c, int ldc);

/// Lower triangle of C(n×n) ← α A Aᵀ + β C, A n×k (the reference's dsyrk "L", "N").
void syrk_lower(int n, int k, double alpha, const double* a, int lda, double beta, double* c,
                int ldc);

/// B(m×n) ← B L⁻ᵀ, L lower triangular n×n with its diagonal (the reference's dtrsm
/// "R", "L", "T", "N" with α = 1).
void trsm_right_lower_transposed(int m, int n, const double* l, int ldl, double* b, int ldb);

/// y(m) ← α A x + β y, A m×n (the reference's dgemv "N", unit strides).
void gemv(int m, int n, double alpha, const double* a, int lda, const double* x, double beta,
          double* y);

/// y(n) ← α Aᵀ x + β y, A m×n (the reference's dgemv "T", unit strides).
void gemv_transposed(int m, int n, double alpha, const double* a, int lda, const double* x,
                     double beta, double* y);

/// x ← L⁻¹ x and x ← L⁻ᵀ x, L lower triangular n×n with its diagonal (the reference's
/// dtrsv "L", "N"/"T", "N", unit stride).
void trsv_lower(int n, const double* l, int ldl, double* x);
void trsv_lower_transposed(int n, const double* l, int ldl, double* x);

/// The variant in use: "sse2" or "avx2" (FLAPSIM_KERNEL=scalar chooses sse2 on an
/// AVX2 machine; the results are the same bits).
std::string_view variant_name();

}  // namespace flapsim::fem::dense
