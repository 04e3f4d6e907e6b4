#include "pipeline/app/optimize/optimizer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include <omp.h>

#include <algorithm>
#include <csignal>
#include <mutex>
#include <sstream>
#include <thread>

#include "pipeline/app/interruption.hpp"
#include "pipeline/app/omp_environment.hpp"
#include "pipeline/app/optimize/bounds_check.hpp"
#include "pipeline/app/optimize/optimize_report.hpp"
#include "pipeline/app/optimize/optimum_case.hpp"
#include "pipeline/app/optimize/point_evaluator.hpp"
#include "pipeline/app/optimize/start_points.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/case_scheduler.hpp"
#include "pipeline/app/sweep/mpi_world.hpp"
#include "pipeline/app/sweep/summary_reader.hpp"
#include "pipeline/app/sweep/sweep_table.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/folder_lock.hpp"
#include "pipeline/io/output_manifest.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::optimize {

namespace {

/// A point the search asked for inside the bounds whose case does not resolve (a varied
/// outline that crosses itself, say): the start's search ends there, as at a failed run.
struct InvalidPoint : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;

// A constraint's violation scaled by its limit (order one for COBYLA's linear models).
double scaled_violation(const Constraint& c, double value) {
  const double scale = std::abs(c.limit) > 0.0 ? std::abs(c.limit) : 1.0;
  return c.violation(value) / scale;
}

bool feasible(const Problem& p, const Evaluation& e) {
  if (e.status != "ok") return false;
  for (const Constraint& c : p.constraints)
    if (!(c.violation(result_value(e, c.result)) <= 0.0)) return false;
  return true;
}

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A start's search as the scheduler carries it to rank 0 (sweep::CaseOutcome's message):
// the first line why it stopped (or the error), then one line per evaluation in order:
// "<inputs hash> <run|kept> <value> <value> ...". Rank 0 reads each evaluation's results
// from DIR/runs/<hash>/summary.json (the ranks share the output folder, as a sweep's do).
std::string encode_start(const std::string& first_line, const std::vector<Evaluation>& evaluations) {
  std::string s = first_line;
  for (const char c : {'\n', '\r'}) std::replace(s.begin(), s.end(), c, ' ');
  for (const Evaluation& e : evaluations) {
    // Appended piece by piece (GCC 12's -Wrestrict false positive, GCC bug 105329).
    s.append("\n").append(e.inputs_hash).append(e.message == "kept" ? " kept" : " run");
    for (const sweep::Assignment& a : e.point) s.append(" ").append(io::format_number(a.value));
  }
  return s;
}

std::vector<Evaluation> decode_start(const Problem& p, const std::string& message, const std::filesystem::path& runs,
                                     int rank, const std::string& host, std::string& first_line) {
  std::istringstream in(message);
  std::getline(in, first_line);
  std::vector<Evaluation> out;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    Evaluation e;
    std::string how;
    fields >> e.inputs_hash >> how;
    for (const Bound& b : p.bounds) {
      std::string v;
      fields >> v;
      e.point.push_back({b.key, std::stod(v)});
    }
    if (auto r = sweep::read_summary_results(runs / e.inputs_hash / "summary.json")) e.results = std::move(*r);
    e.status = e.results.text("status").empty() ? "error" : e.results.text("status");
    e.message = how == "kept" ? "kept" : e.results.text("error");
    e.rank = rank;
    e.host = host;
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace

double result_value(const Evaluation& e, std::size_t result) {
  const auto& v = e.results.at(result);
  if (!v) return std::numeric_limits<double>::quiet_NaN();
  if (const auto* d = std::get_if<double>(&*v)) return *d;
  if (const auto* n = std::get_if<std::int64_t>(&*v)) return static_cast<double>(*n);
  return std::numeric_limits<double>::quiet_NaN();
}

OptimizeReport run_optimization(const std::string& case_file, const Problem& problem, const OptimizeOptions& options) {
  const auto t0 = Clock::now();
  OptimizeReport report;
  report.algorithm = options.algorithm.value_or(problem.constraints.empty() ? Algorithm::bobyqa : Algorithm::cobyla);
  if (report.algorithm == Algorithm::bobyqa && !problem.constraints.empty())
    throw InputError("", 0, "--algorithm", "bobyqa takes bounds only, not --constraint: use cobyla");
  for (std::size_t i = 0; i < problem.bounds.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (problem.bounds[i].key == problem.bounds[j].key)
        throw InputError("", 0, "--vary", "'" + problem.bounds[i].key + "' is varied twice");
  if (options.starts < 1 || (options.starts > 1 && problem.bounds.size() > 20))
    throw InputError("", 0, "--starts", "1 start, or several with at most 20 varied keys");

  sweep::MpiWorld world;
  report.root = world.rank() == 0;
  report.ranks = world.size();
  const sweep::SweepInputs inputs{case_file, options.chain_file, options.spring_scale, options.wing_file};
  EvaluatorOptions eo;
  eo.runs_dir = options.output_dir / "runs";
  eo.vtk_every = options.vtk_every;
  eo.force = options.force;
  eo.rank = world.rank();
  const PointEvaluator evaluator(inputs, eo);
  const std::string host = sweep::host_name();

  // 1. The start and the bounds, checked before anything is written (on every rank: the
  //    same input gives each the same verdict).
  std::vector<double> lo, hi;
  for (const Bound& b : problem.bounds) {
    const std::optional<double> own = value_in_inputs(inputs, b.key);
    report.start.push_back(own ? std::clamp(*own, b.lo, b.hi) : 0.5 * (b.lo + b.hi));
    lo.push_back(b.lo);
    hi.push_back(b.hi);
  }
  // Each key at either bound and at an inner value, and a key that changes nothing there.
  check_start_and_bounds(evaluator, problem, report.start, options.vtk_every);
  const std::vector<std::vector<double>> starts =
      start_points(report.start, lo, hi, static_cast<std::size_t>(options.starts));

  // A folder holding another command's report.md (reduce's) is not overwritten (every rank:
  // the same verdict).
  io::refuse_clashing_outputs(options.output_dir, "optimize");
  std::optional<io::FolderLock> lock;  // rank 0: no other command writes into DIR meanwhile
  std::optional<EvaluationTable> table;
  std::vector<std::string> keys;
  for (const Bound& b : problem.bounds) keys.push_back(b.key);
  if (report.root) {
    io::ensure_directory(options.output_dir);
    io::ensure_directory(eo.runs_dir);
    lock.emplace(options.output_dir, "optimize");
    // An earlier search's end (its optimum and report) goes now; this search writes its
    // own at its end. Left, they stood beside this search's evaluations.csv after it found
    // no optimum (exit 2, "no optimum.toml written") or was interrupted, and
    // `flapsim run DIR/optimum.toml` and make optimize-plots used another problem's optimum.
    for (const char* earlier : {"optimum.toml", "optimum_wing.toml", "report.md"}) {
      std::error_code ec;
      std::filesystem::remove(options.output_dir / earlier, ec);
      if (ec)
        throw io::OutputError(options.output_dir / earlier,
                              "cannot remove an earlier search's file: " + ec.message());
    }
    table.emplace(options.output_dir / "evaluations.csv", keys);
  }
  // The threads of a run: this thread's (--threads, or the cores); under MPI each rank's
  // share of its machine's cores. Set on the worker thread that runs the search (a new
  // thread does not inherit the OpenMP setting of this one).
  int omp_threads = omp_get_max_threads();
  if (world.active() && !app::omp_num_threads_set()) {
    const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    omp_threads = std::max(1, cores / std::max(1, world.ranks_on_host()));
  }

  // 2. The searches, one per start, over the ranks (sweep::schedule_cases, one at a time
  //    per rank: a run uses the rank's cores). Rank 0 records its own evaluations as they
  //    come, the others' when their search ends.
  std::mutex mutex;  // the table and the line on stderr
  const std::string objective_key(app::kRunResults[problem.objective].key);
  const sweep::RunCase run = [&](std::size_t start) {
    sweep::CaseOutcome o;
    o.rank = world.rank();
    o.host = host;
    if (app::pending_interrupt() != 0) {
      o.status = "not run";
      return o;
    }
    omp_set_num_threads(omp_threads);
    std::vector<Evaluation> evaluations;
    // Each evaluation's number: its row's in evaluations.csv where this rank keeps the table
    // (the numbers report.md uses, past an earlier optimisation's rows in the folder), else
    // its place in this start's search.
    std::vector<std::size_t> numbers;
    std::optional<std::size_t> best;
    const Evaluate evaluate = [&](const std::vector<double>& x) {
      const sweep::CasePoint point = point_at(problem, x);
      EvaluationOutcome eval;
      try {
        eval = evaluator.evaluate(point);
      } catch (const InputError& err) {  // only a point that does not resolve (point_evaluator.hpp)
        throw InvalidPoint("the point " + sweep::describe(point) + " is not a valid case: " + err.what());
      }
      evaluations.push_back(eval.evaluation);
      const Evaluation& e = evaluations.back();
      if (feasible(problem, e) && std::isfinite(result_value(e, problem.objective)) &&
          (!best || result_value(e, problem.objective) > result_value(evaluations[*best], problem.objective)))
        best = evaluations.size() - 1;
      {
        const std::lock_guard<std::mutex> guard(mutex);
        numbers.push_back(table ? table->record(e) : evaluations.size());
        if (!options.quiet) {
          std::string line =
              "optimize: " +
              (starts.size() > 1 ? "start " + std::to_string(start + 1) + ", " : std::string()) +
              "evaluation " + std::to_string(numbers.back()) + " (" +
              (e.message == "kept" ? "kept"
               : e.status == "ok"  ? "run"
                                   : e.status) +
              ")  " + sweep::describe(e.point) + "  " + objective_key + " " +
              (e.status == "ok" ? short_number(result_value(e, problem.objective))
                                : std::string("none (no result)"));
          if (!feasible(problem, e) && e.status == "ok") line += " (violates a constraint)";
          if (best)
            line += "  | best " + short_number(result_value(evaluations[*best], problem.objective)) +
                    " at evaluation " + std::to_string(numbers[*best]);
          if (world.active()) line += "  (rank " + std::to_string(world.rank()) + ")";
          std::fprintf(stderr, "%s\n", line.c_str());
        }
      }
      if (eval.error) std::rethrow_exception(eval.error);
      PointValue v;
      v.objective = result_value(e, problem.objective);
      if (!std::isfinite(v.objective))
        throw InputError("", 0, "--maximize",
                         "'" + objective_key + "' is not set by a run of this case at " + sweep::describe(e.point) +
                             " (e.g. a result of runs in air in a case in vacuum); see evaluations.csv");
      for (const Constraint& c : problem.constraints) {
        const double cv = result_value(e, c.result);
        if (!std::isfinite(cv))
          throw InputError("", 0, "--constraint",
                           "'" + c.text + "': the result is not set by a run of this case at " +
                               sweep::describe(e.point));
        v.violations.push_back(scaled_violation(c, cv));
      }
      return v;
    };
    SearchOptions so = options.search;
    so.algorithm = report.algorithm;
    std::string first_line;
    try {
      const SearchResult sr = search(lo, hi, starts[start], problem.constraints.size(), so, evaluate);
      o.status = "ok";
      first_line = (sr.max_evaluations_reached ? "max " : "done ") + sr.stop_reason;
    } catch (const app::Interrupted& e) {
      o.status = "interrupted";
      first_line = e.what();
    } catch (const NumericalFailure& e) {
      o.status = "failed";  // the start's search ends at the failed run; the other starts go on
      first_line = std::string("failed ") + e.what();
    } catch (const InvalidPoint& e) {
      o.status = "failed";  // as a failed run: the other starts go on
      first_line = std::string("failed: ") + e.what();
      if (!options.quiet) {
        const std::lock_guard<std::mutex> guard(mutex);
        std::fprintf(stderr, "optimize: %s%s; the start's search ends here\n",
                     starts.size() > 1 ? ("start " + std::to_string(start + 1) + ", ").c_str() : "",
                     e.what());
      }
    } catch (const InputError& e) {
      o.status = "input";
      first_line = e.what();
    } catch (const std::exception& e) {
      o.status = "error";
      first_line = e.what();
    }
    o.message = encode_start(first_line, evaluations);
    return o;
  };
  std::vector<std::optional<std::vector<Evaluation>>> by_start(starts.size());
  std::vector<std::string> stop_lines(starts.size());
  std::optional<std::size_t> failed_start;
  bool any_failed = false;
  std::string failed_status;
  const sweep::CaseDone done = [&](std::size_t start, sweep::CaseOutcome&& o) {
    if (o.status == "not run") return;
    std::vector<Evaluation> evaluations =
        decode_start(problem, o.message, eo.runs_dir, o.rank, o.host, stop_lines[start]);
    {
      const std::lock_guard<std::mutex> guard(mutex);
      for (const Evaluation& e : evaluations) (void)table->record(e);
    }
    by_start[start] = std::move(evaluations);
    if (o.status == "failed") any_failed = true;
    if (o.status != "ok" && o.status != "failed" && !failed_start) {
      failed_start = start;
      failed_status = o.status;
    }
  };
  std::vector<std::size_t> todo(starts.size());
  for (std::size_t i = 0; i < todo.size(); ++i) todo[i] = i;
  (void)sweep::schedule_cases(world, todo, 1, run, done);
  if (!report.root) return report;
  if (failed_start) {
    const std::string& why = stop_lines[*failed_start];
    if (failed_status == "input") throw InputError::relayed(why);
    if (failed_status == "interrupted") {
      const int signal = app::pending_interrupt() != 0 ? app::pending_interrupt() : SIGINT;
      throw app::Interrupted(signal, why + "; the same command again goes on from the points evaluated so far");
    }
    throw std::runtime_error(why);
  }
  if (const int signal = app::pending_interrupt(); signal != 0)
    throw app::Interrupted(signal, std::string("optimisation interrupted by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM") +
                                       "; the same command again goes on from the points evaluated so far");

  // 3. The optimum over every start (in the order of the starts: the same on any number of
  //    ranks) and the report.
  report.starts = starts.size();
  for (std::size_t s = 0; s < by_start.size(); ++s) {
    if (!by_start[s]) continue;
    const std::string& line = stop_lines[s];
    report.stop_reason += (report.stop_reason.empty() ? "" : "; ") +
                          (starts.size() > 1 ? "start " + std::to_string(s + 1) + ": " : std::string()) +
                          (line.rfind("failed ", 0) == 0 ? "a run failed, so the search stopped: " : "") +
                          line.substr(line.find(' ') + 1);
    if (line.rfind("max ", 0) == 0) report.max_evaluations_reached = true;
    for (Evaluation& e : *by_start[s]) {
      report.numbers.push_back(table->record(e));
      if (e.message != "kept") ++report.runs;
      report.evaluations.push_back(std::move(e));
      report.start_of.push_back(s + 1);
      const Evaluation& last = report.evaluations.back();
      if (feasible(problem, last) && std::isfinite(result_value(last, problem.objective)) &&
          (!report.best ||
           result_value(last, problem.objective) > result_value(report.evaluations[*report.best], problem.objective)))
        report.best = report.evaluations.size() - 1;
    }
  }
  if (report.best) {
    const Evaluation& best = report.evaluations[*report.best];
    const WrittenCase w = write_case_at(
        inputs, best.point, options.output_dir, "optimum",
        "The case at the optimum of flapsim optimize (" + objective_key + " = " +
            short_number(result_value(best, problem.objective)) + ", the run in runs/" + best.inputs_hash +
            "/),\nfrom " + case_file +
            " with " + sweep::describe(best.point) + ". Run it with flapsim run.");
    report.optimum_case = w.case_file;
    report.optimum_spring_scale = w.spring_scale;
  }
  report.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
  write_optimize_report(options.output_dir, case_file, problem, report);
  if (!report.best && any_failed)
    throw NumericalFailure("no evaluated point completed and satisfied the constraints; " + report.stop_reason +
                           " (" + (options.output_dir / "report.md").string() + ")");
  if (!report.best) {
    std::string constraints;
    for (const Constraint& c : problem.constraints) constraints += (constraints.empty() ? "" : ", ") + c.text;
    throw InputError("", 0, "--constraint",
                     "no evaluated point satisfies " + constraints + " (" + std::to_string(report.evaluations.size()) +
                         " evaluations; " + (options.output_dir / "report.md").string() +
                         " lists them): relax the constraint or widen the bounds; no optimum.toml written");
  }
  return report;
}

}  // namespace flapsim::optimize
