#pragma once
/// \file fsi_setup.hpp
/// \brief From a checked Case to everything a coupled run needs: the wing and its
/// lattice, the structure (a rigid one-body chain, a chain file, or the wing reduced in
/// process), the attachment of one to the other, the base motion, the numerics and the
/// reference values of the lift coefficient.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mbd/chain_model.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/chain_file.hpp"
#include "pipeline/fsi/chain_structure.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "uvlm/planform_grid.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::app {

/// Reference values of the lift coefficient CL = L / (½ ρ U_ref² S).
/// The references of the coefficients and the force directions (docs/fsi.md, "Coefficients").
/// Rule: U_ref is the free-stream speed if the case has a free stream, else the cycle-mean
/// speed of the span axis at r2·R (flapping, with any base translation); a case with
/// neither has no coefficients (setup refuses it).
struct LiftReference {
  enum class Kind { Flapping, FreeStream };
  Kind kind = Kind::Flapping;
  double area = 0.0;   ///< S: planform area of the wing outline [m²]
  double speed = 0.0;  ///< U_ref [m/s], by the rule above
  double flapping_speed = 0.0;     ///< cycle-mean speed of the span axis at r2·R [m/s]
  double free_stream_speed = 0.0;  ///< |U∞| [m/s]
  double r2 = 0.0;     ///< non-dimensional radius of gyration of the area [-]
  double span = 0.0;   ///< R [m]
  double mean_chord = 0.0;  ///< c̄ = S / R [m]
  /// Lift direction: +z_G in hover, else the part of +z_G normal to U∞ (unit).
  Eigen::Vector3d lift_direction = Eigen::Vector3d::UnitZ();
  /// Drag direction in a free stream: along U∞ (unit); zero in hover, where the drag is
  /// taken against the wing's horizontal motion at r2·R, step by step.
  Eigen::Vector3d drag_direction = Eigen::Vector3d::Zero();
  double dynamic_pressure_area(double rho) const { return 0.5 * rho * speed * speed * area; }
  const char* kind_name() const { return kind == Kind::FreeStream ? "free_stream" : "flapping_r2"; }
};

struct FsiSetup {
  fsi::FsiModel model;
  /// The run's bar chain (a rigid wing: one body without dofs), the same object as
  /// model.structure: what the chain's warnings and outputs read.
  std::shared_ptr<const fsi::ChainStructureModel> chain_structure;
  const mbd::ChainModel& chain() const { return chain_structure->chain; }
  /// kind = "fem": the wing's FEM, the same object as model.structure (null otherwise; then
  /// chain_structure is a rigid one-body chain of the wing, for what reads a chain).
  std::shared_ptr<const fsi::FemStructureModel> fem_structure;
  std::optional<wings::Wing> wing;        ///< the wing (if the case names one)
  std::optional<uvlm::PlanformGrid> grid; ///< lattice grid in the wing frame (if air)
  LiftReference reference;                ///< valid if air
  std::string structure_source;           ///< how the structure was obtained (for the log)
  std::string chain_file;                 ///< the chain file of a flexible run ("" otherwise)
  /// The chain file's record of the chain against its wing's FEM (made by flapsim reduce).
  std::optional<io::ChainFemRecord> chain_fem;
  int reduced_fem_dofs = 0;               ///< DOFs of the wing's FEM reduced in the setup (0: none was)
  double spring_scale = 1.0;              ///< every joint spring × this (SetupOptions)
  int steps_per_cycle = 0;
  std::int64_t steps = 0;                 ///< total steps of the run (<= io::kMaxTotalSteps)
  double period = 0.0;                    ///< 1/f [s]
  double dt = 0.0;                        ///< time step [s]
};

/// Options of a run that do not come from the case file.
struct SetupOptions {
  std::string chain_file;  ///< overrides the case's chain file (flapsim run --chain)
  /// Multiplies every joint spring (k_θ, k_α) of a flexible chain: a stiffness
  /// calibration factor (natural frequencies scale by √S); 1 = the chain as given.
  double spring_scale = 1.0;
  /// Values set in the wing file before it is read (parameter sweeps), as for a case
  /// file: {"membrane.thickness", "0.015"} (TOML text, in the file's length unit).
  std::vector<std::pair<std::string, std::string>> wing_overrides;
};

/// \brief The case's wing file read with \p overrides applied; std::nullopt if the case
/// names no wing.
/// \throws flapsim::InputError naming the file and key (an overridden key says so)
std::optional<wings::Wing> load_case_wing(const io::Case& c,
                                          const std::vector<std::pair<std::string, std::string>>& overrides);

/// \brief A one-body chain welded to the wing base: the rigid wing (no dofs). The body
/// carries the wing's estimated mass, centre of mass and inertia (wings::estimate_wing_inertia:
/// membrane spread over the outline, veins along their lines); they set the inertial part of
/// the drive moment and power.
mbd::ChainModel make_rigid_chain(const wings::Wing& wing);

/// \brief The cycle-mean speed [m/s] of the point at distance \p radius [m] along y_W,
/// sampled at \p samples points of one period (the first; for a revolving wing the one
/// after its ramp: the steady revolution).
double mean_speed_at_radius(const mbd::WingKinematics& kinematics, double radius, int samples = 720);

/// \brief The stroke disk [m²] of momentum theory for a wing of length \p span [m]: the
/// sector Φ R²/2 its span axis sweeps, Φ the largest angle between two of its directions
/// over one period (\p samples points) [Ellington 1984; Leishman 2006 ch. 2]; a revolving
/// wing's is the whole circle, π R². Used by the convected far wake (uvlm::far_wake_velocity).
double stroke_disk_area(const mbd::WingKinematics& kinematics, double span, int samples = 360);

/// Velocity [m/s] of the span-axis point at `radius` [m] at time t (rotation and base translation).
Eigen::Vector3d span_point_velocity(const mbd::WingKinematics& kinematics, double radius, double t);

/// \brief Builds the coupled model of a case.
/// \throws flapsim::InputError when the structure cannot be obtained (flexible case without
///         chain file and no in-process reduction), a wing is needed but missing, or the
///         chain file is invalid; std::invalid_argument on inconsistent internal sizes
FsiSetup build_fsi_setup(const io::Case& c, const SetupOptions& options);

/// \brief Refuses, for a case in air, a wing whose outline the vortex lattice cannot follow
/// (a gap along the chord: wings::LatticeGap; docs/wing_file.md).
/// \throws flapsim::InputError naming the wing file, the line and the key of the outline
void check_lattice_can_follow(const io::Case& c, const wings::Wing& wing);

/// \brief The warning for a flexible chain driven above its first natural frequency (the
/// linearised chain at rest, reduction::LinearChain), "" if none: the wing flaps with bends
/// its linear joint springs do not represent and the run usually fails (a 50 µm film wing
/// without veins, first bending 15.7 Hz at a 20 Hz wingbeat: joints bent 90°, exit 3).
std::string soft_chain_warning(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
