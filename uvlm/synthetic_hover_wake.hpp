#pragma once
/// \file synthetic_hover_wake.hpp
/// \brief A hover-like wake of any number of cycles without simulating it, for the tree
/// code's test (tests/uvlm/test_segment_tree.cpp) and benchmark (bench/bench_wake_tree.cpp):
/// a 10-panel span of wake rows, 100 per cycle, swept back and forth at 26.1 Hz through
/// ±60° about the z axis like the hawkmoth's wing (root 5 mm, tip 48.3 mm), sinking at
/// 0.5 m/s with a small waviness, with the circulation of a flapping wing (sin of the span
/// position × sin of the stroke) and Lamb–Oseen cores 0.2 × 16.9 mm grown with age
/// (core_growth.hpp, default constants). Segments in the order of uvlm/wake.cpp:
/// spanwise per node row, then streamwise per ring row. Synthetic, not a computed wake.

#include "uvlm/biot_savart.hpp"
#include "uvlm/lattice_segments.hpp"
#include "uvlm/vortex_core.hpp"

namespace flapsim::uvlm {

struct SyntheticHoverWake {
  SegmentSet segments;
  PointSet nodes;  ///< the wake's nodes (targets of its self-induced velocity)
  /// The same segments as a lattice (rows × 11 nodes; lattice_segments.hpp), finished in
  /// double and single precision.
  LatticeSegments lattice;
  VortexCore core{CoreModel::LambOseen, 0.2 * 0.0169};
  explicit SyntheticHoverWake(int cycles);
};

}  // namespace flapsim::uvlm
