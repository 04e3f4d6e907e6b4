#include "reduction/station_compliance.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <string>

#include "fem/mesh.hpp"
#include "reduction/reduction_failure.hpp"

namespace flapsim::reduction {

namespace {

std::string mm(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f mm", metres * 1e3);
  return buf;
}

// The band of station k: free nodes within h of s_k; widened until the weighted fit of
// (w, θ, φ) is well posed (six nodes, BᵀWB well conditioned in scaled units).
StationBand make_band(const ClampedWingAnalysis& an, const Eigen::VectorXd& weight, double s_k, double h0,
                      int body) {
  const Eigen::VectorXd& s = an.s();
  const Eigen::VectorXd& n = an.n();
  const double extent = s.maxCoeff() - s.minCoeff();
  StationBand band;
  band.s = s_k;
  for (double h = h0; h <= 2.0 * extent + h0; h *= 1.25) {
    band.nodes.clear();
    for (Eigen::Index i = 0; i < s.size(); ++i)
      if (!an.clamped()[static_cast<std::size_t>(i)] && std::abs(s[i] - s_k) <= h && weight[i] > 0.0)
        band.nodes.push_back(static_cast<int>(i));
    const int m = static_cast<int>(band.nodes.size());
    if (m < 6) continue;
    double n_lo = 1e300, n_hi = -1e300;
    for (int i : band.nodes) {
      n_lo = std::min(n_lo, n[i]);
      n_hi = std::max(n_hi, n[i]);
    }
    const double ls = h, ln = std::max(0.5 * (n_hi - n_lo), 1e-300);
    Eigen::MatrixX3d b(m, 3);  // scaled: columns of order one
    Eigen::VectorXd w(m);
    for (int r = 0; r < m; ++r) {
      const int i = band.nodes[static_cast<std::size_t>(r)];
      b.row(r) << 1.0, (s[i] - s_k) / ls, -n[i] / ln;
      w[r] = weight[i];
    }
    const Eigen::Matrix3d g = b.transpose() * w.asDiagonal() * b;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(g / w.sum());
    if (!(es.eigenvalues()(0) > 1e-6)) continue;  // nodes (nearly) on one line
    // A_k = W B (BᵀWB)⁻¹ in physical units: undo the column scaling S = diag(1, 1/ls, 1/ln).
    const Eigen::Matrix3d ginv = g.inverse();
    const Eigen::DiagonalMatrix<double, 3> scale(1.0, 1.0 / ls, 1.0 / ln);
    band.weights = w.asDiagonal() * b * ginv * scale;
    band.basis = b * scale.inverse();
    band.mass = w;
    band.half_width = h;
    return band;
  }
  throw ReductionFailure("the wing section at " + mm(s_k) + " along the flexural axis (body " +
                         std::to_string(body) +
                         ") has fewer than six free FEM nodes that span both the span and the chord; "
                         "use fewer bodies or a finer mesh");
}

}  // namespace

Eigen::VectorXd StationCompliance::load_vector(const Eigen::VectorXd& g, int num_fem_dofs) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_fem_dofs);
  for (int k = 0; k < size(); ++k) {
    const StationBand& b = stations[static_cast<std::size_t>(k)];
    const Eigen::Vector3d gk = g.segment<3>(3 * k);
    for (std::size_t r = 0; r < b.nodes.size(); ++r)
      f[fem::dof_index(b.nodes[r], fem::UZ)] += b.weights.row(static_cast<Eigen::Index>(r)).dot(gk);
  }
  return f;
}

Eigen::VectorXd StationCompliance::station_motion(const Eigen::VectorXd& x) const {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * size());
  for (int k = 0; k < size(); ++k) {
    const StationBand& b = stations[static_cast<std::size_t>(k)];
    for (std::size_t r = 0; r < b.nodes.size(); ++r)
      u.segment<3>(3 * k) += b.weights.row(static_cast<Eigen::Index>(r)).transpose() *
                             x[fem::dof_index(b.nodes[r], fem::UZ)];
  }
  return u;
}

StationCompliance station_compliance(const ClampedWingAnalysis& analysis, const std::vector<double>& positions,
                                     double half_width, const std::vector<int>& body_of_station) {
  const Eigen::Index nn = analysis.nodes().cols();
  const int ndof = fem::kDofsPerNode * static_cast<int>(nn);
  // RBE3 weights: the u_z diagonal of the FEM mass matrix (veins and film by their mass).
  Eigen::VectorXd weight(nn);
  for (Eigen::Index i = 0; i < nn; ++i) {
    const int d = fem::dof_index(static_cast<int>(i), fem::UZ);
    weight[i] = analysis.system().mass.coeff(d, d);
  }
  StationCompliance out;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const int body = k < body_of_station.size() ? body_of_station[k] : static_cast<int>(k) + 1;
    out.stations.push_back(make_band(analysis, weight, positions[k], half_width, body));
  }
  const int ns = out.size();
  Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(ndof, 3 * ns);
  for (int c = 0; c < 3 * ns; ++c) loads.col(c) = out.load_vector(Eigen::VectorXd::Unit(3 * ns, c), ndof);
  const Eigen::MatrixXd x = analysis.solve(loads);
  out.compliance.resize(3 * ns, 3 * ns);
  for (int c = 0; c < 3 * ns; ++c) out.compliance.col(c) = out.station_motion(x.col(c));
  if (!out.compliance.allFinite())
    throw ReductionFailure("the static solve of the clamped wing gave non-finite displacements");
  out.compliance = (0.5 * (out.compliance + out.compliance.transpose())).eval();  // reciprocity: round-off only
  return out;
}

}  // namespace flapsim::reduction
