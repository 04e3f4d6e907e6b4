#include "reduction/chain_lumping.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>
#include <string>

#include "reduction/reduction_failure.hpp"

namespace flapsim::reduction {

namespace {

// The consistent-mass share of a thin strip (a sliver of the wing beside the clamp) can
// have a slightly negative principal moment or break I₁ + I₂ ≥ I₃ by round-off of its
// partition: clip to the nearest physical tensor (principal moments ≥ 0, the largest at
// most the sum of the other two); a physical tensor is returned unchanged.
Eigen::Matrix3d physical_inertia(const Eigen::Matrix3d& inertia) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(inertia);
  Eigen::Vector3d p = es.eigenvalues().cwiseMax(0.0);  // ascending
  if (p(0) + p(1) >= p(2) && es.eigenvalues()(0) >= 0.0) return inertia;
  p(2) = std::min(p(2), p(0) + p(1));
  return es.eigenvectors() * p.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace

void check_bodies_outside_clamp(const ClampedWingAnalysis& analysis, int num_bodies) {
  if (num_bodies < 1) throw ReductionFailure("a chain needs at least one body");
  const double a = analysis.s_tip() / num_bodies, s_root = analysis.s_root();
  if (a * (num_bodies - 0.5) > s_root) return;
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "all %d bodies lie inside the root clamp (clamp reaches %.2f mm along the flexural axis, "
                "bodies are %.2f mm long); use more bodies or a smaller clamp_y",
                num_bodies, s_root * 1e3, a * 1e3);
  throw ReductionInputLimit(buf);
}

namespace {

LumpedChain lump_into_chain_as_asked(const ClampedWingAnalysis& analysis, int num_bodies,
                                     SpringModel springs) {
  const AxisFrame& ax = analysis.axis();
  const Eigen::Matrix3d r_wa = ax.rotation();
  const int nb = num_bodies;
  LumpedChain out;
  out.springs = springs;
  out.body_length = analysis.s_tip() / nb;
  const double a = out.body_length;
  out.fem_mass = total_rigid_mass(analysis.system().mass, analysis.nodes()).mass;

  mbd::ChainModel& chain = out.chain;
  chain.root_offset = ax.point(0.0, 0.0);  // the axis point nearest the pivot (n₀ e_n)
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
    body.center_of_mass = rm.mass > 0.0 ? Eigen::Vector3d(r_wa.transpose() * (rm.center_of_mass() - origin))
                                         : Eigen::Vector3d(0.0, 0.5 * a, 0.0);  // a strip the wing does not reach
    body.inertia = r_wa.transpose() * rm.inertia_about_center() * r_wa;
    body.inertia = physical_inertia(0.5 * (body.inertia + body.inertia.transpose()));
    body.outboard_joint = Eigen::Vector3d(0.0, a, 0.0);
    chain.bodies.push_back(body);
    out.joint_s.push_back(a * k);
  }

  // Bodies whose mid-span lies in the clamp do not move: welded to the root. With none
  // of them, joint 1 joins body 1 to the clamp (a sprung root).
  const double s_root = analysis.s_root();
  int welded = 0;
  while (welded < nb && a * (welded + 0.5) <= s_root) ++welded;  // < nb: check_bodies_outside_clamp
  chain.root = welded > 0 ? mbd::RootAttachment::rigid : mbd::RootAttachment::sprung;
  chain.welded_bodies = std::max(welded, 1);
  chain.joints.assign(static_cast<std::size_t>(nb), mbd::ChainJoint{});

  // Two stations per jointed body: its mid-span (twist) and its outboard joint (deflection);
  // bands of a quarter body either side (joint_stiffness.hpp).
  std::vector<double> positions;
  std::vector<int> bodies_1based;
  for (int k = welded; k < nb; ++k) {
    positions.push_back(a * (k + 0.5));
    positions.push_back(a * (k + 1));
    out.station_body.push_back(k);
    bodies_1based.push_back(k + 1);
    bodies_1based.push_back(k + 1);
  }
  out.stations = station_compliance(analysis, positions, 0.25 * a, bodies_1based);
  const std::vector<double> nfa = flexural_axis_offsets(out.stations.compliance);
  for (std::size_t i = 0; i < nfa.size(); i += 2) out.flexural_axis_n.push_back(nfa[i]);
  out.joint_stiffness = joint_stiffness(out.stations.compliance, a);
  if (springs == SpringModel::full) {
    chain.stiffness_matrix = out.joint_stiffness.stiffness;
  } else {
    const Eigen::VectorXd k = out.joint_stiffness.diagonal_springs();
    for (int b = chain.first_jointed_body(); b < nb; ++b) {
      const int d = chain.dof_of_body(b);
      chain.joints[static_cast<std::size_t>(b)].bend_stiffness = k[d];
      chain.joints[static_cast<std::size_t>(b)].twist_stiffness = k[d + 1];
    }
  }
  chain.validate();
  return out;
}

}  // namespace

LumpedChain lump_into_chain(const ClampedWingAnalysis& analysis, int num_bodies, SpringModel springs) {
  check_bodies_outside_clamp(analysis, num_bodies);
  try {
    return lump_into_chain_as_asked(analysis, num_bodies, springs);
  } catch (const ReductionInputLimit&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    // Bodies shorter than the FEM's elements: adjacent sections are measured from nearly the
    // same nodes, and a strip may hold none. The hawkmoth (mean edge 0.461 mm) reduced to 300
    // bodies (0.16 mm) and failed at 500 ("chain: body 483: mass must be > 0") and 1000 ("the
    // joints' compliance ... is not positive definite"), after 23 and 40 s, without a count.
    const double a = analysis.s_tip() / num_bodies, edge = analysis.element_size();
    if (!(edge > 0.0 && a < edge)) throw;
    const int most = std::max(1, static_cast<int>(std::floor(analysis.s_tip() / edge)));
    char advice[320];
    std::snprintf(
        advice, sizeof advice,
        "; the chain's %d bodies are %.3g mm long, shorter than the FEM's mean element edge (%.3g mm), "
        "so neighbouring sections are measured from nearly the same nodes: use at most %d bodies, or "
        "a finer [mesh] element_size (docs/reduction.md, \"Bodies shorter than the elements\")",
        num_bodies, a * 1e3, edge * 1e3, most);
    throw ReductionFailure(std::string(e.what()) + advice);
  }
}

}  // namespace flapsim::reduction
