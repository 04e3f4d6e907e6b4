#pragma once
/// \file case_model.hpp
/// \brief What a simulation case is, after its file has been read and checked
/// (docs/case_file.md): the wing or chain it flaps, the base kinematics, the air,
/// the structure model, the numerics, outputs, extra point loads and markers.
/// All values SI; angles in radians.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mbd/chain_loads.hpp"
#include "mbd/periodic_signal.hpp"
#include "mbd/wing_kinematics.hpp"
#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_core.hpp"
#include "uvlm/vortex_lattice.hpp"
#include "wings/loader/input_warning.hpp"

namespace flapsim::io {

/// Precision of the wake's direct sums (uvlm::VortexLatticeModel::single_precision_wake).
enum class WakePrecision { Single, Double };
enum class CirculationRate { Bdf2, Bdf1 };

/// How a flexible wing's coupling sub-iterations update the chain (fsi::CouplingMethod).
enum class CouplingMethod { Aitken, InterfaceQuasiNewton };

/// A prescribed force and moment on one body of the chain, periodic in the stroke phase.
struct PointLoad {
  int body = 1;                                  ///< 1-based body index in the chain
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< application point [m], body frame
  mbd::LoadFrame frame = mbd::LoadFrame::ground;  ///< frame of the components ("ground" | "body")
  mbd::PeriodicSignal force[3];   ///< [N] as functions of the phase s = f·t
  mbd::PeriodicSignal moment[3];  ///< [N m] as functions of the phase s = f·t
};

/// A point carried by a body whose trajectory goes into the output.
struct Marker {
  std::string name;
  int body = 1;                                     ///< 1-based body index
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< [m], body frame
};

struct Case {
  std::string file;        ///< path of the case file
  /// Line of each key given in the file, by dotted name ("numerics.cycles"; the tables
  /// themselves too: "numerics"; "loads.2.body" in the second [[loads]]), for the errors
  /// found after reading (run setup, size).
  std::map<std::string, int, std::less<>> key_lines;
  /// \brief The line of a dotted key: its own if given, else its table's, else 0.
  int line_of(std::string_view key) const {
    for (std::string_view k = key;;) {
      if (const auto it = key_lines.find(k); it != key_lines.end()) return it->second;
      const auto dot = k.rfind('.');
      if (dot == std::string_view::npos) return 0;
      k = k.substr(0, dot);
    }
  }
  /// Accepted but likely to mislead (a long hover with the whole wake free); the command
  /// line prints each on stderr and carries on (wings/loader/input_warning.hpp).
  std::vector<InputWarning> warnings;
  std::string name;        ///< short name (from the file, else the file stem)
  std::string length_unit = "m";  ///< the file's unit of load and marker points (length_unit)
  double length_scale = 1.0;      ///< metres per length_unit
  std::string wing_file;   ///< resolved path of the wing file (may be empty)
  std::string chain_file;  ///< resolved path of the chain file (may be empty)

  mbd::WingKinematics kinematics;  ///< base kinematics (frequency, φ, θ, α, δψ, β)

  struct Air {
    bool enabled = true;       ///< false: vacuum (`air = "none"`), no aerodynamic loads
    double density = 1.225;    ///< ρ [kg/m³]
    Eigen::Vector3d freestream = Eigen::Vector3d::Zero();  ///< U∞ [m/s], ground frame
  } air;

  struct Structure {
    /// rigid: one body; flexible: the bar chain; fem: the wing's own geometrically
    /// nonlinear FEM (docs/fsi.md, "The FEM as the structure").
    enum class Kind { Rigid, Flexible, Fem };
    Kind kind = Kind::Rigid;
    int bodies = 1;  ///< number of chain bodies (1 for a rigid wing)
    int bodies_line = 0;  ///< line of structure.bodies in the case file (0: not given), for messages
    /// Gravity in the ground frame [m/s²] (`gravity = [0, 0, -9.81]`; default none).
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
    /// Initial joint angles Φ(0) and rates Φ̇(0) [rad, rad/s], bend and twist per jointed
    /// body (`initial_angles_deg`, `initial_rates_deg_per_s`); empty: the rest angles, at rest.
    std::vector<double> initial_angles, initial_rates;
    int initial_angles_line = 0, initial_rates_line = 0;  ///< their lines (0: not given)
    /// kind = "fem": the FEM's element sizes [m] (`element_size_mm`, `vein_element_size_mm`;
    /// 0: the wing file's mesh, as `flapsim modes` meshes it).
    double fem_element_size = 0.0, fem_vein_element_size = 0.0;
    /// kind = "fem": co-rotational stiffness-proportional (Rayleigh) damping a₁ [s]
    /// (`stiffness_damping_s`; 0: none).
    double fem_stiffness_damping = 0.0;
    /// kind = "fem": a new Newton matrix's geometric terms from the elements' forces along
    /// the last correction taken linearly (`newton_geometric_terms = "linearised"`, the
    /// default) or from those at the current state ("current"; faster for thin films:
    /// docs/fem.md, "The geometric terms from the corrections taken linearly").
    bool fem_linearised_geometric_terms = true;
    /// `newton_geometric_terms` written in the case: a thin film's FEM takes "current" where
    /// it is not (app::make_fem_structure; docs/case_file.md).
    bool fem_geometric_terms_written = false;
    /// A kept Newton matrix for each piece of a split FEM step (`newton_matrix_per_piece`;
    /// fem::DynamicsOptions::matrix_per_piece): faster for film wings, on by default.
    bool fem_matrix_per_piece = true;
  } structure;

  struct Numerics {
    int steps_per_cycle = 100;
    int cycles = 3;
    /// steps_per_cycle × cycles, in 64 bits (the reader checks it against kMaxTotalSteps).
    std::int64_t total_steps() const { return std::int64_t{steps_per_cycle} * cycles; }
    int chordwise_panels = 6;
    int spanwise_panels = 10;
    uvlm::Spacing chordwise_spacing = uvlm::Spacing::Uniform;  ///< "uniform" | "cosine" (`spacing` sets both)
    uvlm::Spacing spanwise_spacing = uvlm::Spacing::Uniform;   ///< "uniform" | "cosine"
    uvlm::LoadMethod load_method = uvlm::LoadMethod::Bernoulli;  ///< "bernoulli" | "kutta_joukowski"
    uvlm::LeadingEdge leading_edge = uvlm::LeadingEdge::Separated;  ///< "none" | "attached" | "separated" | "shed"
    /// `skin_friction = "laminar"`: the panels' Blasius skin friction with kinematic_viscosity
    /// (uvlm/skin_friction.hpp); "none" (default): the inviscid lattice.
    bool laminar_skin_friction = false;
    /// Critical leading-edge suction parameter of leading_edge = "shed" (uvlm/leading_edge_sheet.hpp)
    double lesp_critical = 0.11;
    /// leading_edge = "shed": the sheet's rings merge in pairs from this many steps old, 0 =
    /// never (uvlm/leading_edge_sheet.hpp, "Merging the older rings"; docs/uvlm.md)
    int sheet_merge_steps = 8;
    /// leading_edge = "shed": the releases each merge of the sheet's rings is spread over, 1 =
    /// at once (uvlm::VortexLatticeModel::sheet_merge_spread_steps; docs/uvlm.md)
    int sheet_merge_spread_steps = 1;
    /// leading_edge = "shed": the sheet's core radius as a fraction of the mean chord, 0 =
    /// core_radius (uvlm::VortexLatticeModel::sheet_core_radius; docs/uvlm.md, "Why the shed hover's lift is rough: the sheet's core")
    double sheet_core_radius = 0.0;
    uvlm::CoreModel core_model = uvlm::CoreModel::LambOseen;  ///< vortex core: "cutoff" | "lamb_oseen"
    double core_radius = 0.2;                                 ///< core radius as a fraction of the mean chord
    int wake_order = 1;                     ///< 1 | 2 (wake convection order)
    int wake_max_rows = 0;                  ///< 0 = keep all wake rows
    /// First cycle (1-based) of summary.json's settled_ statistics: 2 leaves out the start from
    /// rest; later, a start whose transient lasts longer (docs/fsi.md, "summary.json").
    int settled_from_cycle = 2;
    bool free_wake = true;                  ///< false: wake convected by U∞ and the body only
    bool core_growth = false;               ///< wake cores grow with age (uvlm/core_growth.hpp)
    double core_growth_a1 = 2e-4;           ///< a1 of Squire's δ = 1 + a1 Γ/ν
    double kinematic_viscosity = 1.5e-5;    ///< ν of the air for the core growth [m²/s]
    double near_wing_core = 0.0;            ///< min. core of the wake seen from the wing, fraction of the mean chord
    double frozen_wake_cycles = 0.0;        ///< wake older than this many cycles stops moving; 0 = never
    double far_wake_cycles = 0.0;           ///< wake older than this many cycles moves with momentum theory's velocity; 0 = never
    uvlm::WakeSum wake_sum = uvlm::WakeSum::Direct;  ///< wake velocity sum: "direct" | "tree"
    WakePrecision wake_precision = WakePrecision::Single;  ///< the wake's direct sums: "single" | "double"
    /// ∂Γ/∂t of the pressure: "bdf2" (second order) | "bdf1" (backward Euler;
    /// uvlm::VortexLatticeModel::first_order_circulation_rate)
    CirculationRate circulation_rate = CirculationRate::Bdf2;
    double tree_tolerance = 1e-4;           ///< relative error of the tree code's velocities
    CouplingMethod coupling = CouplingMethod::Aitken;  ///< sub-iteration update: "aitken" | "iqn_ils"
    int max_coupling_iterations = 50;       ///< strong-coupling sub-iterations per step
    int coupling_reuse_steps = 0;           ///< iqn_ils: earlier steps whose secant pairs are kept
    double coupling_tolerance = 1e-6;       ///< relative change that ends the sub-iterations
    double rho_infinity = 0.9;              ///< generalized-α spectral radius ρ∞ in [0, 1]
    /// `rho_infinity` written in the case: a thin film's FEM takes 0 where it is not
    /// (app::make_fem_structure; docs/case_file.md).
    bool rho_infinity_written = false;
    int structure_substeps = 1;             ///< chain sub-steps per time step (docs/multibody.md, "Sub-steps")
    /// The steady vortex lattice at every step (a straight wake 10⁴ mean chords long along the
    /// free stream, no ∂Γ/∂t, nothing shed; uvlm::VortexLatticeModel::steady_wake_length):
    /// results independent of Δt for a wing at rest in a free stream (docs/uvlm.md, "Steady lattice")
    bool steady = false;
    /// The lattice's added mass linearised into the structure's step (docs/fsi.md, "Added
    /// mass in the coupling"); false: the plain partitioned step. Same fixed point either way.
    bool added_mass = true;
  } numerics;

  struct Output {
    int vtk_every = 1;  ///< write VTK every n steps, 0 = never
  } output;

  std::vector<PointLoad> loads;
  std::vector<Marker> markers;
};

/// The largest number of time steps of one run (steps_per_cycle × cycles), documented in
/// docs/case_file.md: 10^8 steps already need tens of GB for the history alone.
inline constexpr std::int64_t kMaxTotalSteps = 100'000'000;
/// The largest wingbeat frequency a case accepts [Hz] (documented in docs/case_file.md).
inline constexpr double kMaxFrequencyHz = 1e6;
/// A hover with the whole wake free longer than this many cycles gets a warning: from the
/// second cycle on its lift hinges on round-off (docs/case_file.md, "Checks").
inline constexpr int kLongFreeHoverCycles = 1;
/// The far_wake_cycles of a hover that were measured to work (docs/uvlm.md, "Hover over many
/// cycles": rigid hawkmoth, eq. 8): from 0.5, the wing never comes within a core radius of
/// the far wake; up to 0.625, the cycle means stay within 0.25 % (0.75: 0.8 %, 1: 1.4 %,
/// 2: 4.8 %, the free wake's instability). A hover outside gets a warning.
inline constexpr double kHoverFarWakeCyclesMin = 0.5;
inline constexpr double kHoverFarWakeCyclesMax = 0.625;
/// air.density [kg/m³] above which a case that leaves numerics.kinematic_viscosity at air's is
/// warned (case_file.cpp, warn_dense_fluid_with_air_viscosity): 8 times sea-level air.
inline constexpr double kDenseFluidDensity = 10.0;
/// far_wake_cycles of a hover case that leaves the key out (read_case; docs/case_file.md).
inline constexpr double kHoverFarWakeCycles = 0.5;

/// The names the case file gives the choices above, each with its value
/// (wings::TomlTable::get_choice reads them, wings::choice_name names a value).
inline constexpr std::array<std::pair<std::string_view, Case::Structure::Kind>, 3> kStructureKindNames{
    {{"rigid", Case::Structure::Kind::Rigid},
     {"flexible", Case::Structure::Kind::Flexible},
     {"fem", Case::Structure::Kind::Fem}}};
inline constexpr std::array<std::pair<std::string_view, uvlm::Spacing>, 2> kSpacingNames{
    {{"uniform", uvlm::Spacing::Uniform}, {"cosine", uvlm::Spacing::Cosine}}};
inline constexpr std::array<std::pair<std::string_view, uvlm::LoadMethod>, 2> kLoadMethodNames{
    {{"bernoulli", uvlm::LoadMethod::Bernoulli}, {"kutta_joukowski", uvlm::LoadMethod::KuttaJoukowski}}};
inline constexpr std::array<std::pair<std::string_view, uvlm::LeadingEdge>, 4> kLeadingEdgeNames{
    {{"none", uvlm::LeadingEdge::None},
     {"attached", uvlm::LeadingEdge::Attached},
     {"separated", uvlm::LeadingEdge::Separated},
     {"shed", uvlm::LeadingEdge::Shed}}};
inline constexpr std::array<std::pair<std::string_view, uvlm::CoreModel>, 2> kCoreModelNames{
    {{"cutoff", uvlm::CoreModel::CutOff}, {"lamb_oseen", uvlm::CoreModel::LambOseen}}};
inline constexpr std::array<std::pair<std::string_view, uvlm::WakeSum>, 2> kWakeSumNames{
    {{"direct", uvlm::WakeSum::Direct}, {"tree", uvlm::WakeSum::Tree}}};
inline constexpr std::array<std::pair<std::string_view, WakePrecision>, 2> kWakePrecisionNames{
    {{"single", WakePrecision::Single}, {"double", WakePrecision::Double}}};
inline constexpr std::array<std::pair<std::string_view, CirculationRate>, 2> kCirculationRateNames{
    {{"bdf2", CirculationRate::Bdf2}, {"bdf1", CirculationRate::Bdf1}}};
inline constexpr std::array<std::pair<std::string_view, CouplingMethod>, 2> kCouplingMethodNames{
    {{"aitken", CouplingMethod::Aitken}, {"iqn_ils", CouplingMethod::InterfaceQuasiNewton}}};
inline constexpr std::array<std::pair<std::string_view, mbd::LoadFrame>, 2> kLoadFrameNames{
    {{"ground", mbd::LoadFrame::ground}, {"body", mbd::LoadFrame::body}}};

}  // namespace flapsim::io
