#pragma once
/// \file influence_lanes.hpp
/// \brief One row of the influence matrix's segment terms: the normal velocity at one
/// collocation point of every unit-circulation segment of the lattice, out[s] = n · v_s(P),
/// vectorised over the segments. Included by the kernel variant files
/// (biot_savart_scalar.cpp, _avx2.cpp, _avx512.cpp), each compiled for its instruction set;
/// everything here is TU-local. Each segment's term is segment_velocity
/// (biot_savart_kernel.hpp) evaluated alone, lane by lane, with no sum across segments: no
/// fused multiply–add (-ffp-contract=off), square root and division correctly rounded, so
/// every variant gives the bits of the scalar formula (influence_matrix.hpp). With the
/// Lamb–Oseen core the exponential is evaluated only for the vector-wide chunks of segments
/// that have one within kLambOseenUnity of the point (biot_savart_kernel.hpp): the same bits.

#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/biot_savart_lanes.hpp"
#include "uvlm/vortex_core.hpp"

#include <cstddef>

namespace flapsim::uvlm::detail {

/// The arguments of one row: `segments` unit segments A→B with their scale
/// 1/(r_c² |B − A|²) (segment_velocity's), the point P and its unit normal n.
struct InfluenceRowCall {
  std::size_t segments = 0;
  const double *ax, *ay, *az, *bx, *by, *bz;  ///< segment ends [m]
  const double* scale;                        ///< 1/(r_c² |B − A|²) [1/m⁴]
  CoreModel model;
  double px, py, pz;  ///< collocation point [m]
  double nx, ny, nz;  ///< its unit normal
  double* out;        ///< n · v_s for each segment s at out[s · out_stride] [1/m] (velocity per unit circulation)
  std::size_t out_stride = 1;
};

namespace {  // TU-local: one copy per instruction set

template <CoreModel M>
void influence_row(const InfluenceRowCall& c) {
  const double *__restrict ax = c.ax, *__restrict ay = c.ay, *__restrict az = c.az;
  const double *__restrict bx = c.bx, *__restrict by = c.by, *__restrict bz = c.bz;
  const double* __restrict scale = c.scale;
  double* __restrict out = c.out;
  const std::size_t os = c.out_stride;
  const double px = c.px, py = c.py, pz = c.pz, nx = c.nx, ny = c.ny, nz = c.nz;
  auto terms = [&](std::size_t s) {
    double u = 0.0, v = 0.0, w = 0.0;
    segment_velocity<M, double>(px, py, pz, ax[s], ay[s], az[s], bx[s], by[s], bz[s], 1.0, scale[s], u, v, w);
    out[s * os] = u * nx + v * ny + w * nz;
  };
  std::size_t full = 0;
  if constexpr (M == CoreModel::LambOseen) {
    // Chunks of one vector: every term with the core factor 1 (and its x), then the chunks
    // with a segment within kLambOseenUnity of the point (a few beside it) evaluated again
    // with the factor. Elsewhere the factor is 1 exactly, so every term has the bits of
    // segment_velocity's, without the exponential that most pairs do not need.
    constexpr std::size_t W = kChunk<double>;
    full = c.segments / W * W;
    for (std::size_t s0 = 0; s0 < full; s0 += W) {
      alignas(64) double x[W];
#pragma omp simd
      for (std::size_t j = 0; j < W; ++j) {
        const std::size_t s = s0 + j;
        double u = 0.0, v = 0.0, w = 0.0;
        x[j] = segment_velocity_terms<M, true, double>(px, py, pz, ax[s], ay[s], az[s], bx[s], by[s], bz[s], 1.0,
                                                       scale[s], u, v, w);
        out[s * os] = u * nx + v * ny + w * nz;
      }
      if (any_below(x, kLambOseenUnity<double>)) {
#pragma omp simd
        for (std::size_t j = 0; j < W; ++j) terms(s0 + j);
      }
    }
  }
#pragma omp simd
  for (std::size_t s = full; s < c.segments; ++s) terms(s);
}

inline void influence_row_any_model(const InfluenceRowCall& c) {
  switch (c.model) {
    case CoreModel::CutOff: influence_row<CoreModel::CutOff>(c); break;
    case CoreModel::LambOseen: influence_row<CoreModel::LambOseen>(c); break;
    case CoreModel::Vatistas: influence_row<CoreModel::Vatistas>(c); break;
  }
}

}  // namespace

void influence_row_scalar(const InfluenceRowCall& c);
void influence_row_avx2(const InfluenceRowCall& c);
void influence_row_avx512(const InfluenceRowCall& c);

}  // namespace flapsim::uvlm::detail
