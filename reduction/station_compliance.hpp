#pragma once
/// \file station_compliance.hpp
/// \brief Stations of the flexural axis and their compliance by reciprocity
/// (docs/reduction.md, "Joint stiffness by reciprocity").
///
/// A station k at axis position s_k has three generalized coordinates u_k = (w, θ, φ):
/// deflection of its reference point (s_k, n = 0), bending rotation about e_n and twist
/// about e_s (the SectionMotion convention: u_z ≈ w + θ (s − s_k) − φ n). One matrix
/// A_k (FEM DOFs × 3), non-zero only at the u_z DOFs of the free nodes of the station's
/// band |s − s_k| ≤ h, does both jobs (RBE3-like, weights W = the nodes' u_z mass):
///   - it averages the nodes' motion into the station's: u_k = A_kᵀ x, the weighted
///     least-squares rigid-section fit  u_k = (BᵀWB)⁻¹ BᵀW u_z,  B rows [1, Δs, −n];
///   - it spreads a station load g_k = (F, M_n, M_s) over the nodes: f = A_k g_k, whose
///     resultant force and moments about the reference point are exactly g_k (Bᵀf = g).
/// The station compliance C = Aᵀ K⁻¹ A (one factorisation of the clamped stiffness, three
/// solves per station) is symmetric, and positive definite whenever every band holds
/// three free nodes not on one line: u = C g for every station load g.

#include <Eigen/Core>

#include <vector>

#include "reduction/clamped_wing_analysis.hpp"

namespace flapsim::reduction {

/// One station's band of nodes.
struct StationBand {
  double s = 0.0;           ///< reference point on the axis [m]
  double half_width = 0.0;  ///< band half-width h finally used [m]
  std::vector<int> nodes;   ///< free nodes of the band
  Eigen::MatrixX3d weights; ///< A_k restricted to the band's u_z DOFs (nodes × 3)
  Eigen::MatrixX3d basis;   ///< B: rows [1, s − s_k, −n] of the band's nodes [-, m, m]
  Eigen::VectorXd mass;     ///< W: the nodes' u_z mass [kg]
};

/// The stations and their compliance.
struct StationCompliance {
  std::vector<StationBand> stations;
  /// C over (w, θ, φ) of every station, station-major: index 3k + {0, 1, 2}
  /// [m/N, 1/N, rad/(N m)].
  Eigen::MatrixXd compliance;
  /// The FEM load of the station loads \p g (size 3 × stations) [N]: f = A g.
  Eigen::VectorXd load_vector(const Eigen::VectorXd& g, int num_fem_dofs) const;
  /// The stations' motion u = Aᵀ x of an FEM displacement \p x (size 3 × stations).
  Eigen::VectorXd station_motion(const Eigen::VectorXd& x) const;
  int size() const { return static_cast<int>(stations.size()); }
};

/// \brief Stations at the axis positions \p positions (increasing) with band
/// half-width at least \p half_width (widened ×1.25 until the band holds six free
/// nodes spanning both s and n).
/// \throws ReductionFailure naming the station (1-based body) when no usable band exists
StationCompliance station_compliance(const ClampedWingAnalysis& analysis, const std::vector<double>& positions,
                                     double half_width, const std::vector<int>& body_of_station = {});

}  // namespace flapsim::reduction
