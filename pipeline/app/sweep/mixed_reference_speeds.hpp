#pragma once
/// \file mixed_reference_speeds.hpp
/// \brief The note under a sweep's table when its rows' coefficients are on different
/// reference speeds (docs/sweeps.md, "Coefficients on different reference speeds").
///
/// A run's CL and CD are on the free-stream speed when there is a free stream, else on the
/// flapping speed at r2 (run_results.hpp, reference_kind). A sweep over the free stream
/// that starts in hover therefore mixes the two in one column: the rigid hawkmoth hover of
/// cases/hover.toml gave mean CL 3.43 in hover (on its 2.22 m/s flapping speed), 17.41 at
/// U∞ = 1 m/s and 2.06 at 3 m/s (on U∞), for lifts of 8.5, 8.7 and 9.3 mN.

#include <string>
#include <vector>

#include "pipeline/app/sweep/sweep_table.hpp"

namespace flapsim::sweep {

/// \brief "" when every row with results has its coefficients on one kind of reference speed,
/// else a note naming how many rows are on each kind and what to compare instead.
std::string mixed_reference_speeds_note(const std::vector<SweepRow>& rows);

}  // namespace flapsim::sweep
