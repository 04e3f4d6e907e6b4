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

#include <cstddef>

namespace flapsim::uvlm::detail {

/// The arguments of one Biot–Savart sum in precision T (segment arrays in T, points in double).
template <class T>
struct KernelCall {
  std::size_t segments = 0;
  const T *ax, *ay, *az, *bx, *by, *bz;  ///< segment ends [m]
  const T* gamma;                         ///< circulations [m²/s]
  const T* inv_length2;                   ///< 1/(|B−A|² (r_c,k/r_c)²) per segment [1/m²]
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
  const double *ax, *ay, *az, *bx, *by, *bz, *gamma, *inv_length2;
  double inv_rc2;
  CoreModel model;
  double px, py, pz;        ///< the point [m]
  double *su, *sv, *sw;     ///< its kLanes<double> partial sums [m/s]
};

/// Lanes of the partial sums: a whole AVX-512 register in either precision.
template <class T> inline constexpr int kLanes = 64 / static_cast<int>(sizeof(T));

// Cost below which threads are not worth starting (point–segment interactions).
inline constexpr std::size_t kParallelThreshold = 100000;

namespace {  // TU-local: one copy per instruction set

template <class T>
struct TailBlock {  // the last, partial block of segments, padded with Γ = 0
  T ax[kLanes<T>], ay[kLanes<T>], az[kLanes<T>], bx[kLanes<T>], by[kLanes<T>], bz[kLanes<T>];
  T g[kLanes<T>], il[kLanes<T>];
};

template <CoreModel M, class T>
[[gnu::always_inline]] inline void lane_block(const T* __restrict ax, const T* __restrict ay,
                                              const T* __restrict az, const T* __restrict bx,
                                              const T* __restrict by, const T* __restrict bz,
                                              const T* __restrict g, const T* __restrict il, T px,
                                              T py, T pz, T inv_rc2, T* __restrict su,
                                              T* __restrict sv, T* __restrict sw) {
#pragma omp simd
  for (int l = 0; l < kLanes<T>; ++l)
    segment_velocity<M>(px, py, pz, ax[l], ay[l], az[l], bx[l], by[l], bz[l], g[l], inv_rc2 * il[l],
                        su[l], sv[l], sw[l]);
}

template <CoreModel M, class T>
void sum_over_segments(const KernelCall<T>& c) {
  constexpr int L = kLanes<T>;
  const std::size_t full = c.segments / L * L;
  TailBlock<T> tail{};
  for (std::size_t k = full; k < c.segments; ++k) {
    const std::size_t l = k - full;
    tail.ax[l] = c.ax[k]; tail.ay[l] = c.ay[k]; tail.az[l] = c.az[k];
    tail.bx[l] = c.bx[k]; tail.by[l] = c.by[k]; tail.bz[l] = c.bz[k];
    tail.g[l] = c.gamma[k]; tail.il[l] = c.inv_length2[k];
  }
  const long n = static_cast<long>(c.points);
#pragma omp parallel for schedule(static) if (c.points * c.segments > kParallelThreshold)
  for (long i = 0; i < n; ++i) {
    const T px = static_cast<T>(c.x[i]), py = static_cast<T>(c.y[i]), pz = static_cast<T>(c.z[i]);
    alignas(64) T su[L] = {}, sv[L] = {}, sw[L] = {};
    for (std::size_t k = 0; k < full; k += L)
      lane_block<M>(c.ax + k, c.ay + k, c.az + k, c.bx + k, c.by + k, c.bz + k, c.gamma + k,
                    c.inv_length2 + k, px, py, pz, c.inv_rc2, su, sv, sw);
    if (full < c.segments)
      lane_block<M>(tail.ax, tail.ay, tail.az, tail.bx, tail.by, tail.bz, tail.g, tail.il, px, py,
                    pz, c.inv_rc2, su, sv, sw);
    T tu = 0, tv = 0, tw = 0;
    for (int l = 0; l < L; ++l) {
      tu += su[l];
      tv += sv[l];
      tw += sw[l];
    }
    c.u[i] += tu;
    c.v[i] += tv;
    c.w[i] += tw;
  }
}

/// One point against `count` segments (count a multiple of kLanes<double>), added to the
/// point's lane sums su/sv/sw[kLanes<double>] (the tree code's direct part).
template <CoreModel M>
void point_range(const PointRangeCall& c) {
  for (std::size_t k = 0; k < c.count; k += kLanes<double>)
    lane_block<M>(c.ax + k, c.ay + k, c.az + k, c.bx + k, c.by + k, c.bz + k, c.gamma + k,
                  c.inv_length2 + k, c.px, c.py, c.pz, c.inv_rc2, c.su, c.sv, c.sw);
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
