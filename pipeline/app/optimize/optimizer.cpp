#include "pipeline/app/optimize/optimizer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pipeline/app/optimize/optimize_report.hpp"
#include "pipeline/app/optimize/optimum_case.hpp"
#include "pipeline/app/optimize/point_evaluator.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/folder_lock.hpp"
#include "wings/input_error.hpp"

namespace flapsim::optimize {

namespace {

using Clock = std::chrono::steady_clock;

sweep::CasePoint point_of(const Problem& p, const std::vector<double>& x) {
  sweep::CasePoint point;
  for (std::size_t i = 0; i < p.bounds.size(); ++i) point.push_back({p.bounds[i].key, x[i]});
  return point;
}

// A point that does not resolve is a bad --vary (a key the case does not have, a bound
// that makes an invalid case): the message names the option and keeps the file's words.
void check_resolves(const PointEvaluator& evaluator, const sweep::CasePoint& point) {
  try {
    (void)evaluator.resolve(point);
  } catch (const InputError& e) {
    throw InputError(e.file(), e.line(), "--vary",
                     (e.key().empty() ? "" : "key '" + e.key() + "': ") + e.message());
  }
}

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

  const sweep::SweepInputs inputs{case_file, options.chain_file, options.spring_scale};
  EvaluatorOptions eo;
  eo.runs_dir = options.output_dir / "runs";
  eo.vtk_every = options.vtk_every;
  eo.force = options.force;
  const PointEvaluator evaluator(inputs, eo);

  // 1. The start and the bounds, checked before anything is written.
  std::vector<double> lo, hi;
  for (const Bound& b : problem.bounds) {
    const std::optional<double> own = value_in_inputs(inputs, b.key);
    report.start.push_back(own ? std::clamp(*own, b.lo, b.hi) : 0.5 * (b.lo + b.hi));
    lo.push_back(b.lo);
    hi.push_back(b.hi);
  }
  check_resolves(evaluator, point_of(problem, report.start));
  for (std::size_t i = 0; i < problem.bounds.size(); ++i)
    for (const double edge : {lo[i], hi[i]}) {
      std::vector<double> x = report.start;
      x[i] = edge;
      check_resolves(evaluator, point_of(problem, x));
    }

  io::ensure_directory(options.output_dir);
  const io::FolderLock lock(options.output_dir, "optimize");  // no other command writes into DIR meanwhile
  std::vector<std::string> keys;
  for (const Bound& b : problem.bounds) keys.push_back(b.key);
  EvaluationTable table(options.output_dir / "evaluations.csv", keys);

  // 2. The search.
  const std::string objective_key(app::kRunResults[problem.objective].key);
  const Evaluate evaluate = [&](const std::vector<double>& x) {
    EvaluationOutcome o = evaluator.evaluate(point_of(problem, x));
    const std::size_t number = table.record(o.evaluation);
    report.evaluations.push_back(o.evaluation);
    report.numbers.push_back(number);
    if (o.evaluation.message != "kept") ++report.runs;
    const Evaluation& e = report.evaluations.back();
    if (feasible(problem, e) && std::isfinite(result_value(e, problem.objective)) &&
        (!report.best || result_value(e, problem.objective) > result_value(report.evaluations[*report.best], problem.objective)))
      report.best = report.evaluations.size() - 1;
    if (!options.quiet) {
      std::string line = "optimize: evaluation " + std::to_string(report.evaluations.size()) + " (" +
                         (e.message == "kept" ? "kept" : e.status == "ok" ? "run" : e.status) + ")  " +
                         sweep::describe(e.point) + "  " + objective_key + " " +
                         short_number(result_value(e, problem.objective));
      if (!feasible(problem, e) && e.status == "ok") line += " (violates a constraint)";
      if (report.best)
        line += "  | best " + short_number(result_value(report.evaluations[*report.best], problem.objective)) +
                " at evaluation " + std::to_string(*report.best + 1);
      std::fprintf(stderr, "%s\n", line.c_str());
    }
    if (o.error) std::rethrow_exception(o.error);
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
  const SearchResult sr = search(lo, hi, report.start, problem.constraints.size(), so, evaluate);
  report.stop_reason = sr.stop_reason;
  report.max_evaluations_reached = sr.max_evaluations_reached;

  // 3. The optimum and the report.
  if (report.best) {
    const Evaluation& best = report.evaluations[*report.best];
    const WrittenCase w = write_case_at(
        inputs, best.point, options.output_dir, "optimum",
        "The case at the optimum of flapsim optimize (" + objective_key + " = " +
            short_number(result_value(best, problem.objective)) + ", evaluation " +
            std::to_string(report.numbers[*report.best]) + " of DIR/evaluations.csv),\nfrom " + case_file +
            " with " + sweep::describe(best.point) + ". Run it with flapsim run.");
    report.optimum_case = w.case_file;
    report.optimum_spring_scale = w.spring_scale;
  }
  report.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
  write_optimize_report(options.output_dir, case_file, problem, report);
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
