#pragma once
/// \file leading_edge_sheet.hpp
/// \brief The vortex sheet a leading edge sheds when its suction exceeds what it can hold
/// (LeadingEdge::Shed; docs/uvlm.md, "Leading-edge vortex shedding").
///
/// The criterion is the leading-edge suction parameter of Ramesh, Gopalarathnam, Granlund,
/// Ol & Edwards 2014 (J. Fluid Mech. 751, 500–538): LESP = A0, the leading-edge
/// singularity of the bound vorticity γ(θ) = 2U [A0 (1 + cos θ)/sin θ + Σ An sin nθ],
/// x = c/2 (1 − cos θ). While |LESP| ≤ LESP_crit the leading edge holds its suction; beyond
/// it vorticity leaves the leading edge in just the amount that holds |LESP| at LESP_crit.
/// On a vortex lattice the LESP of a strip comes from its first bound vortex, Γ_1: the A0
/// term alone gives ∫_0^Δx γ dx = U c A0 (θ1 + sin θ1), θ1 = acos(1 − 2Δx/c), for the first
/// panel of chord Δx, and Hirato, Shen, Gopalarathnam & Edwards (J. Aircraft 2019, eq. 6;
/// 2021 for finite wings) take
///     LESP = 1.13 Γ_1 / (U c (θ1 + sin θ1)),
/// the factor 1.13 being the lattice's lumped first vortex against the integral (test
/// uvlm.LeadingEdgeShedding.SteadyStripLespIsTheThinAerofoilA0: a steady flat strip's LESP
/// is CL/(2π), thin-aerofoil theory's A0, within 0.8 % with 8 to 32 chordwise panels).
/// Here U is the speed of the strip's leading edge through the air in the plane normal to
/// the span (|V∞ − v_LE| without its spanwise part: U∞ for a plate in a stream that
/// pitches about its leading edge, ω r for a revolving wing) and c the strip's chord.
///
/// The sheet, per spanwise strip, like the trailing-edge wake (Katz & Plotkin §13.12):
///  - node rows 0 … rows−1 are free (convected with the local velocity, their cores grow
///    with age like the wake's); row `rows` is the release row R, placed at every solve at
///    R = x_LE + ½ Δt (V∞ − v_LE + v_wake), half of the step's path of the air past the
///    leading edge (Ramesh et al. 2014 place the first vortex of a shedding episode there,
///    the following ones a third of the way to the last one shed, which diverged here:
///    docs/uvlm.md, "What makes the hover's lift rough"; v_wake is the trailing-edge wake's
///    velocity at the edge);
///  - ring r < rows spans node rows r and r+1 with circulation gamma[r ns + j];
///  - the leading-edge ring of strip j spans from the release row to the lattice's first
///    bound vortex (ring-node row 0, a quarter panel behind the edge) with circulation
///    current(j). Its segment on the first bound vortex is part of that bound segment
///    (net circulation current(j) − Γ(0, j)), so the first bound vortex of the strip is
///    Γ_1 = Γ(0, j) − current(j): the LESP counts the vorticity the sheet left on the wing.
///    Unless the strip sheds, current = accepted (the sheet goes on as it was); a strip
///    that sheds gets the increment that puts |LESP| at LESP_crit, found with the
///    circulations in one linear solve (the bordered system through the influence
///    matrix's factorisation; which strips shed: the criterion's complementarity
///    conditions on all strips at once, leading_edge_shedding.cpp);
///  - advance: when any strip shed in the step, the release row leaves (it is convected
///    from where it was) and the leading-edge ring becomes sheet ring `rows` with its
///    circulation; a new release row is placed at the next solve.
/// A node of the sheet that crosses the wing's surface within the chord in a step is put
/// back on its side, mirrored: a free vortex does not pass through a solid surface
/// (without it the sheet of a plate pitched to 45° went under the plate and the shed
/// circulation ran away; docs/uvlm.md, "Leading-edge vortex shedding: measurements").
/// Merging the older rings (model.sheet_merge_steps = M > 0): the sheet gains a ring at
/// nearly every step, and its sums grow with their square. After each release, two
/// neighbouring rings of w rows each (w ≤ kSheetMergeMaxRows/2) merge into one of 2w rows
/// once the newer of them is M·w steps old: the node row between them goes, and strip j's
/// circulation becomes the length-weighted mean (Γ_a ℓ_a + Γ_b ℓ_b)/(ℓ_a + ℓ_b), ℓ the
/// rings' lengths along the strip. That conserves the strip's ∫Γ dℓ (the integral of its
/// streamwise vorticity) and hands the removed spanwise vortex to its two neighbours in
/// inverse proportion to their distances, which keeps its total and its centroid along the
/// sheet (the linear redistribution of vortex-method remeshing, Cottet & Koumoutsakos 2000,
/// "Vortex Methods", on remeshing). A merge may be spread over K releases
/// (model.sheet_merge_spread_steps; 1, at once, by default): at each the two rings'
/// circulations move toward that mean, and the node row between them toward the chord
/// joining its neighbours (at its own fraction of their length), each by 1/(K − k) of what
/// is left after k of them; at the K-th they are the mean and on the chord, and the row goes.
/// Each partial step keeps ∫Γ dℓ as the whole merge does. Done at once, a merge changes the
/// sheet's velocity at the wing within one step, and the wing's circulation answers with
/// ρ ∂Γ/∂t ∝ 1/Δt in its lift: a hover, whose sheet stays within a chord of the wing, has a
/// spike at merges (docs/uvlm.md, "Merging the sheet's older rings", with what spreading
/// them changes). Rings younger than M steps are never merged; a ring of w rows is at least
/// M·w/2 steps old, so a merged ring is about 1/M of the distance it has travelled long, and
/// the sheet holds about merged_sheet_rings(M, n, K) rings after n releases.
/// The sheet's segments are free vortices: no force acts on them. They induce velocity on
/// the wing (the boundary condition and the Bernoulli loads), on the trailing-edge wake
/// and on themselves, summed with the trailing-edge wake's segments as one set
/// (VortexLatticeData::wake_segments): in the precision asked for the wake, and by the
/// tree code when the wake is (not by the convected far wake's tree: the release row's
/// placement sums it, but no part of the sheet). Seen from the wing in single precision, the segments near
/// the edge stay in double (VortexLatticeData::wake_edge_segments, as the wake's newest
/// row; docs/uvlm.md, "Precision of the wake's sums"): those at the release row, which
/// moves with the wing within a step, and at the newest free row (kSheetEdgeRows), and the
/// leading-edge ring's legs to the first bound vortex.

#include "uvlm/biot_savart.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <vector>

namespace flapsim::uvlm {

/// Hirato et al.'s factor between the lattice's first bound vortex and the integral of
/// the A0 term over the first panel (J. Aircraft 2019, eq. 6).
inline constexpr double kLespLatticeFactor = 1.13;

/// A strip whose two node columns' chords differ by more than this factor holds an end of
/// the outline (a rounded root or tip, where the chord falls toward zero): its lattice does
/// not resolve a leading edge that faces the flow, so the 2-D criterion is not applied there
/// and the strip keeps the suction analogy of LeadingEdge::Separated (Polhamus 1966). A
/// rectangular or gently tapered strip (ratio ≥ 0.5) is resolved. Chosen on the geometry
/// (docs/uvlm.md, "Leading-edge vortex shedding: measurements"), not on a result.
inline constexpr double kResolvedStripChordRatio = 0.5;

/// Most segments the sheet of `rings` rings on ns strips holds (its rings and the
/// leading-edge ring: node rows 0 … rings spanwise, the legs of rings 0 … rings).
inline std::size_t sheet_segment_capacity(int ns, int rings) {
  return (static_cast<std::size_t>(rings) + 1) * (2 * static_cast<std::size_t>(ns) + 1);
}
/// The sheet's node rows nearest the leading edge whose segments the wing sees in double
/// precision when it sees the rest of the sheet (and the wake) in single: the release row,
/// which moves with the wing within a step, and the newest free row, the release row of the
/// last step (with the release row's alone, a delta wing's lift oscillated from step to
/// step: docs/uvlm.md, "Precision of the wake's sums").
inline constexpr int kSheetEdgeRows = 2;
/// Most segments at those rows: the spanwise ones along them, the legs to them from the
/// row before and the leading-edge ring's legs to the first bound vortex.
inline std::size_t sheet_edge_segment_capacity(int ns) {
  return kSheetEdgeRows * static_cast<std::size_t>(ns) + (kSheetEdgeRows + 1) * (static_cast<std::size_t>(ns) + 1);
}

/// Most original rows one merged ring of the sheet holds (model.sheet_merge_steps): a
/// ring much longer than the sheet's spiral turns would cut across them.
inline constexpr int kSheetMergeMaxRows = 16;

/// Rings of a sheet that has released a ring at each of `released` steps, merged from M =
/// merge_steps steps old (0: never, all of them), each merge spread over K = spread_steps
/// releases: the youngest M + K − 1 rings apart, about M/2 of each merged size up to
/// kSheetMergeMaxRows, then one ring of that size every kSheetMergeMaxRows steps:
/// min(n, M (1 + ½ log₂ kSheetMergeMaxRows) + K − 1 + max(0, n − 16 M − K + 1)/16).
/// For large n the rule's count lies up to 3.1 rings above it (4.5 at M = 1, K = 4); for n
/// up to ~16 M it may lie well below (the rule run to 1500 releases at M = 1 … 64, K = 1,
/// 4, M/2; test uvlm.LeadingEdgeSheetMerge.*). What the run's estimate counts.
inline double merged_sheet_rings(int merge_steps, double released, int spread_steps = 1) {
  if (merge_steps <= 0) return released;
  const double m = merge_steps, w = kSheetMergeMaxRows, k = std::max(1, spread_steps) - 1.0;
  return std::min(released, m * (1.0 + 0.5 * std::log2(w)) + k + std::max(0.0, released - w * m - k) / w);
}

/// Rings to store for a run of `steps` steps: a ring a step, merged or not. Merged, the
/// sheet holds about merged_sheet_rings (the run's time estimate) while its edge sheds at
/// every step; each pause in the shedding (a hover's reversal) leaves rings that no pair of
/// equal width takes (a ring of 4 and one of 1 between rings of 16), so the count may grow
/// past it by a few rings a pause (test LeadingEdgeSheetMerge.PausesInTheShedding…). Neither
/// wake_max_rows nor the far wake shortens the sheet.
inline int sheet_ring_capacity(double steps) { return static_cast<int>(steps + 1.0); }

struct LeadingEdgeSheet {
  int rows = 0;                      ///< stored rings; node rows 0 … rows (row `rows` = release row)
  int capacity = 0;                  ///< rings the storage holds
  PointSet nodes;                    ///< node (r, j) at r (ns+1) + j [m]
  std::vector<double> gamma;         ///< ring circulations [m²/s], ring r strip j at r ns + j
  std::vector<double> prev_u, prev_v, prev_w;  ///< node velocities of the last step (AB2) [m/s]
  std::vector<char> row_has_prev;
  std::vector<double> row_age;       ///< time since each node row left the leading edge [s]
  std::vector<int> ring_rows;        ///< rows released into each ring (1; more once merged)
  std::vector<int> merge_progress;   ///< steps of its merge with ring r + 1 done (0: none under way)
  std::vector<char> merge_pair;      ///< scratch of merge_older_sheet_rings: ring r pairs with r + 1
  Eigen::VectorXd current;           ///< leading-edge ring circulation of the last solve, per strip [m²/s]
  Eigen::VectorXd accepted;          ///< the same at the last accepted step [m²/s]
  Eigen::VectorXd lesp;              ///< LESP of each strip in the last solve
  Eigen::VectorXd lesp_unshed;       ///< the same before the solve's shedding (every ring as accepted)
  Eigen::VectorXd critical_gamma;    ///< |Γ_1| at LESP_crit per strip in the last solve [m²/s]
  std::vector<char> shedding;        ///< per strip: shed in the last solve
  std::vector<char> resolved;        ///< per strip: the criterion applies (kResolvedStripChordRatio)
  Eigen::VectorXd edge_speed;        ///< U of each strip's LESP in the last solve [m/s]
  Eigen::VectorXd strip_chord;       ///< c of each strip's LESP in the last solve [m]
  // Scratch of the bordered solve (allocated once).
  Eigen::MatrixXd columns;           ///< np × ns: normal velocity of each unit leading-edge ring
  Eigen::MatrixXd response;          ///< np × ns: A⁻¹ columns
  Eigen::MatrixXd border;            ///< ns × ns
  Eigen::VectorXd border_rhs, increment, gamma0, target;
  Eigen::PartialPivLU<Eigen::MatrixXd> border_lu;
  SegmentSet unit_ring;              ///< one leading-edge ring's four segments, or one strip's first bound one
  PointSet at_collocation;           ///< the collocation points, for unit_ring's velocity at all of them
  bool active() const { return capacity > 0; }
  /// Allocate for ns strips, np panels and `rings` sheet rings.
  void allocate(int ns, int np, int rings);
};

}  // namespace flapsim::uvlm
