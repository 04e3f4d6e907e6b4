#include "reduction/tip_loads.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "reduction/reduction_failure.hpp"

namespace flapsim::reduction {

TipZone make_tip_zone(const Eigen::VectorXd& s, const Eigen::VectorXd& n, double length,
                      const std::vector<bool>& excluded, int min_nodes) {
  if (s.size() == 0) throw std::invalid_argument("make_tip_zone: no nodes");
  const double s_max = s.maxCoeff();
  const double extent = s_max - s.minCoeff();
  double ell = std::max(length, 1e-12 * extent);
  for (;;) {
    TipZone zone;
    zone.s_start = s_max - ell;
    double s_lo = 1e300, s_hi = -1e300, n_lo = 1e300, n_hi = -1e300;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
      if (!excluded.empty() && excluded[static_cast<std::size_t>(i)]) continue;
      if (s[i] < zone.s_start) continue;
      zone.nodes.push_back(static_cast<int>(i));
      s_lo = std::min(s_lo, s[i]);
      s_hi = std::max(s_hi, s[i]);
      n_lo = std::min(n_lo, n[i]);
      n_hi = std::max(n_hi, n[i]);
    }
    const double tol = 1e-9 * std::max(extent, 1e-300);
    if (static_cast<int>(zone.nodes.size()) >= min_nodes && s_hi - s_lo > tol && n_hi - n_lo > tol) {
      for (int i : zone.nodes) {
        zone.s_centroid += s[i];
        zone.n_centroid += n[i];
      }
      zone.s_centroid /= static_cast<double>(zone.nodes.size());
      zone.n_centroid /= static_cast<double>(zone.nodes.size());
      zone.n_min = n_lo;
      zone.n_max = n_hi;
      // Nodes on one line (a straight tip edge oblique to the axis: all of them spread in
      // s and in n) cannot carry a bending moment and a torque independently: the load
      // cases' 3 × 3 system is singular and the bending moment came out as no load at all
      // (a forward-swept plate with --axis flexural: EI = inf at every station). The zone
      // must have an area: the smaller principal variance of (s, n) at least 1e-6 of the
      // larger (a band 1e-3 of its length wide).
      double ss = 0.0, nn = 0.0, sn = 0.0;
      for (int i : zone.nodes) {
        const double ds = s[i] - zone.s_centroid, dn = n[i] - zone.n_centroid;
        ss += ds * ds;
        nn += dn * dn;
        sn += ds * dn;
      }
      const double mean = 0.5 * (ss + nn), dev = std::sqrt(0.25 * (ss - nn) * (ss - nn) + sn * sn);
      if (mean - dev > 1e-6 * (mean + dev)) return zone;
    }
    if (ell > extent)
      throw ReductionInputLimit(
          "the wing has too few free FEM nodes to load at its tip (fewer than " + std::to_string(min_nodes) +
          " spanning both the span and the chord outside the root clamp); use a smaller [mesh] element_size "
          "or a smaller clamp_y");
    ell *= 1.25;
  }
}

Eigen::VectorXd tip_load_vector(const TipZone& zone, const Eigen::VectorXd& s,
                                const Eigen::VectorXd& n, const TipWrench& wrench) {
  const int m = static_cast<int>(zone.nodes.size());
  // Constraint rows: resultant force, moment about e_n, moment about e_s.
  Eigen::MatrixXd a(3, m);
  for (int r = 0; r < m; ++r) {
    const int i = zone.nodes[static_cast<std::size_t>(r)];
    a.col(r) << 1.0, s[i] - zone.s_centroid, -(n[i] - zone.n_centroid);
  }
  const Eigen::Vector3d b(wrench.force_z, wrench.moment_n, wrench.moment_s);
  const Eigen::Vector3d lambda = (a * a.transpose()).ldlt().solve(b);
  const Eigen::VectorXd f = a.transpose() * lambda;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(6 * s.size());
  for (int r = 0; r < m; ++r) load[6 * zone.nodes[static_cast<std::size_t>(r)] + 2] = f[r];
  return load;
}

Eigen::VectorXd weighted_wrench_load(const std::vector<int>& nodes, const Eigen::VectorXd& s,
                                     const Eigen::VectorXd& n, const Eigen::VectorXd& weights, double s_ref,
                                     double n_ref, const TipWrench& wrench) {
  const auto m = static_cast<Eigen::Index>(nodes.size());
  Eigen::MatrixX3d b(m, 3);
  Eigen::VectorXd w(m);
  for (Eigen::Index r = 0; r < m; ++r) {
    const int i = nodes[static_cast<std::size_t>(r)];
    b.row(r) << 1.0, s[i] - s_ref, -(n[i] - n_ref);
    w[r] = weights[i];
  }
  const Eigen::Matrix3d g = b.transpose() * w.asDiagonal() * b;
  const Eigen::Vector3d rhs(wrench.force_z, wrench.moment_n, wrench.moment_s);
  Eigen::Vector3d lambda = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(g);
  if (ldlt.info() == Eigen::Success && ldlt.isPositive() && ldlt.vectorD().minCoeff() > 1e-12 * ldlt.vectorD().maxCoeff())
    lambda = ldlt.solve(rhs);
  const Eigen::VectorXd f = w.asDiagonal() * (b * lambda);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(6 * s.size());
  for (Eigen::Index r = 0; r < m; ++r) load[6 * nodes[static_cast<std::size_t>(r)] + 2] = f[r];
  return load;
}

TipWrench force_at(const TipZone& zone, double force_z, double n_point) {
  TipWrench w;
  w.force_z = force_z;
  w.moment_s = -force_z * (n_point - zone.n_centroid);
  return w;
}

}  // namespace flapsim::reduction
