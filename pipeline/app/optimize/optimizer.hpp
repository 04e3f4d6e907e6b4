#pragma once
/// \file optimizer.hpp
/// \brief `flapsim optimize` (docs/optimize.md): NLopt (nlopt_search.hpp) searches the
/// bounded keys for the largest value of a result, subject to constraints on results; each
/// point it asks for is an evaluation (point_evaluator.hpp: the case resolved and checked
/// as a sweep's, run, or its earlier results reused), recorded in DIR/evaluations.csv.
///
/// 1. Before any run: the start (each key at the case's own value, clamped into its
///    bounds; the middle of the bounds when the files do not write the key) and each
///    key at either bound and at an inner value that is no whole number are resolved and
///    checked, so a bad key, a bound that makes an invalid case, an integer key or a key
///    that changes nothing at those points (bounds_check.hpp) stops with exit status 2 and
///    nothing run.
/// 2. The search: one NLopt search per start (--starts N; start_points.hpp), each on one
///    worker, the starts spread over MPI ranks under mpirun/srun by the sweep's scheduler
///    (sweep::schedule_cases); a run uses its rank's share of the cores. A progress line per
///    evaluation (stderr). Rank 0 writes evaluations.csv: its own evaluations as they come,
///    another rank's when its search ends (their runs are in the shared DIR/runs/).
/// 3. The optimum is the best evaluated point, over the starts in their order, that satisfies every constraint (not
///    NLopt's last iterate, which COBYLA may leave slightly infeasible): DIR/optimum.toml
///    and DIR/report.md. No evaluated point satisfies the constraints: report.md says so,
///    no optimum.toml, and flapsim::InputError naming --constraint (exit status 2).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/app/optimize/evaluation_table.hpp"
#include "pipeline/app/optimize/nlopt_search.hpp"
#include "pipeline/app/optimize/optimize_problem.hpp"

namespace flapsim::optimize {

struct OptimizeOptions {
  std::filesystem::path output_dir;
  std::string chain_file;          ///< for every run (flapsim run --chain)
  std::string wing_file;           ///< flown by every run instead of the case's 'wing' (flapsim run --wing)
  double spring_scale = 1.0;       ///< for every run (a varied spring_scale replaces it)
  int vtk_every = 0;               ///< ParaView series of each run (0: none)
  bool force = false;              ///< run every point, also those an earlier run evaluated
  bool quiet = false;              ///< no progress lines
  std::optional<Algorithm> algorithm;  ///< none: BOBYQA, or COBYLA with constraints
  int starts = 1;                  ///< independent searches (start_points.hpp), spread over MPI ranks
  SearchOptions search;            ///< its algorithm is set from `algorithm`
};

struct OptimizeReport {
  bool root = true;                    ///< this process holds the table (rank 0, or no MPI)
  int ranks = 1;
  std::size_t starts = 1;
  std::vector<std::size_t> start_of;   ///< the start (1-based) of each evaluation
  Algorithm algorithm = Algorithm::bobyqa;
  std::vector<double> start;           ///< the start, one value per bound
  std::vector<Evaluation> evaluations; ///< the distinct points of this search, in order
  std::vector<std::size_t> numbers;    ///< their numbers in evaluations.csv
  std::optional<std::size_t> best;     ///< index into evaluations: the optimum
  std::size_t runs = 0;                ///< evaluations run (the others were kept)
  std::string stop_reason;
  bool max_evaluations_reached = false;
  std::filesystem::path optimum_case;  ///< DIR/optimum.toml (empty: none)
  double optimum_spring_scale = 1.0;
  double wall_s = 0.0;
};

/// \brief The objective's or a constraint's value of an evaluation (an integer result as a
/// number; NaN when not set).
double result_value(const Evaluation& e, std::size_t result);

/// \brief Runs the optimisation.
/// A run that fails numerically ends its start's search (its row in evaluations.csv says
/// status "failed"; report.md says which start stopped and why); the other starts go on,
/// and the optimum is the best of the points that completed, as a sweep goes on past a
/// failed case.
/// \throws flapsim::InputError before any run for bad input, and after the search when no
///         evaluated point satisfies the constraints; NumericalFailure when no point
///         completed and a run failed; app::Interrupted; io::OutputError
OptimizeReport run_optimization(const std::string& case_file, const Problem& problem, const OptimizeOptions& options);

}  // namespace flapsim::optimize
