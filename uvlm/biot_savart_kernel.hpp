#pragma once
/// \file biot_savart_kernel.hpp
/// \brief The inline, branch-free point–segment Biot–Savart interaction shared by
/// every loop in uvlm/ (induced velocities, influence matrix). Branch-free so that
/// the loops over segments vectorise (`#pragma omp simd`). Always inlined: the kernel
/// variants (biot_savart_lanes.hpp) compile it for several instruction sets, and an
/// out-of-line copy built for one of them must never be called from another.

#include "uvlm/vortex_core.hpp"

#include <cmath>

namespace flapsim::uvlm::detail {

constexpr double kInvFourPi = 0.079577471545947667884;  // 1/(4π)
constexpr double kLambOseen = 1.25643;  // makes the Lamb–Oseen peak velocity sit at h = r_c
// Keeps 0/0 (point on a segment, zero-length segment) at 0; normal numbers in each precision.
template <class T>
inline constexpr T kTiny = T(1e-300);
template <>
inline constexpr float kTiny<float> = 1e-36f;

/// x = h²/r_c² from which the Lamb–Oseen factor is exactly 1 in precision T. Double:
/// e^(−1.25643·30) = 4.3e-17 < 2^-54, so 1 − e^(−1.25643 x) rounds to 1 for x ≥ 30;
/// float: e^(−1.25643·14) = 2.3e-8 < 2^-25. The kernels skip the exponential for a block
/// of segments all this far from the point, with the same result as evaluating it.
template <class T> inline constexpr T kLambOseenUnity = T(30);
template <> inline constexpr float kLambOseenUnity<float> = 14.0f;

/// exp(−y) for 0 ≤ y ≤ 40 without a library call (vectorisable, only +, × and no fused
/// multiply–add, so every instruction set rounds alike). Double: e^(−y) = (e^(−y/64))^64,
/// e^z for z = −y/64 ∈ [−0.625, 0] by its degree-10 Taylor polynomial (truncation below
/// 1.2e-19 absolute; rounding, amplified 64× by the squarings, about 1e-14 absolute).
/// Float, used up to y = 1.25643·kLambOseenUnity<float> = 17.6: (e^(−y/32))^32 with the
/// degree-6 polynomial (truncation below 2e-10 absolute, rounding about 2e-6). Both by
/// Estrin's scheme (a short dependency chain); tests/uvlm/test_kernel_dispatch.cpp
/// checks them against std::exp.
template <class T>
[[gnu::always_inline]] inline T exp_neg(T y) {
  y = y < T(40) ? y : T(40);  // keeps lanes that are not used (x ≥ kLambOseenUnity<T>) finite
  if constexpr (sizeof(T) == sizeof(float)) {
    const T z = y * T(-1.0 / 32.0);
    const T z2 = z * z, z4 = z2 * z2;
    const T a0 = T(1) + z;
    const T a1 = T(1.0 / 2.0) + T(1.0 / 6.0) * z;
    const T a2 = T(1.0 / 24.0) + T(1.0 / 120.0) * z;
    const T a3 = T(1.0 / 720.0);
    T p = (a0 + a1 * z2) + (a2 + a3 * z2) * z4;
    p *= p; p *= p; p *= p; p *= p; p *= p;
    return p;
  } else {
    const T z = y * T(-1.0 / 64.0);
    const T z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
    const T a0 = T(1) + z;
    const T a1 = T(1.0 / 2.0) + T(1.0 / 6.0) * z;
    const T a2 = T(1.0 / 24.0) + T(1.0 / 120.0) * z;
    const T a3 = T(1.0 / 720.0) + T(1.0 / 5040.0) * z;
    const T a4 = T(1.0 / 40320.0) + T(1.0 / 362880.0) * z;
    const T a5 = T(1.0 / 3628800.0);
    const T b0 = a0 + a1 * z2, b1 = a2 + a3 * z2, b2 = a4 + a5 * z2;
    T p = (b0 + b1 * z4) + b2 * z8;
    p *= p; p *= p; p *= p; p *= p; p *= p; p *= p;
    return p;
  }
}

/// Core factor f(x), x = h²/r_c² (see vortex_core.hpp).
template <CoreModel M, class T>
[[gnu::always_inline]] inline T core_factor(T x) {
  if constexpr (M == CoreModel::CutOff) {
    return x > T(1) ? T(1) : T(0);  // compiles to a mask/blend, not a branch
  } else if constexpr (M == CoreModel::LambOseen) {
    return x < kLambOseenUnity<T> ? T(1) - exp_neg(T(kLambOseen) * x) : T(1);
  } else {
    return x / std::sqrt(T(1) + x * x);
  }
}

/// segment_velocity's formula (below) with the core factor f = core_factor<M>(x), or with
/// f = 1 exactly if `Unit` (the Lamb–Oseen factor's value wherever x ≥ kLambOseenUnity<T>,
/// so there the same bits); returns x = h²/r_c².
template <CoreModel M, bool Unit, class T>
[[gnu::always_inline]] inline T segment_velocity_terms(T px, T py, T pz, T ax, T ay, T az, T bx, T by, T bz,
                                                       T gamma, T scale, T& u, T& v, T& w) {
  using Real = T;  // the precision of this evaluation
  const Real r1x = px - ax, r1y = py - ay, r1z = pz - az;
  const Real r2x = px - bx, r2y = py - by, r2z = pz - bz;
  const Real cx = r1y * r2z - r1z * r2y;
  const Real cy = r1z * r2x - r1x * r2z;
  const Real cz = r1x * r2y - r1y * r2x;
  const Real cross2 = cx * cx + cy * cy + cz * cz;
  const Real s1 = r1x * r1x + r1y * r1y + r1z * r1z;
  const Real s2 = r2x * r2x + r2y * r2y + r2z * r2z;
  const Real n1 = std::sqrt(s1);
  const Real n2 = std::sqrt(s2);
  const Real dot12 = r1x * r2x + r1y * r2y + r1z * r2z;
  // P projects beyond an end exactly when r1·r2 exceeds the smaller of |r1|², |r2|².
  const Real near2 = s1 < s2 ? s1 : s2;
  const Real lx = bx - ax, ly = by - ay, lz = bz - az;
  const Real len2 = lx * lx + ly * ly + lz * lz;  // |B − A|² (not s1 + s2 − 2 r1·r2: cancellation far away)
  const Real x = dot12 > near2 ? near2 * len2 * scale : cross2 * scale;  // h²/r_c²
  const Real f = Unit ? Real(1) : core_factor<M>(x);
  const Real p12 = n1 * n2;
  const bool between = dot12 < Real(0);
  const Real num = between ? p12 - dot12 : Real(1);
  const Real den = between ? p12 * cross2 : p12 * (p12 + dot12);
  const Real k = gamma * T(kInvFourPi) * f * (n1 + n2) * num / (den + kTiny<T>);
  u += k * cx;
  v += k * cy;
  w += k * cz;
  return x;
}

/// Velocity induced at P by the straight segment A→B of circulation Γ, added to (u, v, w):
///   v = Γ/(4π) · f(h²/r_c²) · (|r1|+|r2|)(|r1||r2| − r1·r2) / (|r1||r2| |r1×r2|²) · (r1×r2),
/// r1 = P − A, r2 = P − B (algebraically the textbook r0·(r1/|r1| − r2/|r2|)/|r1×r2|² form
/// [Katz & Plotkin eq. 2.68]); (|r1||r2| − r1·r2)/|r1×r2|² is evaluated as 1/(|r1||r2| + r1·r2)
/// where r1·r2 ≥ 0 (no cancellation beyond the ends). h is the distance from P to the
/// segment: to its line where P projects inside it, to the nearer end beyond the ends (a
/// point far beyond a segment's end is not in its core, so far away every core model is
/// the singular kernel, which the tree code's expansions assume).
/// \param scale  1/(r_c² |B − A|²) [1/m⁴] (0 for a zero-length segment), so that
///               h²/r_c² = |r1×r2|²·scale inside and |r_end|² |B − A|²·scale beyond an end
template <CoreModel M, class T>
[[gnu::always_inline]] inline void segment_velocity(T px, T py, T pz, T ax, T ay, T az, T bx, T by, T bz, T gamma, T scale,
                             T& u, T& v, T& w) {
  segment_velocity_terms<M, false>(px, py, pz, ax, ay, az, bx, by, bz, gamma, scale, u, v, w);
}

/// 1/(r_c² |B − A|²) for segment_velocity; 0 for a zero-length segment (no velocity).
inline double segment_scale(double ax, double ay, double az, double bx, double by, double bz,
                            double inv_rc2) {
  const double dx = bx - ax, dy = by - ay, dz = bz - az;
  const double len2 = dx * dx + dy * dy + dz * dz;
  return len2 > 0.0 ? inv_rc2 / len2 : 0.0;
}

}  // namespace flapsim::uvlm::detail
