#pragma once
/// \file multipole_batch.hpp
/// \brief The tree code's expansions evaluated for up to kMultipoleBatch nodes at once
/// (one target, several nodes): the velocity of a node's expansion of order p at R = x − c,
///     v = Σ_{|n|≤p} ∇∂ⁿ(1/R) × Q̃_n,  Q̃_n = (−1)^|n| Q_n/(n! 4π) (segment_tree.hpp),
/// with the derivatives of 1/R from their recurrence (multipole_expansion.hpp), one node
/// per vector lane. Each lane does the same operations in the same order as a single
/// evaluation, with every loop bound and table entry known at compile time, so every
/// instruction-set variant (scalar baseline, AVX2, AVX-512; compiled like the Biot–Savart
/// kernel's, chosen by kernel_isa(), kernel_dispatch.hpp) gives the same bits.

#include "uvlm/multipole_expansion.hpp"

#include <cmath>

namespace flapsim::uvlm::detail {

inline constexpr int kMultipoleBatch = 8;

struct MultipoleBatch {
  int order = 4;  ///< p, 0..4
  int count = 0;  ///< lanes in use (≤ kMultipoleBatch); the rest are ignored
  const double* moments[kMultipoleBatch];  ///< each node's 3 × terms scaled moments
  double rx[kMultipoleBatch], ry[kMultipoleBatch], rz[kMultipoleBatch];  ///< R [m]
  double u[kMultipoleBatch], v[kMultipoleBatch], w[kMultipoleBatch];     ///< out [m/s]
};

void multipole_batch_scalar(MultipoleBatch& b);
void multipole_batch_avx2(MultipoleBatch& b);
void multipole_batch_avx512(MultipoleBatch& b);

namespace {  // TU-local: one copy per instruction set

template <int P>
[[gnu::flatten]] void multipole_lanes(MultipoleBatch& b) {
  constexpr int L = kMultipoleBatch;
  constexpr const MultiIndexTable& T = kTable;
  constexpr int derivatives = terms_up_to(P + 1), terms = terms_up_to(P);
  // Unused lanes: R = (1, 0, 0) and no moments (finite, ignored).
  alignas(64) double R[3][L], inv_r2[L];
  alignas(64) double Q[3 * terms][L];
  for (int j = 0; j < L; ++j) {
    const bool used = j < b.count;
    R[0][j] = used ? b.rx[j] : 1.0;
    R[1][j] = used ? b.ry[j] : 0.0;
    R[2][j] = used ? b.rz[j] : 0.0;
    for (int t = 0; t < 3 * terms; ++t) Q[t][j] = used ? b.moments[j][t] : 0.0;
  }
  alignas(64) double D[derivatives][L];
#pragma omp simd
  for (int j = 0; j < L; ++j) {
    const double r2 = R[0][j] * R[0][j] + R[1][j] * R[1][j] + R[2][j] * R[2][j];
    inv_r2[j] = 1.0 / r2;
    D[0][j] = std::sqrt(inv_r2[j]);
  }
#pragma GCC unroll 64
  for (int t = 1; t < derivatives; ++t) {
    const int m = T.order[t];
    const int n[3] = {T.a[t], T.b[t], T.c[t]};
#pragma omp simd
    for (int j = 0; j < L; ++j) {
      double s1 = 0.0, s2 = 0.0;
#pragma GCC unroll 3
      for (int i = 0; i < 3; ++i) {
        if (n[i] >= 1) s1 += n[i] * R[i][j] * D[T.minus[t][i]][j];
        if (n[i] >= 2) s2 += n[i] * (n[i] - 1) * D[T.minus2[t][i]][j];
      }
      // (2m − 1)/m and (m − 1)/m as compile-time constants: no division per term.
      D[t][j] = -(kRecurrence1[m] * s1 + kRecurrence2[m] * s2) * inv_r2[j];
    }
  }
  alignas(64) double su[L] = {}, sv[L] = {}, sw[L] = {};
#pragma GCC unroll 64
  for (int t = 0; t < terms; ++t) {
    const double f = T.factor[t];
#pragma omp simd
    for (int j = 0; j < L; ++j) {
      const double gx = D[T.plus[t][0]][j], gy = D[T.plus[t][1]][j], gz = D[T.plus[t][2]][j];
      const double qx = Q[3 * t][j], qy = Q[3 * t + 1][j], qz = Q[3 * t + 2][j];
      su[j] += f * (gy * qz - gz * qy);
      sv[j] += f * (gz * qx - gx * qz);
      sw[j] += f * (gx * qy - gy * qx);
    }
  }
  for (int j = 0; j < L; ++j) {
    b.u[j] = su[j];
    b.v[j] = sv[j];
    b.w[j] = sw[j];
  }
}

[[maybe_unused]] inline void multipole_batch_any_order(MultipoleBatch& b) {
  switch (b.order) {
    case 0: multipole_lanes<0>(b); break;
    case 1: multipole_lanes<1>(b); break;
    case 2: multipole_lanes<2>(b); break;
    case 3: multipole_lanes<3>(b); break;
    default: multipole_lanes<4>(b); break;
  }
}

}  // namespace

}  // namespace flapsim::uvlm::detail
