#include "reduction/clamped_wing_analysis.hpp"

#include <Eigen/QR>

#include "reduction/joint_stiffness.hpp"
#include "reduction/reduction_failure.hpp"
#include "reduction/station_compliance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace flapsim::reduction {

ClampedWingAnalysis::ClampedWingAnalysis(const fem::Mesh& mesh, const fem::AssembledSystem& system,
                                         const fem::Constraints& constraints,
                                         const AnalysisOptions& options,
                                         std::shared_ptr<const fem::StaticSolver> factor)
    : system_(&system), constraints_(&constraints), options_(options), solver_(std::move(factor)) {
  const int nn = mesh.num_nodes();
  if (nn == 0) throw std::invalid_argument("reduction: empty mesh");
  if (constraints.num_dofs() != mesh.num_dofs())
    throw std::invalid_argument("reduction: constraints do not match the mesh");
  nodes_.resize(3, nn);
  clamped_.assign(static_cast<std::size_t>(nn), false);
  bool any = false;
  for (int i = 0; i < nn; ++i) {
    nodes_.col(i) = mesh.nodes[static_cast<std::size_t>(i)];
    clamped_[static_cast<std::size_t>(i)] = constraints.is_fixed(fem::dof_index(i, fem::UZ));
    any = any || clamped_[static_cast<std::size_t>(i)];
  }
  if (!any) throw std::invalid_argument("reduction: the FEM needs a clamped root (no node is clamped)");
  if (nodes_.row(2).cwiseAbs().maxCoeff() > 1e-9 * (nodes_.row(1).maxCoeff() - nodes_.row(1).minCoeff()))
    throw std::invalid_argument("reduction: the wing must be flat (z = 0) at rest");
  // Typical element size: mean triangle edge (or beam length if there are no shells).
  double total = 0.0;
  long count = 0;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      total += (mesh.nodes[static_cast<std::size_t>(t[e])] - mesh.nodes[static_cast<std::size_t>(t[(e + 1) % 3])]).norm();
      ++count;
    }
  for (const auto& b : mesh.beams) {
    total += (mesh.nodes[static_cast<std::size_t>(b.nodes[0])] - mesh.nodes[static_cast<std::size_t>(b.nodes[1])]).norm();
    ++count;
  }
  element_size_ = count > 0 ? total / static_cast<double>(count) : 0.0;

  if (!solver_) solver_ = std::make_shared<const fem::StaticSolver>(system.stiffness, constraints);
  if (solver_->constraints().num_dofs() != constraints.num_dofs() ||
      solver_->constraints().num_free() != constraints.num_free())
    throw std::invalid_argument("reduction: the given factorisation is not of these constraints");
  const double span = nodes_.row(1).maxCoeff();
  const double zone_length = options.tip_zone_fraction * span;

  // First pass along y_W; then the fitted axis through the pivot.
  setup_frame(AxisFrame{0.0}, zone_length);
  solve_load_cases();
  if (options.axis == AxisChoice::given) {
    setup_frame(AxisFrame{options.psi}, zone_length);
    solve_load_cases();
  } else if (options.axis == AxisChoice::fitted) {
    const int cells = std::max(options.axis_fit_cells, 4);
    std::vector<double> sections;
    const double s_end = zone_.s_start;
    for (int k = 0; k <= cells; ++k)
      sections.push_back(s_root_ + (s_end - s_root_) * static_cast<double>(k) / cells);
    const SectionSampler smp = sampler(sections, 0.5 * (s_end - s_root_) / cells);
    const std::vector<double> nea = cell_elastic_axis(smp);
    double num = 0.0, den = 0.0;
    for (int k = 0; k < cells; ++k) {
      const double sc = 0.5 * (sections[static_cast<std::size_t>(k)] + sections[static_cast<std::size_t>(k + 1)]);
      const double w = sections[static_cast<std::size_t>(k + 1)] - sections[static_cast<std::size_t>(k)];
      if (!std::isfinite(nea[static_cast<std::size_t>(k)])) continue;
      num += w * sc * nea[static_cast<std::size_t>(k)];
      den += w * sc * sc;
    }
    const double psi = den > 0.0 ? std::atan(num / den) : 0.0;
    setup_frame(AxisFrame{psi}, zone_length);
    solve_load_cases();
    // The cells' elastic axes of the ψ = 0 pass mean nothing when sections cut along y are
    // not the wing's sections: on a strongly swept wing they twist as they bend and their
    // n_ea scatter far outside the wing. A chain axis that leaves the planform puts the
    // bodies beside the wing; then the axis is the line through the pivot and the
    // sections' mid-chords, the wing's own geometric axis (docs/reduction.md).
    if (axis_inside_fraction() < kFittedAxisMinInside) {
      fitted_axis_rejected_ = true;
      fitted_psi_rejected_ = psi;
      setup_frame(AxisFrame{0.0}, zone_length);
      const ChordExtents c = chord_extents(kAxisCheckCells);
      double num_m = 0.0, den_m = 0.0;
      for (std::size_t k = 0; k < c.s.size(); ++k) {
        num_m += c.s[k] * 0.5 * (c.lo[k] + c.hi[k]);
        den_m += c.s[k] * c.s[k];
      }
      setup_frame(AxisFrame{den_m > 0.0 ? std::atan(num_m / den_m) : 0.0}, zone_length);
      solve_load_cases();
    }
  } else if (options.axis == AxisChoice::flexural) {
    // Stations on the span (ψ = 0) frame, each over its whole strip; the flexural axis
    // of each from the station compliance (n_fa = C_φw / C_φφ, joint_stiffness.hpp);
    // the line n = n₀ + s tan ψ through them by least squares (weights: strip length).
    const int ns = std::max(options.flexural_axis_stations, 3);
    const double a = (s_tip_ - s_root_) / ns;
    std::vector<double> positions;
    for (int k = 0; k < ns; ++k) positions.push_back(s_root_ + a * (k + 0.5));
    const StationCompliance st = station_compliance(*this, positions, 0.5 * a);
    const std::vector<double> nfa = flexural_axis_offsets(st.compliance);
    Eigen::MatrixX2d b(ns, 2);
    Eigen::VectorXd y(ns);
    for (int k = 0; k < ns; ++k) {
      b.row(k) << 1.0, positions[static_cast<std::size_t>(k)];
      y[k] = nfa[static_cast<std::size_t>(k)];
    }
    const Eigen::Vector2d c = b.colPivHouseholderQr().solve(y);  // n = c₀ + c₁ s in the ψ = 0 frame
    AxisFrame f;
    f.psi = std::atan(c[1]);
    f.offset = c[0] * std::cos(f.psi);  // distance of the line from the pivot along e_n
    setup_frame(f, zone_length);
    solve_load_cases();
  }
}

ClampedWingAnalysis::ChordExtents ClampedWingAnalysis::chord_extents(int cells) const {
  // Equal cells of the flexible span in the current frame; in each, the chordwise extent
  // of its nodes (cells without a node are left out).
  ChordExtents out;
  const double a = (s_tip_ - s_root_) / cells;
  if (!(a > 0.0)) return out;
  std::vector<double> lo(static_cast<std::size_t>(cells), 1e300), hi(static_cast<std::size_t>(cells), -1e300);
  for (Eigen::Index i = 0; i < s_.size(); ++i) {
    if (s_[i] < s_root_) continue;
    const auto k = static_cast<std::size_t>(std::min(cells - 1, static_cast<int>((s_[i] - s_root_) / a)));
    lo[k] = std::min(lo[k], n_[i]);
    hi[k] = std::max(hi[k], n_[i]);
  }
  for (std::size_t k = 0; k < lo.size(); ++k) {
    if (lo[k] > hi[k]) continue;
    out.s.push_back(s_root_ + a * (static_cast<double>(k) + 0.5));
    out.lo.push_back(lo[k]);
    out.hi.push_back(hi[k]);
  }
  return out;
}

double ClampedWingAnalysis::axis_inside_fraction() const {
  // The axis is inside a cell when n = 0 lies in its nodes' chordwise extent, widened by
  // one element size (an axis along a straight edge vein is inside).
  const ChordExtents c = chord_extents(kAxisCheckCells);
  if (c.s.empty()) return 1.0;
  std::size_t inside = 0;
  for (std::size_t k = 0; k < c.s.size(); ++k)
    if (c.lo[k] - element_size_ <= 0.0 && 0.0 <= c.hi[k] + element_size_) ++inside;
  return static_cast<double>(inside) / static_cast<double>(c.s.size());
}

void ClampedWingAnalysis::setup_frame(const AxisFrame& axis, double tip_zone_length) {
  axis_ = axis;
  const Eigen::Index nn = nodes_.cols();
  s_.resize(nn);
  n_.resize(nn);
  s_root_ = -1e300;
  for (Eigen::Index i = 0; i < nn; ++i) {
    s_[i] = axis_.s(nodes_.col(i));
    n_[i] = axis_.n(nodes_.col(i));
    if (clamped_[static_cast<std::size_t>(i)]) s_root_ = std::max(s_root_, s_[i]);
  }
  s_tip_ = s_.maxCoeff();
  zone_ = make_tip_zone(s_, n_, tip_zone_length, clamped_);
  if (zone_.s_start <= s_root_) {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "the root clamp reaches %.2f mm along the axis, into the loaded tip zone (from %.2f mm to the tip "
                  "at %.2f mm): too little of the wing is free to bend; use a smaller clamp_y or a finer mesh",
                  s_root_ * 1e3, zone_.s_start * 1e3, s_tip_ * 1e3);
    throw ReductionInputLimit(buf);
  }
  // The two forces for the elastic axis: a quarter of the zone's chord either side.
  const double half = 0.25 * (zone_.n_max - zone_.n_min);
  n1_ = zone_.n_centroid + half;
  n2_ = zone_.n_centroid - half;
}

void ClampedWingAnalysis::solve_load_cases() {
  moment_ = options_.unit_moment;
  force_ = options_.unit_force;
  wrenches_.assign(kNumLoadCases, TipWrench{});
  wrenches_[kBendingMoment].moment_n = moment_;
  wrenches_[kTorque].moment_s = moment_;
  wrenches_[kForceLeading] = force_at(zone_, force_, n1_);
  wrenches_[kForceTrailing] = force_at(zone_, force_, n2_);
  wrenches_[kForceOnAxis] = force_at(zone_, force_, 0.0);
  Eigen::MatrixXd loads(6 * nodes_.cols(), kNumLoadCases);
  for (int c = 0; c < kNumLoadCases; ++c)
    loads.col(c) = tip_load_vector(zone_, s_, n_, wrenches_[static_cast<std::size_t>(c)]);
  const Eigen::MatrixXd u = solver_->solve(loads);
  uz_.resize(nodes_.cols(), kNumLoadCases);
  for (Eigen::Index i = 0; i < nodes_.cols(); ++i) uz_.row(i) = u.row(fem::dof_index(static_cast<int>(i), fem::UZ));
  if (!uz_.allFinite()) throw std::runtime_error("reduction: static solve gave non-finite displacements");
}

SectionSampler ClampedWingAnalysis::sampler(const std::vector<double>& sections, double half_width) const {
  // At least four element sizes: a band only two node rows wide gives a noisy slope c₁.
  return SectionSampler(s_, n_, sections, std::max(half_width, 4.0 * element_size_));
}

std::vector<RigidMass> ClampedWingAnalysis::strips(const std::vector<double>& edges) const {
  const int ns = static_cast<int>(edges.size()) - 1;
  if (ns < 1) throw std::invalid_argument("reduction: at least one strip expected");
  std::vector<int> strip(static_cast<std::size_t>(nodes_.cols()));
  for (Eigen::Index i = 0; i < nodes_.cols(); ++i) {
    const auto it = std::upper_bound(edges.begin() + 1, edges.end() - 1, s_[i]);
    strip[static_cast<std::size_t>(i)] = static_cast<int>(it - (edges.begin() + 1));
  }
  return strip_rigid_masses(system_->mass, nodes_, strip, ns);
}

std::vector<double> ClampedWingAnalysis::cell_elastic_axis(const SectionSampler& sampler) const {
  std::vector<double> out;
  const Eigen::VectorXd u1 = uz_.col(kForceLeading), u2 = uz_.col(kForceTrailing);
  for (int k = 0; k + 1 < sampler.num_sections(); ++k) {
    const double d1 = sampler.sample(k + 1, u1).phi - sampler.sample(k, u1).phi;
    const double d2 = sampler.sample(k + 1, u2).phi - sampler.sample(k, u2).phi;
    // n_ea = (n₂Δφ₁ − n₁Δφ₂)/(Δφ₁ − Δφ₂), per cell (docs/reduction.md, "Elastic axis")
    out.push_back(std::abs(d1 - d2) > 0.0 ? (n2_ * d1 - n1_ * d2) / (d1 - d2)
                                          : std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

}  // namespace flapsim::reduction
