#pragma once
/// \file after_run_notes.hpp
/// \brief What a run's results say about it after the run, in a few words: the notes that
/// sweep.csv's message column, the optimiser's evaluations.csv and its report carry beside
/// the case's own warnings, as `flapsim run`'s report warns of the same (run_results.hpp):
/// a chain bent beyond its springs (large_deflection_note), a shed sheet come apart near the
/// wing (shed_sheet_came_apart), a tip that zigzags from step to step (tip_zigzagged).

#include <string>
#include <vector>

#include "pipeline/app/run_results.hpp"

namespace flapsim::app {

/// The notes of \p results in that order ("large deflection: tip bend 103.5 deg, twist 31.8
/// deg (over 30 deg)", "shed sheet came apart: CL changed by 251 in a step (into step 169)",
/// "tip zigzags from step to step: 5.86 deg (step 75)"); empty when none.
std::vector<std::string> after_run_notes(const RunResults& results);

/// What the optimiser tells of an optimum whose run carries such notes: how to keep the search
/// where the model holds. "" when it carries none.
std::string after_run_advice(const RunResults& results);

}  // namespace flapsim::app
