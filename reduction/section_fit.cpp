#include "reduction/section_fit.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flapsim::reduction {

SectionSampler::SectionSampler(const Eigen::VectorXd& s, const Eigen::VectorXd& n,
                               const std::vector<double>& sections, double half_width,
                               int min_nodes) {
  if (s.size() != n.size()) throw std::invalid_argument("SectionSampler: s and n differ in size");
  if (!(half_width > 0.0)) throw std::invalid_argument("SectionSampler: half width must be > 0");
  min_nodes = std::max(min_nodes, 6);
  const double s_extent = s.size() > 0 ? s.maxCoeff() - s.minCoeff() : 0.0;
  bands_.reserve(sections.size());
  for (const double s_star : sections) {
    Band band;
    band.s_star = s_star;
    double h = half_width;
    bool done = false;
    while (!done) {
      band.nodes.clear();
      for (Eigen::Index i = 0; i < s.size(); ++i)
        if (std::abs(s[i] - s_star) <= h) band.nodes.push_back(static_cast<int>(i));
      const int m = static_cast<int>(band.nodes.size());
      if (m >= min_nodes) {
        // Scaled design matrix: columns of order one keep the fit well conditioned.
        double n_lo = 1e300, n_hi = -1e300;
        for (int i : band.nodes) {
          n_lo = std::min(n_lo, n[i]);
          n_hi = std::max(n_hi, n[i]);
        }
        const double c_scale = std::max(0.5 * (n_hi - n_lo), 1e-300);
        Eigen::MatrixXd a(m, 6);
        for (int r = 0; r < m; ++r) {
          const int i = band.nodes[static_cast<std::size_t>(r)];
          const double ds = (s[i] - s_star) / h, dn = n[i] / c_scale;
          a.row(r) << 1.0, ds, dn, ds * dn, ds * ds, dn * dn;
        }
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
        qr.setThreshold(1e-8);
        if (qr.rank() == 6) {
          const Eigen::MatrixXd pinv = qr.solve(Eigen::MatrixXd::Identity(m, m));  // 6 × m
          band.rows.resize(3, m);
          band.rows.row(0) = pinv.row(0);
          band.rows.row(1) = pinv.row(1) / h;          // undo the Δs scaling
          band.rows.row(2) = -pinv.row(2) / c_scale;   // φ = −c₂
          band.half_width = h;
          band.n_min = n_lo;
          band.n_max = n_hi;
          done = true;
          break;
        }
      }
      if (h > 2.0 * s_extent + 1.0)
        throw std::runtime_error("SectionSampler: no usable band of nodes around s = " +
                                 std::to_string(s_star) + " m");
      h *= 1.25;
    }
    bands_.push_back(std::move(band));
  }
}

SectionMotion SectionSampler::sample(int k, const Eigen::VectorXd& uz) const {
  const Band& band = bands_.at(static_cast<std::size_t>(k));
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();
  for (std::size_t r = 0; r < band.nodes.size(); ++r)
    acc += band.rows.col(static_cast<Eigen::Index>(r)) * uz[band.nodes[r]];
  return {acc[0], acc[1], acc[2]};
}

std::vector<SectionMotion> SectionSampler::sample_all(const Eigen::VectorXd& uz) const {
  std::vector<SectionMotion> out;
  out.reserve(bands_.size());
  for (int k = 0; k < num_sections(); ++k) out.push_back(sample(k, uz));
  return out;
}

}  // namespace flapsim::reduction
