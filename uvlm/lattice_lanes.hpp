#pragma once
/// \file lattice_lanes.hpp
/// \brief The point × lattice loop of the lattice kernel (lattice_segments.hpp), written
/// like biot_savart_lanes.hpp so that its result does not depend on the vector width:
/// node a's segments go to lane a mod kLanes<T> of the point's partial sums (its spanwise
/// segment, then its streamwise one; nodes in increasing order), the lanes are added in
/// order at the end. Included by the kernel variant files after biot_savart_lanes.hpp.

#include "uvlm/biot_savart_lanes.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace flapsim::uvlm::detail {

/// The arguments of one lattice sum in precision T (lattice arrays in T, points in double).
template <class T>
struct LatticeCall {
  std::size_t cols = 0;  ///< nodes per row
  std::size_t span = 0;  ///< node indices carrying segments (a multiple of kLanes<float>)
  const T *nx, *ny, *nz;     ///< node positions, span + cols + 17 entries [m]
  const T *gs, *ils, *crs;   ///< spanwise segment a → a+1: Γ [m²/s], (r_c/r_c,k)²/|B−A|² [1/m²], (r_c/r_c,k)²
  const T *gc, *ilc, *crc;   ///< streamwise segment a+cols → a: the same
  T inv_rc2;                 ///< 1/r_c² [1/m²]
  CoreModel model;
  std::size_t points = 0;
  const double *x, *y, *z;  ///< target points [m]
  double *u, *v, *w;        ///< velocities, added to [m/s]
};

/// Node indices per tile: the nodes' vectors to NP points for a tile (plus the cols + 1
/// nodes its segments reach beyond it) and the tile's pair terms stay in the L1 cache
/// (about 20 KB in either precision).
template <class T> inline constexpr int kLatticeTile = 64;
template <> inline constexpr int kLatticeTile<float> = 128;
/// Node-buffer entries per quantity and point: a constant for rows of up to 63 nodes
/// (kFixedStride − tile − one vector − 1; 62 spanwise panels); longer rows use a
/// per-thread buffer on the heap.
template <class T> inline constexpr std::size_t kFixedStride = kLatticeTile<T> + 80;

namespace {  // TU-local: one copy per instruction set

/// Per-thread buffer of the node vectors (grows once; no allocation afterwards).
template <class T>
T* node_buffer(std::size_t size) {
  thread_local std::vector<T> buffer;
  if (buffer.size() < size) buffer.resize(size);
  return buffer.data();
}

/// The pair (point, segment) with r1 = node ia's vector, r2 = node ib's (buffer entries).
template <CoreModel M, class T>
[[gnu::always_inline]] inline void lattice_pair(const T* __restrict rx, const T* __restrict ry,
                                                const T* __restrict rz, const T* __restrict rs,
                                                const T* __restrict rn, std::size_t ia,
                                                std::size_t ib, T g, T il_rc, T cr_rc, T& k, T& x,
                                                T& cx, T& cy, T& cz) {
  pair_terms<M>(rx[ia], ry[ia], rz[ia], rs[ia], rn[ia], rx[ib], ry[ib], rz[ib], rs[ib], rn[ib], g,
                il_rc, cr_rc, k, x, cx, cy, cz);
}

/// Points i0 … i0+NP−1 against every segment of the lattice, added to their velocities.
/// Per tile of kLatticeTile<T> node indices: (0) each node's r = P − node, |r|², |r| into the
/// buffer (the first cols + 1 entries carried over from the previous tile); (1) every
/// pair's terms but the Lamb–Oseen factor, listing the vector-wide chunks that need it;
/// (2) that factor for the listed chunks; (3) the lane sums (as lane_blocks).
template <CoreModel M, int NP, bool Fixed, class T>
void lattice_points(const LatticeCall<T>& c, std::size_t i0) {
  constexpr int L = kLanes<T>;
  constexpr int W = kChunk<T>;
  constexpr int TT = kLatticeTile<T>;
  static_assert(TT % L == 0);
  constexpr int N = 2 * NP * TT;  // pairs per tile: spanwise and streamwise, NP points
  const std::size_t cols = c.cols;
  const std::size_t reach = cols + 1;
  // Buffer entries per quantity and point (the first reach rounded up to W entries are
  // computed W at a time): a constant when the rows are short enough (Fixed), so that the
  // buffer is one array on the stack addressed with constant offsets.
  const std::size_t stride = Fixed ? kFixedStride<T> : TT + reach + W;
  [[maybe_unused]] alignas(64) T fixed_buf[Fixed ? 5 * NP * kFixedStride<T> : 1];
  T* buf = Fixed ? fixed_buf : node_buffer<T>(5 * NP * stride);
  T px[NP], py[NP], pz[NP];
  for (int p = 0; p < NP; ++p) {
    px[p] = static_cast<T>(c.x[i0 + p]);
    py[p] = static_cast<T>(c.y[i0 + p]);
    pz[p] = static_cast<T>(c.z[i0 + p]);
  }
  alignas(64) T su[NP * L] = {}, sv[NP * L] = {}, sw[NP * L] = {};
  alignas(64) T kk[N], xx[N], cxs[N], cys[N], czs[N];
  [[maybe_unused]] int need[N / W];
  // Node entries e ∈ [e0, e0 + W) (node t0 + e): r = P − node, |r|², |r|.
  auto nodes = [&](std::size_t t0, std::size_t e0) {
    for (int p = 0; p < NP; ++p) {
      T* __restrict rx = buf + (5 * p) * stride + e0;
      T* __restrict ry = rx + stride;
      T* __restrict rz = ry + stride;
      T* __restrict rs = rz + stride;
      T* __restrict rn = rs + stride;
      const T* __restrict nx = c.nx + t0 + e0;
      const T* __restrict ny = c.ny + t0 + e0;
      const T* __restrict nz = c.nz + t0 + e0;
#pragma omp simd
      for (int j = 0; j < W; ++j) {
        const T ex = px[p] - nx[j], ey = py[p] - ny[j], ez = pz[p] - nz[j];
        const T s = ex * ex + ey * ey + ez * ez;
        rx[j] = ex;
        ry[j] = ey;
        rz[j] = ez;
        rs[j] = s;
        rn[j] = std::sqrt(s);
      }
    }
  };
  for (std::size_t t0 = 0; t0 < c.span; t0 += TT) {
    const int tn = static_cast<int>(std::min<std::size_t>(TT, c.span - t0));
    // (0) node entries: the first reach carried over from the previous (full) tile, which
    // computed nodes t0 … t0 + reach − 1, or computed; then W more; the rest one chunk
    // ahead of the pairs (the pairs of chunk h reach entry h + W − 1 + cols < h + reach + W),
    // so that a square root is under way while the pairs before it are evaluated.
    if (t0 > 0)
      for (int q = 0; q < 5 * NP; ++q)
        for (std::size_t e = 0; e < reach; e += W) {  // whole vectors, forward (TT ≥ W: safe)
          T* __restrict to = buf + q * stride + e;
          const T* __restrict from = to + TT;
#pragma omp simd
          for (int j = 0; j < W; ++j) to[j] = from[j];
        }
    else
      for (std::size_t e = 0; e < reach; e += W) nodes(0, e);
    nodes(t0, reach);
    // (1) pair terms: spanwise (r1 = node e, r2 = node e + 1) and streamwise
    // (r1 = node e + cols, r2 = node e) into the scratch at ((p·2 + kind)·TT + e).
    [[maybe_unused]] int needed = 0;
    for (int h = 0; h < tn; h += W) {
      const std::size_t o = t0 + static_cast<std::size_t>(h);
      if (h + W < tn) nodes(t0, h + W + reach);
      alignas(64) T ils[W], crs[W], ilc[W], crc[W];
#pragma omp simd
      for (int j = 0; j < W; ++j) {
        ils[j] = c.inv_rc2 * c.ils[o + j];
        crs[j] = c.inv_rc2 * c.crs[o + j];
        ilc[j] = c.inv_rc2 * c.ilc[o + j];
        crc[j] = c.inv_rc2 * c.crc[o + j];
      }
      for (int p = 0; p < NP; ++p) {
        const T* __restrict rx = buf + (5 * p) * stride;
        const T* __restrict ry = rx + stride;
        const T* __restrict rz = ry + stride;
        const T* __restrict rs = rz + stride;
        const T* __restrict rn = rs + stride;
        const int qs = (2 * p) * TT + h, qc = qs + TT;
#pragma omp simd
        for (int j = 0; j < W; ++j) {
          const std::size_t e = static_cast<std::size_t>(h + j);
          T k, x, cx, cy, cz;
          lattice_pair<M>(rx, ry, rz, rs, rn, e, e + 1, c.gs[o + j], ils[j], crs[j], k, x, cx, cy, cz);
          kk[qs + j] = k;
          xx[qs + j] = x;
          cxs[qs + j] = cx;
          cys[qs + j] = cy;
          czs[qs + j] = cz;
        }
#pragma omp simd
        for (int j = 0; j < W; ++j) {
          const std::size_t e = static_cast<std::size_t>(h + j);
          T k, x, cx, cy, cz;
          lattice_pair<M>(rx, ry, rz, rs, rn, e + cols, e, c.gc[o + j], ilc[j], crc[j], k, x, cx, cy, cz);
          kk[qc + j] = k;
          xx[qc + j] = x;
          cxs[qc + j] = cx;
          cys[qc + j] = cy;
          czs[qc + j] = cz;
        }
        if constexpr (M == CoreModel::LambOseen) {
          list_if_core_needed(xx, qs, need, needed);
          list_if_core_needed(xx, qc, need, needed);
        }
      }
    }
    // (2) the Lamb–Oseen factor where a pair needs it (exactly 1 elsewhere).
    if constexpr (M == CoreModel::LambOseen) apply_listed_core_factors(kk, xx, need, needed);
    // (3) lane sums: node t0 + e into lane e mod L (t0 is a multiple of L), spanwise first.
    for (int p = 0; p < NP; ++p)
      for (int h = 0; h < tn; h += W) {
        const int qs = (2 * p) * TT + h, qc = qs + TT;
        const int l = p * L + h % L;
#pragma omp simd
        for (int j = 0; j < W; ++j) {
          su[l + j] += kk[qs + j] * cxs[qs + j];
          sv[l + j] += kk[qs + j] * cys[qs + j];
          sw[l + j] += kk[qs + j] * czs[qs + j];
          su[l + j] += kk[qc + j] * cxs[qc + j];
          sv[l + j] += kk[qc + j] * cys[qc + j];
          sw[l + j] += kk[qc + j] * czs[qc + j];
        }
      }
  }
  add_lane_sums<NP>(su, sv, sw, c.u + i0, c.v + i0, c.w + i0);
}

/// Points taken NP at a time (the rest one at a time).
inline constexpr int kLatticePointsPerPass = 2;

template <CoreModel M, class T>
void lattice_sum(const LatticeCall<T>& c) {
  constexpr int NP = kLatticePointsPerPass;
  const long passes = static_cast<long>(c.points / NP);
  const std::size_t work = c.points * 2 * c.span;
  if (c.cols + 1 + kChunk<T> + kLatticeTile<T> <= kFixedStride<T>) {
#pragma omp parallel for schedule(static) if (work > kParallelThreshold)
    for (long q = 0; q < passes; ++q) lattice_points<M, NP, true>(c, static_cast<std::size_t>(q) * NP);
    for (std::size_t i = static_cast<std::size_t>(passes) * NP; i < c.points; ++i) lattice_points<M, 1, true>(c, i);
    return;
  }
#pragma omp parallel for schedule(static) if (work > kParallelThreshold)
  for (long q = 0; q < passes; ++q) lattice_points<M, NP, false>(c, static_cast<std::size_t>(q) * NP);
  for (std::size_t i = static_cast<std::size_t>(passes) * NP; i < c.points; ++i) lattice_points<M, 1, false>(c, i);
}

template <class T>
void lattice_sum_any_model(const LatticeCall<T>& c) {
  switch (c.model) {
    case CoreModel::CutOff: lattice_sum<CoreModel::CutOff>(c); break;
    case CoreModel::LambOseen: lattice_sum<CoreModel::LambOseen>(c); break;
    case CoreModel::Vatistas: lattice_sum<CoreModel::Vatistas>(c); break;
  }
}

}  // namespace

// One pair per variant, defined in its file (biot_savart_scalar/avx2/avx512.cpp).
void lattice_sum_scalar(const LatticeCall<double>& c);
void lattice_sum_scalar(const LatticeCall<float>& c);
void lattice_sum_avx2(const LatticeCall<double>& c);
void lattice_sum_avx2(const LatticeCall<float>& c);
void lattice_sum_avx512(const LatticeCall<double>& c);
void lattice_sum_avx512(const LatticeCall<float>& c);

}  // namespace flapsim::uvlm::detail
