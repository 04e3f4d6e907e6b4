#pragma once
/// \file segment_tree.hpp
/// \brief A Barnes–Hut tree code for the velocity induced by many vortex segments:
/// O(M log N) for M target points and N segments instead of the direct sum's O(M N).
///
/// The segments are sorted along a Morton (Z-order) curve of their midpoints and grouped
/// in an octree whose leaves hold at most kLeafSegments segments. Each node keeps the
/// Cartesian multipole moments of its segments' vorticity up to order p about its centre
/// c (exact for straight segments: Gauss–Legendre along each segment),
///     Q_n = Σ_k Γ_k (B_k − A_k) ∫₀¹ (y_k(s) − c)^n ds,   |n| ≤ p,
/// and the velocity of a node at a target x, R = x − c, is the Taylor expansion of the
/// Biot–Savart law v(x) = (1/4π) ∫ ∇φ(x − y) × ω(y) dy, φ = 1/|r|:
///     v(x) = (1/4π) Σ_{|n|≤p} ∇∂ⁿφ(R) × (−1)^|n| Q_n / n!,
/// with the derivatives ∂ⁿ(1/r) from their recurrence
///     |n| r² ∂ⁿφ + (2|n| − 1) Σ_i n_i R_i ∂^(n−e_i)φ + (|n| − 1) Σ_i n_i (n_i − 1) ∂^(n−2e_i)φ = 0.
/// A node is used as a whole when the target is far enough away (multipole acceptance):
/// |R| θ > b (b the node's radius: farthest segment end from c) and |R| − b larger than
/// the distance beyond which the vortex core no longer matters (the expansion is of the
/// singular kernel); otherwise its children are visited, and a leaf's segments are summed
/// directly with the dispatched Biot–Savart kernel (biot_savart_lanes.hpp).
///
/// Accuracy: `tree_parameters(tolerance)` chooses p and θ for a relative error of the
/// induced velocities, ‖v_tree − v_direct‖₂ / ‖v_direct‖₂ over the targets, below the
/// tolerance (the table and how it was measured: docs/uvlm.md, "Tree code"); the direct
/// sum (biot_savart.hpp) is the reference (tests/uvlm/test_segment_tree.cpp).
///
/// Storage is reserved once (`reserve`); `build` and `add_induced_velocity` do not
/// allocate. The result does not depend on the thread count or on the kernel variant.

#include "uvlm/biot_savart.hpp"
#include "uvlm/vortex_core.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace flapsim::uvlm {

/// Expansion order p (0..4) and opening angle θ of the tree code.
struct TreeParameters {
  int order = 3;
  double theta = 0.5;
  double tolerance = 1e-4;  ///< the relative error asked for (sets the core distance)
};

/// p and θ for a relative error of the induced velocities below `tolerance` (> 0).
TreeParameters tree_parameters(double tolerance);

class SegmentTree {
 public:
  static constexpr int kLeafSegments = 64;  ///< most segments in a leaf

  /// Allocate for up to `segments` segments.
  void reserve(std::size_t segments);

  /// Sort `segments` into the tree and compute the node moments.
  /// \param core  the core the segments are summed with (its radius and model; each
  ///              segment's own core through SegmentSet::core_ratio2)
  /// \throws std::length_error beyond the reserved size
  void build(const SegmentSet& segments, const VortexCore& core, const TreeParameters& parameters);

  /// Add the velocity induced by the segments at n points (x, y, z) [m] to (u, v, w) [m/s].
  /// Parallel over points (OpenMP).
  void add_induced_velocity(const double* x, const double* y, const double* z, std::size_t n,
                            double* u, double* v, double* w) const;

  std::size_t nodes() const { return node_count_; }
  /// Node–target multipole evaluations and direct point–segment interactions of the last
  /// add_induced_velocity (for benchmarks).
  std::size_t last_multipole_evaluations() const { return last_multipoles_; }
  std::size_t last_direct_interactions() const { return last_direct_; }

 private:
  struct Node {
    double cx, cy, cz;     ///< centre [m]
    double radius;         ///< farthest segment end from the centre [m]
    double safe_distance;  ///< |R| − radius beyond which the cores do not matter [m]
    std::uint32_t first_child, child_count;  ///< children (consecutive nodes); 0 for a leaf
    std::uint32_t begin, count;              ///< a leaf's block in the padded arrays
    std::uint32_t seg_begin, seg_end;        ///< the node's segments in sorted order
  };
  void compute_moments(std::size_t node);
  void multipole_velocity(const Node& node, const double* moments, double x, double y, double z,
                          double& u, double& v, double& w) const;

  TreeParameters params_;
  VortexCore core_;
  int terms_ = 0;  ///< multi-indices |n| ≤ p
  std::size_t size_ = 0, node_count_ = 0;
  std::vector<std::uint64_t> keys_;          // Morton key << 20 | ... (sorted pairs)
  std::vector<std::uint32_t> order_;         // sorted position → segment index
  std::vector<double> sx_, sy_, sz_, tx_, ty_, tz_, sg_, srat_;  // segments in sorted order
  std::vector<double> pax_, pay_, paz_, pbx_, pby_, pbz_, pg_, pil_, prat_;  // leaves, padded
  std::vector<Node> nodes_;
  std::vector<double> moments_;  // 3 × terms_ per node, scaled by (−1)^|n|/(n! 4π)
  std::vector<std::uint32_t> stack_;  // build stack
  mutable std::size_t last_multipoles_ = 0, last_direct_ = 0;
};

}  // namespace flapsim::uvlm
