#include "reduction/reduction_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>

#include "reduction/tip_loads.hpp"

namespace flapsim::reduction {

double modal_assurance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double ab = a.dot(b), aa = a.squaredNorm(), bb = b.squaredNorm();
  return aa > 0.0 && bb > 0.0 ? ab * ab / (aa * bb) : 0.0;
}

namespace {

double rel(double chain, double fem) { return relative_error(chain, fem); }

}  // namespace

std::vector<ModeMatch> pair_modes_by_mac(const std::vector<Eigen::VectorXd>& fem_samples,
                                         const std::vector<double>& fem_hz,
                                         const std::vector<StationModeKind>& fem_kinds,
                                         const std::vector<Eigen::VectorXd>& chain_samples,
                                         const std::vector<double>& chain_hz) {
  std::vector<ModeMatch> out;
  for (std::size_t i = 0; i < fem_samples.size() && i < fem_kinds.size() && i < fem_hz.size(); ++i) {
    if (fem_kinds[i] != StationModeKind::bending && fem_kinds[i] != StationModeKind::torsion)
      continue;  // beam modes only
    ModeMatch mm;
    mm.fem_mode = static_cast<int>(i);
    for (std::size_t j = 0; j < chain_samples.size() && j < chain_hz.size(); ++j) {
      const double mac = modal_assurance(fem_samples[i], chain_samples[j]);
      if (mac > mm.mac) {
        mm.mac = mac;
        mm.chain_mode = static_cast<int>(j);
      }
    }
    if (mm.chain_mode < 0) continue;
    mm.found = true;
    mm.fem_hz = fem_hz[i];
    mm.chain_hz = chain_hz[static_cast<std::size_t>(mm.chain_mode)];
    mm.relative_error = rel(mm.chain_hz, mm.fem_hz);
    out.push_back(mm);
  }
  return out;
}

ModeMatch first_pair_of_kind(const std::vector<ModeMatch>& pairs, const std::vector<StationModeKind>& fem_kinds,
                             StationModeKind kind) {
  for (const ModeMatch& p : pairs)
    if (p.found && p.fem_mode >= 0 && static_cast<std::size_t>(p.fem_mode) < fem_kinds.size() &&
        fem_kinds[static_cast<std::size_t>(p.fem_mode)] == kind)
      return p;
  return ModeMatch{};
}

double relative_error(double chain, double fem) {
  // Against a zero reference there is no relative error: it was 0 ("+0.00 %", a perfect
  // match) when a load case had failed to load the FEM (tip_loads.cpp).
  return fem != 0.0 ? chain / fem - 1.0 : std::numeric_limits<double>::quiet_NaN();
}

ChainFemComparison compare_chain_with_fem(const ClampedWingAnalysis& analysis,
                                          const LumpedChain& lumped, const fem::ModalResult& modes,
                                          const std::vector<fem::ModeKind>& kinds) {
  ChainFemComparison out;
  const mbd::ChainModel& chain = lumped.chain;
  const int nb = chain.num_bodies();
  const double a = lumped.body_length;
  out.num_bodies = nb;
  out.body_length = a;
  out.fem_element_size = analysis.element_size();
  out.flexible_span = analysis.s_tip();
  out.fem_mass = lumped.fem_mass;
  out.chain_mass = chain.total_mass();
  const LinearChain lin(chain);
  const std::vector<ChainMode> cmodes = lin.modes();
  for (const auto& m : cmodes) {
    out.chain_hz.push_back(m.frequency_hz);
    out.chain_kinds.push_back(m.is_bending() ? "bending" : "torsion");
  }
  // FEM modes named from the motion of the chain's stations (film modes are not beam modes).
  const std::vector<StationModeMeasures> station_kinds = classify_modes_by_stations(lumped, modes.shapes);
  for (Eigen::Index i = 0; i < modes.frequencies_hz.size(); ++i) {
    const auto& sk = station_kinds[static_cast<std::size_t>(i)];
    out.fem_hz.push_back(modes.frequencies_hz[i]);
    out.fem_kinds.push_back(to_string(sk.kind));
    out.fem_shape_kinds.push_back(i < static_cast<Eigen::Index>(kinds.size()) ? fem::to_string(kinds[static_cast<std::size_t>(i)]) : "?");
    out.fem_beam_share.push_back(sk.beam_share);
  }

  // Every FEM beam mode with the chain mode whose shape correlates best; the first bending
  // and torsion rows are taken from these pairs (the chain's own kind of its mode is not
  // asked: on a coupled mode it may differ from the FEM's, docs/reduction.md).
  // The MAC is taken in the chain's own coordinates, weighted by its mass matrix: the FEM
  // mode's joint angles Φ (its stations' motion, as its kind is named) against the chain
  // mode's q, (Φᵀ M q)² / (Φᵀ M Φ · qᵀ M q), as plain MACs of Lᵀ Φ and Lᵀ q (M = L Lᵀ, positive
  // definite: the chain's modes are those of K q = ω² M q). The surface samples it replaced
  // (two points a body, fitted over every node of a band) read a film wing's trailing-edge
  // film: a 25 µm wing on a spar (tests/data/rod_film_25um_wing.toml) at 8 bodies paired its
  // first bending mode (717 Hz) with the chain's first torsion mode (66.7 Hz, MAC 0.67; the
  // chain's bending mode at 711.9 Hz had 0.04) and warned of −90.7 %.
  const Eigen::MatrixXd mass_root_t = Eigen::LLT<Eigen::MatrixXd>(lin.mass_matrix()).matrixU();
  std::vector<Eigen::VectorXd> fem_s, chain_s;
  std::vector<StationModeKind> fem_k;
  for (const auto& sk : station_kinds) fem_s.push_back(mass_root_t * sk.joint_angles);
  for (const auto& m : cmodes) chain_s.push_back(mass_root_t * m.shape);
  for (const auto& sk : station_kinds) fem_k.push_back(sk.kind);
  out.beam_mode_pairs = pair_modes_by_mac(fem_s, out.fem_hz, fem_k, chain_s, out.chain_hz);
  out.bending = first_pair_of_kind(out.beam_mode_pairs, fem_k, StationModeKind::bending);
  out.torsion = first_pair_of_kind(out.beam_mode_pairs, fem_k, StationModeKind::torsion);

  // Statics at the inboard edge of the loaded tip zone, the same wrenches on both.
  const TipZone& zone = analysis.tip_zone();
  // At the mid-point of the outermost body clear of the loaded zone: under a tip moment
  // or torque the chain's rotations equal the FEM's there (Hencky), so the rotation
  // errors measure the load cases' departure from that and the deflection the lumping.
  out.measure_s = a * 0.5;
  for (int k = nb - 1; k >= 0; --k)
    if (a * (k + 0.5) <= analysis.measurement_limit()) {
      out.measure_s = a * (k + 0.5);
      break;
    }
  const SectionSampler edge = analysis.sampler({out.measure_s}, 0.25 * a);
  const SectionMotion f_force = edge.sample(0, analysis.uz().col(kForceOnAxis));
  const SectionMotion f_torque = edge.sample(0, analysis.uz().col(kTorque));
  // The FEM read in the chain's coordinates: its station motion u = Aᵀ x under the load
  // case mapped to joint angles Φ = T u, the map that defines K (joint_stiffness.hpp).
  // The chain's kinematics then read both at the same point, so the rows compare the
  // chain with the FEM under the FEM's own tip-zone load, not two definitions of a
  // section's rotation (the section fit above weighs every node alike and carries camber
  // terms; the stations weigh the nodes by mass: on the swept film wing of
  // docs/reduction.md they differed by 1.4× in the bending rotation, 0.63× in the twist).
  const int ndof = fem::kDofsPerNode * static_cast<int>(analysis.nodes().cols());
  auto fem_joint_angles = [&](int load_case) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(ndof);
    for (Eigen::Index i = 0; i < analysis.nodes().cols(); ++i)
      x[fem::dof_index(static_cast<int>(i), fem::UZ)] = analysis.uz()(i, load_case);
    return Eigen::VectorXd(lumped.joint_stiffness.joint_angles(lumped.stations.station_motion(x)));
  };
  const int b_load = lin.body_at(zone.s_centroid);
  const int b_meas = lin.body_at(out.measure_s);
  const Eigen::Vector3d p_load(0.0, zone.s_centroid, 0.0), p_meas(0.0, out.measure_s, 0.0);
  const auto& w = analysis.wrenches();
  // The force case is a force on the axis (n = 0) at the zone's centroid span.
  const Eigen::VectorXd q_force = lin.static_response(lin.generalized_force(
      b_load, p_load, Eigen::Vector3d(0.0, 0.0, w[kForceOnAxis].force_z), Eigen::Vector3d::Zero()));
  const Eigen::VectorXd q_torque = lin.static_response(lin.generalized_force(
      b_load, p_load, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, w[kTorque].moment_s, 0.0)));
  out.tip_deflection = {lin.displacement(b_meas, p_meas, fem_joint_angles(kForceOnAxis)).z(),
                        lin.displacement(b_meas, p_meas, q_force).z(), 0.0, f_force.w};
  // The bending rotation is read where its sign is certain: the rotation conjugate to the
  // load, on both sides, for a moment M_n on the chain's tip body (docs/reduction.md, "A tip
  // moment on a film tip"). Read at the measuring body, as the two rows above, the tip-zone
  // moment's rotation took the sign of whatever the stations there saw: on a film wing the
  // film, which the couple twists about the rod (a 75 mm rod-and-film wing: FEM −1.6e-4 rad at
  // 6 bodies under the positive 1e-6 N m, rows −36 … −131 %). The FEM: f the moment spread over
  // the tip body's strip by mass, as a station spreads its loads (station_compliance.hpp),
  // θ = fᵀ K⁻¹ f / M_n; the chain: its generalized force Q of the same moment on the same
  // body (the strip's nodal forces are that moment: Σ f = 0, Σ f (s − s_j) = M_n,
  // Σ f n = 0), θ = Qᵀ K_c⁻¹ Q / M_n, the tip body's rotation. Both are positive (K and K_c
  // positive definite) and both the same thing, twice the strain energy over M_n; the
  // chain's equals the FEM's under the station loads Tᵀ Q of the same Q (exact at the
  // stations), so the row shows how the FEM takes the moment spread over the body against
  // how the chain's stations take it.
  const int b_tip = nb - 1;
  const double s_body = a * b_tip;  // the tip body's inboard joint [m]
  {
    const Eigen::Index nn = analysis.nodes().cols();
    Eigen::VectorXd mass(nn);
    std::vector<int> strip;
    for (Eigen::Index i = 0; i < nn; ++i) {
      const int d = fem::dof_index(static_cast<int>(i), fem::UZ);
      mass[i] = analysis.system().mass.coeff(d, d);
      if (!analysis.clamped()[static_cast<std::size_t>(i)] && analysis.s()[i] >= s_body)
        strip.push_back(static_cast<int>(i));
    }
    const double m_n = w[kBendingMoment].moment_n;
    const Eigen::VectorXd f_body =
        weighted_wrench_load(strip, analysis.s(), analysis.n(), mass, s_body, 0.0, TipWrench{0.0, m_n, 0.0});
    double theta_fem = std::numeric_limits<double>::quiet_NaN(), theta_fit = theta_fem;
    if (f_body.allFinite()) {
      const Eigen::VectorXd x_body = analysis.solve(f_body);
      theta_fem = f_body.dot(x_body) / m_n;
      Eigen::VectorXd uz(nn);
      for (Eigen::Index i = 0; i < nn; ++i) uz[i] = x_body[fem::dof_index(static_cast<int>(i), fem::UZ)];
      theta_fit = analysis.sampler({s_body + 0.5 * a}, 0.25 * a).sample(0, uz).theta;
    }
    const Eigen::VectorXd q_tip = lin.generalized_force(b_tip, Eigen::Vector3d(0.0, s_body + 0.5 * a, 0.0),
                                                        Eigen::Vector3d::Zero(), Eigen::Vector3d(m_n, 0.0, 0.0));
    out.tip_bending_rotation = {theta_fem, q_tip.dot(lin.static_response(q_tip)) / m_n, 0.0, theta_fit};
  }
  out.bending_body_s = s_body;
  out.tip_twist = {lin.rotation(b_meas, fem_joint_angles(kTorque)).y(), lin.rotation(b_meas, q_torque).y(), 0.0,
                   f_torque.phi};
  // Per unit load: the load cases are small (AnalysisOptions::unit_force, unit_moment) and the
  // solves linear, so the rows are compliances, [m/N] and [rad/(N m)], as the load-case table of
  // docs/reduction.md reads (1 N, 1 N m). They were the responses to the small loads themselves,
  // labelled [m] and [rad]: a 100 mm aluminium strip's tip deflection 4.0e-7 m for 3.5e-3 m/N.
  const std::pair<StaticMatch*, double> per_unit[] = {{&out.tip_deflection, w[kForceOnAxis].force_z},
                                                      {&out.tip_bending_rotation, w[kBendingMoment].moment_n},
                                                      {&out.tip_twist, w[kTorque].moment_s}};
  for (const auto& [s, load] : per_unit) {
    s->fem /= load;
    s->chain /= load;
    s->fem_section_fit /= load;
    s->relative_error = rel(s->chain, s->fem);
  }
  return out;
}

}  // namespace flapsim::reduction
