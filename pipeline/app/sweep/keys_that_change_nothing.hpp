#pragma once
/// \file keys_that_change_nothing.hpp
/// \brief A varied key whose values give every case the same run is refused before any case
/// runs (docs/sweeps.md, "Keys that change nothing"): every row would be the same numbers,
/// and the user would believe they had swept it. Two ways a key changes nothing:
///  - something else sets what it sets: a FEM case's structure.element_size_mm (or
///    vein_element_size_mm) sets the FEM's mesh in place of the wing file's
///    mesh.element_size (vein_element_size); the sweep's --vtk-every sets every case's
///    ParaView series in place of output.vtk_every;
///  - the cases resolve to the same inputs: points that differ only in the key's value have
///    the same inputs hash (io::input_hash: every field of the resolved case and wing), e.g.
///    wing.surface.twist_axis of a wing with no twist. A key that changes the inputs of some
///    points (a grid where it matters for some values of another key) is not refused.

#include <string>
#include <vector>

#include "pipeline/app/sweep/sweep_case.hpp"
#include "pipeline/app/sweep/sweep_runner.hpp"

namespace flapsim::sweep {

/// \brief Refuses the first varied key of \p plan that changes nothing in these runs.
/// \param cases     the resolved case of each point of the plan, in order
/// \param vtk_every the sweep's --vtk-every (every case's ParaView interval)
/// \throws flapsim::InputError naming the key, its values and what sets what it sets: for
///         --vary values, the case file and the key; for a case table, the table's header line
///         and the column
void refuse_keys_that_change_nothing(const SweepInputs& inputs, const SweepPlan& plan,
                                     const std::vector<ResolvedCase>& cases, int vtk_every);

}  // namespace flapsim::sweep
