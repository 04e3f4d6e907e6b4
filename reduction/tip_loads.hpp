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

/// \brief The wrench of a force F_z applied at chordwise position \p n_point (at the
/// zone's centroid span position).
/// \param zone      the tip zone
/// \param force_z   force along e_z [N]
/// \param n_point   chordwise position of the force [m]
TipWrench force_at(const TipZone& zone, double force_z, double n_point);

}  // namespace flapsim::reduction
