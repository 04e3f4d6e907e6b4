#pragma once
/// \file clamped_wing_analysis.hpp
/// \brief The measurements the reduction makes on the root-clamped FEM: the
/// flexural-axis frame, the tip zone, and the static load cases (unit bending
/// moment, unit torque, tip forces at two chord positions, tip force on the axis),
/// solved with one CHOLMOD factorisation (docs/reduction.md).

#include <Eigen/Core>

#include <algorithm>
#include <memory>
#include <vector>

#include "fem/assembly.hpp"
#include "fem/constraints.hpp"
#include "fem/mesh.hpp"
#include "fem/static_solver.hpp"
#include "reduction/axis_frame.hpp"
#include "reduction/section_fit.hpp"
#include "reduction/strip_mass.hpp"
#include "reduction/tip_loads.hpp"

namespace flapsim::reduction {

/// How the flexural axis is chosen.
enum class AxisChoice {
  fitted,    ///< least-squares line through the pivot and the per-cell elastic-axis points
  flexural,  ///< least-squares line n = n₀ + s tan ψ through the stations' flexural axes
  span,      ///< y_W itself (ψ = 0)
  given,     ///< AnalysisOptions::psi
};

struct AnalysisOptions {
  AxisChoice axis = AxisChoice::fitted;
  double psi = 0.0;                   ///< axis angle for AxisChoice::given [rad]
  int axis_fit_cells = 20;            ///< cells of the first (ψ = 0) pass for the axis fit
  int flexural_axis_stations = 10;    ///< stations of the flexural-axis fit (AxisChoice::flexural)
  double tip_zone_fraction = 0.025;    ///< loaded tip zone, fraction of the span [-]
  double unit_moment = 1e-6;          ///< magnitude of the load cases [N m] (linear: any value)
  double unit_force = 1e-4;           ///< [N]
};

/// The static load cases, in the order of the columns of ClampedWingAnalysis::uz().
enum LoadCase : int {
  kBendingMoment = 0,  ///< moment about e_n
  kTorque = 1,         ///< moment about e_s
  kForceLeading = 2,   ///< force at n₁ (leading side of the tip zone)
  kForceTrailing = 3,  ///< force at n₂ (trailing side)
  kForceOnAxis = 4,    ///< force at n = 0
  kNumLoadCases = 5
};

/// \brief The root-clamped FEM seen from the flexural axis.
class ClampedWingAnalysis {
 public:
  /// \param mesh         FEM mesh (wing frame, pivot at the origin)
  /// \param system       assembled K and M
  /// \param constraints  the root clamp (at least one clamped node)
  /// \param options      axis choice, tip zone, load magnitudes
  /// \param factor       the factorised clamped stiffness, if the caller has it already
  ///                     (a fem::StaticSolver of system.stiffness and these constraints;
  ///                     used from one thread at a time); else the analysis factorises
  ClampedWingAnalysis(const fem::Mesh& mesh, const fem::AssembledSystem& system,
                      const fem::Constraints& constraints, const AnalysisOptions& options = {},
                      std::shared_ptr<const fem::StaticSolver> factor = nullptr);

  const AxisFrame& axis() const { return axis_; }
  const TipZone& tip_zone() const { return zone_; }
  double s_root() const { return s_root_; }  ///< outboard end of the clamp on the axis [m]
  double s_tip() const { return s_tip_; }    ///< largest s of the wing [m]
  const Eigen::VectorXd& s() const { return s_; }  ///< node span coordinates [m]
  const Eigen::VectorXd& n() const { return n_; }  ///< node chordwise coordinates [m]
  const Eigen::Matrix3Xd& nodes() const { return nodes_; }
  const std::vector<bool>& clamped() const { return clamped_; }
  /// Out-of-plane displacement of every node, one column per LoadCase [m].
  const Eigen::MatrixXd& uz() const { return uz_; }
  /// The wrench of each load case (about the tip zone's centroid).
  const std::vector<TipWrench>& wrenches() const { return wrenches_; }
  double n_force_leading() const { return n1_; }   ///< [m]
  double n_force_trailing() const { return n2_; } ///< [m]
  double moment() const { return moment_; }        ///< bending moment of its case [N m]
  double torque() const { return moment_; }        ///< torque of its case [N m]
  /// Outermost section position whose fit band stays clear of the loaded tip zone and
  /// its local deformation: zone start − max(zone length, band half-width) [m].
  double measurement_limit() const {
    return zone_.s_start - std::max(s_tip_ - zone_.s_start, 4.0 * element_size_);
  }
  /// Typical element size (mean edge length) [m].
  double element_size() const { return element_size_; }
  /// FEM mass matrix and stiffness (for strip sums and modes).
  const fem::AssembledSystem& system() const { return *system_; }
  const fem::Constraints& constraints() const { return *constraints_; }
  /// Static displacements of the clamped FEM for the loads \p loads (one column per
  /// case, full DOF numbering), from the analysis's one factorisation [m, rad].
  Eigen::MatrixXd solve(const Eigen::MatrixXd& loads) const { return solver_->solve(loads); }

  /// \brief A section sampler at axis positions \p sections, band half-width at least
  /// \p half_width and four element sizes.
  SectionSampler sampler(const std::vector<double>& sections, double half_width) const;

  /// \brief Rigid-body mass properties (about the pivot, wing axes) of the strips
  /// cut at the increasing axis positions \p edges (size N + 1): strip k holds the
  /// nodes with edges[k] ≤ s < edges[k+1]; the first also everything below
  /// edges[0], the last everything from edges[N] on.
  std::vector<RigidMass> strips(const std::vector<double>& edges) const;

  /// \brief Per-cell elastic-axis offsets n_ea from the twist increments under the two
  /// tip forces, for cells between the sections of \p sampler (size N_sections − 1) [m].
  std::vector<double> cell_elastic_axis(const SectionSampler& sampler) const;

  /// \brief Share of the flexible span's cells (20, in the current frame) whose nodes'
  /// chordwise extent, widened by one element size, contains the axis (n = 0) [-].
  double axis_inside_fraction() const;

  /// True when AxisChoice::fitted was asked for but its line left the planform (the
  /// cells' elastic axes of the ψ = 0 pass scatter outside the wing, as on a strongly
  /// swept wing): the axis is then the least-squares line through the pivot and the
  /// mid-chords of 20 cells cut along y (the wing's geometric axis).
  bool fitted_axis_rejected() const { return fitted_axis_rejected_; }
  /// The rejected fitted angle [rad] (when fitted_axis_rejected()).
  double fitted_psi_rejected() const { return fitted_psi_rejected_; }

  /// The fitted axis must lie inside the planform over at least this share of the span.
  static constexpr double kFittedAxisMinInside = 0.8;
  /// Cells of the planform check and of the mid-chord line.
  static constexpr int kAxisCheckCells = 20;

 private:
  void setup_frame(const AxisFrame& axis, double tip_zone_length);
  struct ChordExtents {
    std::vector<double> s, lo, hi;  ///< cell centre, smallest and largest n of its nodes [m]
  };
  ChordExtents chord_extents(int cells) const;
  void solve_load_cases();

  const fem::AssembledSystem* system_ = nullptr;
  const fem::Constraints* constraints_ = nullptr;
  AnalysisOptions options_;
  std::shared_ptr<const fem::StaticSolver> solver_;  // one factorisation for both passes
  Eigen::Matrix3Xd nodes_;

  std::vector<bool> clamped_;
  AxisFrame axis_;
  Eigen::VectorXd s_, n_;
  TipZone zone_;
  double s_root_ = 0.0, s_tip_ = 0.0, n1_ = 0.0, n2_ = 0.0, moment_ = 0.0, force_ = 0.0;
  double element_size_ = 0.0;
  bool fitted_axis_rejected_ = false;
  double fitted_psi_rejected_ = 0.0;
  std::vector<TipWrench> wrenches_;
  Eigen::MatrixXd uz_;
};

}  // namespace flapsim::reduction
