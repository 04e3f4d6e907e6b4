#pragma once
/// \file biot_savart_lanes.hpp
/// \brief The point × segment loop of the Biot–Savart sum in a form whose result does
/// not depend on the vector width: each point's sum over segments is accumulated in
/// kLanes<T> partial sums (segment k into lane k mod kLanes), which are added in lane
/// order at the end. SSE2, AVX2 and AVX-512 then only differ in how many lanes one
/// instruction handles, never in the arithmetic. Included by the kernel variant files
/// (biot_savart_scalar.cpp, biot_savart_avx2.cpp, biot_savart_avx512.cpp), each compiled
/// for its instruction set; everything here is TU-local so no copy built for one
/// instruction set is linked into another.

#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/vortex_core.hpp"

#include <algorithm>
#include <immintrin.h>
#include <cstddef>

namespace flapsim::uvlm::detail {

/// The arguments of one Biot–Savart sum in precision T (segment arrays in T, points in double).
template <class T>
struct KernelCall {
  std::size_t segments = 0;
  const T *ax, *ay, *az, *bx, *by, *bz;  ///< segment ends [m]
  const T* gamma;                         ///< circulations [m²/s]
  const T* inv_length2;                   ///< (r_c/r_c,k)²/|B−A|² per segment [1/m²]
  const T* core_ratio2;                   ///< (r_c/r_c,k)² per segment [-]
  T inv_rc2;                              ///< 1/r_c² [1/m²]
  CoreModel model;
  std::size_t points = 0;
  const double *x, *y, *z;  ///< target points [m]
  double *u, *v, *w;        ///< velocities, added to [m/s]
};

/// One target point against a contiguous block of segments whose count is a multiple of
/// kLanes<double> (padded with Γ = 0), accumulating into the point's lane sums.
struct PointRangeCall {
  std::size_t count = 0;
  const double *ax, *ay, *az, *bx, *by, *bz, *gamma, *inv_length2, *core_ratio2;
  double inv_rc2;
  CoreModel model;
  double px, py, pz;        ///< the point [m]
  double *su, *sv, *sw;     ///< its kLanes<double> partial sums [m/s]
};

/// Lanes of the partial sums: a whole AVX-512 register in either precision.
template <class T> inline constexpr int kLanes = 64 / static_cast<int>(sizeof(T));

#ifndef FLAPSIM_KERNEL_VECTOR_BYTES  // set by each variant file; SSE2 otherwise
#define FLAPSIM_KERNEL_VECTOR_BYTES 16
#endif
/// Lanes handled by one loop: one vector register of the variant's instruction set
/// (kLanes<T> at once would need more registers than AVX2 has). Does not change the
/// arithmetic of any lane.
template <class T> inline constexpr int kChunk = FLAPSIM_KERNEL_VECTOR_BYTES / static_cast<int>(sizeof(T));

// Cost below which threads are not worth starting (point–segment interactions).
inline constexpr std::size_t kParallelThreshold = 100000;

namespace {  // TU-local: one copy per instruction set

/// kLanes<T> consecutive segments (pointers to their first entries).
template <class T>
struct Lanes {
  const T *__restrict ax, *__restrict ay, *__restrict az, *__restrict bx, *__restrict by,
      *__restrict bz, *__restrict g, *__restrict il, *__restrict cr;
};

template <class T>
struct TailBlock {  // the last, partial block of segments, padded with Γ = 0
  T ax[kLanes<T>], ay[kLanes<T>], az[kLanes<T>], bx[kLanes<T>], by[kLanes<T>], bz[kLanes<T>];
  T g[kLanes<T>], il[kLanes<T>], cr[kLanes<T>];
  Lanes<T> lanes() const { return {ax, ay, az, bx, by, bz, g, il, cr}; }
};

/// The segment_velocity formula (biot_savart_kernel.hpp) for one pair, given r1 = P − A,
/// r2 = P − B, their squares s and lengths n: k·(cx, cy, cz) is the velocity without the
/// core factor (times it already unless the model is Lamb–Oseen, whose factor the callers
/// apply or skip per block), x = h²/r_c,k² the core factor's argument.
template <CoreModel M, class T>
[[gnu::always_inline]] inline void pair_terms(T r1x, T r1y, T r1z, T s1, T n1, T r2x, T r2y,
                                              T r2z, T s2, T n2, T g, T il_rc, T cr_rc,
                                              T& k, T& x, T& cx, T& cy, T& cz) {
  cx = r1y * r2z - r1z * r2y;
  cy = r1z * r2x - r1x * r2z;
  cz = r1x * r2y - r1y * r2x;
  const T cross2 = cx * cx + cy * cy + cz * cz;
  const T dot12 = r1x * r2x + r1y * r2y + r1z * r2z;
  // P projects beyond an end exactly when r1·r2 exceeds the smaller of |r1|², |r2|²;
  // h² is then that end's |r|², and h²/r_c,k² = |r_end|² (r_c/r_c,k)²/r_c².
  const T near2 = s1 < s2 ? s1 : s2;
  const T x_end = near2 * cr_rc;  // both evaluated: no masked loads
  const T x_line = cross2 * il_rc;
  x = dot12 > near2 ? x_end : x_line;
  const T p12 = n1 * n2;
  const bool between = dot12 < T(0);
  const T num = between ? p12 - dot12 : T(1);
  const T den = between ? p12 * cross2 : p12 * (p12 + dot12);
  k = g * T(kInvFourPi) * (n1 + n2) * num / (den + kTiny<T>);
  if constexpr (M != CoreModel::LambOseen) k *= core_factor<M>(x);
}

/// True if one of the kChunk<T> values at x (64-byte aligned) is below u: one vector
/// compare and a mask test (a reduction in the loop would cost a chain of shuffles).
/// Only decides which chunks get the core factor, never the arithmetic.
[[gnu::always_inline]] inline bool any_below(const double* x, double u) {
#if FLAPSIM_KERNEL_VECTOR_BYTES == 64 && defined(__AVX512F__)
  return _mm512_cmp_pd_mask(_mm512_load_pd(x), _mm512_set1_pd(u), _CMP_LT_OQ) != 0;
#elif FLAPSIM_KERNEL_VECTOR_BYTES == 32 && defined(__AVX__)
  return _mm256_movemask_pd(_mm256_cmp_pd(_mm256_load_pd(x), _mm256_set1_pd(u), _CMP_LT_OQ)) != 0;
#else
  static_assert(kChunk<double> == 2);
  return _mm_movemask_pd(_mm_cmplt_pd(_mm_load_pd(x), _mm_set1_pd(u))) != 0;
#endif
}
[[gnu::always_inline]] inline bool any_below(const float* x, float u) {
#if FLAPSIM_KERNEL_VECTOR_BYTES == 64 && defined(__AVX512F__)
  return _mm512_cmp_ps_mask(_mm512_load_ps(x), _mm512_set1_ps(u), _CMP_LT_OQ) != 0;
#elif FLAPSIM_KERNEL_VECTOR_BYTES == 32 && defined(__AVX__)
  return _mm256_movemask_ps(_mm256_cmp_ps(_mm256_load_ps(x), _mm256_set1_ps(u), _CMP_LT_OQ)) != 0;
#else
  static_assert(kChunk<float> == 4);
  return _mm_movemask_ps(_mm_cmplt_ps(_mm_load_ps(x), _mm_set1_ps(u))) != 0;
#endif
}

/// Pass 1 of the kernels: lists the chunk of kChunk<T> pairs at xx + q in need[] if one of
/// them needs the Lamb–Oseen factor (x below kLambOseenUnity<T>), without a branch.
template <class T>
[[gnu::always_inline]] inline void list_if_core_needed(const T* xx, int q, int* need, int& needed) {
  need[needed] = q;
  needed += any_below(xx + q, kLambOseenUnity<T>) ? 1 : 0;
}

/// Pass 2 of the kernels: the listed chunks' k times the Lamb–Oseen factor of their x
/// (everywhere else the factor is 1 exactly).
template <class T>
[[gnu::always_inline]] inline void apply_listed_core_factors(T* __restrict kk, const T* __restrict xx,
                                                             const int* need, int needed) {
  constexpr int W = kChunk<T>;
  for (int i = 0; i < needed; ++i) {
    const int q = need[i];
#pragma omp simd
    for (int j = 0; j < W; ++j) kk[q + j] *= core_factor<CoreModel::LambOseen>(xx[q + j]);
  }
}

/// The velocities of NP points from their kLanes<T> partial sums each (su/sv/sw[NP ×
/// kLanes<T>]): the lanes added in lane order, whatever the vector width, then added to
/// u/v/w[0 … NP−1] [m/s].
template <int NP, class T>
[[gnu::always_inline]] inline void add_lane_sums(const T* su, const T* sv, const T* sw, double* u, double* v,
                                                 double* w) {
  constexpr int L = kLanes<T>;
  for (int p = 0; p < NP; ++p) {
    T tu = 0, tv = 0, tw = 0;
    for (int l = 0; l < L; ++l) {
      tu += su[p * L + l];
      tv += sv[p * L + l];
      tw += sw[p * L + l];
    }
    u[p] += tu;
    v[p] += tv;
    w[p] += tw;
  }
}

/// Blocks of kLanes<T> segments taken together by lane_blocks (the scratch arrays,
/// 5 × NP × kBatchBlocks × kLanes<T> values, stay in the L1 cache).
inline constexpr int kBatchBlocks = 16;

/// NP target points against `blocks` (≤ kBatchBlocks) consecutive blocks of kLanes<T>
/// segments, added to the points' lane sums su/sv/sw[NP × kLanes<T>] (segment k of a block
/// into lane k; blocks in order): the segment_velocity formula (biot_savart_kernel.hpp) in
/// three passes, (1) everything but the core factor, for every pair, (2) the Lamb–Oseen core
/// factor, only for the vector-wide chunks of pairs that have one with x < kLambOseenUnity<T>
/// (elsewhere it is 1 exactly, so skipping it does not change a bit; the chunks are listed
/// in pass 1 without a branch, so a sparse, irregular need costs no mispredicted branches),
/// (3) the sums. Several points per block give the processor independent work while one
/// waits for a square root or division; each pair's arithmetic, and the order of each
/// lane's sum, are the same whatever NP, the vector width and the batching.
template <CoreModel M, int NP, class T>
[[gnu::always_inline]] inline void lane_blocks(const Lanes<T>& s, int blocks, const T* px,
                                               const T* py, const T* pz, T inv_rc2,
                                               T* __restrict su, T* __restrict sv,
                                               T* __restrict sw) {
  constexpr int L = kLanes<T>;
  constexpr int W = kChunk<T>;
  constexpr int N = kBatchBlocks * NP * L;
  alignas(64) T kk[N], xx[N], cxs[N], cys[N], czs[N];
  [[maybe_unused]] int need[N / W];
  [[maybe_unused]] int needed = 0;
  for (int b = 0; b < blocks; ++b)
    for (int h = 0; h < L; h += W) {
      const int o = b * L + h;  // first segment of the chunk
      alignas(64) T il[W], cr[W];
#pragma omp simd
      for (int j = 0; j < W; ++j) {
        il[j] = inv_rc2 * s.il[o + j];
        cr[j] = inv_rc2 * s.cr[o + j];
      }
      for (int p = 0; p < NP; ++p) {
        const int q = (b * NP + p) * L + h;  // first pair of the chunk in the scratch arrays
#pragma omp simd
        for (int j = 0; j < W; ++j) {
          const int l = o + j;
          const T r1x = px[p] - s.ax[l], r1y = py[p] - s.ay[l], r1z = pz[p] - s.az[l];
          const T r2x = px[p] - s.bx[l], r2y = py[p] - s.by[l], r2z = pz[p] - s.bz[l];
          const T s1 = r1x * r1x + r1y * r1y + r1z * r1z;
          const T s2 = r2x * r2x + r2y * r2y + r2z * r2z;
          T k, x, cx, cy, cz;
          pair_terms<M>(r1x, r1y, r1z, s1, std::sqrt(s1), r2x, r2y, r2z, s2, std::sqrt(s2), s.g[l],
                        il[j], cr[j], k, x, cx, cy, cz);
          kk[q + j] = k;
          xx[q + j] = x;
          cxs[q + j] = cx;
          cys[q + j] = cy;
          czs[q + j] = cz;
        }
        if constexpr (M == CoreModel::LambOseen) list_if_core_needed(xx, q, need, needed);
      }
    }
  if constexpr (M == CoreModel::LambOseen) apply_listed_core_factors(kk, xx, need, needed);
  for (int b = 0; b < blocks; ++b)
    for (int h = 0; h < NP * L; h += W) {
      const int q = b * NP * L + h;
#pragma omp simd
      for (int j = 0; j < W; ++j) {
        su[h + j] += kk[q + j] * cxs[q + j];
        sv[h + j] += kk[q + j] * cys[q + j];
        sw[h + j] += kk[q + j] * czs[q + j];
      }
    }
}

template <class T>
Lanes<T> lanes_at(const KernelCall<T>& c, std::size_t k) {
  return {c.ax + k, c.ay + k, c.az + k, c.bx + k, c.by + k, c.bz + k, c.gamma + k,
          c.inv_length2 + k, c.core_ratio2 + k};
}

/// Points i0 … i0+NP−1 against every segment, added to their velocities.
template <CoreModel M, int NP, class T>
void points_against_segments(const KernelCall<T>& c, const TailBlock<T>& tail, std::size_t full,
                             std::size_t i0) {
  constexpr int L = kLanes<T>;
  T px[NP], py[NP], pz[NP];
  for (int p = 0; p < NP; ++p) {
    px[p] = static_cast<T>(c.x[i0 + p]);
    py[p] = static_cast<T>(c.y[i0 + p]);
    pz[p] = static_cast<T>(c.z[i0 + p]);
  }
  alignas(64) T su[NP * L] = {}, sv[NP * L] = {}, sw[NP * L] = {};
  for (std::size_t k = 0; k < full; k += kBatchBlocks * L) {
    const int blocks = static_cast<int>(std::min<std::size_t>(kBatchBlocks, (full - k) / L));
    lane_blocks<M, NP>(lanes_at(c, k), blocks, px, py, pz, c.inv_rc2, su, sv, sw);
  }
  if (full < c.segments) lane_blocks<M, NP>(tail.lanes(), 1, px, py, pz, c.inv_rc2, su, sv, sw);
  add_lane_sums<NP>(su, sv, sw, c.u + i0, c.v + i0, c.w + i0);
}

/// Points taken two at a time (one more alone when their number is odd).
inline constexpr int kPointsPerPass = 2;

template <CoreModel M, class T>
void sum_over_segments(const KernelCall<T>& c) {
  constexpr int L = kLanes<T>;
  const std::size_t full = c.segments / L * L;
  TailBlock<T> tail{};
  for (std::size_t k = full; k < c.segments; ++k) {
    const std::size_t l = k - full;
    tail.ax[l] = c.ax[k]; tail.ay[l] = c.ay[k]; tail.az[l] = c.az[k];
    tail.bx[l] = c.bx[k]; tail.by[l] = c.by[k]; tail.bz[l] = c.bz[k];
    tail.g[l] = c.gamma[k]; tail.il[l] = c.inv_length2[k]; tail.cr[l] = c.core_ratio2[k];
  }
  const long passes = static_cast<long>(c.points / kPointsPerPass);
  if (c.points * c.segments > kParallelThreshold) {
#pragma omp parallel for schedule(static)
    for (long q = 0; q < passes; ++q)
      points_against_segments<M, kPointsPerPass>(c, tail, full, static_cast<std::size_t>(q) * kPointsPerPass);
  } else {  // (no parallel region of one thread: its entry costs more than a small sum)
    for (long q = 0; q < passes; ++q)
      points_against_segments<M, kPointsPerPass>(c, tail, full, static_cast<std::size_t>(q) * kPointsPerPass);
  }
  for (std::size_t i = static_cast<std::size_t>(passes) * kPointsPerPass; i < c.points; ++i)
    points_against_segments<M, 1>(c, tail, full, i);
}

/// One point against `count` segments (count a multiple of kLanes<double>), added to the
/// point's lane sums su/sv/sw[kLanes<double>] (the tree code's direct part).
template <CoreModel M>
void point_range(const PointRangeCall& c) {
  constexpr std::size_t L = kLanes<double>;
  for (std::size_t k = 0; k < c.count; k += kBatchBlocks * L) {
    const Lanes<double> s{c.ax + k, c.ay + k, c.az + k, c.bx + k, c.by + k, c.bz + k,
                          c.gamma + k, c.inv_length2 + k, c.core_ratio2 + k};
    const int blocks = static_cast<int>(std::min<std::size_t>(kBatchBlocks, (c.count - k) / L));
    lane_blocks<M, 1>(s, blocks, &c.px, &c.py, &c.pz, c.inv_rc2, c.su, c.sv, c.sw);
  }
}

inline void point_range_any_model(const PointRangeCall& c) {
  switch (c.model) {
    case CoreModel::CutOff: point_range<CoreModel::CutOff>(c); break;
    case CoreModel::LambOseen: point_range<CoreModel::LambOseen>(c); break;
    case CoreModel::Vatistas: point_range<CoreModel::Vatistas>(c); break;
  }
}

template <class T>
void sum_any_model(const KernelCall<T>& c) {
  switch (c.model) {
    case CoreModel::CutOff: sum_over_segments<CoreModel::CutOff>(c); break;
    case CoreModel::LambOseen: sum_over_segments<CoreModel::LambOseen>(c); break;
    case CoreModel::Vatistas: sum_over_segments<CoreModel::Vatistas>(c); break;
  }
}

}  // namespace

// One pair per variant, defined in its file.
void sum_scalar(const KernelCall<double>& c);
void sum_scalar(const KernelCall<float>& c);
void sum_avx2(const KernelCall<double>& c);
void sum_avx2(const KernelCall<float>& c);
void sum_avx512(const KernelCall<double>& c);
void sum_avx512(const KernelCall<float>& c);
void point_range_scalar(const PointRangeCall& c);
void point_range_avx2(const PointRangeCall& c);
void point_range_avx512(const PointRangeCall& c);
/// point_range of the variant in use (kernel_dispatch.hpp).
void point_range_dispatch(const PointRangeCall& c);

}  // namespace flapsim::uvlm::detail
