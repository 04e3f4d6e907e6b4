#pragma once
/// \file run_history.hpp
/// \brief history.csv, one row per step: the columns of every run (defined here, once,
/// each with how it is computed from a StepSample), then the joint angles of the chain
/// and the positions of the case's markers (docs/fsi.md, "Outputs").
/// How to add a column: docs/output_files.md, "Adding a result or a history column".

#include <Eigen/Core>

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mbd/chain_data.hpp"
#include "mbd/chain_model.hpp"
#include "mbd/wing_kinematics.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/phase_analysis.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// One step of a run as the history and the results see it (SI units, radians).
struct StepSample {
  double time = 0.0;                 ///< t [s]
  mbd::WingKinematics::Angles base;  ///< prescribed base angles φ, θ, α [rad] and their rates
  /// The tip section relative to the undeformed wing [rad]: the chain's last body, the FEM's
  /// fitted outer tenth of the span (fsi::StructureReadout).
  mbd::StrokeAngles tip;
  mbd::StrokeAngles outer;          ///< the outer section: the chain's outer body (fsi::outer_body), the FEM's band at 5/6 R [rad]
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< total aerodynamic force, ground [N]
  double lift = 0.0;                 ///< force along the lift direction [N] (LiftReference)
  double drag = 0.0;                 ///< force along the air's motion relative to the wing [N]; < 0: thrust
  double side = 0.0;                 ///< force along drag direction × lift direction [N]
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< aerodynamic moment about the pivot, ground [N m]
  double power = 0.0;                ///< aerodynamic power, −Σ F_panel · v_panel [W]
  /// Moment the base (the drive) exerts on the wing about the pivot, ground [N m]:
  /// inertial, aerodynamic, gravity and point loads together (mbd::base_moment).
  Eigen::Vector3d drive_moment = Eigen::Vector3d::Zero();
  double drive_power = 0.0;          ///< power the base supplies, ω·M + v·F at the pivot (mbd::base_power) [W]
  double cl = 0.0;                   ///< lift coefficient [-] (0 in vacuum)
  double cd = 0.0;                   ///< drag coefficient [-]
  double cp = 0.0;                   ///< power coefficient P / (½ ρ U_ref³ S) [-]
  int coupling_iterations = 0;       ///< lattice solves of the step
  double coupling_change = 0.0;      ///< structure change at the end of the step [rad]
  /// The tip's deflection relative to the base (0 for a rigid wing): the chain's sum over the
  /// joints of bend − rest bend, and of twist − rest twist; the FEM's tip section rotation
  /// relative to the base, Rx(bend) Ry(twist) [rad] (fsi::StructureReadout).
  double tip_bend = 0.0;
  double tip_twist = 0.0;
  /// The tip point, ground frame [m] (fsi::StructureReadout::tip_position; tip_path.vtp).
  Eigen::Vector3d tip_position = Eigen::Vector3d::Zero();
};

/// In hover a step whose horizontal speed at r2·R is below this fraction of the reference
/// speed lies on a stroke reversal: its drag direction is undefined, and its drag and side
/// force are 0 (docs/fsi.md, "Directions").
inline constexpr double kReversalSpeedFraction = 1e-9;

/// \brief The sample of the step just taken (after fsi::coupled_step).
/// \param kinematics  the case's base kinematics (angles, stroke plane)
/// \param reference   references and directions of the coefficients (ignored in vacuum)
StepSample sample_step(const fsi::FsiModel& model, const fsi::FsiData& data,
                       const mbd::WingKinematics& kinematics, const LiftReference& reference);

/// A column every run writes.
struct HistoryColumn {
  std::string_view name;         ///< CSV header, unit as a suffix ("lift_N")
  std::string_view description;  ///< for docs/fsi.md
  double (*value)(const StepSample&);
};

/// The columns every run writes, in order (before joint angles and markers).
std::span<const HistoryColumn> history_columns();

/// \brief All column names of a run's history.csv: history_columns(), then
/// bend_<k>_rad, twist_<k>_rad for each jointed body k (1-based), then
/// <marker>_x_m, _y_m, _z_m for each marker.
std::vector<std::string> history_header(const io::Case& c, const mbd::ChainModel& chain);

/// \brief A row of history.csv in the order of history_header().
/// \param row  resized to the header's length by the caller; filled here
void history_row(const StepSample& sample, const io::Case& c, const fsi::FsiData& data,
                 std::vector<double>& row);

}  // namespace flapsim::app
