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

/// \brief The equivalent beam and the chain for ParaView, one data set per kind of
/// thing, each with only the fields that apply to it (docs/reduction.md, "Files"):
///  - DIR/reduction/stations.vtp: the beam stations along the flexural axis, one
///    polyline; point data s_m, EI_N_m2, GJ_N_m2, m_per_length_kg_per_m, I_alpha_kg_m,
///    n_ea_m, n_cg_m, in_tip_zone;
///  - DIR/reduction/bodies.vtp: one line per body from its inboard to its outboard
///    joint; cell data body, mass_kg, length_m;
///  - DIR/reduction/joints.vtp: the jointed bodies' inboard joints as vertices; point
///    data joint (the body it carries, 1-based), k_theta_N_m_per_rad, k_alpha_N_m_per_rad;
///  - DIR/reduction/centres_of_mass.vtp: one vertex per body; point data body, mass_kg;
///  - DIR/reduction.vtm: a VTK multiblock file naming the four as blocks, so ParaView
///    opens them together.
/// \param dir  the output folder
/// \throws OutputError
void write_reduction_vtk(const std::filesystem::path& dir, const reduction::BeamProperties& beam,
                         const reduction::LumpedChain& chain);

/// \brief report.md: method, masses, chain against FEM (first bending and torsion
/// frequencies with MAC, static tip responses), the FEM and chain modes and the bodies.
/// \param wing_file  the wing file, named in the title
std::string reduction_report(const std::string& wing_file, const reduction::BeamProperties& beam,
                             const reduction::LumpedChain& chain,
                             const reduction::ChainFemComparison& comparison);

/// \brief The report's note when the fitted axis left the planform and the flexural axis
/// was taken instead (reduction::BeamProperties::fitted_axis_rejected); else "".
std::string fitted_axis_note(const reduction::BeamProperties& beam);

/// \brief summary.json of the reduction: sizes, masses, the chain-against-FEM numbers.
/// \throws OutputError
void write_reduction_summary(const std::filesystem::path& path, const reduction::BeamProperties& beam,
                             const reduction::LumpedChain& chain,
                             const reduction::ChainFemComparison& comparison);

/// \brief A relative error as signed percent text, e.g. "+1.62 %".
std::string format_percent(double fraction);

}  // namespace flapsim::io
