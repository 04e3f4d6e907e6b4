#pragma once
/// \file keys_that_change_nothing.hpp
/// \brief A varied key whose values give every case the same run is refused before any case
/// runs, by `flapsim sweep` and `flapsim optimize` alike (docs/sweeps.md, "Keys that change
/// nothing"; docs/optimize.md): every row would be the same numbers, or the objective flat,
/// and the user would believe they had varied it. Two ways a key changes nothing:
///  - something else sets what it sets: a FEM case's structure.element_size_mm (or
///    vein_element_size_mm) sets the FEM's mesh in place of the wing file's
///    mesh.element_size (vein_element_size); the command's --vtk-every sets every case's
///    ParaView series in place of output.vtk_every;
///  - the cases resolve to the same inputs: points that differ only in the key's value have
///    the same inputs hash (io::input_hash: every field of the resolved case and wing the
///    results depend on), e.g. wing.surface.twist_axis of a wing with no twist. A key that
///    changes the inputs of some points (a grid where it matters for some values of another
///    key) is not refused.

#include <string>
#include <vector>

#include "pipeline/app/sweep/sweep_case.hpp"
#include "pipeline/app/sweep/sweep_runner.hpp"

namespace flapsim::sweep {

/// The varied keys of a sweep or an optimisation as the user gave them, for the messages.
struct VariedKeys {
  std::string command;  ///< "sweep", "optimisation": "the sweep's --vtk-every", "drop it from the sweep"
  std::vector<std::string> keys;   ///< the varied keys, in the order of the points' values
  std::vector<std::string> given;  ///< how each key's values were given: "--vary KEY = 0.3, 0.5"
  std::string file;                ///< where the keys were given: the case file (--vary), a case table
  int line = 0;                    ///< the line there: 0 for --vary, a case table's header line
};

/// \brief Refuses a varied output.vtk_every: the command's --vtk-every sets every case's
/// ParaView series. Needs no resolved case, so a command may call it before resolving its
/// points (an optimisation would otherwise refuse the key as an integer key, without saying
/// that varying it is useless).
/// \throws flapsim::InputError at varied.file and varied.line, naming the key
void refuse_interval_the_command_sets(const VariedKeys& varied, int vtk_every);

/// \brief Refuses the first varied key that changes nothing in these runs (the interval
/// above for every key first, then each key in order: a mesh size the case sets, the same
/// inputs at every value).
/// \param points    the points compared: each key's value in the order of varied.keys
/// \param cases     the resolved case of each point, in the same order
/// \param vtk_every the command's --vtk-every (every case's ParaView interval)
/// \throws flapsim::InputError at varied.file and varied.line, naming the key, how its values
///         were given and what sets what it sets
void refuse_keys_that_change_nothing(const VariedKeys& varied, const SweepInputs& inputs,
                                     const std::vector<CasePoint>& points,
                                     const std::vector<ResolvedCase>& cases, int vtk_every);

/// \brief The same for the cases of a sweep's plan: --vary values named at the case file,
/// a case table's columns at the table's header line.
void refuse_keys_that_change_nothing(const SweepInputs& inputs, const SweepPlan& plan,
                                     const std::vector<ResolvedCase>& cases, int vtk_every);

}  // namespace flapsim::sweep
