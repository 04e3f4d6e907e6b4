#pragma once
/// \file reduction_report.hpp
/// \brief How well a lumped chain reproduces the clamped FEM: first bending and
/// first torsion frequencies, MAC of their shapes, static tip deflection, bending
/// rotation and twist (docs/reduction.md, "Checking the chain against the FEM").

#include <string>
#include <vector>

#include "fem/modal_solver.hpp"
#include "fem/mode_classification.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/linear_chain.hpp"
#include "reduction/station_mode_kind.hpp"

namespace flapsim::reduction {

/// One mode family (first bending or first torsion) in both models: the FEM's first mode of
/// that kind (from the stations) and the chain mode whose shape correlates best with it.
struct ModeMatch {
  bool found = false;      ///< both models have a mode of this kind
  int fem_mode = -1;       ///< index among the FEM modes
  int chain_mode = -1;     ///< index among the chain modes
  double fem_hz = 0.0, chain_hz = 0.0;  ///< [Hz]
  double relative_error = 0.0;          ///< chain / FEM − 1 [-]
  double mac = 0.0;                     ///< modal assurance criterion of the sampled shapes [-]
};

/// One static response in both models, read with the chain's own coordinates: the FEM's
/// station motion u under the load case mapped to joint angles Φ = T u (the map that
/// defines the chain's joint stiffness, joint_stiffness.hpp) and read with the chain's
/// kinematics at the same point as the chain's (docs/reduction.md, "Checking the chain
/// against the FEM").
struct StaticMatch {
  double fem = 0.0, chain = 0.0;  ///< per unit load: [m/N] or [rad/(N m)]
  double relative_error = 0.0;    ///< chain / FEM − 1 [-]
  /// The FEM's section fit at the same position (section_fit.hpp: every band node with
  /// equal weight, camber terms), shown beside: on a wing whose sections are not rigid
  /// (film beyond a rod) it measures something else than the chain's stations [m/N] or [rad/(N m)].
  double fem_section_fit = 0.0;
};

struct ChainFemComparison {
  int num_bodies = 0;
  double fem_mass = 0.0, chain_mass = 0.0;  ///< [kg]
  ModeMatch bending, torsion;  ///< the FEM's first bending / torsion mode, paired by MAC
  double measure_s = 0.0;           ///< axis position of the deflection and twist rows [m]
  StaticMatch tip_deflection;       ///< w per unit tip force on the axis, at measure_s [m/N]
  /// θ conjugate to a bending moment M_n on the chain's tip body, on both sides: the FEM's
  /// fᵀ K⁻¹ f / M_n for the moment spread over the tip body's strip by mass, the chain's
  /// Qᵀ K_c⁻¹ Q / M_n (its tip body's rotation); positive by construction on both. Beside
  /// it (fem_section_fit) the section fit's θ at the tip body's mid-span under that load.
  /// All three per unit of M_n [rad/(N m)].
  StaticMatch tip_bending_rotation;
  double bending_body_s = 0.0;      ///< inboard joint of the tip body, where that moment's strip starts [m]
  StaticMatch tip_twist;            ///< φ per unit tip torque, at measure_s [rad/(N m)]
  std::vector<double> fem_hz;       ///< all FEM modes [Hz]
  std::vector<std::string> fem_kinds;        ///< from the stations: "bending", "torsion", "film", "in-plane"
  std::vector<std::string> fem_shape_kinds;  ///< fem::classify_modes (strip fits of the whole shape)
  std::vector<double> fem_beam_share;        ///< share of u_z the stations' rigid sections carry [-]
  /// Every FEM beam mode (kind bending or torsion) with the chain mode whose shape
  /// correlates best with it (largest MAC), in the order of the FEM modes.
  std::vector<ModeMatch> beam_mode_pairs;
  std::vector<double> chain_hz;     ///< all chain modes [Hz]
  std::vector<std::string> chain_kinds;  ///< "bending" / "torsion" by spring energy
  double body_length = 0.0;              ///< the chain's body length a [m]
  double fem_element_size = 0.0;  ///< the FEM's mean element edge [m] (ClampedWingAnalysis::element_size)
  double flexible_span = 0.0;     ///< s_tip: the axis length the bodies divide [m]
};

/// \brief chain / fem − 1; NaN when \p fem is 0 (no relative error against a zero
/// reference: report.md shows "n/a", summary.json null).
double relative_error(double chain, double fem);

/// \brief Compares the chain with the FEM.
/// \param analysis  the clamped FEM with its load cases
/// \param lumped    the chain lumped from it
/// \param modes     clamped-root FEM modes (fem::wing_modes or fem::solve_modes)
/// \param kinds     the FEM's shape classification of each mode (reported beside the
///                  stations' kinds, which decide the first bending and torsion modes)
ChainFemComparison compare_chain_with_fem(const ClampedWingAnalysis& analysis,
                                          const LumpedChain& lumped, const fem::ModalResult& modes,
                                          const std::vector<fem::ModeKind>& kinds);

/// \brief Every FEM beam mode (kind bending or torsion, in the order of the FEM modes) with
/// the chain mode whose sampled shape correlates best with it (largest MAC; ties keep the
/// lower chain mode): the table "FEM beam modes and the chain mode that correlates best".
/// \param fem_samples    each FEM mode's shape at the sample points
/// \param fem_hz         each FEM mode's frequency [Hz]
/// \param fem_kinds      each FEM mode's kind from the stations (film modes are skipped)
/// \param chain_samples  each chain mode's shape at the same points
/// \param chain_hz       each chain mode's frequency [Hz]
std::vector<ModeMatch> pair_modes_by_mac(const std::vector<Eigen::VectorXd>& fem_samples,
                                         const std::vector<double>& fem_hz,
                                         const std::vector<StationModeKind>& fem_kinds,
                                         const std::vector<Eigen::VectorXd>& chain_samples,
                                         const std::vector<double>& chain_hz);

/// \brief The first pair of \p pairs (pair_modes_by_mac) whose FEM mode is of \p kind: the
/// FEM's first bending or torsion mode with the chain mode of the same shape, whatever the
/// chain's own energy split calls that mode (on a strongly coupled mode the chain's and the
/// FEM's 0.5 cuts can name the same shape differently). Not found when no FEM mode is of
/// \p kind.
ModeMatch first_pair_of_kind(const std::vector<ModeMatch>& pairs, const std::vector<StationModeKind>& fem_kinds,
                             StationModeKind kind);

/// \brief MAC = (aᵀb)² / (aᵀa · bᵀb).
double modal_assurance(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

}  // namespace flapsim::reduction
