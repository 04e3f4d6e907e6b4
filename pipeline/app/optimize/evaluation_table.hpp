#pragma once
/// \file evaluation_table.hpp
/// \brief DIR/evaluations.csv of `flapsim optimize`: one row per evaluated point, in the
/// order they were first evaluated, kept across reruns (docs/optimize.md, "Outputs").
/// Columns: evaluation (1-based), the varied keys (their dotted names), every result of a
/// run (app::kRunResults, summary.json's keys, among them inputs_hash, io::input_hash of the
/// resolved case, and status; numbers in shortest round-trip form, "" when not set; a
/// result named as a varied key, spring_scale, is that key's column), then message, rank
/// and host. The whole table is rewritten atomically after every evaluation, so an
/// interrupted optimisation leaves a valid table of the points evaluated so far.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"

namespace flapsim::optimize {

/// One evaluated point: where it is, its inputs' fingerprint, its results, how it ended.
struct Evaluation {
  sweep::CasePoint point;
  std::string inputs_hash;
  app::RunResults results;
  std::string status;   ///< "ok", "failed" (numerical failure), "error", "interrupted"
  std::string message;  ///< the error; "kept" when an earlier run's results were reused
  int rank = 0;
  std::string host;
};

/// \brief What the evaluation's run was warned of, in a few words: its case's warnings
/// (summary.json's "warnings") and a tip deflection beyond the chain's range
/// (app::large_deflection_note), '; '-separated; "" when none.
std::string evaluation_notes(const Evaluation& e);

class EvaluationTable {
 public:
  /// Reads the rows of an earlier run from \p path when its header is the one of \p keys
  /// (a table of other keys is replaced).
  EvaluationTable(std::filesystem::path path, std::vector<std::string> keys);

  /// \brief Adds the evaluation's row unless a row with its inputs hash is there already
  /// (a point evaluated by an earlier run keeps its row and number), then rewrites the
  /// file atomically.
  /// \return the point's evaluation number (1-based)
  /// \throws io::OutputError
  std::size_t record(const Evaluation& e);

  std::size_t rows() const { return rows_.size(); }
  const std::vector<std::string>& header() const { return header_; }

 private:
  std::filesystem::path path_;
  std::vector<std::string> header_;
  std::vector<std::size_t> results_;  ///< the results in the table, by index in kRunResults
  std::size_t hash_column_ = 0, status_column_ = 0;
  std::vector<std::vector<std::string>> rows_;
  std::map<std::string, std::size_t> row_of_hash_;
};

}  // namespace flapsim::optimize
