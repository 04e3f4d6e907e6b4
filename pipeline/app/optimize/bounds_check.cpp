#include "pipeline/app/optimize/bounds_check.hpp"

#include <string>

#include "pipeline/app/sweep/keys_that_change_nothing.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::optimize {

namespace {

// The inner value of a key, this fraction of the way from LO to HI (1/π: no whole number,
// so an integer key, which NLopt's values would break mid-search, is refused).
constexpr double kInnerFraction = 0.31830988618379067;

// A point that does not resolve is a bad --vary (a key the case does not have, a bound
// that makes an invalid case): the message names the option and keeps the file's words.
sweep::ResolvedCase resolved_or_refused(const PointEvaluator& evaluator, const sweep::CasePoint& point) {
  try {
    return evaluator.resolve(point);
  } catch (const InputError& e) {
    throw InputError(e.file(), e.line(), "--vary",
                     (e.key().empty() ? "" : "key '" + e.key() + "': ") + e.message());
  }
}

}  // namespace

void check_start_and_bounds(const PointEvaluator& evaluator, const Problem& problem,
                            const std::vector<double>& start, int vtk_every) {
  const sweep::SweepInputs& inputs = evaluator.inputs();
  sweep::VariedKeys varied{"optimisation", {}, {}, inputs.case_file, 0};
  for (const Bound& b : problem.bounds) {
    varied.keys.push_back(b.key);
    varied.given.push_back("--vary " + b.key + "=" + io::format_number(b.lo) + ":" + io::format_number(b.hi));
  }
  // output.vtk_every first: its inner value would be refused as that of an integer key.
  sweep::refuse_interval_the_command_sets(varied, vtk_every);

  std::vector<sweep::CasePoint> points{point_at(problem, start)};
  for (std::size_t i = 0; i < problem.bounds.size(); ++i) {
    const Bound& b = problem.bounds[i];
    for (const double value : {b.lo, b.hi, b.lo + (b.hi - b.lo) * kInnerFraction}) {
      std::vector<double> x = start;
      x[i] = value;
      points.push_back(point_at(problem, x));
    }
  }
  std::vector<sweep::ResolvedCase> cases;
  for (const sweep::CasePoint& point : points) cases.push_back(resolved_or_refused(evaluator, point));
  sweep::refuse_keys_that_change_nothing(varied, inputs, points, cases, vtk_every);
}

}  // namespace flapsim::optimize
