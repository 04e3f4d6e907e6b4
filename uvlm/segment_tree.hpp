#pragma once
/// \file segment_tree.hpp
/// \brief A Barnes–Hut tree code for the velocity induced by many vortex segments:
/// O(M log N) for M target points and N segments instead of the direct sum's O(M N).
///
/// The segments' pieces (below) are sorted along a Morton (Z-order) curve of their
/// midpoints and grouped in an octree whose leaves hold at most kLeafSegments pieces. Each
/// node keeps the Cartesian multipole moments of its pieces' vorticity up to order p about its centre
/// c (exact for straight segments: Gauss–Legendre along each segment),
///     Q_n = Σ_k Γ_k (B_k − A_k) ∫₀¹ (y_k(s) − c)^n ds,   |n| ≤ p,
/// and the velocity of a node at a target x, R = x − c, is the Taylor expansion of the
/// Biot–Savart law v(x) = (1/4π) ∫ ∇φ(x − y) × ω(y) dy, φ = 1/|r|:
///     v(x) = (1/4π) Σ_{|n|≤p} ∇∂ⁿφ(R) × (−1)^|n| Q_n / n!,
/// with the derivatives ∂ⁿ(1/r) from their recurrence
///     |n| r² ∂ⁿφ + (2|n| − 1) Σ_i n_i R_i ∂^(n−e_i)φ + (|n| − 1) Σ_i n_i (n_i − 1) ∂^(n−2e_i)φ = 0.
/// Long segments are cut into straight pieces of at most a piece length ℓ first (below):
/// the tree holds the pieces, and its node radii are then set by the pieces' spread, not
/// by the segments' length (a free hover wake's segments are several centimetres long).
/// A node is used as a whole when the target is far enough away (multipole acceptance):
/// |R| θ > b (b the node's radius: farthest piece end from c) and |R| − b larger than
/// the distance s_k beyond which the vortex core of its segments no longer matters;
/// otherwise its children are visited, and a leaf's pieces are summed directly.
///
/// Pieces and cores. The tree sums the pieces with the singular kernel (the dispatched
/// kernel, biot_savart_lanes.hpp, with a cut-off core of 1e-6 r_c): for a straight
/// segment the singular velocity is exactly the sum of its pieces' singular velocities,
/// and each piece's multipole moments are those of a segment. The core factor f(h²/r_c,k²)
/// of the direct sum takes h as the distance to the *whole* segment (vortex_core.hpp), so
/// it is added as a correction per whole segment,
///     v_direct = Σ_pieces v_singular + Σ_{segments with h < s_k} (f − 1) v_singular,
/// the correction evaluated as v_core − v_singular of the whole segment with the same
/// kernel (f − 1 < tolerance/10 for h ≥ s_k: omitted). The segments with h < s_k at a
/// target are found while the tree is traversed: a piece within s_k of the target lies
/// in an opened leaf (the acceptance test above), and each such piece names its segment
/// (counted once per target).
///
/// Piece length ℓ (`TreeParameters::piece_length`, 0 = automatic): the smallest core's
/// distance s_0 = s(r_c) times kPieceLengthPerCoreDistance, the size of the near field
/// that the tree sums directly anyway (pieces much shorter than it add nodes, not
/// accuracy; measured in docs/performance.md), but at least total length / (capacity −
/// segments) so the pieces fit the reserved storage (kPiecesPerSegment per segment).
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
  double piece_length = 0.0;  ///< longest piece ℓ [m]; 0: automatic (segment_tree.hpp)
};

/// p and θ for a relative error of the induced velocities below `tolerance` (> 0).
TreeParameters tree_parameters(double tolerance);

class SegmentTree {
 public:
  static constexpr int kLeafSegments = 64;  ///< most pieces in a leaf
  /// A build (cut into pieces, sorted, the moments) takes about as long as this many direct
  /// double-precision pairs per segment: 20 ms for the 40 771 segments of the 20-cycle far
  /// wake of cases/hover_periodic.toml, 0.50 µs a segment against 2.66 ns a direct pair
  /// (bench_wake_tree, BM_PeriodicFarWake, 1 thread, FLAPSIM_KERNEL=avx2, 2-core AMD EPYC,
  /// 4 Dec 2026; 18.6–20.6 ms at tolerances 1e-3 … 1e-5).
  static constexpr double kBuildPairsPerSegment = 188.0;
  static constexpr int kPiecesPerSegment = 4;  ///< pieces reserved per segment (on average)
  static constexpr double kPieceLengthPerCoreDistance = 1.0;  ///< automatic ℓ / s_0

  /// Allocate for up to `segments` segments (and kPiecesPerSegment pieces per segment),
  /// and the scratch of omp_get_max_threads() threads (more threads are not used).
  void reserve(std::size_t segments);
  /// The bytes reserve(segments) allocates with `threads` threads' scratch (about 2.6 kB a
  /// segment on two threads): what a run's memory estimate counts for the tree code.
  static double reserved_bytes(std::size_t segments, int threads);

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
  std::size_t pieces() const { return pieces_; }
  double piece_length() const { return piece_length_; }  ///< ℓ of the last build [m]
  /// Node–target multipole evaluations, direct point–piece interactions (padding
  /// included) and point–segment core corrections of the last add_induced_velocity (for
  /// benchmarks).
  std::size_t last_multipole_evaluations() const { return last_multipoles_; }
  std::size_t last_direct_interactions() const { return last_direct_; }
  std::size_t last_core_corrections() const { return last_corrections_; }

 private:
  struct Node {
    double cx, cy, cz;     ///< centre [m]
    double radius;         ///< farthest piece end from the centre [m]
    double safe_distance;  ///< largest core distance s_k of its pieces' segments [m]
    std::uint32_t first_child, child_count;  ///< children (consecutive nodes); 0 for a leaf
    std::uint32_t begin, count;              ///< a leaf's block in the padded arrays
    std::uint32_t seg_begin, seg_end;        ///< the node's pieces in sorted order
  };
  /// One thread's storage for the core corrections of a target.
  struct NearScratch {
    std::vector<std::uint32_t> stamp;  ///< per segment: the last target that listed it
    std::vector<std::uint32_t> list;   ///< segments within their core distance
    std::vector<double> ax, ay, az, bx, by, bz, g, neg_g, il, cr, il_cut, one;  ///< packed
    std::uint32_t visit = 0;
  };
  std::size_t cut_pieces(const SegmentSet& segments, double core_distance);
  void build_nodes();
  void compute_moments(std::size_t node);
  void add_core_corrections(NearScratch& s, std::size_t count, double x, double y, double z,
                            double* su, double* sv, double* sw) const;

  TreeParameters params_;
  VortexCore core_;
  int terms_ = 0;  ///< multi-indices |n| ≤ p
  std::size_t size_ = 0, pieces_ = 0, node_count_ = 0;
  double piece_length_ = 0.0, inv_cut2_ = 0.0;  ///< ℓ [m]; 1/δ² of the singular kernel [1/m²]
  // The segments as given: ends [m], Γ [m²/s], (r_c/r_c,k)²/|B−A|² [1/m²], (r_c/r_c,k)².
  std::vector<double> wax_, way_, waz_, wbx_, wby_, wbz_, wg_, wil_, wrat_, wsafe2_;
  std::vector<std::uint64_t> keys_;   // Morton keys of the pieces, then sorted
  std::vector<std::uint32_t> order_;  // sorted position → piece
  std::vector<std::uint32_t> parent_, sparent_;  // piece → segment (unsorted, sorted)
  std::vector<double> qax_, qay_, qaz_, qbx_, qby_, qbz_;  // pieces, unsorted
  std::vector<double> sx_, sy_, sz_, tx_, ty_, tz_, sg_;  // pieces in sorted order
  // Leaves' pieces, padded to whole blocks of lanes: ends, Γ, 1/|B−A|², 1 (core ratio),
  // the segment and its core distance² (−1 for padding).
  std::vector<double> pax_, pay_, paz_, pbx_, pby_, pbz_, pg_, pil_, prat_, psafe2_;
  std::vector<std::uint32_t> ppar_;
  std::vector<Node> nodes_;
  std::vector<double> moments_;  // 3 × terms_ per node, scaled by (−1)^|n|/(n! 4π)
  std::vector<std::uint32_t> stack_;  // build stack
  mutable std::vector<NearScratch> scratch_;
  mutable std::size_t last_multipoles_ = 0, last_direct_ = 0, last_corrections_ = 0;
};

}  // namespace flapsim::uvlm
