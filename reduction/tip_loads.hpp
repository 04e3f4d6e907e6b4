#pragma once
/// \file tip_loads.hpp
/// \brief The reduction's static load cases: a wrench (out-of-plane force, bending
/// moment, torque) spread over the tip zone as out-of-plane nodal forces of minimum
/// norm (docs/reduction.md, "Load cases").

#include <Eigen/Core>

#include <vector>

namespace flapsim::reduction {

/// A wrench in the axis frame, about the tip zone's centroid.
struct TipWrench {
  double force_z = 0.0;   ///< F along e_z [N]
  double moment_n = 0.0;  ///< moment about e_n (bending, tip up > 0) [N m]
  double moment_s = 0.0;  ///< moment about e_s (torque, right-handed) [N m]
};

/// The nodes that carry the tip loads and their centroid.
struct TipZone {
  std::vector<int> nodes;
  double s_start = 0.0;     ///< inboard edge of the zone [m]
  double s_centroid = 0.0;  ///< [m]
  double n_centroid = 0.0;  ///< [m]
  double n_min = 0.0, n_max = 0.0;  ///< chordwise extent of the zone's nodes [m]
};

/// \brief The nodes with s ≥ s_max − length (widened until it holds \p min_nodes
/// nodes with at least two distinct s and two distinct n positions, not all on one line:
/// the zone must carry a bending moment and a torque independently).
/// \param s, n        axis coordinates of the nodes [m]
/// \param length      zone length along the axis [m]
/// \param excluded    nodes that must not carry load (clamped), may be empty
/// \param min_nodes   minimum number of loaded nodes
TipZone make_tip_zone(const Eigen::VectorXd& s, const Eigen::VectorXd& n, double length,
                      const std::vector<bool>& excluded, int min_nodes = 6);

/// \brief Out-of-plane nodal forces f_i of minimum Σ f_i² on the zone's nodes with
/// Σ f = F_z, Σ f (s − s̄) = M_n, −Σ f (n − n̄) = M_s.
/// \param zone    loaded nodes and centroid
/// \param s, n    axis coordinates of all nodes [m]
/// \param wrench  the resultant about the zone's centroid
/// \return a full load vector (6 DOF per node, only u_z entries set) [N]
Eigen::VectorXd tip_load_vector(const TipZone& zone, const Eigen::VectorXd& s,
                                const Eigen::VectorXd& n, const TipWrench& wrench);

/// \brief Out-of-plane nodal forces on \p nodes weighted by \p weights, as a station spreads
/// its load over its band (RBE3-like, station_compliance.hpp): f = W B (BᵀWB)⁻¹ g with B rows
/// [1, s − s_ref, −(n − n_ref)] and g = (F_z, M_n, M_s), so that Σ f = F_z,
/// Σ f (s − s_ref) = M_n, −Σ f (n − n_ref) = M_s. Used for a moment spread over the chain's
/// tip body by mass (reduction_report.cpp; docs/reduction.md, "A tip moment on a film tip").
/// \param nodes    loaded nodes
/// \param s, n     axis coordinates of all nodes [m]
/// \param weights  weight of every node (e.g. its u_z mass) [any unit, ≥ 0]
/// \param s_ref, n_ref  reference point of the wrench [m]
/// \param wrench   the resultant about the reference point
/// \return a full load vector (6 DOF per node, only u_z entries set) [N]; non-finite entries
///         when the weighted nodes cannot carry the wrench (fewer than three, or on one line)
Eigen::VectorXd weighted_wrench_load(const std::vector<int>& nodes, const Eigen::VectorXd& s,
                                     const Eigen::VectorXd& n, const Eigen::VectorXd& weights, double s_ref,
                                     double n_ref, const TipWrench& wrench);

/// \brief The wrench of a force F_z applied at chordwise position \p n_point (at the
/// zone's centroid span position).
/// \param zone      the tip zone
/// \param force_z   force along e_z [N]
/// \param n_point   chordwise position of the force [m]
TipWrench force_at(const TipZone& zone, double force_z, double n_point);

}  // namespace flapsim::reduction
