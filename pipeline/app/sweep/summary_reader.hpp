#pragma once
/// \file summary_reader.hpp
/// \brief Reading a run's summary.json back into its results (run_results.hpp): the sweep
/// keeps the results of cases an earlier run completed, and ranks send their results to
/// rank 0 as summary.json text. Reads the flat object io::SummaryJson writes: each key of
/// kRunResults is read as its kind (numbers in shortest round-trip form read back to the
/// same double; null is NaN); keys that are not results are ignored.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "pipeline/app/run_results.hpp"

namespace flapsim::sweep {

/// \brief The results in a summary.json text; std::nullopt if it is not a flat JSON
/// object of the kinds the definition expects.
std::optional<app::RunResults> parse_summary_json(std::string_view text);

/// \brief The results in a summary.json file; std::nullopt if it is missing or does not read.
std::optional<app::RunResults> read_summary_results(const std::filesystem::path& summary_json);

/// \brief The results of an earlier run of a case that can be kept: its summary.json
/// exists, reads, has status "ok" and the inputs hash \p inputs_hash; else std::nullopt.
std::optional<app::RunResults> kept_results(const std::filesystem::path& summary_json,
                                            const std::string& inputs_hash);

}  // namespace flapsim::sweep
