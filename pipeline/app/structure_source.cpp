#include "pipeline/app/structure_source.hpp"

#include <cstdio>

#include "fem/wing_fem.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/reduction_input_limit.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/chain_file.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/clamped_wing_analysis.hpp"
#include "reduction/reduction_failure.hpp"
#include "reduction/reduction_report.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::app {

namespace {
// FEM modes computed to compare a chain reduced in process with its wing (reduce's default --modes).
constexpr int kComparedFemModes = 12;
}  // namespace

StructureChoice choose_structure(const io::Case& c, const std::string& chain_override,
                                 const wings::Wing* wing) {
  using Kind = io::Case::Structure::Kind;
  StructureChoice s;
  if (c.structure.kind == Kind::Rigid) {
    if (!wing)
      throw InputError(c.file, c.line_of("structure.kind"), "structure.kind",
                       "a rigid wing is built from the wing file: name one with 'wing'");
    s.chain = make_rigid_chain(*wing);
    s.description = "rigid wing (one body welded to the base)";
    return s;
  }
  if (c.structure.kind == Kind::Fem) {
    // The FEM is built by the setup (fem_structure_setup.hpp); the rigid chain of the wing
    // stands for it where a chain is read (its outline length, the chain-only warnings).
    if (!wing)
      throw InputError(c.file, c.line_of("structure.kind"), "structure.kind",
                       "the FEM structure is built from the wing file: name one with 'wing'");
    s.chain = make_rigid_chain(*wing);
    s.description = "the wing's FEM (geometrically nonlinear shells and veins)";
    return s;
  }
  const std::string path = !chain_override.empty() ? chain_override : c.chain_file;
  if (!path.empty()) {
    s.chain = io::read_chain_file(path, &s.chain_fem);
    s.chain_file = path;
    // The case's body count must be the chain's: markers and loads name bodies by number.
    if (s.chain.num_bodies() != c.structure.bodies)
      throw InputError(c.file, c.structure.bodies_line, "structure.bodies",
                       "the case says " + std::to_string(c.structure.bodies) + " bodies, but the chain file " +
                           path + " has " + std::to_string(s.chain.num_bodies()) +
                           ": set bodies = " + std::to_string(s.chain.num_bodies()) +
                           " or reduce the wing again with 'flapsim reduce --bodies " +
                           std::to_string(c.structure.bodies) + "'");
    s.description = "chain file " + path + " (" + std::to_string(s.chain.num_bodies()) + " bodies)";
    return s;
  }
  if (wing) {
    // No chain given: the wing's FEM reduced here, as `flapsim reduce --bodies N` would
    // (docs/reduction.md), without writing its files.
    const fem::WingFem fem = fem::build_wing_fem(*wing);
    s.reduced_fem_dofs = static_cast<int>(fem.model.mesh.num_dofs());
    try {
      // A clamp or mesh that leaves too little free is the wing file's error (exit 2).
      const reduction::ClampedWingAnalysis analysis = reduce_wing_input_checked(*wing, [&] {
        return reduction::ClampedWingAnalysis(fem.model.mesh, fem.system, fem.root_clamp, {});
      });
      const reduction::LumpedChain lumped = reduce_wing_input_checked(
          *wing, [&] { return reduction::lump_into_chain(analysis, c.structure.bodies); });
      s.chain = lumped.chain;
      // The chain against the wing's first FEM modes, as reduce compares them (its default
      // 12 modes; about 0.5 s for the hawkmoth): run and check warn as reduce does. A modal
      // solve that fails leaves the run without the comparison, not without its chain.
      try {
        const fem::WingModes modes = fem::wing_modes(fem, kComparedFemModes);
        const reduction::ChainFemComparison cmp =
            reduction::compare_chain_with_fem(analysis, lumped, modes.modes, modes.kinds);
        s.chain_fem = io::chain_fem_record(c.wing_file, cmp);
      } catch (const std::exception&) {
        s.chain_fem.reset();
      }
      if (analysis.fitted_axis_rejected())
        std::fprintf(stderr,
                     "flapsim: note: the fitted axis of %s left the planform (a swept wing?); the chain's axis is "
                     "the line through the pivot and the sections' mid-chords (docs/reduction.md)\n",
                     c.wing_file.c_str());
    } catch (const reduction::ReductionFailure& e) {
      throw NumericalFailure("cannot reduce the wing " + c.wing_file + " to " +
                             std::to_string(c.structure.bodies) + " bodies: " + e.what());
    }
    s.description = "wing reduced in process (FEM + reduction, " +
                    std::to_string(s.chain.num_bodies()) + " bodies)";
    return s;
  }
  throw InputError(c.file, 0, "chain",
                   "a flexible wing needs its bar chain or its wing: give 'chain = \"...\"' or "
                   "'wing = \"...\"' in the case, or 'flapsim run CASE --chain FILE'");
}

}  // namespace flapsim::app
