#pragma once
/// \file lattice_segments.hpp
/// \brief The vortex segments of a structured lattice — a wake's node grid of rows × cols
/// nodes, row-major (node a = row · cols + col) — and the velocity they induce, by the
/// lattice kernel: for each target point the vector to every NODE, its square and its
/// length are computed once and shared by the segments meeting at the node (one square
/// root per node, about half a square root per segment, where the segment kernel of
/// biot_savart.hpp needs two per segment). Each node a carries up to two segments, reached
/// by fixed index offsets (contiguous loads, no gathers):
///  - the spanwise segment a → a + 1 (along its row; none at a row's last node),
///  - the streamwise segment a + cols → a (from the next row; none on the last row).
/// Each pair (point, segment) is evaluated by exactly the arithmetic of the segment kernel
/// (biot_savart_kernel.hpp), so the lattice and the segment kernel differ only in the
/// order in which a point's terms are added; every instruction-set variant gives the same
/// bits (kernel_dispatch.hpp).

#include "uvlm/vortex_core.hpp"

#include <cstddef>
#include <vector>

namespace flapsim::uvlm {

class LatticeSegments {
 public:
  /// Allocate room for grids of up to `nodes` nodes with up to `cols` nodes per row
  /// (no allocation later while within these).
  void reserve(std::size_t nodes, std::size_t cols);
  /// Start a grid of rows × cols nodes with every segment's circulation 0.
  /// \throws std::length_error beyond the reserved room
  void assign_grid(std::size_t rows, std::size_t cols);
  /// Position of node a [m].
  void set_node(std::size_t a, double x, double y, double z);
  /// The spanwise segment a → a + 1: circulation [m²/s] and (r_c/r_c,k)² (as SegmentSet::push).
  /// \throws std::invalid_argument at a row's last node
  void set_spanwise(std::size_t a, double gamma, double core_ratio2 = 1.0);
  /// The streamwise segment a + cols → a. \throws std::invalid_argument on the last row
  void set_streamwise(std::size_t a, double gamma, double core_ratio2 = 1.0);
  /// After the nodes and segments are set: each segment's (r_c/r_c,k)²/|B − A|² and the
  /// single-precision copies (if `single`), which the velocity sums read.
  void finish(bool single);

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  std::size_t nodes() const { return rows_ * cols_; }
  /// Segments of the grid: rows (cols − 1) spanwise + (rows − 1) cols streamwise, set or not.
  std::size_t segments() const;

  /// Node indices that carry segments, rounded up to the kernel's lanes (zero circulation
  /// beyond); the node arrays hold span() + cols() + 17 entries (copies of the last node beyond).
  std::size_t span() const { return span_; }
  /// Arrays, in double (`Real` = double) or the single-precision copies (float): node
  /// positions x, y, z [m]; spanwise gamma, inv_length2, core_ratio2; streamwise the same
  /// (as SegmentSet's, biot_savart.hpp).
  enum Array { X, Y, Z, SpanGamma, SpanInvLength2, SpanCoreRatio2, StreamGamma,
               StreamInvLength2, StreamCoreRatio2, kArrays };
  const double* data(Array a) const { return double_[a].data(); }
  const float* single(Array a) const { return single_[a].data(); }

 private:
  std::vector<double> double_[kArrays];
  std::vector<float> single_[kArrays];
  std::size_t rows_ = 0, cols_ = 0, span_ = 0;
};

/// Add the velocity induced by every segment of `lattice` at the n points (x, y, z) [m] to
/// (u, v, w) [m/s]. Parallel over points (OpenMP) unless called inside a parallel region.
/// \param core  regularisation; core.radius > 0 [m]
void add_induced_velocity(const LatticeSegments& lattice, const double* x, const double* y,
                          const double* z, std::size_t n, double* u, double* v, double* w,
                          const VortexCore& core);

/// The same in single precision (reads the copies made by finish(true)); as
/// add_induced_velocity_single of biot_savart.hpp, for the free-wake convection.
void add_induced_velocity_single(const LatticeSegments& lattice, const double* x,
                                 const double* y, const double* z, std::size_t n, double* u,
                                 double* v, double* w, const VortexCore& core);

}  // namespace flapsim::uvlm
