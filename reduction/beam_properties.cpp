#include "reduction/beam_properties.hpp"

#include "reduction/reduction_failure.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace flapsim::reduction {

BeamProperties extract_beam_properties(const ClampedWingAnalysis& analysis, int num_stations) {
  if (num_stations < 2) throw std::invalid_argument("extract_beam_properties: at least 2 stations");
  BeamProperties beam;
  beam.axis = analysis.axis();
  beam.fitted_axis_rejected = analysis.fitted_axis_rejected();
  beam.fitted_psi_rejected = analysis.fitted_psi_rejected();
  beam.s_root = analysis.s_root();
  beam.s_tip = analysis.s_tip();
  const AxisFrame& ax = beam.axis;
  const int n = num_stations;
  std::vector<double> edges;
  for (int k = 0; k <= n; ++k)
    edges.push_back(beam.s_root + (beam.s_tip - beam.s_root) * static_cast<double>(k) / n);
  const double ds = edges[1] - edges[0];
  const SectionSampler smp = analysis.sampler(edges, 0.5 * ds);

  const std::vector<RigidMass> strips = analysis.strips(edges);
  beam.total_mass = total_rigid_mass(analysis.system().mass, analysis.nodes()).mass;

  const Eigen::VectorXd um = analysis.uz().col(kBendingMoment);
  const Eigen::VectorXd ut = analysis.uz().col(kTorque);
  const std::vector<SectionMotion> mot_m = smp.sample_all(um);
  const std::vector<SectionMotion> mot_t = smp.sample_all(ut);
  const std::vector<double> nea = analysis.cell_elastic_axis(smp);
  // Cells up to one tip-zone length inboard of the loaded zone are disturbed by the
  // local deformation where the loads are applied (as in lump_into_chain).
  const double z_start = analysis.measurement_limit();

  for (int k = 0; k < n; ++k) {
    BeamStation st;
    st.s_start = edges[static_cast<std::size_t>(k)];
    st.s_end = edges[static_cast<std::size_t>(k + 1)];
    st.s = 0.5 * (st.s_start + st.s_end);
    st.y = ax.point(st.s, 0.0).y();
    const RigidMass& rm = strips[static_cast<std::size_t>(k)];
    beam.strip_mass_sum += rm.mass;
    st.mass_per_length = rm.mass / ds;
    const Eigen::Vector3d c = rm.center_of_mass();
    st.n_cg = ax.n(c);
    st.x_cg = c.x();
    // Inertia about the axis line: the e_s component of the inertia tensor about the
    // axis point at the strip's own s (I_ss does not depend on where along e_s).
    st.I_alpha = ax.e_s().dot(rm.inertia_about(ax.point(ax.s(c), 0.0)) * ax.e_s()) / ds;
    // Section rotations at the cell edges; the clamped root section does not rotate.
    const double th0 = k == 0 ? 0.0 : mot_m[static_cast<std::size_t>(k)].theta;
    const double ph0 = k == 0 ? 0.0 : mot_t[static_cast<std::size_t>(k)].phi;
    const double dth = mot_m[static_cast<std::size_t>(k + 1)].theta - th0;
    const double dph = mot_t[static_cast<std::size_t>(k + 1)].phi - ph0;
    st.EI = analysis.moment() * ds / dth;  // EI = M Δs / Δθ
    st.GJ = analysis.torque() * ds / dph;  // GJ = T Δs / Δφ
    // A section turned against the load (or not at all) identifies no stiffness: NaN, counted
    // (the chain's springs come from the stations' compliance, not from these).
    if (!(st.EI > 0.0) || !std::isfinite(st.EI)) st.EI = std::numeric_limits<double>::quiet_NaN();
    if (!(st.GJ > 0.0) || !std::isfinite(st.GJ)) st.GJ = std::numeric_limits<double>::quiet_NaN();
    st.n_ea = nea[static_cast<std::size_t>(k)];
    st.in_tip_zone = st.s_end > z_start + 1e-12 * ds;
    beam.stations.push_back(st);
  }
  // Cells reaching into the loaded tip zone see a moment that is no longer uniform:
  // they take the stiffness and elastic axis of the last cell outside it.
  int last_ok = -1;
  for (int k = 0; k < n; ++k)
    if (!beam.stations[static_cast<std::size_t>(k)].in_tip_zone) last_ok = k;
  if (last_ok < 0) {
    // The loaded tip zone grows until it holds enough nodes: on a coarse mesh it reaches
    // the root and leaves no cell to measure the beam in.
    char buf[480];
    std::snprintf(buf, sizeof buf,
                  "the mesh is too coarse along the span for the beam: the loaded tip zone and its "
                  "disturbed band reach from the tip at %.2f mm to %.2f mm along the axis, over the whole "
                  "flexible span from %.2f mm (mean element edge %.2f mm); use a smaller [mesh] element_size "
                  "(or clamp_y, if the clamp leaves little of the wing free)",
                  beam.s_tip * 1e3, z_start * 1e3, beam.s_root * 1e3, analysis.element_size() * 1e3);
    throw ReductionInputLimit(buf);
  }
  for (int k = last_ok + 1; k < n; ++k) {
    auto& st = beam.stations[static_cast<std::size_t>(k)];
    const auto& ok = beam.stations[static_cast<std::size_t>(last_ok)];
    st.EI = ok.EI;
    st.GJ = ok.GJ;
    st.n_ea = ok.n_ea;
  }
  for (auto& st : beam.stations) {
    st.x_ea = ax.point(st.s, st.n_ea).x();
    beam.unidentified_ei += std::isnan(st.EI) ? 1 : 0;
    beam.unidentified_gj += std::isnan(st.GJ) ? 1 : 0;
  }

  // Mean elastic axis from the twists at the tip zone's edge, and the coupling measure.
  const SectionSampler edge = analysis.sampler({z_start}, 0.5 * ds);  // clear of the loads
  const double p1 = edge.sample(0, analysis.uz().col(kForceLeading)).phi;
  const double p2 = edge.sample(0, analysis.uz().col(kForceTrailing)).phi;
  const double n1 = analysis.n_force_leading(), n2 = analysis.n_force_trailing();
  beam.n_ea_tip = (n2 * p1 - n1 * p2) / (p1 - p2);
  const double tw_m = edge.sample(0, um).phi, tw_t = edge.sample(0, ut).phi;
  beam.bend_twist_coupling = tw_t != 0.0 ? tw_m / tw_t : 0.0;
  return beam;
}

}  // namespace flapsim::reduction
