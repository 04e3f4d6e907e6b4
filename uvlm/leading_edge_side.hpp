#pragma once
/// \file leading_edge_side.hpp
/// \brief Which side of a strip the separated leading-edge force (LeadingEdge::Separated,
/// Polhamus' suction analogy) pushes toward: the side its leading-edge bound vortex lifts
/// toward, the sign of the first ring's circulation Γ(0, j) — unless the side is held.
///
/// The force is the suction's magnitude |S_j| along ±n, and |S_j|, the in-plane sum over
/// the whole strip, need not vanish where Γ(0, j) changes sign: the force jumps by 2|S_j|
/// there. A coupled step (pipeline/fsi/coupled_step.cpp) whose iterates put Γ(0, j) on
/// either side in turn then has no fixed point; after many sub-iterations it holds each
/// strip's side as the last solve had it for the rest of the step (hold_leading_edge_sides),
/// and the next accepted step frees it again (advance). A step that converges without it
/// never holds a side: its answer is the same with or without the rule.

#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm {

/// +1 or −1: the side of strip j's separated leading-edge force (file comment).
inline double leading_edge_side(const VortexLatticeModel& m, const VortexLatticeData& d, int j) {
  if (d.held_edge_side.size() == m.spanwise && d.held_edge_side(j) != 0) return d.held_edge_side(j);
  return d.gamma(m.panel(0, j)) >= 0.0 ? 1.0 : -1.0;
}

/// Holds every strip's side as the last solve has it, until the next advance.
inline void hold_leading_edge_sides(const VortexLatticeModel& m, VortexLatticeData& d) {
  d.held_edge_side.resize(m.spanwise);
  for (int j = 0; j < m.spanwise; ++j) d.held_edge_side(j) = d.gamma(m.panel(0, j)) >= 0.0 ? 1 : -1;
}

/// Frees the sides (each follows its strip's circulation again).
inline void release_leading_edge_sides(VortexLatticeData& d) { d.held_edge_side.setZero(); }

}  // namespace flapsim::uvlm
