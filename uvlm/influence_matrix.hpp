#pragma once
/// \file influence_matrix.hpp
/// \brief Storage for building the influence matrix a(i, k) = v_k(x_i) · n_i (the normal
/// velocity at collocation point i of unit ring k) from the lattice's segments, each once.
///
/// A ring shares each side with a neighbour, so the lattice has about 2N distinct
/// segments for its N rings' 4N sides. For each collocation point the normal velocity of
/// every distinct unit segment, t_s = v_s(x_i) · n_i, is computed in one vectorised loop
/// (influence_lanes.hpp, in the kernel variant of kernel_dispatch.hpp); the ring's entry is
/// then, in the order of its traversal R(i,j+1) → R(i,j) → R(i+1,j) → R(i+1,j+1) → R(i,j+1),
///     a = −t_front + t_root + t_rear − t_tip,
/// the front and tip sides being their segments reversed. A reversed segment's velocity is
/// exactly the negated one (r1 and r2 swap: the cross product changes sign, every other
/// term is symmetric), so the matrix is bit for bit the ring-by-ring sum of the four
/// sides (the way it was built before, tests/uvlm/test_iterative_solve.cpp), at half the
/// segment evaluations and vectorised. Katz & Plotkin §12.3 (the vortex-ring influence).

#include <cstddef>
#include <vector>

namespace flapsim::uvlm {

struct InfluenceSegments {
  /// Room for a lattice of nc × ns rings and `threads` rows of segment terms.
  void reserve(int chordwise, int spanwise, int threads);

  // The distinct unit segments of the rings being built (first `size` entries) [m].
  std::vector<double> ax, ay, az, bx, by, bz;
  std::vector<double> scale;  ///< 1/(r_c² |B − A|²) with the segment's core [1/m⁴]
  std::size_t size = 0;
  /// The matrix columns being built (ring index i + nc j) and, for each, the segment index
  /// of its sides 0..3 (front, root, rear, tip in the traversal above).
  std::vector<int> column;
  std::vector<int> side[4];
  int columns = 0;
  /// Collocation points whose rows a thread computes together.
  static constexpr int kRowBlock = 8;
  /// Per thread, the segment terms t_s of kRowBlock rows, segment-major (the kRowBlock
  /// rows' terms of one segment next to each other: entry s·kRowBlock + r), row_stride()
  /// segments long: a column's kRowBlock entries are then read from one cache line per side.
  std::vector<double> scratch;
  std::size_t row_stride() const { return (capacity + 7) / 8 * 8; }
  std::size_t capacity = 0;
  int threads = 1;
};

}  // namespace flapsim::uvlm
