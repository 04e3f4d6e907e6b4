#pragma once
/// \file vortex_core.hpp
/// \brief Regularisation of the Biot–Savart kernel near a vortex segment.
///
/// A straight segment induces v = Γ/(4π) K (r1 × r2) with K ∝ 1/h² near the line.
/// Each model multiplies the singular kernel by a factor f(x), x = h²/r_c², h the
/// distance from the point to the segment (to its line beside it, to the nearer end
/// beyond its ends), that goes to zero on the segment and to one far away, so the
/// velocity on a segment is zero instead of infinite (on a collinear neighbour the
/// singular kernel is zero already):
///  - CutOff:    f = 1 if h > r_c else 0 (Katz & Plotkin's cut-off, branch-free mask).
///  - LambOseen: f = 1 − exp(−1.25643 x) (viscous core, peak velocity at h = r_c).
///  - Vatistas:  f = x / sqrt(1 + x²) (Vatistas n = 2, close to Lamb–Oseen, no exp).

namespace flapsim::uvlm {

enum class CoreModel { CutOff, LambOseen, Vatistas };

struct VortexCore {
  CoreModel model = CoreModel::LambOseen;
  double radius = 1e-6;  ///< core radius r_c [m]; must be > 0
};

}  // namespace flapsim::uvlm
