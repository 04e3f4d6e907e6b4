/// \file leading_edge_sheet.cpp
/// \brief The leading-edge vortex sheet (leading_edge_sheet.hpp): storage, the release row,
/// its segments, and its convection and release at the end of a step.

#include "uvlm/leading_edge_sheet.hpp"

#include "uvlm/lattice_internal.hpp"
#include "uvlm/old_wake_hold.hpp"
#include "uvlm/vortex_lattice.hpp"
#include "uvlm/wake_age.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

void LeadingEdgeSheet::allocate(int ns, int np, int rings) {
  capacity = rings;
  rows = 0;
  const std::size_t n1 = static_cast<std::size_t>(ns) + 1;
  const std::size_t node_rows = static_cast<std::size_t>(rings) + 1;
  nodes.reserve(node_rows * n1);
  gamma.assign(static_cast<std::size_t>(rings) * ns, 0.0);
  prev_u.assign(node_rows * n1, 0.0);
  prev_v.assign(node_rows * n1, 0.0);
  prev_w.assign(node_rows * n1, 0.0);
  row_has_prev.assign(node_rows, 0);
  row_age.assign(node_rows, 0.0);
  ring_rows.assign(static_cast<std::size_t>(rings), 1);
  merge_progress.assign(static_cast<std::size_t>(rings), 0);
  merge_pair.assign(static_cast<std::size_t>(rings) + 1, 0);
  current.setZero(ns);
  accepted.setZero(ns);
  lesp.setZero(ns);
  lesp_unshed.setZero(ns);
  critical_gamma.setZero(ns);
  shedding.assign(static_cast<std::size_t>(ns), 0);
  resolved.assign(static_cast<std::size_t>(ns), 1);
  edge_speed.setZero(ns);
  strip_chord.setZero(ns);
  columns.setZero(np, ns);
  response.setZero(np, ns);
  border.setZero(ns, ns);
  border_rhs.setZero(ns);
  increment.setZero(ns);
  target.setZero(ns);
  gamma0.setZero(np);
  border_lu = Eigen::PartialPivLU<Eigen::MatrixXd>(ns);
  unit_ring.reserve(4);
  at_collocation.reserve(static_cast<std::size_t>(np));
}

namespace detail {

void place_release_row(const VortexLatticeModel& m, VortexLatticeData& d) {
  LeadingEdgeSheet& s = d.le_sheet;
  const int ns = m.spanwise;
  // The edge's velocity below: the trailing-edge wake's only.
  d.wake_segments.truncate(d.trailing_wake_segments);
  d.wake_edge_segments.truncate(d.trailing_wake_edge_segments);
  d.young_wake_segments.truncate(d.trailing_young_wake_segments);
  for (int j = 0; j <= ns; ++j) d.eval.set(j, d.nodes.col(m.node(0, j)));
  induced_at_eval_points(m, d, ns + 1, false);
  const std::size_t base = static_cast<std::size_t>(s.rows) * (ns + 1);
  for (int j = 0; j <= ns; ++j) {
    const Eigen::Vector3d w = d.free_stream - d.node_velocities.col(m.node(0, j)) + d.eval.velocity(j);
    s.nodes.set(base + j, d.nodes.col(m.node(0, j)) + 0.5 * d.dt * w);
  }
  s.nodes.size = base + ns + 1;
  s.row_age[s.rows] = 0.0;
}

void build_sheet_segments(const VortexLatticeModel& m, VortexLatticeData& d, WakeView view) {
  LeadingEdgeSheet& s = d.le_sheet;
  const int ns = m.spanwise, L = s.rows;
  const std::size_t n1 = static_cast<std::size_t>(ns) + 1;
  // After the trailing-edge wake's segments, in its precision. Seen from the wing in single
  // precision, those at the kSheetEdgeRows node rows nearest the edge go to the
  // double-precision set (the spanwise ones along them, the legs to them and the
  // leading-edge ring's legs ending on the first bound vortex). The rows older than the
  // far-wake age stay here too, not in the far wake's tree (model.far_wake_by_tree): the
  // release row's placement sums that tree but none of the sheet (place_release_row).
  d.wake_segments.truncate(d.trailing_wake_segments);
  d.wake_edge_segments.truncate(d.trailing_wake_edge_segments);
  d.young_wake_segments.truncate(d.trailing_young_wake_segments);
  const bool wing_single = view == WakeView::Wing && m.single_precision_wake;
  SegmentSet& near_edge = wing_single ? d.wake_edge_segments : d.wake_segments;
  // The rest: with the older wake kept apart (old_wake_hold.hpp), a segment with a node at
  // most model.young_wake_rows steps old goes to the young rows (summed at every solve),
  // the others to the older wake's (held within a step), as the wake's own rows.
  const bool apart = wing_single && old_wake_kept_apart(m, d);
  const double young_age = (m.young_wake_rows + 0.5) * d.dt;  // [s]
  auto fixed_set = [&](double youngest_age) -> SegmentSet& {
    return apart && youngest_age <= young_age ? d.young_wake_segments : d.wake_segments;
  };
  // Ring r ≤ L (ring L: the leading-edge ring, to the first bound vortex = node row L+1).
  auto G = [&](int r, int j) {
    if (r < 0 || r > L || j < 0 || j >= ns) return 0.0;
    return r == L ? s.current(j) : s.gamma[static_cast<std::size_t>(r) * ns + j];
  };
  auto node = [&](int q, int j) -> Eigen::Vector3d {
    return q <= L ? s.nodes.position(static_cast<std::size_t>(q) * n1 + j) : Eigen::Vector3d(d.ring_nodes.col(m.node(0, j)));
  };
  auto age = [&](int q) { return q <= L ? s.row_age[q] : 0.0; };
  // Each segment's core relative to the wake's, which the sums' kernel takes (biot_savart.hpp):
  // the sheet's own core (model.sheet_core()), grown with age.
  const double rc0_2 = m.core.radius * m.core.radius, sheet_rc0 = m.sheet_core().radius;
  const double floor2 = view == WakeView::Wing ? m.near_wing_core * m.near_wing_core : 0.0;
  auto ratio = [&](double g, double a) {
    double rc2 = grown_core_radius2(m.core_growth, sheet_rc0, a, g);
    if (a > m.near_wing_min_age) rc2 = std::max(rc2, floor2);
    return rc0_2 / rc2;
  };
  auto push = [&](SegmentSet& to, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double g, double a_age) {
    if (g != 0.0) to.push(a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), g, ratio(g, a_age));
  };
  // Spanwise, node rows 0 … L, direction j → j+1: rear of ring q−1 minus front of ring q.
  // (Row L+1, on the first bound vortex, is part of the bound segment there.)
  const int edge_row = L + 1 - kSheetEdgeRows;  // the first of the node rows near the edge
  for (int q = 0; q <= L; ++q)
    for (int j = 0; j < ns; ++j)
      push(q >= edge_row ? near_edge : fixed_set(age(q)), node(q, j), node(q, j + 1), G(q - 1, j) - G(q, j),
           age(q));
  // Legs of ring r, column j, from node row r to r+1: root side of (r, j) minus tip side of (r, j−1).
  for (int r = 0; r <= L; ++r)
    for (int j = 0; j <= ns; ++j)
      push(r >= edge_row - 1 ? near_edge : fixed_set(age(r + 1)), node(r, j), node(r + 1, j),
           G(r, j) - G(r, j - 1), 0.5 * (age(r) + age(r + 1)));
}

void sheet_node_velocities(const VortexLatticeModel& m, VortexLatticeData& d, bool by_tree) {
  LeadingEdgeSheet& s = d.le_sheet;
  PointSet& P = s.nodes;
  P.zero_velocity();
  if (m.wake_model != WakeModel::Free || P.size == 0) return;
  // Rows older than the far-wake age (the oldest rows, stored first) move with the far-wake
  // velocity, those older than the frozen wake's age not at all (move_and_release_sheet):
  // their induced velocity is not summed, as the wake's
  // (the same positions bit for bit; the flexible hover with the shipped chain 19.9 → 12.5
  // CPU s, docs/performance.md).
  std::size_t first = 0;
  const double old_age = m.far_wake_age > 0.0 ? m.far_wake_age : m.frozen_wake_age;  // frozen: they do not move
  if (old_age > 0.0) {
    int r = 0;
    while (r < s.rows && reached_age(s.row_age[r], old_age)) ++r;
    first = static_cast<std::size_t>(r) * (m.spanwise + 1);
  }
  if (first >= P.size) return;
  const std::size_t n = P.size - first;
  double *x = P.x.data() + first, *y = P.y.data() + first, *z = P.z.data() + first, *u = P.u.data() + first,
         *v = P.v.data() + first, *w = P.w.data() + first;
  add_far_wake_velocity(d, x, y, z, n, u, v, w);
  // The wake and the sheet, one set (advance built it, and the tree over it when by_tree).
  if (by_tree) d.wake_tree.add_induced_velocity(x, y, z, n, u, v, w);
  const VortexCore bound_seen_from_wake{m.core.model, std::max(m.core.radius, m.near_wing_core)};
  const std::size_t segments =
      (by_tree ? 0 : d.wake_segments.size()) + d.bound_segments.size() + d.trailing_edge_segments.size();
  for_target_chunks(n, n * segments, [&](std::size_t i0, std::size_t c) {
    const double *xi = x + i0, *yi = y + i0, *zi = z + i0;
    double *ui = u + i0, *vi = v + i0, *wi = w + i0;
    if (!by_tree) add_free_vortex_velocity(m, d, xi, yi, zi, c, ui, vi, wi);
    add_induced_velocity(d.bound_segments, xi, yi, zi, c, ui, vi, wi, bound_seen_from_wake);
    add_induced_velocity(d.trailing_edge_segments, xi, yi, zi, c, ui, vi, wi, m.core);
  });
}

namespace {

/// Where p lies against the wing along node column j: true with its height η above the
/// surface [m] (along the panel normal n) when its foot falls within the chord, on the
/// panel (i, j) (or (i, j−1) at the tip column) whose chordwise side it projects onto.
bool height_over_wing(const VortexLatticeModel& m, const VortexLatticeData& d, const Eigen::Vector3d& p, int j,
                      double& eta, Eigen::Vector3d& n) {
  const int strip = std::min(j, m.spanwise - 1);
  for (int i = 0; i < m.chordwise; ++i) {
    const Eigen::Vector3d a = d.nodes.col(m.node(i, j)), u = d.nodes.col(m.node(i + 1, j)) - a;
    const double t = (p - a).dot(u) / u.squaredNorm();
    if (t < 0.0 || t >= 1.0) continue;
    n = d.normal.col(m.panel(i, strip));
    eta = (p - a - t * u).dot(n);
    return true;
  }
  return false;
}

}  // namespace

void move_and_release_sheet(const VortexLatticeModel& m, VortexLatticeData& d, const Eigen::Vector3d& far_velocity) {
  LeadingEdgeSheet& s = d.le_sheet;
  const int ns = m.spanwise;
  const std::size_t n1 = static_cast<std::size_t>(ns) + 1;
  bool release = false;
  for (int j = 0; j < ns; ++j) release = release || s.current(j) != s.accepted(j);
  // Rows 0 … rows−1 are free; the release row moves only when it leaves.
  const int moving = s.rows + (release ? 1 : 0);
  const double dt = d.dt;
  const Eigen::Vector3d& V = d.free_stream;
  const double far_age = m.far_wake_age;
  PointSet& P = s.nodes;
  for (int r = 0; r < moving; ++r) {
    const bool far = far_age > 0.0 && reached_age(s.row_age[r], far_age);
    // Rows older than the frozen wake's age stay where they are, as the wake's (wake.cpp).
    if (m.frozen_wake_age > 0.0 && reached_age(s.row_age[r], m.frozen_wake_age)) {
      s.row_age[r] += dt;
      continue;
    }
    const bool ab2 = !far && m.wake_integrator == WakeIntegrator::AdamsBashforth2 && s.row_has_prev[r];
    for (std::size_t j = 0; j < n1; ++j) {
      const std::size_t k = static_cast<std::size_t>(r) * n1 + j;
      double eta0 = 0.0;
      Eigen::Vector3d normal;
      const bool over = !far && height_over_wing(m, d, P.position(k), static_cast<int>(j), eta0, normal);
      const Eigen::Vector3d vel = far ? far_velocity : Eigen::Vector3d(P.u[k] + V.x(), P.v[k] + V.y(), P.w[k] + V.z());
      if (ab2) {
        P.x[k] += dt * (1.5 * vel.x() - 0.5 * s.prev_u[k]);
        P.y[k] += dt * (1.5 * vel.y() - 0.5 * s.prev_v[k]);
        P.z[k] += dt * (1.5 * vel.z() - 0.5 * s.prev_w[k]);
      } else {
        P.x[k] += dt * vel.x();
        P.y[k] += dt * vel.y();
        P.z[k] += dt * vel.z();
      }
      s.prev_u[k] = vel.x();
      s.prev_v[k] = vel.y();
      s.prev_w[k] = vel.z();
      // A free vortex does not pass through the wing: a node that crossed the surface
      // within the chord in this step is put back on its side, mirrored.
      double eta1 = 0.0;
      Eigen::Vector3d normal1;
      if (over && height_over_wing(m, d, P.position(k), static_cast<int>(j), eta1, normal1) && eta0 * eta1 < 0.0) {
        P.x[k] -= 2.0 * eta1 * normal1.x();
        P.y[k] -= 2.0 * eta1 * normal1.y();
        P.z[k] -= 2.0 * eta1 * normal1.z();
      }
    }
    s.row_has_prev[r] = 1;
    s.row_age[r] += dt;
  }
  if (release) {
    if (s.rows + 1 > s.capacity)
      throw std::length_error("vortex lattice: leading-edge sheet exceeds its capacity of " +
                              std::to_string(s.capacity) + " rows");
    for (int j = 0; j < ns; ++j) s.gamma[static_cast<std::size_t>(s.rows) * ns + j] = s.current(j);
    s.ring_rows[static_cast<std::size_t>(s.rows)] = 1;
    s.merge_progress[static_cast<std::size_t>(s.rows)] = 0;
    ++s.rows;
    s.row_has_prev[s.rows] = 0;
    s.row_age[s.rows] = 0.0;
    const std::size_t from = static_cast<std::size_t>(s.rows - 1) * n1, to = from + n1;
    for (std::size_t j = 0; j < n1; ++j) s.nodes.set(to + j, P.position(from + j));  // placed again at the next solve
    P.size = to + n1;
  }
  s.accepted = s.current;
  if (release && m.sheet_merge_steps > 0) merge_older_sheet_rings(m, d);
}

namespace {

/// Node row q of the sheet goes (q > 0, q < rows): the rings above it and node rows q+1 …
/// rows move down by one; ring q−1 then spans node rows q−1 and q (the old q+1).
void remove_sheet_node_row(LeadingEdgeSheet& s, int ns, int q) {
  const std::size_t n1 = static_cast<std::size_t>(ns) + 1;
  PointSet& P = s.nodes;
  for (int r = q + 1; r < s.rows; ++r) {
    s.ring_rows[static_cast<std::size_t>(r) - 1] = s.ring_rows[static_cast<std::size_t>(r)];
    s.merge_progress[static_cast<std::size_t>(r) - 1] = s.merge_progress[static_cast<std::size_t>(r)];
    for (int j = 0; j < ns; ++j)
      s.gamma[static_cast<std::size_t>(r - 1) * ns + j] = s.gamma[static_cast<std::size_t>(r) * ns + j];
  }
  for (int r = q + 1; r <= s.rows; ++r) {
    const std::size_t from = static_cast<std::size_t>(r) * n1, to = from - n1;
    for (std::size_t j = 0; j < n1; ++j) {
      P.set(to + j, P.position(from + j));
      P.u[to + j] = P.u[from + j];
      P.v[to + j] = P.v[from + j];
      P.w[to + j] = P.w[from + j];
      s.prev_u[to + j] = s.prev_u[from + j];
      s.prev_v[to + j] = s.prev_v[from + j];
      s.prev_w[to + j] = s.prev_w[from + j];
    }
    s.row_has_prev[static_cast<std::size_t>(r) - 1] = s.row_has_prev[static_cast<std::size_t>(r)];
    s.row_age[static_cast<std::size_t>(r) - 1] = s.row_age[static_cast<std::size_t>(r)];
  }
  --s.rows;
  P.size -= n1;
}

}  // namespace

int merge_older_sheet_rings(const VortexLatticeModel& m, VortexLatticeData& d) {
  LeadingEdgeSheet& s = d.le_sheet;
  const int ns = m.spanwise;
  const std::size_t n1 = static_cast<std::size_t>(ns) + 1;
  PointSet& P = s.nodes;
  const double steps_age = m.sheet_merge_steps * d.dt;  // [s]
  const int blend_steps = std::max(1, m.sheet_merge_spread_steps);
  auto length = [&](int q0, int q1, int j) {  // ring's length along strip j, node rows q0 → q1 [m]
    const std::size_t a = static_cast<std::size_t>(q0) * n1 + j, b = static_cast<std::size_t>(q1) * n1 + j;
    return 0.5 * ((P.position(b) - P.position(a)).norm() + (P.position(b + 1) - P.position(a + 1)).norm());
  };
  // Rings 0 … rows−1, oldest first; ring r spans node rows r and r+1 (row `rows`: release).
  // pair[r]: ring r merges with ring r + 1 in this call's pass. A pair under way goes on; a
  // new pair is taken from the newest back among rings in no pair, of equal rows w (2w ≤
  // kSheetMergeMaxRows), once the newer is M·w steps old (its newer node row's age).
  std::vector<char>& pair = s.merge_pair;
  std::fill(pair.begin(), pair.begin() + s.rows, 0);
  auto taken = [&](int r) { return pair[r] || (r > 0 && pair[r - 1]); };
  for (int r = 0; r + 1 < s.rows; ++r)
    if (s.merge_progress[static_cast<std::size_t>(r)] > 0) pair[r] = 1;
  for (int r = s.rows - 2; r >= 0; --r) {
    const int w = s.ring_rows[static_cast<std::size_t>(r)];
    if (taken(r) || taken(r + 1) || w != s.ring_rows[static_cast<std::size_t>(r) + 1] ||
        2 * w > kSheetMergeMaxRows)
      continue;
    if (s.row_age[static_cast<std::size_t>(r) + 2] >= steps_age * w * (1.0 - 1e-9)) pair[r] = 1;
  }
  int merges = 0;
  // From the newest pair back: a merge moves only the rings and rows above it.
  for (int r = s.rows - 2; r >= 0; --r) {
    if (!pair[r]) continue;
    const int done = s.merge_progress[static_cast<std::size_t>(r)];
    const double f = 1.0 / (blend_steps - done);  // of what is left of the way; 1 at the last step
    for (int j = 0; j < ns; ++j) {
      const std::size_t a = static_cast<std::size_t>(r) * ns + j, b = a + ns;
      const double la = length(r, r + 1, j), lb = length(r + 1, r + 2, j);
      const double merged =
          la + lb > 0.0 ? (s.gamma[a] * la + s.gamma[b] * lb) / (la + lb) : 0.5 * (s.gamma[a] + s.gamma[b]);
      s.gamma[a] += f * (merged - s.gamma[a]);
      s.gamma[b] += f * (merged - s.gamma[b]);
    }
    if (done + 1 < blend_steps) {
      // The middle node row toward the chord between its neighbours, at its own fraction of
      // the way along them (at the last step it would lie on the merged ring's side: it goes).
      for (std::size_t j = 0; j < n1; ++j) {
        const std::size_t ia = static_cast<std::size_t>(r) * n1 + j, im = ia + n1, ic = im + n1;
        const Eigen::Vector3d pa = P.position(ia), pm = P.position(im), pc = P.position(ic);
        const double la = (pm - pa).norm(), lb = (pc - pm).norm();
        const double t = la + lb > 0.0 ? la / (la + lb) : 0.5;
        P.set(im, pm + f * (pa + t * (pc - pa) - pm));
      }
      s.merge_progress[static_cast<std::size_t>(r)] = done + 1;
      continue;
    }
    s.merge_progress[static_cast<std::size_t>(r)] = 0;
    s.ring_rows[static_cast<std::size_t>(r)] *= 2;
    remove_sheet_node_row(s, ns, r + 1);
    ++merges;
  }
  return merges;
}

}  // namespace detail

}  // namespace flapsim::uvlm
