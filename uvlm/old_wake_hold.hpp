#pragma once
/// \file old_wake_hold.hpp
/// \brief Holding the wing's sums over the older wake within a step.
///
/// Within a coupled step the wake stands still and the wing's points move only by what the
/// sub-iterations change, a change that shrinks by a factor of 30–50 a solve. The older
/// wake — its node rows more than model.young_wake_rows steps old — induces a smooth field
/// at the wing, and summing it anew at every solve is most of a large lattice's work
/// (docs/performance.md, "The older wake within a step"). A caller that may hold those sums
/// sets VortexLatticeData::old_wake_apart before the first solve: every solve then sums the
/// older rows apart from the younger ones (the newest in double precision as always) and
/// records their velocity at the collocation points and at the bound segments' midpoints
/// (old_wake_record.hpp). After hold_old_wake_sums the solves, until the next advance, take
/// the older rows' velocity from the last two records: the last one, moved along their
/// secant to the points' new places; the younger rows, the bound vortices and everything
/// else are summed anew. At the last recorded points the held value is the record's bits,
/// so a solve there gives the same answer held or not. The coupled step holds once two
/// solves are made and the last change is small, until a change grows, and then not again
/// in the step (pipeline/fsi/coupled_step.hpp, CouplingSettings::old_wake_hold_after,
/// old_wake_hold_change; docs/fsi.md).
///
/// A shed leading edge's sheet (leading_edge_sheet.hpp) is kept apart by age as the wake
/// is: its rows older than the young ones join the held sums, the younger ones are summed
/// anew with the young wake, and those at the edge (its release row, placed at every solve,
/// and the last step's) in double precision as always (build_sheet_segments). Only for the
/// single-precision wake: otherwise the wake is never kept apart and nothing is held
/// (old_wake_kept_apart).

#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm {

/// Whether the wing's sums over the wake keep the older rows apart: asked for by the caller
/// (d.old_wake_apart), with young rows to keep and the wake in single precision.
inline bool old_wake_kept_apart(const VortexLatticeModel& m, const VortexLatticeData& d) {
  return d.old_wake_apart && m.young_wake_rows > 0 && m.single_precision_wake;
}

/// The solves until the next advance take the older wake's velocity at the wing's points
/// from the records (file comment); nothing if the wake is not kept apart or nothing was
/// recorded since the last advance.
inline void hold_old_wake_sums(const VortexLatticeModel& m, VortexLatticeData& d) {
  d.old_wake_held = old_wake_kept_apart(m, d) && d.old_wake[0].size > 0;
}

/// The next solves sum the older wake anew (and record it); the records are kept.
inline void sum_old_wake_anew(VortexLatticeData& d) { d.old_wake_held = false; }

/// Frees the hold and forgets the records (advance: the wake has moved).
inline void release_old_wake_sums(VortexLatticeData& d) {
  d.old_wake_held = false;
  d.old_wake[0].clear();
  d.old_wake[1].clear();
}

}  // namespace flapsim::uvlm
