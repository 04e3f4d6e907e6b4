#include "reduction/chain_lumping.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flapsim::reduction {

LumpedChain lump_into_chain(const ClampedWingAnalysis& analysis, int num_bodies) {
  if (num_bodies < 1) throw std::invalid_argument("lump_into_chain: at least one body");
  const AxisFrame& ax = analysis.axis();
  const Eigen::Matrix3d r_wa = ax.rotation();
  const int nb = num_bodies;
  LumpedChain out;
  out.body_length = analysis.s_tip() / nb;
  const double a = out.body_length;
  out.fem_mass = total_rigid_mass(analysis.system().mass, analysis.nodes()).mass;

  mbd::ChainModel& chain = out.chain;
  chain.root_offset = Eigen::Vector3d::Zero();  // the pivot
  chain.root_rotation = r_wa;

  // Bodies: strips [(k−1)a, ka) of the axis.
  std::vector<double> edges;
  for (int k = 0; k <= nb; ++k) edges.push_back(a * k);
  const std::vector<RigidMass> strips = analysis.strips(edges);
  for (int k = 0; k < nb; ++k) {
    const RigidMass& rm = strips[static_cast<std::size_t>(k)];
    const Eigen::Vector3d origin = ax.point(a * k, 0.0);
    mbd::ChainBody body;
    body.length = a;
    body.mass = rm.mass;
    body.center_of_mass = r_wa.transpose() * (rm.center_of_mass() - origin);
    body.inertia = r_wa.transpose() * rm.inertia_about_center() * r_wa;
    body.inertia = 0.5 * (body.inertia + body.inertia.transpose()).eval();
    body.outboard_joint = Eigen::Vector3d(0.0, a, 0.0);
    chain.bodies.push_back(body);
    out.joint_s.push_back(a * k);
  }

  // Springs: joint k represents the cell between the mid-points of bodies k−1 and k;
  // the root joint the half cell from the clamp to the middle of body 0.
  const double s_root = analysis.s_root();
  const bool rigid_root = 0.5 * a <= s_root;
  chain.root = rigid_root ? mbd::RootAttachment::rigid : mbd::RootAttachment::sprung;
  // Section positions: the clamp, then the mid-point of every body. A mid-point inside
  // the loaded tip zone (only the last body's, with many bodies) is moved to the
  // zone's inboard edge and its cell's compliance scaled to the full cell length.
  // Sections stay one tip-zone length inboard of the loaded zone, clear of the local
  // deformation where the loads are applied.
  const double z_start = analysis.measurement_limit();
  std::vector<double> sections;
  for (int k = 0; k < nb; ++k) sections.push_back(std::min(a * (k + 0.5), z_start));
  if (nb >= 2 && sections[static_cast<std::size_t>(nb - 2)] >= z_start)
    throw std::invalid_argument("lump_into_chain: " + std::to_string(nb) +
                                " bodies put joint cells into the loaded tip zone (s > " +
                                std::to_string(z_start) + " m); use fewer bodies");
  // A root half cell shorter than a fit band (many bodies, or a long clamp) is measured
  // over one band width from the clamp and scaled to its length (uniform compliance).
  const double min_cell = 4.0 * analysis.element_size();  // one fit band half-width
  const double root_out = std::max(sections.front(), std::min(s_root + min_cell, z_start));
  std::vector<double> fit_sections = sections;
  fit_sections.push_back(root_out);
  const SectionSampler smp = analysis.sampler(fit_sections, 0.25 * a);
  const std::vector<SectionMotion> mot_m = smp.sample_all(analysis.uz().col(kBendingMoment));
  const std::vector<SectionMotion> mot_t = smp.sample_all(analysis.uz().col(kTorque));
  chain.joints.assign(static_cast<std::size_t>(nb), mbd::ChainJoint{});
  for (int k = 0; k < nb; ++k) {
    if (k == 0 && rigid_root) {
      out.cell_start.push_back(0.0);
      out.cell_end.push_back(0.0);
      continue;
    }
    // Rotations at the cell's inboard and outboard sections; the clamp does not rotate.
    double th_in = 0.0, ph_in = 0.0, s_in = s_root;
    if (k > 0) {
      th_in = mot_m[static_cast<std::size_t>(k - 1)].theta;
      ph_in = mot_t[static_cast<std::size_t>(k - 1)].phi;
      s_in = sections[static_cast<std::size_t>(k - 1)];
    }
    const std::size_t out_index = k == 0 ? sections.size() : static_cast<std::size_t>(k);
    const double th_out = mot_m[out_index].theta;
    const double ph_out = mot_t[out_index].phi;
    const double s_out = k == 0 ? root_out : sections[static_cast<std::size_t>(k)];
    const double full = k == 0 ? 0.5 * a - s_root : a;  // nominal cell length [m]
    const double scale = full / (s_out - s_in);          // 1 unless the cell was shortened
    mbd::ChainJoint& j = chain.joints[static_cast<std::size_t>(k)];
    j.bend_stiffness = analysis.moment() / ((th_out - th_in) * scale);   // k_θ = M / Δθ
    j.twist_stiffness = analysis.torque() / ((ph_out - ph_in) * scale);  // k_α = T / Δφ
    if (!(j.bend_stiffness > 0.0) || !(j.twist_stiffness > 0.0) || !std::isfinite(j.bend_stiffness) ||
        !std::isfinite(j.twist_stiffness))
      throw std::runtime_error("lump_into_chain: joint " + std::to_string(k) +
                               " has a non-positive spring (cell " + std::to_string(s_in) + " … " +
                               std::to_string(s_out) + " m); the FEM rotations are not monotonic there");
    out.cell_start.push_back(s_in);
    out.cell_end.push_back(s_out);
  }
  chain.validate();
  return out;
}

}  // namespace flapsim::reduction
