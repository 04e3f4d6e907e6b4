/// \file leading_edge_loads.cpp
/// \brief The leading-edge force of a strip with LeadingEdge::Shed (leading_edge_sheet.hpp).
///
/// - A strip that does not shed holds its suction in the plane, as LeadingEdge::Attached:
///   the in-plane part of the Kutta–Joukowski forces on its spanwise bound segments, summed
///   (aero_loads.cpp; in 2-D exactly ρΓU sin α, thin-aerofoil theory's π ρ U² c A0²).
/// - A strip that sheds holds its LESP at ±LESP_crit, and its suction is that of the
///   leading-edge singularity with A0 = LESP: π ρ U² c A0² per unit span, along the plane,
///   normal to the edge, forward — the suction force of the LDVM [Ramesh et al. 2014,
///   J. Fluid Mech. 751, §2: C_S = 2π A0²], with U and c of the strip's LESP. The lattice's
///   sum is not used there: in a continuous sheet the only in-plane force is the edge
///   singularity's, but on the lattice the normal velocity is zero only at the collocation
///   points, and the sheet's vortices close over the first panels make the normal velocity
///   at the bound segments between them large, so the sum then holds in-plane forces that
///   the continuous sheet does not have (on the Robofly wing at 50° they turned the force
///   ~12° forward of the wing's normal; docs/uvlm.md, "Leading-edge vortex shedding:
///   measurements").
/// - A strip at an end of the outline, which the criterion does not resolve
///   (kResolvedStripChordRatio), turns its suction normal to the surface: the suction
///   analogy of LeadingEdge::Separated [Polhamus 1966, NASA TN D-3767].

#include "uvlm/lattice_internal.hpp"
#include "uvlm/leading_edge_sheet.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <cmath>

namespace flapsim::uvlm::detail {

Eigen::Vector3d shed_edge_force(const VortexLatticeModel& m, const VortexLatticeData& d, int j,
                                const Eigen::Vector3d& suction) {
  const LeadingEdgeSheet& s = d.le_sheet;
  const int k = m.panel(0, j);
  if (!s.active() || s.lesp.size() != m.spanwise) return suction;  // no unsteady solve yet
  const Eigen::Vector3d n = d.normal.col(k);
  if (!s.resolved[j]) {
    const double gamma1 = d.gamma(k) - s.current(j);
    return (gamma1 >= 0.0 ? suction.norm() : -suction.norm()) * n;
  }
  if (!s.shedding[j]) return suction;
  const Eigen::Vector3d a = d.nodes.col(m.node(0, j)), b = d.nodes.col(m.node(0, j + 1));
  const Eigen::Vector3d behind = 0.5 * (d.nodes.col(m.node(1, j)) + d.nodes.col(m.node(1, j + 1)));
  const Eigen::Vector3d e = (b - a).normalized();
  Eigen::Vector3d forward = 0.5 * (a + b) - behind;
  forward -= forward.dot(n) * n;
  forward -= forward.dot(e) * e;
  // Per unit span: the strip's width along the span (of a swept edge, not the edge's length).
  const double width = std::abs((b - a).dot(d.span_tangent.col(k))), U = s.edge_speed(j), A0 = s.lesp(j);
  return M_PI * d.rho * U * U * s.strip_chord(j) * A0 * A0 * width * forward.normalized();
}

}  // namespace flapsim::uvlm::detail
