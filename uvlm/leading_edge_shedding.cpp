/// \file leading_edge_shedding.cpp
/// \brief The LESP criterion in the lattice's solve (leading_edge_sheet.hpp): the LESP of
/// each strip and the circulations with the leading-edge rings of the strips that shed.
///
/// Every strip's leading-edge ring first keeps the circulation it had (nothing shed:
/// Γ* = A⁻¹ r). The strips whose |LESP| then exceeds LESP_crit (Ramesh et al. 2014, J.
/// Fluid Mech. 751: a leading edge sheds only when its suction parameter exceeds the
/// critical value, and then just enough to hold it there) get an increment δ_j of their
/// leading-edge ring, which adds the column b_j (its normal velocity at the collocation
/// points) to the system: A Γ = r − B δ, and the condition
///     Γ(0, j) − (G_j + δ_j) = ±Γ_crit,j   (Γ_1 at ±LESP_crit, the sign of the LESP without shedding)
/// closes it. With Γ = Γ* − A⁻¹ B δ (the influence matrix's factorisation, one solve per
/// column) this is the small bordered system (I + [A⁻¹B]_first row) δ = Γ*_1 ∓ Γ_crit,
/// solved exactly. The strips are coupled (a strip's shedding changes its neighbours'
/// LESP), so the set of strips that shed is found by iteration until it satisfies the
/// criterion's complementarity conditions on every strip: a strip that sheds holds ±LESP_crit
/// with an increment of the sign of its LESP (it sheds vorticity of that sign); a strip
/// that does not shed has |LESP| ≤ LESP_crit. A strip that would need an increment of the
/// other sign to stay at ±LESP_crit once its neighbours shed leaves the set (its LESP is
/// then inside the band); one that exceeds LESP_crit only once its neighbours shed joins;
/// the system is solved again after each change (at most 2 ns + 1 solves). Without the
/// first rule such strips shed vorticity of the wrong sign to hold their LESP (6 of 310
/// strip-steps on the Robofly wing at 50°, 30 steps; test
/// uvlm.RevolvingWing.ShedLeadingEdgeHoldsEveryStripAtTheCriticalLesp). A strip at an end of
/// the outline (kResolvedStripChordRatio) never joins.

#include "uvlm/lattice_internal.hpp"
#include "uvlm/leading_edge_sheet.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <algorithm>
#include <cmath>

namespace flapsim::uvlm::detail {

namespace {

/// Γ_1 at LESP = 1 for strip j [m²/s]: U c (θ1 + sin θ1) / 1.13 (leading_edge_sheet.hpp);
/// keeps U and c in the sheet (the suction of a shedding strip, leading_edge_loads.cpp).
double unit_lesp_gamma(const VortexLatticeModel& m, VortexLatticeData& d, int j) {
  double chord = 0.0;
  for (int i = 0; i < m.chordwise; ++i) chord += d.chord_length(m.panel(i, j));
  const double first = d.chord_length(m.panel(0, j));
  const double theta1 = std::acos(std::clamp(1.0 - 2.0 * first / chord, -1.0, 1.0));
  const Eigen::Vector3d w =
      d.free_stream - 0.5 * (d.node_velocities.col(m.node(0, j)) + d.node_velocities.col(m.node(0, j + 1)));
  const Eigen::Vector3d e = d.span_tangent.col(m.panel(0, j));
  const double speed = (w - w.dot(e) * e).norm();
  d.le_sheet.edge_speed(j) = speed;
  d.le_sheet.strip_chord(j) = chord;
  return speed * chord * (theta1 + std::sin(theta1)) / kLespLatticeFactor;
}

/// Whether strip j resolves a leading edge (kResolvedStripChordRatio): the chords of its
/// two node columns, leading- to trailing-edge node, within the factor of each other.
bool strip_is_resolved(const VortexLatticeModel& m, const VortexLatticeData& d, int j) {
  const int nc = m.chordwise;
  const double c0 = (d.nodes.col(m.node(nc, j)) - d.nodes.col(m.node(0, j))).norm();
  const double c1 = (d.nodes.col(m.node(nc, j + 1)) - d.nodes.col(m.node(0, j + 1))).norm();
  return std::min(c0, c1) >= kResolvedStripChordRatio * std::max(c0, c1);
}

/// LESP of every strip from d.gamma and the sheet's current leading-edge rings; returns
/// whether a strip not yet shedding exceeds LESP_crit (and marks it, with its target sign).
bool update_lesp(const VortexLatticeModel& m, VortexLatticeData& d, Eigen::VectorXd& target) {
  LeadingEdgeSheet& s = d.le_sheet;
  bool joined = false;
  for (int j = 0; j < m.spanwise; ++j) {
    s.resolved[j] = strip_is_resolved(m, d, j) ? 1 : 0;
    const double unit = unit_lesp_gamma(m, d, j);
    const double gamma1 = d.gamma(m.panel(0, j)) - s.current(j);
    s.critical_gamma(j) = m.lesp_critical * unit;
    s.lesp(j) = unit > 0.0 ? gamma1 / unit : (gamma1 == 0.0 ? 0.0 : std::copysign(HUGE_VAL, gamma1));
    if (s.resolved[j] && !s.shedding[j] && std::abs(gamma1) > s.critical_gamma(j)) {
      s.shedding[j] = 1;
      target(j) = std::copysign(s.critical_gamma(j), gamma1);
      joined = true;
    }
  }
  return joined;
}

/// s.at_collocation's velocities: zeroed, then the velocity of the segments in s.unit_ring
/// (their cores relative to `core`) at every collocation point, summed as one set: a call a
/// ring or a solve, not a segment (a call's setup, about 6 µs at 60 points, costs more than
/// its pairs).
void unit_ring_at_collocation(const VortexLatticeModel& m, VortexLatticeData& d, const VortexCore& core) {
  LeadingEdgeSheet& s = d.le_sheet;
  PointSet& p = s.at_collocation;
  const int np = m.panels();
  for (int k = 0; k < np; ++k) p.set(static_cast<std::size_t>(k), d.collocation.col(k));
  p.size = static_cast<std::size_t>(np);
  p.zero_velocity();
  add_induced_velocity(s.unit_ring, p, core);
}

/// Normal velocity at every collocation point of the unit leading-edge ring of strip j:
/// release row R_(j+1) → R_j, legs R → first bound vortex (the sheet's core, as its
/// segments), and the segment on the first bound vortex (the bound core, as the bound segment).
void unit_ring_column(const VortexLatticeModel& m, VortexLatticeData& d, int j) {
  LeadingEdgeSheet& s = d.le_sheet;
  const std::size_t base = static_cast<std::size_t>(s.rows) * (m.spanwise + 1);
  const Eigen::Vector3d r0 = s.nodes.position(base + j), r1 = s.nodes.position(base + j + 1);
  const Eigen::Vector3d a0 = d.ring_nodes.col(m.node(0, j)), a1 = d.ring_nodes.col(m.node(0, j + 1));
  // The sheet's core for the sum; the bound segment's by its core ratio (biot_savart.hpp).
  const VortexCore sheet = m.sheet_core();
  const double bound_ratio = sheet.radius / m.bound_core().radius;
  SegmentSet& ring = s.unit_ring;
  ring.clear();
  ring.push(r1, r0, 1.0);
  ring.push(r0, a0, 1.0);
  ring.push(a1, r1, 1.0);
  ring.push(a0.x(), a0.y(), a0.z(), a1.x(), a1.y(), a1.z(), 1.0, bound_ratio * bound_ratio);
  unit_ring_at_collocation(m, d, sheet);
  for (int k = 0; k < m.panels(); ++k) s.columns(k, j) = s.at_collocation.velocity(k).dot(d.normal.col(k));
}

}  // namespace

void add_leading_edge_ring_to_rhs(const VortexLatticeModel& m, VortexLatticeData& d) {
  LeadingEdgeSheet& s = d.le_sheet;
  // A strip at a time (its ring's part subtracted before the next strip's): summed as one
  // set the rounding differs, and Ramesh et al.'s plunging SD7003 then starts shedding one
  // step later in its second cycle (test uvlm.LeadingEdgeShedding.PlungingSd7003*).
  for (int j = 0; j < m.spanwise; ++j) {
    if (s.accepted(j) == 0.0) continue;
    s.unit_ring.clear();
    s.unit_ring.push(d.ring_nodes.col(m.node(0, j)), d.ring_nodes.col(m.node(0, j + 1)), s.accepted(j));
    unit_ring_at_collocation(m, d, m.bound_core());
    for (int k = 0; k < m.panels(); ++k) d.rhs(k) -= s.at_collocation.velocity(k).dot(d.normal.col(k));
  }
}

bool shed_leading_edge_vorticity(const VortexLatticeModel& m, VortexLatticeData& d) {
  LeadingEdgeSheet& s = d.le_sheet;
  const int ns = m.spanwise;
  s.current = s.accepted;
  std::fill(s.shedding.begin(), s.shedding.end(), 0);
  Eigen::VectorXd& target = s.border_rhs;
  Eigen::VectorXd& signed_target = s.target;  // ±Γ_crit of each shedding strip
  signed_target.setZero();
  const bool exceeded = update_lesp(m, d, signed_target);
  s.lesp_unshed = s.lesp;
  if (!exceeded) return false;
  s.gamma0 = d.gamma;
  s.columns.setZero();
  for (int pass = 0;; ++pass) {
    for (int j = 0; j < ns; ++j)
      if (s.shedding[j]) unit_ring_column(m, d, j);
    s.response = d.lu.solve(s.columns);
    s.border.setIdentity();
    for (int j = 0; j < ns; ++j) {
      target(j) = 0.0;
      if (!s.shedding[j]) continue;
      for (int k = 0; k < ns; ++k)
        if (s.shedding[k]) s.border(j, k) += s.response(m.panel(0, j), k);
      target(j) = s.gamma0(m.panel(0, j)) - s.accepted(j) - signed_target(j);
    }
    s.border_lu.compute(s.border);
    s.increment = s.border_lu.solve(target);
    d.gamma = s.gamma0;
    d.gamma.noalias() -= s.response * s.increment;
    s.current = s.accepted + s.increment;
    if (pass >= 2 * ns) {  // no consistent set found (not met in the tests): keep the last solve
      update_lesp(m, d, signed_target);
      break;
    }
    // A strip sheds only vorticity of the sign of its LESP (the increment that lowers |Γ_1|
    // to Γ_crit); one that would have to shed the opposite sign to stay at ±LESP_crit once
    // its neighbours shed does not shed (its LESP is then inside the band), and the system
    // is solved again without it.
    bool dropped = false;
    for (int j = 0; j < ns; ++j)
      if (s.shedding[j] && !(s.increment(j) * signed_target(j) > 0.0)) {
        s.shedding[j] = 0;
        signed_target(j) = 0.0;
        dropped = true;
      }
    if (dropped) continue;
    if (!update_lesp(m, d, signed_target)) break;
  }
  for (int j = 0; j < ns; ++j)
    if (s.shedding[j]) return true;
  return false;
}

}  // namespace flapsim::uvlm::detail
