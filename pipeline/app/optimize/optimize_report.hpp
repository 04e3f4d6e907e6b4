#pragma once
/// \file optimize_report.hpp
/// \brief DIR/report.md of `flapsim optimize`: the problem (case, keys and bounds,
/// objective, constraints, algorithm), the start, every evaluation of the search with its
/// values, objective and constraints, the optimum (or why there is none), why the search
/// stopped, and how to run the optimum (docs/optimize.md, "Outputs").

#include <filesystem>
#include <string>

#include "pipeline/app/optimize/optimizer.hpp"

namespace flapsim::optimize {

/// \brief The report's Markdown text.
/// What a user can do about the warnings of the optimum's run (evaluation_notes): for what its
/// results say after the run (app::after_run_advice: a chain beyond its range, a shed sheet come
/// apart, a zigzagging tip) the constraints that keep the search where the model holds;
/// otherwise that the result maximised is the model's.
std::string optimum_warning_advice(const Evaluation& best);

std::string optimize_report(const std::string& case_file, const Problem& problem, const OptimizeReport& report);

/// \brief Writes it atomically as DIR/report.md.
/// \throws io::OutputError
void write_optimize_report(const std::filesystem::path& dir, const std::string& case_file, const Problem& problem,
                           const OptimizeReport& report);

}  // namespace flapsim::optimize
