#pragma once
/// \file point_evaluator.hpp
/// \brief One evaluation of `flapsim optimize`: the case at a point of the varied keys,
/// resolved and checked as a sweep's case (sweep::resolve_case: the case and wing files
/// with the values set, checked as `flapsim run` checks them), then either the results an
/// earlier run left for the same inputs (the folder's summary.json has status "ok" and the
/// inputs hash: sweep::kept_results; with --vtk-every, the folder holds the ParaView series:
/// sweep/kept_series.hpp) or a run of the case (app::run_case) in the folder
/// DIR/runs/<inputs hash>/ (history.csv, summary.json), cleared of an earlier run's files
/// first. A run uses the local cores.

#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/app/optimize/evaluation_table.hpp"
#include "pipeline/app/optimize/optimize_problem.hpp"
#include "pipeline/app/sweep/sweep_case.hpp"

namespace flapsim::optimize {

/// \brief The point of the varied keys at \p x (one value per bound, in the bounds' order).
sweep::CasePoint point_at(const Problem& problem, const std::vector<double>& x);

struct EvaluatorOptions {
  std::filesystem::path runs_dir;  ///< DIR/runs
  int vtk_every = 0;               ///< ParaView series of each run every N steps (0: none)
  bool force = false;              ///< run every point, also those an earlier run evaluated
  int rank = 0;                    ///< MPI rank of this process (for the table)
};

/// An evaluation and, when the run did not complete, what stopped it.
struct EvaluationOutcome {
  Evaluation evaluation;
  std::exception_ptr error;  ///< null when status is "ok"
};

class PointEvaluator {
 public:
  PointEvaluator(sweep::SweepInputs inputs, EvaluatorOptions options);

  /// \brief The case at \p point, resolved and checked.
  /// \throws flapsim::InputError as sweep::resolve_case
  sweep::ResolvedCase resolve(const sweep::CasePoint& point) const;

  /// \brief Evaluates the point: the earlier results if its folder holds them, else a run.
  /// Never throws for a failed run (the outcome carries the error); throws InputError for a
  /// point that does not resolve, io::OutputError when the folder cannot be made or locked.
  EvaluationOutcome evaluate(const sweep::CasePoint& point) const;

  /// \brief The folder of a point's run.
  std::filesystem::path folder(const std::string& inputs_hash) const { return options_.runs_dir / inputs_hash; }

  const sweep::SweepInputs& inputs() const { return inputs_; }

 private:
  sweep::SweepInputs inputs_;
  EvaluatorOptions options_;
  std::string host_;
};

}  // namespace flapsim::optimize
