/// \file fem_readout.cpp
/// \brief What a run records of the FEM structure (structure.hpp, StructureReadout): its
/// tip and outer sections as best-fit rigid rotations of the nodes in a band of the span,
/// and the force and moment the base exerts on the wing from the balance of the whole FEM.
///
/// Sections. The nodes whose reference span coordinate y_W lies in the outer tenth of the
/// span (y ≥ 0.9 R: where the last body of a 10-body chain sits) and in the band ±R/20
/// about 5/6 R (the chain's outer body, fsi::outer_body) are fitted by the rotation that
/// best carries their reference positions (about their centroid) onto the current ones,
/// equal weights (Kabsch 1976; Horn 1987: the SVD of the cross-covariance). On a film wing
/// the band's film cambers: the fit is the section's mean rotation. A band whose nodes do
/// not span a plane (fewer than three, or one row along the chord, as on a coarse mesh or a
/// pointed tip) takes the nearest nodes beside it until they do.
///
/// Drive. The base acts on the wing through the driven (clamp) nodes: their reactions
/// r = f_int + M v̇ − f_ext (with f_ext the loads of the last solve, aerodynamic and
/// external). The free nodes' equations hold to Newton's tolerance and the co-rotational
/// internal forces are self-equilibrated (Felippa & Haugen 2005, the projector), so the
/// reactions' wrench is that of M v̇ − f_ext summed over all nodes: F = Σ (M v̇ − f_ext)_t,
/// N = Σ (x − p) × (M v̇ − f_ext)_t + (M v̇ − f_ext)_r about the pivot p. It carries the
/// wing's stiff modes as they ring: a run started from rest relative to an accelerating
/// base excites them, and generalized-α with ρ∞ near 1 hardly damps them (docs/fsi.md,
/// "The FEM as the structure").

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "fem/nodal_rotation.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/fsi/tip_deflection.hpp"

namespace flapsim::fsi {

namespace {

constexpr double kTipBandStart = 0.9;        ///< tip section: y ≥ 0.9 R
constexpr double kOuterBandCentre = 5.0 / 6.0;  ///< outer section: about 5/6 R ...
constexpr double kOuterBandHalfWidth = 0.05;    ///< ... ± R/20

/// A band's nodes fix a rotation when their reference positions span a plane: the second
/// principal spread at least this fraction of the first (a row of nodes along one line
/// leaves the rotation about it free).
constexpr double kPlanarSpread = 1e-4;

bool spans_a_plane(const std::vector<Eigen::Vector3d>& reference, const std::vector<int>& nodes) {
  if (nodes.size() < 3) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int n : nodes) mean += reference[static_cast<std::size_t>(n)];
  mean /= static_cast<double>(nodes.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (int n : nodes) {
    const Eigen::Vector3d d = reference[static_cast<std::size_t>(n)] - mean;
    spread += d * d.transpose();
  }
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(spread).singularValues();
  return sigma(1) > kPlanarSpread * sigma(0);
}

/// The nodes of a band of the span: those at distance 0 from it (`distance(y)` [m] of a
/// reference span coordinate), and where they do not span a plane (a coarse mesh, a pointed
/// tip: two nodes on the tip, none within R/20 of 5/6 R), the nearest others added one by
/// one until they do. Before, such a band read as the identity, the ground frame: a stiff
/// delta wing on 5 mm elements reported a tip bent by 60° and twisted by 135°.
template <class Distance>
std::vector<int> band_nodes(const std::vector<Eigen::Vector3d>& reference, Distance distance) {
  std::vector<std::pair<double, int>> by_distance;
  for (std::size_t n = 0; n < reference.size(); ++n)
    by_distance.emplace_back(distance(reference[n].y()), static_cast<int>(n));
  std::stable_sort(by_distance.begin(), by_distance.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> nodes;
  std::size_t k = 0;
  while (k < by_distance.size() && by_distance[k].first <= 0.0) nodes.push_back(by_distance[k++].second);
  while (k < by_distance.size() && !spans_a_plane(reference, nodes)) nodes.push_back(by_distance[k++].second);
  return nodes;
}

// The rotation that best carries the reference positions of `nodes` onto their current
// ones (both about their centroids): ground ← W for an undeformed wing at the base.
Eigen::Matrix3d fitted_rotation(const std::vector<Eigen::Vector3d>& reference, const fem::CorotationalState& s,
                                const std::vector<int>& nodes) {
  if (nodes.size() < 3) return Eigen::Matrix3d::Identity();  // a mesh of fewer nodes: none
  Eigen::Vector3d X = Eigen::Vector3d::Zero(), x = Eigen::Vector3d::Zero();
  for (int n : nodes) {
    X += reference[static_cast<std::size_t>(n)];
    x += s.position[static_cast<std::size_t>(n)];
  }
  X /= static_cast<double>(nodes.size());
  x /= static_cast<double>(nodes.size());
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();  // Σ (X − X̄)(x − x̄)ᵀ
  for (int n : nodes)
    H += (reference[static_cast<std::size_t>(n)] - X) * (s.position[static_cast<std::size_t>(n)] - x).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixV() * D * svd.matrixU().transpose();
}

}  // namespace

StructureReadout FemStructureData::readout() const {
  const fem::CorotationalModel& c = model_.corotational;
  const fem::DynamicsData& d = *dynamics_;
  const std::vector<Eigen::Vector3d>& X = c.reference_positions;
  double span = 0.0;
  for (const auto& p : X) span = std::max(span, p.y());
  // The tip point: of the nodes at the largest y_W (an outline's tip, or its tip edge), the
  // one nearest the span axis y_W (where a chain's end is).
  std::size_t tip_node = 0;
  double tip_distance = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < X.size(); ++n)
    if (X[n].y() >= span * (1.0 - 1e-9) && X[n].x() * X[n].x() + X[n].z() * X[n].z() < tip_distance) {
      tip_distance = X[n].x() * X[n].x() + X[n].z() * X[n].z();
      tip_node = n;
    }
  const std::vector<int> tip =
      band_nodes(X, [&](double y) { return std::max(0.0, kTipBandStart * span - y); });
  const std::vector<int> outer = band_nodes(X, [&](double y) {
    return std::max(0.0, std::abs(y - kOuterBandCentre * span) - kOuterBandHalfWidth * span);
  });
  StructureReadout r;
  r.tip_rotation = fitted_rotation(X, d.state, tip);
  r.outer_rotation = fitted_rotation(X, d.state, outer);
  if (!X.empty()) r.tip_position = d.state.position[tip_node];

  const mbd::BasePose pose = model_.base_motion(d.time);
  // Tip relative to the base, in W: Rx(bend) Ry(twist) (tip_deflection.hpp).
  const TipDeflection deflection = tip_deflection(pose.rotation.transpose() * r.tip_rotation);
  r.tip_bend = deflection.bend;
  r.tip_twist = deflection.twist;

  const Eigen::VectorXd f = c.mass * d.acceleration - loads_;  // [N, N m]
  for (int n = 0; n < c.num_nodes(); ++n) {
    const Eigen::Vector3d force = f.segment<3>(fem::dof_index(n, fem::UX));
    r.drive_force += force;
    r.drive_moment += (d.state.position[static_cast<std::size_t>(n)] - pose.position).cross(force) +
                      f.segment<3>(fem::dof_index(n, fem::RX));
  }
  r.drive_power = pose.angular_velocity.dot(r.drive_moment) + pose.velocity.dot(r.drive_force);
  return r;
}

}  // namespace flapsim::fsi
