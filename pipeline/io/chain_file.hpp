#pragma once
/// \file chain_file.hpp
/// \brief `chain.toml`: the Hencky bar chain (mbd::ChainModel) as a file, written by
/// `flapsim reduce` and read by `flapsim run` (docs/multibody.md, "Chain file").
///
/// \code
///   length_unit = "m"                 # lengths (length, centre of mass, joints, offset)
///   root = "rigid"                    # or "sprung" (joint of body 1 has springs)
///   root_offset = [0.0, 0.0, 0.0]     # root point in the wing frame W
///   root_rotation = [[1,0,0],[0,1,0],[0,0,1]]   # R_WR, row by row (optional)
///   welded_bodies = 1                 # optional, rigid root: bodies welded to the root
///   joint_stiffness = [[...], ...]    # optional: full K over [θ, α] per joint [N m/rad]
///   joint_damping = [[...], ...]      # optional: full C [N m s/rad]
///   [[bodies]]
///   length = 0.0161                   # [length unit]
///   mass = 13.27e-6                   # [kg]
///   center_of_mass = [-0.001, 0.00805, 0.0]     # body frame [length unit]
///   inertia = [[...],[...],[...]]     # about the centre of mass, body axes [kg m²]
///   outboard_joint = [0, 0.0161, 0]   # optional, default (0, length, 0)
///   [bodies.joint]                    # the joint inboard of this body
///   bend_stiffness = 4e-3             # k_θ [N m/rad]
///   twist_stiffness = 1e-3            # k_α [N m/rad]
///   bend_damping = 0.0                # optional [N m s/rad]
///   twist_damping = 0.0               # optional [N m s/rad]
///   bend_rest = 0.0                   # optional [rad]
///   twist_rest = 0.0                  # optional [rad]
///   [fem_comparison]                  # optional, written by flapsim reduce (see ChainFemRecord)
///   wing = "wings/x.toml"
///   chain_fingerprint = "0123456789abcdef"   # FNV-1a 64 of the chain's numbers (optional):
///                                            # a chain edited since drops the table
///   bending_chain_hz = 72.1           # first bending mode of the chain and of the FEM [Hz]
///   bending_fem_hz = 70.4
///   bending_mac = 0.998               # modal assurance criterion of the two shapes [-]
///   torsion_chain_hz = 112.0          # the same for the first torsion mode
///   torsion_fem_hz = 131.2
///   torsion_mac = 0.93
///   measure_s_m = 0.0435              # the static rows (all eight or none): where the deflection
///   bending_body_s_m = 0.0435         # and twist are read, and where the tip body starts [m];
///   tip_deflection_chain_m_per_n = 1.2   # per unit tip force [m/N], per unit moment
///   tip_deflection_fem_m_per_n = 1.2     # [rad/(N m)], chain and FEM
///   tip_bending_rotation_chain_rad_per_n_m = 2.3
///   tip_bending_rotation_fem_rad_per_n_m = 2.3
///   tip_twist_chain_rad_per_n_m = 40.0
///   tip_twist_fem_rad_per_n_m = 41.0
/// \endcode
/// With a rigid root the welded bodies' joints are optional and ignored. With
/// joint_stiffness the joints carry no springs (only dampers and rest angles). Masses, inertias
/// and springs are SI whatever the length unit.

#include "mbd/chain_model.hpp"
#include "reduction/reduction_report.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace flapsim::io {

/// What `flapsim reduce` found of a chain against the FEM of its wing, kept in the chain
/// file's [fem_comparison] table so that `run` and `check` of the chain, later and
/// elsewhere, can repeat reduce's warning about a chain that misses the FEM's modes
/// (report.md of the reduction has the whole comparison). A kind the FEM's computed modes
/// did not show has found = false (its keys are absent from the file).
struct ChainFemRecord {
  std::string wing_file;                  ///< the wing reduced, as reduce was given it
  reduction::ModeMatch bending, torsion;  ///< chain_hz, fem_hz, relative_error, mac
  /// The static rows of reduce's report (reduction::ChainFemComparison: tip deflection, the
  /// tip body's bending rotation and twist per unit load, chain and FEM), so that run and
  /// check repeat reduce's static warning too; absent in files written before 6 Dec.
  struct StaticRows {
    double measure_s = 0.0;       ///< axis position of the deflection and twist rows [m]
    double bending_body_s = 0.0;  ///< inboard joint of the tip body [m]
    reduction::StaticMatch tip_deflection, tip_bending_rotation, tip_twist;
  };
  std::optional<StaticRows> statics;
};

/// \brief What a chain file keeps of reduce's comparison \p c of the chain with the FEM of
/// \p wing_file: the first modes and the static rows.
ChainFemRecord chain_fem_record(const std::string& wing_file, const reduction::ChainFemComparison& c);

/// Reads and checks a chain file; with \p fem, also its [fem_comparison] (nullopt when the
/// file has none: a chain written by hand or by an earlier flapsim).
/// \throws flapsim::InputError naming file, line and key (missing keys, bad values,
///         non-physical inertia tensors, unknown keys)
mbd::ChainModel read_chain_file(const std::string& path, std::optional<ChainFemRecord>* fem = nullptr);

/// Same from text (tests); \p name is used as the file name in errors.
mbd::ChainModel parse_chain_text(std::string_view text, const std::string& name,
                                 std::optional<ChainFemRecord>* fem = nullptr);

/// The chain as chain-file text (SI, length_unit = "m", round-trip exact numbers), with
/// \p fem as its [fem_comparison] table when given.
std::string format_chain_file(const mbd::ChainModel& chain, const ChainFemRecord* fem = nullptr);

/// Writes the chain file atomically (temporary name, then rename).
/// \throws flapsim::OutputError
void write_chain_file(const std::filesystem::path& path, const mbd::ChainModel& chain,
                      const ChainFemRecord* fem = nullptr);

}  // namespace flapsim::io
