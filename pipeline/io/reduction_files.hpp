#pragma once
/// \file reduction_files.hpp
/// \brief The files of `flapsim reduce` (docs/reduction.md): the equivalent beam as a
/// table, the beam and the chain for ParaView, the report of how well the chain
/// reproduces the FEM, and its numbers as summary.json. Each is written atomically.

#include <filesystem>
#include <string>

#include "reduction/beam_properties.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/reduction_report.hpp"

namespace flapsim::io {

/// \brief beam.csv: one row per station — s, y, m', x_cg, x_ea, n_cg, n_ea, EI, GJ,
/// I_α and whether it lies in the loaded tip zone (SI units in the column names).
/// \throws OutputError
void write_beam_csv(const std::filesystem::path& path, const reduction::BeamProperties& beam);

/// \brief reduction.vtp: the beam stations along the flexural axis (point data EI, GJ,
/// m', I_α, n_ea, n_cg), the chain's joints and the bodies' centres of mass (body_mass_kg);
/// point data kind_station0_joint1_com2 tells them apart.
/// \throws OutputError
void write_reduction_vtp(const std::filesystem::path& path, const reduction::BeamProperties& beam,
                         const reduction::LumpedChain& chain);

/// \brief report.md: method, masses, chain against FEM (first bending and torsion
/// frequencies with MAC, static tip responses), the FEM and chain modes and the bodies.
/// \param wing_file  the wing file, named in the title
std::string reduction_report(const std::string& wing_file, const reduction::BeamProperties& beam,
                             const reduction::LumpedChain& chain,
                             const reduction::ChainFemComparison& comparison);

/// \brief summary.json of the reduction: sizes, masses, the chain-against-FEM numbers.
/// \throws OutputError
void write_reduction_summary(const std::filesystem::path& path, const reduction::BeamProperties& beam,
                             const reduction::LumpedChain& chain,
                             const reduction::ChainFemComparison& comparison);

/// \brief A relative error as signed percent text, e.g. "+1.62 %".
std::string format_percent(double fraction);

}  // namespace flapsim::io
