#pragma once
/// \file structure_source.hpp
/// \brief Where the structure of a run comes from: a rigid wing is a one-body chain
/// welded to the base; a flexible wing is the chain file given on the command line
/// (`flapsim run --chain`), else the case's `chain` file, else the wing reduced in
/// process (FEM + reduction with `structure.bodies` bodies).

#include <optional>
#include <string>

#include "mbd/chain_model.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/chain_file.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::app {

struct StructureChoice {
  mbd::ChainModel chain;
  std::string description;  ///< e.g. "chain file out/hawkmoth/chain.toml (10 bodies)"
  std::string chain_file;   ///< the chain file read ("" for a rigid wing or one reduced in process)
  /// The chain against the wing's FEM modes: a chain file's [fem_comparison], if it has
  /// one; for a wing reduced in process, computed here as reduce does.
  std::optional<io::ChainFemRecord> chain_fem;
  int reduced_fem_dofs = 0;  ///< DOFs of the wing's FEM reduced in process (0: none was)
};

/// \brief Chooses and builds the structure of a case (see the file comment).
/// \param chain_override  chain file from the command line ("" = none)
/// \param wing            the case's wing, or nullptr
/// \throws flapsim::InputError naming the case file and key when nothing usable is given;
///         what the FEM and the reduction throw for a wing they cannot mesh or reduce
StructureChoice choose_structure(const io::Case& c, const std::string& chain_override,
                                 const wings::Wing* wing);

}  // namespace flapsim::app
